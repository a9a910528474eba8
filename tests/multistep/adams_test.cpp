// SPDX-License-Identifier: BSL-1.0
// The Adams multistep steppers: coefficients, observed order, the self-start, the history checks
// (step_mismatch), rollback of a non-finite step, the fixed-step loops and the evaluation counts.
#include <doctest/doctest.h>
#include <odestep/integrate.hpp>
#include <odestep/multistep/adams.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/methods.hpp"
#include "support/order_fit.hpp"
#include "support/problems.hpp"
#include "support/type_list.hpp"

namespace {

namespace tables = odestep::adams_tables;

using odestep_test::adams_methods;
using odestep_test::exp_sin;
using odestep_test::for_each_type;
using odestep_test::same_bits;
using odestep_test::state3;

// The test problem of observed_order_test.cpp (problems.hpp), y0' = y0 y1, y1' = -y2, y2' = y1, in double.
using state = state3<double>;

// exp_sin that counts its calls, and returns `poison` in its first component on call number `poisoned`
// (counting from 1; 0 never).
struct counting_exp_sin {
    std::size_t* calls;
    std::size_t poisoned = 0;
    double poison = std::numeric_limits<double>::quiet_NaN();
    void operator()(double t, const state& y, state& dydt) const noexcept {
        odestep_test::counting<exp_sin>{{}, calls}(t, y, dydt);
        if (*calls == poisoned) dydt[0] = poison;
    }
};

// The start state (1, 1, 0), read through a volatile so that no compiler can see its value. The bit-for-bit
// comparisons below compare the same arithmetic in two places, and clang (whose default is
// -ffp-contract=on) rounds x * y + z once where it folds it at compile time but twice at run time: a
// run whose start it could see might differ in the last bit from the same run on a run-time state.
state opaque_start() {
    volatile double one = 1.0;
    volatile double zero = 0.0;
    return state{one, one, zero};
}
const state y_start = opaque_start();

// ---------------------------------------------------------------------------------------------------------
// Coefficients

// The largest residual of the first `conditions` order conditions sum_j w_j s_j^q = 1/(q+1), q < conditions,
// each relative to the magnitude of its terms; and the residual of the condition q = conditions.
// Normalisation: y(t_n + h) - y(t_n) = h * integral_0^1 f(t_n + s h) ds, and a weight vector with nodes s_j
// (s_j = -j for Adams-Bashforth, s_j = 1 - j for Adams-Moulton) is exact for f = s^q iff the condition holds.
template <std::size_t K>
void order_residuals(const std::array<long double, K>& w, long double first_node, long double& worst_relative,
                     long double& next_residual) {
    worst_relative = 0;
    for (std::size_t q = 0; q <= K; ++q) {
        long double sum = 0;
        long double magnitude = 1.0L / static_cast<long double>(q + 1);
        for (std::size_t j = 0; j < K; ++j) {
            const long double s = first_node - static_cast<long double>(j);
            long double power = 1;  // s^q, with 0^0 = 1
            for (std::size_t i = 0; i < q; ++i) power *= s;
            sum += w[j] * power;
            magnitude += std::fabs(w[j] * power);
        }
        const long double residual = sum - 1.0L / static_cast<long double>(q + 1);
        if (q < K) {
            const long double relative = std::fabs(residual) / magnitude;
            if (relative > worst_relative) worst_relative = relative;
        } else {
            next_residual = residual;
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// Observed order

// Largest component error at t_end after `steps` steps in T.
template <class M, class T>
T error_after(T t_end, std::size_t steps) {
    return odestep_test::error_after<odestep::adams<M, state3<T>>, exp_sin>(t_end, steps);
}

// The coarsest step count of the fit (then 2x, 4x, 8x), at t_end = 20. Chosen from the local slopes
// log2(e(N) / e(2N)) in double:
//   AB2   N = 128 .. 1024: 1.99 1.98 2.02         (least squares 2.01)
//   AB3   N = 256 .. 2048: 2.96 2.98 2.99         (2.98; from N = 128 it is 2.94, the N = 128 error is pre-asymptotic)
//   AB4   N = 512 .. 4096: 4.13 4.07 4.04         (4.08; from N = 128 4.23: the h^5 term still shows)
//   AB5   N = 256 .. 2048: 5.03 5.01 5.00         (5.01)
//   ABM4  N = 2048 .. 16384: 4.15 4.08 4.04       (4.09; the excess over 4 halves with h, an h^5 term, and
//                                                  from N = 512 the fit is 4.26; at N = 16384 the error is
//                                                  1.4e-12, within 1% of the long double error)
template <class M>
constexpr std::size_t coarsest_steps() {
    if constexpr (std::is_same_v<M, tables::bashforth2>)
        return 128;
    else if constexpr (std::is_same_v<M, tables::bashforth3>)
        return 256;
    else if constexpr (std::is_same_v<M, tables::bashforth4>)
        return 512;
    else if constexpr (std::is_same_v<M, tables::bashforth5>)
        return 256;
    else
        return 2048;
}

// ---------------------------------------------------------------------------------------------------------
// Reference runs

// A run of `steps` steps of dt from t = 0 with a fresh stepper, by hand, the state after each step kept.
template <class Stepper, std::size_t Steps>
std::array<state, Steps> clean_run(double dt) {
    Stepper stepper;
    state y = y_start;
    std::array<state, Steps> after{};
    for (std::size_t i = 0; i < Steps; ++i) {
        REQUIRE(stepper.step(exp_sin{}, y, static_cast<double>(i) * dt, dt) == odestep::status::ok);
        after[i] = y;
    }
    return after;
}

}  // namespace

// Compile-time: traits and types.
static_assert(std::is_same_v<odestep::adams_bashforth4<std::array<float, 2>>::value_type, float>);
static_assert(odestep::adams_bashforth5<std::array<float, 2>>::steps == 5);
static_assert(odestep::adams_bashforth2<std::array<double, 1>>::rhs_evals_per_step == 4);  // rk4's, starting
static_assert(
    odestep::adams_bashforth2<std::array<double, 1>, odestep::euler<std::array<double, 1>>>::rhs_evals_per_step == 1);
static_assert(odestep::adams_bashforth_moulton4<std::array<double, 1>,
                                                odestep::heun<std::array<double, 1>>>::rhs_evals_per_step == 2);

TEST_CASE(
    "adams: the traits say k steps, one stage, no estimate, self-starting, and the starter's evaluations as the most "
    "per step") {
    struct expected {
        int order;
        std::size_t steps, evals_started;
    };
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper = odestep::adams<M, state>;
        // From the formulas in multistep.hpp: AB-k has order k and reads k derivatives, one new per step;
        // ABM4 PECE has order 4 and evaluates twice per step.
        constexpr expected e = std::is_same_v<M, tables::bashforth2>   ? expected{2, 2, 1}
                               : std::is_same_v<M, tables::bashforth3> ? expected{3, 3, 1}
                               : std::is_same_v<M, tables::bashforth4> ? expected{4, 4, 1}
                               : std::is_same_v<M, tables::bashforth5> ? expected{5, 5, 1}
                                                                       : expected{4, 4, 2};
        INFO(doctest::String(M::name));
        CHECK(stepper::order == e.order);
        CHECK(stepper::steps == e.steps);
        CHECK(stepper::stages == 1);
        CHECK(stepper::rhs_evals_per_started_step == e.evals_started);
        CHECK(stepper::rhs_evals_per_step == 4);  // the rk4 starter's four
        CHECK_FALSE(stepper::error_estimate);
        CHECK_FALSE(stepper::symplectic);
        CHECK(stepper::self_starting);
    });
}

TEST_CASE("adams: each table satisfies its order conditions to long double round-off and fails the next one") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        constexpr auto tab = M::template table<long double>;
        constexpr std::size_t K = decltype(tab)::steps;
        long double worst = 0, next = 0;
        order_residuals(tab.beta, 0.0L, worst, next);  // Adams-Bashforth nodes s_j = -j
        INFO(doctest::String(M::name), ": worst relative residual ", static_cast<double>(worst),
             ", residual of condition q = k ", static_cast<double>(next));
        CHECK(worst <= 4 * std::numeric_limits<long double>::epsilon());
        CHECK(std::fabs(next) > 1e-2L);  // the next condition fails by far more than round-off
        CHECK(tab.order == static_cast<int>(K));
        if constexpr (decltype(tab)::has_corrector) {
            order_residuals(tab.gamma, 1.0L, worst, next);  // Adams-Moulton nodes s_j = 1 - j
            INFO("corrector: worst relative residual ", static_cast<double>(worst), ", next ",
                 static_cast<double>(next));
            CHECK(worst <= 4 * std::numeric_limits<long double>::epsilon());
            CHECK(std::fabs(next) > 1e-3L);
        }
    });
}

