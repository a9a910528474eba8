// SPDX-License-Identifier: BSL-1.0
// The C API's single steps (src/capi_impl.hpp) compiled here with ODESTEP_C_EXACT_STATES 2, so that both of
// their forms run: n = 1 and 2 compiled for n, n = 3 .. ODESTEP_C_MAX_STATES the form over a run-time n (for
// the explicit Runge-Kutta methods, src/capi_rk.hpp; padded for Adams and velocity Verlet). Expected values:
// the C++ steppers called directly on std::array<double, n> (each component's arithmetic is theirs), and
// RK4 written out by hand. Also the binding a step checks instead of the method and n: a new n starts
// afresh, the bound one continues, a loop's history goes on in single steps, and every status of the header
// on a bound stepper, with the caller's state untouched. (The library's own tests, tests/c/, run the
// default build, where no n is compiled on its own.)
#include "methods.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <utility>

#include "support/compare.hpp"

namespace {

namespace capi = odestep::capi;

using capi_test::ab4_method;
using capi_test::dop853_method;
using capi_test::dp54_method;
using capi_test::midpoint_method;
using capi_test::rk4_method;
using capi_test::verlet_method;

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinite = std::numeric_limits<double>::infinity();

// y_i' = -(i + 1) y_i / 4 + sin t, written for the C API (n components) and for the C++ steppers.
void decay_c(double t, const double* y, double* d, void* ctx) {
    const std::size_t n = *static_cast<const std::size_t*>(ctx);
    for (std::size_t i = 0; i < n; ++i) d[i] = -static_cast<double>(i + 1) / 4.0 * y[i] + std::sin(t);
}
template <std::size_t N>
void decay_cpp(double t, const std::array<double, N>& y, std::array<double, N>& d) {
    for (std::size_t i = 0; i < N; ++i) d[i] = -static_cast<double>(i + 1) / 4.0 * y[i] + std::sin(t);
}

template <std::size_t N>
void compare_rk4() {
    std::size_t n = N;
    const odestep_system_d sys{decay_c, &n, N};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &rk4_method) == ODESTEP_OK);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 + 0.5 * static_cast<double>(i);
    std::array<double, N> expected = y;
    for (int k = 0; k < 10; ++k) {
        const double t = 0.1 * k;
        REQUIRE(capi::step<double>(&s, &sys, y.data(), t, 0.1, nullptr, nullptr) == ODESTEP_OK);
        REQUIRE(odestep::rk4<std::array<double, N>>{}.step(decay_cpp<N>, expected, t, 0.1) == odestep::status::ok);
    }
    CHECK(odestep_test::same_bits(y, expected));
}
template <std::size_t... I>
void compare_rk4_sizes(std::index_sequence<I...>) {
    (compare_rk4<I + 1>(), ...);
}

// Classic RK4 written out here (Kutta 1901; Hairer, Norsett and Wanner, Solving ODE I, Table II.1.1):
// y + h/6 (k1 + 2 k2 + 2 k3 + k4), an implementation that shares nothing with odestep's templates.
template <std::size_t N>
std::array<double, N> hand_rk4(std::array<double, N> y, double t, double h) {
    std::size_t n = N;
    std::array<double, N> k1, k2, k3, k4, yt;
    decay_c(t, y.data(), k1.data(), &n);
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h / 2 * k1[i];
    decay_c(t + h / 2, yt.data(), k2.data(), &n);
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h / 2 * k2[i];
    decay_c(t + h / 2, yt.data(), k3.data(), &n);
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k3[i];
    decay_c(t + h, yt.data(), k4.data(), &n);
    for (std::size_t i = 0; i < N; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return y;
}

// 20 steps of h = 0.1 through the C API against hand_rk4. The two sum the stages in different orders, so
// they agree to round-off, not bit for bit: a relative 1e-14 (y is of order 1, each step adds a few ulp of
// rounding to either side); a wrong component, a padding that leaked into the first n or a stage of
// another size would differ by far more (one step's RK4 increment here is of order 1e-2).
template <std::size_t N>
void compare_hand_rk4() {
    std::size_t n = N;
    const odestep_system_d sys{decay_c, &n, N};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &rk4_method) == ODESTEP_OK);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 - 0.25 * static_cast<double>(i);
    std::array<double, N> hand = y;
    for (int k = 0; k < 20; ++k) {
        const double t = 0.1 * k;
        REQUIRE(capi::step<double>(&s, &sys, y.data(), t, 0.1, nullptr, nullptr) == ODESTEP_OK);
        hand = hand_rk4(hand, t, 0.1);
    }
    for (std::size_t i = 0; i < N; ++i) CHECK(std::fabs(y[i] - hand[i]) <= 1e-14 * std::fmax(1.0, std::fabs(hand[i])));
}