TEST_CASE("adams: y' = t^(k-1) is integrated exactly, with a starter exact for it too") {
    // The k-step formulas integrate a polynomial f(t) of degree k - 1 exactly, so y(t) = t^k / k; rk4 (Simpson's
    // rule for f(t)) is exact up to degree 3, Dormand-Prince 5 up to degree 4 (its quadrature order is 5).
    // dt = 1/8 and t = 2 are binary; what is left is round-off.
    auto check = [](auto stepper, int k) {
        using S = std::array<double, 1>;
        auto f = [k](double t, const S&) { return S{std::pow(t, k - 1)}; };
        S y{0.0};
        REQUIRE(odestep::integrate_n_steps(stepper, f, y, 0.0, 0.125, 16).status == odestep::status::ok);
        const double exact = std::pow(2.0, k) / k;
        INFO("k = ", k, ": y(2) = ", y[0], ", exact ", exact);
        CHECK(y[0] == doctest::Approx(exact).epsilon(1e-14));
    };
    using S = std::array<double, 1>;
    check(odestep::adams_bashforth2<S>{}, 2);
    check(odestep::adams_bashforth3<S>{}, 3);
    check(odestep::adams_bashforth4<S>{}, 4);
    check(odestep::adams_bashforth5<S, odestep::dormand_prince54<S>>{}, 5);
    check(odestep::adams_bashforth_moulton4<S>{}, 4);
}