// The estimating step (odestep_step_error_d's path) against the C++ Dormand-Prince step with its estimate.
template <std::size_t N>
void compare_dp54_error() {
    std::size_t n = N;
    const odestep_system_d sys{decay_c, &n, N};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &dp54_method) == ODESTEP_OK);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 + 0.5 * static_cast<double>(i);
    std::array<double, N> expected = y;
    std::array<double, N> error{};
    std::array<double, N> expected_error{};
    for (int k = 0; k < 5; ++k) {
        const double t = 0.2 * k;
        REQUIRE(capi::step<double>(&s, &sys, y.data(), t, 0.2, error.data(), nullptr) == ODESTEP_OK);
        REQUIRE(odestep::dormand_prince54<std::array<double, N>>{}.step(decay_cpp<N>, expected, t, 0.2,
                                                                        expected_error) == odestep::status::ok);
    }
    CHECK(odestep_test::same_bits(y, expected));
    CHECK(odestep_test::same_bits(error, expected_error));
    // A step that makes NaN (t = NaN reaches f only through sin t: refused before as invalid_time, so a
    // state of NaN instead) leaves y and the estimate as they were.
    const std::array<double, N> kept = y;
    const std::array<double, N> kept_error = error;
    y[0] = not_a_number;
    CHECK(capi::step<double>(&s, &sys, y.data(), 1.0, 0.2, error.data(), nullptr) == ODESTEP_NON_FINITE);
    CHECK(std::isnan(y[0]));
    for (std::size_t i = 1; i < N; ++i) CHECK(y[i] == kept[i]);
    CHECK(odestep_test::same_bits(error, kept_error));
}

// DOP853's two estimates (the estimating step with e2) against the C++ step, bit for bit.
template <std::size_t N>
void compare_dop853_two_estimates() {
    std::size_t n = N;
    const odestep_system_d sys{decay_c, &n, N};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &dop853_method) == ODESTEP_OK);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 + 0.5 * static_cast<double>(i);
    std::array<double, N> expected = y;
    std::array<double, N> e1{};
    std::array<double, N> e2{};
    std::array<double, N> expected_e1{};
    std::array<double, N> expected_e2{};
    for (int k = 0; k < 3; ++k) {
        const double t = 0.25 * k;
        REQUIRE(capi::step<double>(&s, &sys, y.data(), t, 0.25, e1.data(), e2.data()) == ODESTEP_OK);
        REQUIRE(odestep::dop853<std::array<double, N>>{}.step(decay_cpp<N>, expected, t, 0.25, expected_e1,
                                                              expected_e2) == odestep::status::ok);
    }
    CHECK(odestep_test::same_bits(y, expected));
    CHECK(odestep_test::same_bits(e1, expected_e1));
    CHECK(odestep_test::same_bits(e2, expected_e2));
}

// y_i' = y_i * 1e300 for the last component, -y_i for the others: from a last component of 1e10 the first stage
// overflows to Inf there (every other component stays finite).
void blow_up_last(double, const double* y, double* d, void* ctx) {
    const std::size_t n = *static_cast<const std::size_t*>(ctx);
    for (std::size_t i = 0; i < n; ++i) d[i] = i + 1 == n ? y[i] * 1e300 : -y[i];
}

// A step that is not finite in its last component only puts every component back, bit for bit (the step
// over n writes y_{n+1} over y before its test and puts y_n back): -0.0 and a subnormal included.
template <std::size_t N>
void roll_back_every_component() {
    std::size_t n = N;
    const odestep_system_d sys{blow_up_last, &n, N};
    for (const odestep_method_d* method : {&rk4_method, &dp54_method}) {
        odestep_stepper_d s;
        REQUIRE(capi::init<double>(&s, method) == ODESTEP_OK);
        std::array<double, N> y{};
        for (std::size_t i = 0; i < N; ++i) y[i] = 0.5 + static_cast<double>(i);
        y[0] = -0.0;
        if (N > 2) y[1] = std::numeric_limits<double>::denorm_min();
        y[N - 1] = 1e10;
        const std::array<double, N> kept = y;
        CHECK(capi::step<double>(&s, &sys, y.data(), 0.0, 0.1, nullptr, nullptr) == ODESTEP_NON_FINITE);
        CHECK(odestep_test::same_bits(y, kept));
        std::array<double, N> error{};
        const std::array<double, N> kept_error = error;
        if (method == &dp54_method) {
            CHECK(capi::step<double>(&s, &sys, y.data(), 0.0, 0.1, error.data(), nullptr) == ODESTEP_NON_FINITE);
            CHECK(odestep_test::same_bits(y, kept));
            CHECK(odestep_test::same_bits(error, kept_error));
        }
    }
}

// A forcing y_i' = g(t) that is NaN at its first call only: the midpoint rule's first stage k1 has weight 0
// (y + h k2), so its NaN reaches no result; the step still reports it (explicit_rk's test of the stages no
// weight reaches), and the C step agrees with the C++ one.
struct first_call_nan {
    std::size_t n;
    int calls;
};
void forcing_c(double t, const double*, double* d, void* ctx) {
    auto* c = static_cast<first_call_nan*>(ctx);
    const double g = c->calls++ == 0 ? std::numeric_limits<double>::quiet_NaN() : std::cos(t);
    for (std::size_t i = 0; i < c->n; ++i) d[i] = g;
}
template <std::size_t N>
void unweighted_stage_not_finite() {
    first_call_nan c{N, 0};
    const odestep_system_d sys{forcing_c, &c, N};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &midpoint_method) == ODESTEP_OK);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = static_cast<double>(i);
    const std::array<double, N> kept = y;
    CHECK(capi::step<double>(&s, &sys, y.data(), 0.0, 0.1, nullptr, nullptr) == ODESTEP_NON_FINITE);
    CHECK(odestep_test::same_bits(y, kept));
    first_call_nan cpp_calls{N, 0};
    std::array<double, N> cpp = kept;
    const auto f = [&cpp_calls](double t, const std::array<double, N>& in, std::array<double, N>& d) {
        forcing_c(t, in.data(), d.data(), &cpp_calls);
    };
    CHECK(odestep::euler_richardson<std::array<double, N>>{}.step(f, cpp, 0.0, 0.1) == odestep::status::non_finite);
    // The next step (no NaN any more) is good in both.
    CHECK(capi::step<double>(&s, &sys, y.data(), 0.0, 0.1, nullptr, nullptr) == ODESTEP_OK);
    CHECK(odestep::euler_richardson<std::array<double, N>>{}.step(f, cpp, 0.0, 0.1) == odestep::status::ok);
    CHECK(odestep_test::same_bits(y, cpp));
}

}  // namespace

TEST_CASE(
    "C API single steps: the step over n puts every component back when it fails, and tests the stages no "
    "weight reaches") {
    roll_back_every_component<1>();
    roll_back_every_component<3>();
    roll_back_every_component<capi::max_states>();
    unweighted_stage_not_finite<3>();
    unweighted_stage_not_finite<capi::max_states>();
}