TEST_CASE("adams: every method reaches its nominal order on y0' = y0 y1, y1' = -y2, y2' = y1 (slope within 0.2)") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        constexpr int order = odestep::adams<M, state>::order;
        const std::size_t n0 = coarsest_steps<M>();
        std::array<double, 4> errors{};
        for (std::size_t i = 0; i < errors.size(); ++i) errors[i] = error_after<M, double>(20.0, n0 << i);
        const double slope = odestep_test::fitted_order(errors);
        const auto local = odestep_test::local_slopes(errors);
        INFO(doctest::String(M::name), ": errors ", errors[0], " ", errors[1], " ", errors[2], " ", errors[3],
             "; local slopes ", local[0], " ", local[1], " ", local[2]);
        MESSAGE(doctest::String(M::name), ": order ", order, ", fitted slope ", slope, " (N = ", n0, " to ", n0 << 3,
                ", error ", errors[0], " to ", errors[3], ")");
        CHECK(std::fabs(slope - order) < 0.2);
        CHECK(errors[3] > 1e3 * std::numeric_limits<double>::epsilon());  // far above round-off
    });
}

TEST_CASE("adams: every method works in float and long double: the error is the double error to within round-off") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        const std::size_t n = coarsest_steps<M>();
        const double err_double = error_after<M, double>(20.0, n);
        const double err_float = static_cast<double>(error_after<M, float>(20.0f, n));
        const double err_long = static_cast<double>(error_after<M, long double>(20.0L, n));
        // Round-off: a few ULPs of the solution (|y| <= e) per step, growing at most like the step count.
        const double float_roundoff =
            8.0 * static_cast<double>(n) * static_cast<double>(std::numeric_limits<float>::epsilon());
        const double double_roundoff = 8.0 * static_cast<double>(n) * std::numeric_limits<double>::epsilon();
        INFO(doctest::String(M::name), ": float error ", err_float, ", double error ", err_double,
             ", long double error ", err_long, ", float allowance ", float_roundoff);
        CHECK(std::fabs(err_float - err_double) <= float_roundoff);
        CHECK(std::fabs(err_long - err_double) <= double_roundoff);
    });
}

TEST_CASE(
    "adams: with the history empty, the first k-1 steps are bit-identical to the starter's, then the formula takes "
    "over") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        auto compare = [](auto multistep, auto starter) {
            using stepper = decltype(multistep);
            const double dt = 0.1;
            state a = y_start;
            state b = y_start;
            std::size_t calls = 0;
            for (std::size_t i = 0; i + 1 < stepper::steps; ++i) {
                const double t = static_cast<double>(i) * dt;
                REQUIRE(multistep.step(exp_sin{}, a, t, dt) == odestep::status::ok);
                REQUIRE(starter.step(exp_sin{}, b, t, dt) == odestep::status::ok);
                CHECK(same_bits(a, b));
                CHECK(multistep.history_size() == i + 1);
            }
            // Step k is the formula's: different from the starter's, and one (AB) or two (PECE) evaluations.
            const double t = static_cast<double>(stepper::steps - 1) * dt;
            REQUIRE(multistep.step(counting_exp_sin{&calls}, a, t, dt) == odestep::status::ok);
            REQUIRE(starter.step(exp_sin{}, b, t, dt) == odestep::status::ok);
            CHECK_FALSE(same_bits(a, b));
            CHECK(calls == stepper::rhs_evals_per_started_step);
            CHECK(multistep.history_size() == stepper::steps - 1);
        };
        INFO(doctest::String(M::name));
        compare(odestep::adams<M, state>{}, odestep::rk4<state>{});
        compare(odestep::adams<M, state, odestep::heun<state>>{}, odestep::heun<state>{});
        compare(odestep::adams<M, state, odestep::dormand_prince54<state>>{}, odestep::dormand_prince54<state>{});
    });
}

TEST_CASE("adams: a step makes exactly one evaluation (AB) or two (PECE) once started, and the starter's before") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        stepper_t stepper;
        state y = y_start;
        INFO(doctest::String(M::name));
        for (std::size_t i = 0; i < 20; ++i) {
            std::size_t calls = 0;
            REQUIRE(stepper.step(counting_exp_sin{&calls}, y, 0.05 * static_cast<double>(i), 0.05) ==
                    odestep::status::ok);
            const std::size_t expected = i + 1 < stepper_t::steps ? 4 : stepper_t::rhs_evals_per_started_step;
            CHECK(calls == expected);
            CHECK(calls <= stepper_t::rhs_evals_per_step);
        }
    });
}

TEST_CASE("adams: both right-hand-side signatures give bit-identical runs") {
    auto returning = [](double, const state& y) { return state{y[0] * y[1], -y[2], y[1]}; };
    for_each_type<adams_methods>([&](auto method) {
        using M = decltype(method);
        odestep::adams<M, state> a;
        odestep::adams<M, state> b;
        state ya = y_start;
        state yb = y_start;
        REQUIRE(odestep::integrate_n_steps(a, exp_sin{}, ya, 0.0, 0.1, 30).status == odestep::status::ok);
        REQUIRE(odestep::integrate_n_steps(b, returning, yb, 0.0, 0.1, 30).status == odestep::status::ok);
        INFO(doctest::String(M::name));
        CHECK(same_bits(ya, yb));
    });
}

TEST_CASE("adams: a different dt or a wrong t returns step_mismatch, evaluates nothing, and changes nothing") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        constexpr std::size_t steps = 12;
        const double dt = 0.1;
        const auto reference = clean_run<stepper_t, steps>(dt);
        stepper_t stepper;
        state y = y_start;
        for (std::size_t i = 0; i < steps; ++i) {
            const double t = static_cast<double>(i) * dt;
            if (i > 0) {  // the first step accepts anything; every later one, during the start or after, is checked
                const state before = y;
                const double bad_dt[] = {2 * dt,
                                         dt / 2,
                                         -dt,
                                         std::nextafter(dt, 1.0),
                                         std::nextafter(dt, 0.0),
                                         std::numeric_limits<double>::quiet_NaN()};
                const double bad_t[] = {t + dt, t - dt, t + 1e-9};
                const double non_finite_t[] = {std::numeric_limits<double>::quiet_NaN(),
                                               std::numeric_limits<double>::infinity(),
                                               -std::numeric_limits<double>::infinity()};
                std::size_t calls = 0;
                for (double d : bad_dt)
                    CHECK(stepper.step(counting_exp_sin{&calls}, y, t, d) == odestep::status::step_mismatch);
                for (double s : bad_t)
                    CHECK(stepper.step(counting_exp_sin{&calls}, y, s, dt) == odestep::status::step_mismatch);
                for (double s : non_finite_t)  // on no grid at all
                    CHECK(stepper.step(counting_exp_sin{&calls}, y, s, dt) == odestep::status::invalid_time);
                CHECK(stepper.step(counting_exp_sin{&calls}, y, t + dt, 2 * dt) == odestep::status::step_mismatch);
                CHECK(calls == 0);
                CHECK(same_bits(y, before));
            }
            REQUIRE(stepper.step(exp_sin{}, y, t, dt) == odestep::status::ok);
            INFO(doctest::String(M::name), ", step ", i);
            CHECK(same_bits(y, reference[i]));  // as if the bad calls had never been made
        }
    });
}

TEST_CASE("adams: after a step whose end time overflows to Inf, no time continues the history") {
    // t + dt = Inf: the next step has no finite time to start at, so every t is a mismatch (the allowance
    // around an infinite expected time must not admit everything). y' = 0, so that y stays finite whatever dt.
    const double big = std::numeric_limits<double>::max();
    auto still = [](double, const state&, state& dydt) { dydt = state{}; };
    for_each_type<adams_methods>([big, still](auto method) {
        using stepper_t = odestep::adams<decltype(method), state>;
        stepper_t stepper;
        state y = y_start;
        REQUIRE(stepper.step(still, y, big, big / 2) == odestep::status::ok);
        REQUIRE(same_bits(y, y_start));
        INFO(doctest::String(decltype(method)::name));
        for (double t : {0.0, 1.0, -big, big})
            CHECK(stepper.step(still, y, t, big / 2) == odestep::status::step_mismatch);
        CHECK(stepper.step(still, y, std::numeric_limits<double>::infinity(), big / 2) ==
              odestep::status::invalid_time);
        CHECK(same_bits(y, y_start));
    });
}