TEST_CASE("C API single steps: DOP853's two estimates over n give the C++ step's bit for bit") {
    compare_dop853_two_estimates<1>();
    compare_dop853_two_estimates<3>();
    compare_dop853_two_estimates<capi::max_states>();
}

TEST_CASE("C API single steps: n = 1 (exact), 2 (exact), 3 and MAX (padded) give RK4 written out by hand") {
    compare_hand_rk4<1>();
    compare_hand_rk4<2>();
    compare_hand_rk4<3>();
    compare_hand_rk4<capi::max_states>();
}

TEST_CASE("C API single steps: the estimating step, exact and padded, gives the C++ step and its estimate") {
    compare_dp54_error<1>();
    compare_dp54_error<2>();
    compare_dp54_error<3>();
    compare_dp54_error<capi::max_states>();
}

TEST_CASE("C API single steps: every n, exact or padded, gives the C++ step on std::array<double, n> bit for bit") {
    static_assert(capi::max_states >= 3, "the test needs a padded size");
    compare_rk4_sizes(std::make_index_sequence<capi::max_states>{});
}

TEST_CASE("C API single steps: Adams continues its bound n, starts afresh on another, and continues a loop") {
    std::size_t n2 = 2, n3 = 3;
    const odestep_system_d sys2{decay_c, &n2, 2};
    const odestep_system_d sys3{decay_c, &n3, 3};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &ab4_method) == ODESTEP_OK);
    std::array<double, 2> y{1.0, 2.0};
    for (int k = 0; k < 5; ++k) REQUIRE(capi::step<double>(&s, &sys2, y.data(), 0.1 * k, 0.1, nullptr, nullptr) == 0);
    const std::array<double, 2> kept = y;
    CHECK(capi::step<double>(&s, &sys2, y.data(), 0.0, 0.1, nullptr, nullptr) == ODESTEP_STEP_MISMATCH);
    CHECK(odestep_test::same_bits(y, kept));
    // Another n: a new object of its size, an empty history, so any t is accepted.
    std::array<double, 3> z{1.0, 2.0, 3.0};
    CHECK(capi::step<double>(&s, &sys3, z.data(), 7.0, 0.25, nullptr, nullptr) == ODESTEP_OK);
    // Back to n = 2: afresh again (the history of n = 2 is gone), so the old grid's time is not required.
    CHECK(capi::step<double>(&s, &sys2, y.data(), 3.0, 0.5, nullptr, nullptr) == ODESTEP_OK);

    // A loop (padded object), then single steps of its n: its history goes on (the C++ stepper's result),
    // and a step off its grid is refused. n = 2 and n = 3 (exact and padded single-step sizes alike).
    for (const odestep_system_d* sys : {&sys2, &sys3}) {
        // (c as long as the padded state: GCC's -Warray-bounds cannot see that the loop reads only n of it)
        std::array<double, capi::max_states> c{1.0, 2.0, 3.0};
        std::array<double, 3> cpp{1.0, 2.0, 3.0};
        REQUIRE(capi::integrate<double>(&s, sys, c.data(), 0.0, 1.0, 0.125, nullptr, nullptr, nullptr) == ODESTEP_OK);
        CHECK(capi::step<double>(&s, sys, c.data(), 0.5, 0.125, nullptr, nullptr) == ODESTEP_STEP_MISMATCH);
        REQUIRE(capi::step<double>(&s, sys, c.data(), 1.0, 0.125, nullptr, nullptr) == ODESTEP_OK);
        odestep::adams_bashforth4<std::array<double, 3>> ab4;
        std::size_t n = sys->n;
        const auto f = [&n](double t, const std::array<double, 3>& y3, std::array<double, 3>& d) {
            decay_c(t, y3.data(), d.data(), &n);
            for (std::size_t i = n; i < 3; ++i) d[i] = 0.0;
        };
        if (n == 2) cpp[2] = 0.0;
        REQUIRE(odestep::integrate_n_steps(ab4, f, cpp, 0.0, 0.125, 9).status == odestep::status::ok);
        for (std::size_t i = 0; i < n; ++i) CHECK(c[i] == cpp[i]);
    }
}