TEST_CASE(
    "adams: a NaN or infinite t is invalid_time on the first step too, within rhs_evals_per_step evaluations (none), "
    "nothing touched") {
    // The starting step recorded f(t, y) by comparing the stage time with t; with t NaN that never matched
    // (NaN == NaN is false), so the step evaluated f once more than rhs_evals_per_step, and returned ok for an
    // f that ignores t. Non-finite t is on no grid: invalid_time, before any evaluation.
    for_each_type<adams_methods>([](auto method) {
        using stepper_t = odestep::adams<decltype(method), state>;
        INFO(doctest::String(decltype(method)::name));
        for (const double t : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()}) {
            stepper_t stepper;
            state y = y_start;
            std::size_t calls = 0;
            CHECK(stepper.step(counting_exp_sin{&calls}, y, t, 0.1) == odestep::status::invalid_time);
            CHECK(calls == 0);
            CHECK(calls <= stepper_t::rhs_evals_per_step);
            CHECK(same_bits(y, y_start));
            CHECK(stepper.history_size() == 0);
            // ... and the stepper starts afresh at a finite t, as if the call had not been made.
            CHECK(stepper.step(counting_exp_sin{&calls}, y, 0.0, 0.1) == odestep::status::ok);
            CHECK(stepper.history_size() == 1);
        }
    });
}

TEST_CASE("adams: a run on a finite grid near the largest double is not refused by its own history check") {
    // From t0 = 0.8 max in steps of 0.019 max (exact times up to 0.99 max, all finite): |t| + |t_first| passes
    // the largest double from the second step on, and the history check's allowance, written
    // 8 eps (|t| + |dt| + |t_first|), overflowed to Inf and was taken as "accepts nothing": the run stopped
    // with step_mismatch after 2 steps wherever the counter's time differed from the stepper's t + dt in the
    // last bit. y' = 0 keeps y finite; the expected result is every step done and y as it was.
    const double big = std::numeric_limits<double>::max();
    auto still = [](double, const state&, state& dydt) { dydt = state{}; };
    for_each_type<adams_methods>([&](auto method) {
        using stepper_t = odestep::adams<decltype(method), state>;
        INFO(doctest::String(decltype(method)::name));
        for (const odestep::step_count n : {10U, 20U, 100U}) {
            const double t0 = 0.8 * big;
            const double dt = 0.19 * big / static_cast<double>(n);
            state y = y_start;
            std::size_t observed = 0;
            double last = 0.0;
            bool monotone = true;
            auto observe = [&](double t, const state&) {
                monotone = monotone && (observed == 0 || t > last) && std::isfinite(t);
                last = t;
                ++observed;
            };
            INFO("n = ", n);
            const auto r = odestep::integrate_n_steps(stepper_t{}, still, y, t0, dt, n, observe);
            CHECK(r.status == odestep::status::ok);
            CHECK(r.steps == n);
            CHECK(observed == n + 1);
            CHECK(monotone);
            CHECK(same_bits(y, y_start));
        }
    });
}

TEST_CASE("adams: t within a few ULPs of the expected time is accepted, as the times of a step counter are") {
    // The check allows 8 ULPs of |t| + |dt| + |t_first|; t0 + i dt and t_prev + dt differ by a few.
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        constexpr std::size_t steps = 10;
        const auto reference = clean_run<stepper_t, steps>(0.1);
        stepper_t stepper;
        state y = y_start;
        for (std::size_t i = 0; i < steps; ++i) {
            double t = static_cast<double>(i) * 0.1;
            if (i % 2 == 1) t = std::nextafter(std::nextafter(t, 10.0), 10.0);  // two ULPs late
            REQUIRE(stepper.step(exp_sin{}, y, t, 0.1) == odestep::status::ok);
        }
        // exp_sin does not read t, so the run is the reference run bit for bit.
        INFO(doctest::String(M::name));
        CHECK(same_bits(y, reference[steps - 1]));
    });
}

TEST_CASE("adams: the edge of the allowance is the same on the inline check as on the full one") {
    // A grid of exact binary times (dt = 1/8 from 0): after 8 steps the expected time is 1 and the allowance
    // 8 eps (|1| + |dt| + |t_first|) = 9 eps (detail::continuation). Above 1 an ULP is eps, below it eps / 2:
    // 1 + k eps is on the grid for k <= 9 and 1 - k eps / 2 for k <= 18, nothing beyond. The step checks
    // t - dt == t_prev first, then within half the allowance inline (4 eps here), then the full check out
    // of line; each offset below is on one of the three paths, and a wider inline test would admit 1 + 10 eps.
    const double eps = std::numeric_limits<double>::epsilon();
    const double dt = 0.125;
    for_each_type<adams_methods>([&](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        const auto reference = clean_run<stepper_t, 9>(dt);
        INFO(doctest::String(M::name));
        for (const double k : {0.0, 3.0, 4.0, 7.0, 9.0, -4.0, -8.0, -18.0}) {
            INFO("k = ", k);
            stepper_t stepper;
            state y = y_start;
            for (std::size_t i = 0; i < 8; ++i)
                REQUIRE(stepper.step(exp_sin{}, y, static_cast<double>(i) * dt, dt) == odestep::status::ok);
            std::size_t calls = 0;
            const state before = y;
            for (const double bad : {1.0 + 10 * eps, 1.0 + 16 * eps, 1.0 - 19 * eps / 2, 1.0 - 32 * eps / 2})
                CHECK(stepper.step(counting_exp_sin{&calls}, y, bad, dt) == odestep::status::step_mismatch);
            CHECK(calls == 0);
            CHECK(same_bits(y, before));
            const double t = k > 0 ? 1.0 + k * eps : 1.0 + k * eps / 2;
            REQUIRE(stepper.step(exp_sin{}, y, t, dt) == odestep::status::ok);
            CHECK(same_bits(y, reference[8]));  // exp_sin does not read t
        }
    });
}

TEST_CASE("adams: counter times t0 + i dt are accepted across zero and over 10^6 float steps") {
    // From t0 = -1000 to 10 in steps of 0.1 in double: near t = 0 the counter time has the rounding of
    // t0 and i dt (about 1e-13), far more than a few ULPs of |t| + |dt| alone; the tolerance includes
    // the time of the first step. And in float, 10^6 steps of 1e-3 from 0 and from -500.
    using S = std::array<double, 2>;
    auto sho = [](double, const S& y) { return S{y[1], -y[0]}; };
    odestep::adams_bashforth_moulton4<S> stepper;
    S y{1.0, 0.0};
    const auto r = odestep::integrate_n_steps(stepper, sho, y, -1000.0, 0.1, 10100);
    CHECK(r.status == odestep::status::ok);
    CHECK(r.steps == 10100);

    using F = std::array<float, 1>;
    for (const float t0 : {0.0f, -500.0f}) {
        odestep::adams_bashforth2<F> ab2;
        F x{1.0f};
        const auto rf = odestep::integrate_n_steps(
            ab2, [](float, const F&) { return F{1.0f}; }, x, t0, 1e-3f, 1000000);
        INFO("float from ", t0);
        CHECK(rf.status == odestep::status::ok);
        CHECK(rf.steps == 1000000);
    }
}

TEST_CASE(
    "adams: the first step after construction or reset accepts any t and dt, and reset restarts with the starter") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        stepper_t stepper;
        state y = y_start;
        // any t and dt, even backwards
        REQUIRE(stepper.step(exp_sin{}, y, 123.0, -0.25) == odestep::status::ok);
        REQUIRE(stepper.step(exp_sin{}, y, 122.75, -0.25) == odestep::status::ok);
        CHECK(stepper.step(exp_sin{}, y, 122.5, 0.05) == odestep::status::step_mismatch);
        // reset, then a new dt and t: the starter's step, bit for bit, then a new history
        stepper.reset();
        CHECK(stepper.history_size() == 0);
        state a = y_start;
        state b = y_start;
        odestep::rk4<state> rk4;
        for (std::size_t i = 0; i < 8; ++i) {
            const double t = 1.0 + 0.05 * static_cast<double>(i);
            REQUIRE(stepper.step(exp_sin{}, a, t, 0.05) == odestep::status::ok);
            if (i + 1 < stepper_t::steps) {
                REQUIRE(rk4.step(exp_sin{}, b, t, 0.05) == odestep::status::ok);
                CHECK(same_bits(a, b));
            }
        }
        // and that run is the same as a fresh stepper's from t = 1
        stepper_t fresh;
        state c = y_start;
        REQUIRE(odestep::integrate_n_steps(fresh, exp_sin{}, c, 1.0, 0.05, 8).status == odestep::status::ok);
        INFO(doctest::String(M::name));
        CHECK(same_bits(a, c));
    });
}