TEST_CASE("C API single steps: a bound stepper still refuses every bad argument and touches nothing") {
    std::size_t n2 = 2;
    odestep_system_d sys{decay_c, &n2, 2};
    odestep_stepper_d s;
    REQUIRE(capi::init<double>(&s, &rk4_method) == ODESTEP_OK);
    std::array<double, 2> y{1.0, 2.0};
    REQUIRE(capi::step<double>(&s, &sys, y.data(), 0.0, 0.1, nullptr, nullptr) == ODESTEP_OK);  // bound to n = 2
    const std::array<double, 2> kept = y;
    for (const double t : {not_a_number, infinite, -infinite})
        CHECK(capi::step<double>(&s, &sys, y.data(), t, 0.1, nullptr, nullptr) == ODESTEP_INVALID_TIME);
    for (const double dt : {0.0, -0.0, not_a_number, infinite, -infinite})
        CHECK(capi::step<double>(&s, &sys, y.data(), 0.1, dt, nullptr, nullptr) == ODESTEP_INVALID_STEP);
    CHECK(capi::step<double>(&s, &sys, nullptr, 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
    CHECK(capi::step<double>(nullptr, &sys, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
    CHECK(capi::step<double>(&s, nullptr, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
    for (const std::size_t bad_n : {std::size_t{0}, capi::max_states + 1, ~std::size_t{0}}) {
        sys.n = bad_n;
        CHECK(capi::step<double>(&s, &sys, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
    }
    sys.n = 2;
    sys.f = nullptr;
    CHECK(capi::step<double>(&s, &sys, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
    sys.f = decay_c;
    double e[2] = {0.0, 0.0};  // rk4 has no estimate
    CHECK(capi::step<double>(&s, &sys, y.data(), 0.1, 0.1, e, nullptr) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_test::same_bits(y, kept));
    // Bound to a first-order n, a Newtonian step of that n is refused (the kinds are bound apart).
    const odestep_newton_d newton{decay_c, &n2, 2};
    double v[2] = {0.0, 0.0};
    CHECK(capi::step_newton<double>(&s, &newton, y.data(), v, nullptr, 0.1, 0.1) == ODESTEP_INVALID_SETTING);

    // A zeroed stepper (never initialised: no method, nothing bound) refuses every n, 0 included.
    odestep_stepper_d zeroed;
    std::memset(&zeroed, 0, sizeof zeroed);
    for (const std::size_t any_n : {std::size_t{0}, std::size_t{1}, std::size_t{2}}) {
        sys.n = any_n;
        CHECK(capi::step<double>(&zeroed, &sys, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
        const odestep_newton_d nz{decay_c, &n2, any_n};
        CHECK(capi::step_newton<double>(&zeroed, &nz, y.data(), v, nullptr, 0.1, 0.1) == ODESTEP_INVALID_SETTING);
    }
    CHECK(odestep_test::same_bits(y, kept));

    // A Newtonian method bound to its n refuses a first-order step of that n.
    odestep_stepper_d vv;
    REQUIRE(capi::init<double>(&vv, &verlet_method) == ODESTEP_OK);
    double x[2] = {1.0, 0.0};
    REQUIRE(capi::step_newton<double>(&vv, &newton, x, v, nullptr, 0.0, 0.1) == ODESTEP_OK);
    sys.n = 2;
    CHECK(capi::step<double>(&vv, &sys, y.data(), 0.1, 0.1, nullptr, nullptr) == ODESTEP_INVALID_SETTING);
}