TEST_CASE("adams: reset() or a restored memory from before the history filled restarts the starter on the same grid") {
    // The common path's test (dt the history's and t - dt the last step's t) passes on the same grid after a
    // reset() too; the history is empty then, so the step must be the starter's (rk4's, bit for bit), and the
    // run the same as a fresh stepper's from there. Likewise a memory() kept before the step that filled the
    // history and restored after it: the retried step is the starter's again.
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        INFO(doctest::String(M::name));
        const double dt = 0.125;
        stepper_t stepper;
        state y = y_start;
        for (std::size_t i = 0; i < 8; ++i)
            REQUIRE(stepper.step(exp_sin{}, y, static_cast<double>(i) * dt, dt) == odestep::status::ok);
        stepper.reset();
        state by_rk4 = y;
        REQUIRE(odestep::rk4<state>{}.step(exp_sin{}, by_rk4, 1.0, dt) == odestep::status::ok);
        state c = y;
        stepper_t fresh;
        for (std::size_t i = 8; i < 16; ++i) {
            const double t = static_cast<double>(i) * dt;
            REQUIRE(stepper.step(exp_sin{}, y, t, dt) == odestep::status::ok);
            REQUIRE(fresh.step(exp_sin{}, c, t, dt) == odestep::status::ok);
            if (i == 8) CHECK(same_bits(y, by_rk4));
            CHECK(same_bits(y, c));
        }

        stepper_t s2;
        state z = y_start;
        for (std::size_t i = 0; i + 2 < stepper_t::steps; ++i)
            REQUIRE(s2.step(exp_sin{}, z, static_cast<double>(i) * dt, dt) == odestep::status::ok);
        const auto kept = s2.memory();
        const state z_kept = z;
        const double t_fill = static_cast<double>(stepper_t::steps - 2) * dt;
        REQUIRE(s2.step(exp_sin{}, z, t_fill, dt) == odestep::status::ok);  // the history is full now
        REQUIRE(s2.history_size() == stepper_t::steps - 1);
        const state z_filled = z;
        s2.restore_memory(kept);
        z = z_kept;
        REQUIRE(s2.step(exp_sin{}, z, t_fill, dt) == odestep::status::ok);  // the same starter's step again
        CHECK(same_bits(z, z_filled));
        CHECK(s2.history_size() == stepper_t::steps - 1);
    });
}

TEST_CASE(
    "adams: a NaN or Inf from any evaluation rolls the step back, y and history, and a retry continues "
    "bit-identically") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        const double inf = std::numeric_limits<double>::infinity();
        const double qnan = std::numeric_limits<double>::quiet_NaN();
        constexpr std::size_t steps = 12;
        const double dt = 0.1;
        const auto reference = clean_run<stepper_t, steps>(dt);
        // Every evaluation of the run: during the start (each rk4 stage) and after it (each E of PECE).
        const std::size_t total =
            4 * (stepper_t::steps - 1) + stepper_t::rhs_evals_per_started_step * (steps - stepper_t::steps + 1);
        for (const double poison : {qnan, inf, -inf}) {
            for (std::size_t poisoned = 1; poisoned <= total; ++poisoned) {
                INFO(doctest::String(M::name), ", evaluation ", poisoned, " returns ", poison);
                stepper_t stepper;
                state y = y_start;
                std::size_t calls = 0;
                const counting_exp_sin f{&calls, poisoned, poison};
                std::size_t failures = 0;
                for (std::size_t i = 0; i < steps; ++i) {
                    const double t = static_cast<double>(i) * dt;
                    const state before = y;
                    const std::size_t history = stepper.history_size();
                    odestep::status s = stepper.step(f, y, t, dt);
                    if (s == odestep::status::non_finite) {
                        ++failures;
                        CHECK(same_bits(y, before));
                        CHECK(stepper.history_size() == history);
                        s = stepper.step(f, y, t, dt);  // f is healthy again: the retry goes through
                    }
                    REQUIRE(s == odestep::status::ok);
                    CHECK(same_bits(y, reference[i]));
                }
                CHECK(failures == 1);
            }
        }
    });
}

TEST_CASE("adams: a new state that overflows to Inf, from finite derivatives, is rolled back") {
    // y' = 1e308 from y = 0 with dt = 1: the Euler starter gives y_1 = 1e308, and AB2 then
    // y_2 = y_1 + (3/2 - 1/2) 1e308 = 2e308, which overflows; every derivative is finite.
    using S = std::array<double, 1>;
    auto f = [](double, const S&) { return S{1e308}; };
    odestep::adams_bashforth2<S, odestep::euler<S>> stepper;
    S y{0.0};
    const auto r = odestep::integrate_n_steps(stepper, f, y, 0.0, 1.0, 10);
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.steps == 1);
    CHECK(r.t == 1.0);
    CHECK(y[0] == 1e308);
    CHECK(stepper.history_size() == 1);
}

TEST_CASE(
    "adams: integrate over a whole number of steps works and equals integrate_n_steps; a run that needs a shortened "
    "last step is refused with step_mismatch before anything is touched") {
    for_each_type<adams_methods>([](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::adams<M, state>;
        INFO(doctest::String(M::name));
        // 2 / 0.125 = 16 steps exactly
        stepper_t a;
        stepper_t b;
        state ya = y_start;
        state yb = y_start;
        const auto ra = odestep::integrate(a, exp_sin{}, ya, 0.0, 2.0, 0.125);
        const auto rb = odestep::integrate_n_steps(b, exp_sin{}, yb, 0.0, 0.125, 16);
        CHECK(ra.status == odestep::status::ok);
        CHECK(ra.t == 2.0);
        CHECK(rb.status == odestep::status::ok);
        CHECK(same_bits(ya, yb));
        CHECK(ya[1] == doctest::Approx(std::cos(2.0)).epsilon(0.05));  // AB2 at h = 1/8 is 3% off, the others less

        // 1 / 0.15 = 6.67: six steps of 0.15, then a shortened one of 0.1, which an Adams history cannot take
        // (uniform_steps): integrate refuses the run before the first step, and nothing is touched.
        stepper_t c;
        state yc = y_start;
        std::size_t observed = 0;
        const auto rc = odestep::integrate(c, exp_sin{}, yc, 0.0, 1.0, 0.15, [&](double, const state&) { ++observed; });
        CHECK(rc.status == odestep::status::step_mismatch);
        CHECK(rc.steps == 0);
        CHECK(rc.t == 0.0);
        CHECK(observed == 0);
        CHECK(same_bits(yc, y_start));
        CHECK(c.history_size() == 0);

        // 1 / 0.1 is ten steps; integrate's last step t1 - t_9 = 0.0999999999999999778 is dt up to the grid's
        // rounding, so integrate takes it as dt: the same states as integrate_n_steps.
        stepper_t g;
        state yg = y_start;
        const auto rg = odestep::integrate(g, exp_sin{}, yg, 0.0, 1.0, 0.1);
        CHECK(rg.status == odestep::status::ok);
        CHECK(rg.steps == 10);
        stepper_t h;
        state yh = y_start;
        REQUIRE(odestep::integrate_n_steps(h, exp_sin{}, yh, 0.0, 0.1, 10).status == odestep::status::ok);
        CHECK(same_bits(yg, yh));

        // backwards, a whole number of steps
        stepper_t e;
        state ye{std::exp(std::sin(2.0)), std::cos(2.0), std::sin(2.0)};
        const auto re = odestep::integrate(e, exp_sin{}, ye, 2.0, 0.0, -0.0625);
        CHECK(re.status == odestep::status::ok);
        CHECK(ye[0] == doctest::Approx(1.0).epsilon(1e-2));  // y0(0) = 1; AB2 at h = 1/16 is 0.4% off
    });
}

TEST_CASE("adams: a copy of a stepper carries its history, so two copies continue identically") {
    odestep::adams_bashforth_moulton4<state> stepper;
    state y = y_start;
    REQUIRE(odestep::integrate_n_steps(stepper, exp_sin{}, y, 0.0, 0.1, 6).status == odestep::status::ok);
    auto copy = stepper;
    state y2 = y;
    REQUIRE(stepper.step(exp_sin{}, y, 0.6, 0.1) == odestep::status::ok);
    REQUIRE(copy.step(exp_sin{}, y2, 0.6, 0.1) == odestep::status::ok);
    CHECK(same_bits(y, y2));
}

TEST_CASE(
    "adams: a large state's history (a ring) gives each component the result of the same component stepped alone "
    "(a small state's, shifted as a block), bit for bit") {
    // 40 decoupled decays y_i' = -c_i y_i: component i of the large run meets exactly the arithmetic of a run of
    // y' = -c_i y alone (the formula is component by component), so the two layouts of the history must
    // agree bit for bit; the closed form exp(-c_i t) bounds the method's error on top. (40 components: past
    // the size at which adams switches from the shifted history to the ring, (k - 2) N > 32, for every method
    // that keeps more than one derivative; AB2 keeps one, which neither layout moves.)
    constexpr std::size_t n = 40;
    using big = std::array<double, n>;
    using one = std::array<double, 1>;
    for_each_type<adams_methods>([](auto method) {
        using table = decltype(method);
        odestep::adams<table, big> large;
        big y{};
        for (std::size_t i = 0; i < n; ++i) y[i] = 1.0;
        const auto decay = [](double, const big& x, big& d) {
            for (std::size_t i = 0; i < n; ++i) d[i] = -(0.1 + 0.05 * static_cast<double>(i)) * x[i];
        };
        REQUIRE(odestep::integrate_n_steps(large, decay, y, 0.0, 0.05, 40).status == odestep::status::ok);
        for (std::size_t i = 0; i < n; ++i) {
            const double c = 0.1 + 0.05 * static_cast<double>(i);
            odestep::adams<table, one> small;
            one z{1.0};
            const auto decay1 = [c](double, const one& x, one& d) { d[0] = -c * x[0]; };
            REQUIRE(odestep::integrate_n_steps(small, decay1, z, 0.0, 0.05, 40).status == odestep::status::ok);
            CHECK(same_bits(std::array<double, 1>{y[i]}, z));
            CHECK(std::fabs(y[i] - std::exp(-c * 2.0)) < 1e-3);  // AB2, the least accurate: about 3e-4
        }
    });
}
