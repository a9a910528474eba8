// SPDX-License-Identifier: BSL-1.0
// Newton's equations with the textbook methods of newtonian.hpp: orders, energy, reversibility,
// evaluation counts, restarts, bad input and NaN rollback.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/methods.hpp"
#include "support/order_fit.hpp"
#include "support/problems.hpp"
#include "support/type_list.hpp"

namespace {

using odestep_test::for_each_type;
using odestep_test::kepler;  // a = -x / |x|^3, GM = 1
using odestep_test::same_bits;
using odestep_test::vec2;

// Counts its calls; the harmonic oscillator a = -x.
using counting_oscillator = odestep_test::counting<odestep_test::spring>;

// The largest error in x and v at t_end after `steps` steps on Kepler's circular orbit (problems.hpp).
template <class Stepper, class T>
T circular_orbit_error(T t_end, std::size_t steps) {
    using orbit = odestep_test::circular_orbit;
    Stepper stepper;
    vec2<T> x = orbit::start_x<T>();
    vec2<T> v = orbit::start_v<T>();
    const auto r = odestep::integrate_n_steps(stepper, kepler{}, x, v, T(0), t_end / static_cast<T>(steps), steps);
    REQUIRE(r.status == odestep::status::ok);
    return odestep_test::max_abs_difference(x, orbit::x_at(t_end), v, orbit::v_at(t_end));
}

using newtonian_methods = odestep_test::classic_newtonian_steppers<vec2<double>>;

template <class Stepper>
const char* name_of() {
    if constexpr (std::is_same_v<Stepper, odestep::newtonian_euler<vec2<double>>>)
        return "newtonian_euler";
    else if constexpr (std::is_same_v<Stepper, odestep::newtonian_midpoint<vec2<double>>>)
        return "newtonian_midpoint";
    else if constexpr (std::is_same_v<Stepper, odestep::newtonian_euler_richardson<vec2<double>>>)
        return "newtonian_euler_richardson";
    else if constexpr (std::is_same_v<Stepper, odestep::half_step<vec2<double>>>)
        return "half_step";
    else if constexpr (std::is_same_v<Stepper, odestep::leapfrog_position_form<vec2<double>>>)
        return "leapfrog_position_form";
    else if constexpr (std::is_same_v<Stepper, odestep::beeman<vec2<double>>>)
        return "beeman";
    else
        return "predictor_corrector";
}

template <class Stepper>
struct rebind;
template <template <class> class S, class State>
struct rebind<S<State>> {
    template <class T>
    using to = S<vec2<T>>;
};

}  // namespace

TEST_CASE("newtonian: every method reaches its order on the circular Kepler orbit (slope within 0.2)") {
    for_each_type<newtonian_methods>([](auto method) {
        using S = decltype(method);
        // First-order methods need smaller steps to leave the pre-asymptotic range (local slopes 0.89 to
        // 0.99 for N = 512 to 16384 at t = 5); the second-order ones are asymptotic from N = 64.
        const std::size_t n0 = S::order == 1 ? 2048 : 128;
        std::array<double, 4> errors{};
        for (std::size_t i = 0; i < errors.size(); ++i) errors[i] = circular_orbit_error<S, double>(5.0, n0 << i);
        const double slope = odestep_test::fitted_order(errors);
        MESSAGE(doctest::String(name_of<S>()), ": order ", S::order, ", fitted slope ", slope);
        CHECK(std::fabs(slope - S::order) < 0.2);
    });
}

TEST_CASE("newtonian: every method works in float, to its double accuracy plus float round-off") {
    for_each_type<newtonian_methods>([](auto method) {
        using S = decltype(method);
        using Sf = typename rebind<S>::template to<float>;
        const std::size_t n = 256;
        const double err_double = circular_orbit_error<S, double>(5.0, n);
        const double err_float = static_cast<double>(circular_orbit_error<Sf, float>(5.0f, n));
        INFO(doctest::String(name_of<S>()), ": float ", err_float, ", double ", err_double);
        CHECK(std::fabs(err_float - err_double) <=
              8.0 * n * static_cast<double>(std::numeric_limits<float>::epsilon()));
    });
}

TEST_CASE("newtonian_euler: on the oscillator the energy grows by exactly (1 + dt^2) per step") {
    // x_{n+1} = x + v dt, v_{n+1} = v - x dt: the map's matrix [[1, dt], [-dt, 1]] scales x^2 + v^2 by 1 + dt^2.
    std::size_t calls = 0;
    vec2<double> x{1.0, 0.0};
    vec2<double> v{0.0, 0.5};
    const double e0 = x[0] * x[0] + x[1] * x[1] + v[0] * v[0] + v[1] * v[1];
    const double dt = 0.01;
    const auto r = odestep::integrate_n_steps(odestep::newtonian_euler<vec2<double>>{}, counting_oscillator{{}, &calls},
                                              x, v, 0.0, dt, 1000);
    REQUIRE(r.status == odestep::status::ok);
    const double e = x[0] * x[0] + x[1] * x[1] + v[0] * v[0] + v[1] * v[1];
    CHECK(e / e0 == doctest::Approx(std::pow(1 + dt * dt, 1000)).epsilon(1e-12));
    CHECK(calls == 1000);
}

TEST_CASE("newtonian_euler_richardson: the error estimate is the difference to the Euler step") {
    // Written out for a = -x: a0 = -x, v_mid = v + a0 dt/2, x_mid = x + v dt/2, a_mid = -x_mid;
    // Euler: x + v dt, v + a0 dt. Estimate: x: a0 dt^2/2, v: (a_mid - a0) dt.
    const double dt = 0.1;
    const vec2<double> x0{0.7, -0.2};
    const vec2<double> v0{0.1, 0.4};
    vec2<double> x = x0;
    vec2<double> v = v0;
    vec2<double> ex{};
    vec2<double> ev{};
    std::size_t calls = 0;
    REQUIRE(odestep::newtonian_euler_richardson<vec2<double>>{}.step(counting_oscillator{{}, &calls}, x, v, 0.0, dt, ex,
                                                                     ev) == odestep::status::ok);
    CHECK(calls == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        const double a0 = -x0[i];
        const double v_mid = v0[i] + a0 * dt / 2;
        const double a_mid = -(x0[i] + v0[i] * dt / 2);
        CHECK(x[i] == doctest::Approx(x0[i] + v_mid * dt).epsilon(1e-15));
        CHECK(v[i] == doctest::Approx(v0[i] + a_mid * dt).epsilon(1e-15));
        CHECK(ex[i] == doctest::Approx(x[i] - (x0[i] + v0[i] * dt)).epsilon(1e-12));
        CHECK(ev[i] == doctest::Approx(v[i] - (v0[i] + a0 * dt)).epsilon(1e-12));
    }
}

TEST_CASE(
    "newtonian_euler_richardson: an estimate ex = a0 dt^2 / 2 that overflows is non_finite, even where x1 and v1 are "
    "finite") {
    // a = 2.5e307 (constant), x = 0, v = -5e307, dt = 4: v_mid = v + a dt/2 = 0, so x1 = x + v_mid dt = 0 and
    // v1 = v + a dt = 5e307 are finite, and ev = (a_mid - a0) dt = 0; but ex = a0 dt^2 / 2 = 2e308 overflows
    // (the largest double is 1.8e308).
    using state1 = std::array<double, 1>;
    auto a = [](double, const state1&) { return state1{2.5e307}; };
    const odestep::newtonian_euler_richardson<state1> stepper;
    for (int form = 0; form < 2; ++form) {
        INFO((form == 0 ? "the estimating step" : "the plain step"));
        state1 x{0.0};
        state1 v{-5e307};
        state1 ex{7.0};
        state1 ev{8.0};
        const odestep::status s = form == 0 ? stepper.step(a, x, v, 0.0, 4.0, ex, ev) : stepper.step(a, x, v, 0.0, 4.0);
        CHECK(s == odestep::status::non_finite);
        CHECK(x[0] == 0.0);
        CHECK(v[0] == -5e307);
        CHECK(ex[0] == 7.0);
        CHECK(ev[0] == 8.0);
    }
}

TEST_CASE("newtonian: history-keeping methods make one evaluation per step once started, and restart when asked") {
    auto check = [](auto stepper, const char* name) {
        INFO(name);
        std::size_t calls = 0;
        vec2<double> x{1.0, 0.0};
        vec2<double> v{0.0, 1.0};
        REQUIRE(odestep::integrate_n_steps(stepper, counting_oscillator{{}, &calls}, x, v, 0.0, 0.01, 100).status ==
                odestep::status::ok);
        CHECK(calls == 101);  // two on the first step, one on each of the other 99
        calls = 0;
        REQUIRE(stepper.step(counting_oscillator{{}, &calls}, x, v, 1.0, 0.01) == odestep::status::ok);
        CHECK(calls == 1);  // continues: t = 1 is where the history expects it
        stepper.reset();
        calls = 0;
        REQUIRE(stepper.step(counting_oscillator{{}, &calls}, x, v, 1.01, 0.01) == odestep::status::ok);
        CHECK(calls == 2);  // after reset(): a fresh start
        calls = 0;
        vec2<double> other_x = x;
        vec2<double> other_v = v;
        REQUIRE(stepper.step(counting_oscillator{{}, &calls}, other_x, other_v, 1.02, 0.01) == odestep::status::ok);
        CHECK(calls == 2);  // another state object: never someone else's history
        calls = 0;
        REQUIRE(stepper.step(counting_oscillator{{}, &calls}, other_x, other_v, 1.03, 0.02) == odestep::status::ok);
        CHECK(calls == 2);  // another dt: a new grid, a fresh start
    };
    // check takes its own copy of each stepper and keeps it across the calls above
    odestep::half_step<vec2<double>> h;
    odestep::leapfrog_position_form<vec2<double>> l;
    odestep::beeman<vec2<double>> b;
    check(h, "half_step");
    check(l, "leapfrog_position_form");
    check(b, "beeman");
}

TEST_CASE("newtonian: far from t = 0 the counter's times still continue the history (no silent restarts)") {
    // integrate's t0 + i dt and the stepper's t + dt differ by more than an ULP of dt at |t| ~ 1000; the
    // history must still be recognised: 20000 steps cost 20001 evaluations, and a time of Inf never continues.
    std::size_t calls = 0;
    odestep::half_step<vec2<double>> stepper;
    vec2<double> x{1.0, 0.0};
    vec2<double> v{0.0, 1.0};
    REQUIRE(odestep::integrate_n_steps(stepper, counting_oscillator{{}, &calls}, x, v, -1000.0, 0.1, 20000).status ==
            odestep::status::ok);
    CHECK(calls == 20001);
    calls = 0;
    (void)stepper.step(counting_oscillator{{}, &calls}, x, v, std::numeric_limits<double>::infinity(), 0.1);
    CHECK(calls == 2);  // a fresh start (this force ignores t), never a continuation of the history
}

TEST_CASE("newtonian: the reversible methods return to their start after N steps forward and N back") {
    // On the oscillator (no orbital shear to amplify round-off): 1000 steps each way. The reversal is a
    // fresh start of the history (dt changed sign), so the return is exact in real arithmetic and off by
    // round-off only. The half-step algorithm comes back within 2 ULPs; the position form within 350,
    // because its velocity is the difference quotient (x_{n+1} - x_{n-1}) / (2 dt), which multiplies the
    // rounding of x by 1/dt = 100, and the restart at the reversal starts from that velocity.
    auto run = [](auto stepper, const char* name, double ulps) {
        INFO(name);
        std::size_t calls = 0;
        vec2<double> x{1.0, 0.0};
        vec2<double> v{0.0, 0.5};
        const vec2<double> x0 = x;
        const vec2<double> v0 = v;
        REQUIRE(odestep::integrate(stepper, counting_oscillator{{}, &calls}, x, v, 0.0, 10.0, 0.01).status ==
                odestep::status::ok);
        REQUIRE(odestep::integrate(stepper, counting_oscillator{{}, &calls}, x, v, 10.0, 0.0, -0.01).status ==
                odestep::status::ok);
        const double ulp = std::numeric_limits<double>::epsilon();
        for (std::size_t i = 0; i < 2; ++i) {
            MESSAGE(doctest::String(name), ": return error x ", std::fabs(x[i] - x0[i]) / ulp, " ULPs, v ",
                    std::fabs(v[i] - v0[i]) / ulp, " ULPs");
            CHECK(std::fabs(x[i] - x0[i]) <= ulps * ulp);
            CHECK(std::fabs(v[i] - v0[i]) <= ulps * ulp);
        }
    };
    run(odestep::half_step<vec2<double>>{}, "half_step", 8.0);
    run(odestep::leapfrog_position_form<vec2<double>>{}, "leapfrog_position_form", 8.0 / 0.01);
}

TEST_CASE("predictor_corrector: iterates to its tolerance, and past its cap says no_convergence and rolls back") {
    odestep::predictor_corrector<vec2<double>> pc;
    vec2<double> x{1.0, 0.0};
    vec2<double> v{0.0, 1.0};
    REQUIRE(pc.step(kepler{}, x, v, 0.0, 0.01) == odestep::status::ok);
    CHECK(pc.last_iterations() >= 2);
    CHECK(pc.last_iterations() <= 6);  // contraction ~ (dt^2 / 4) |da/dx| ~ 5e-5 per iteration
    // A stiff spring: the fixed-point iteration's factor k dt^2 / 4 = 2500 > 1 diverges
    auto stiff = [](double, const vec2<double>& q) { return vec2<double>{-1e6 * q[0], -1e6 * q[1]}; };
    pc.reset();
    const vec2<double> x0 = x;
    const vec2<double> v0 = v;
    CHECK(pc.step(stiff, x, v, 0.0, 0.1) == odestep::status::no_convergence);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(v, v0));
}

TEST_CASE("predictor_corrector: a zero, negative or NaN tolerance is invalid_tolerance, nothing touched") {
    for (const double tol :
         {0.0, -1e-12, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        odestep::predictor_corrector<vec2<double>> pc;
        pc.tolerance = tol;
        vec2<double> x{1.0, 0.0};
        vec2<double> v{0.0, 1.0};
        CHECK(pc.step(kepler{}, x, v, 0.0, 0.01) == odestep::status::invalid_tolerance);
        CHECK(x[0] == 1.0);
        CHECK(v[1] == 1.0);
    }
}

TEST_CASE(
    "predictor_corrector: integrate and integrate_n_steps refuse a bad tolerance before observing or evaluating "
    "anything") {
    // The tolerance was checked only by step, so the loops observed the initial state and then returned
    // invalid_tolerance: a rejected setting must leave nothing observed, as a rejected argument does.
    for (const double tol :
         {0.0, -1e-12, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        odestep::predictor_corrector<vec2<double>> pc;
        pc.tolerance = tol;
        CHECK(pc.settings_status() == odestep::status::invalid_tolerance);
        for (int loop = 0; loop < 2; ++loop) {
            INFO("tolerance ", tol, (loop == 0 ? ", integrate" : ", integrate_n_steps"));
            vec2<double> x{1.0, 0.0};
            vec2<double> v{0.0, 1.0};
            std::size_t calls = 0;
            std::size_t observed = 0;
            auto observe = [&observed](double, const vec2<double>&, const vec2<double>&) { ++observed; };
            const auto r =
                loop == 0
                    ? odestep::integrate(pc, counting_oscillator{{}, &calls}, x, v, 0.0, 1.0, 0.01, observe)
                    : odestep::integrate_n_steps(pc, counting_oscillator{{}, &calls}, x, v, 0.0, 0.01, 10, observe);
            CHECK(r.status == odestep::status::invalid_tolerance);
            CHECK(r.steps == 0);
            CHECK(observed == 0);
            CHECK(calls == 0);
            CHECK(x[0] == 1.0);
            CHECK(v[1] == 1.0);
        }
    }
    CHECK(odestep::predictor_corrector<vec2<double>>{}.settings_status() == odestep::status::ok);
}

TEST_CASE("newtonian: a NaN or Inf from the force rolls every method back, bit for bit") {
    for_each_type<newtonian_methods>([](auto method) {
        using S = decltype(method);
        for (std::size_t poisoned = 1; poisoned <= 3; ++poisoned) {
            S stepper;
            std::size_t calls = 0;
            auto force = [&calls, poisoned](double, const vec2<double>& q) {
                ++calls;
                return calls == poisoned ? vec2<double>{std::numeric_limits<double>::quiet_NaN(), 0.0}
                                         : vec2<double>{-q[0], -q[1]};
            };
            vec2<double> x{1.0, 0.0};
            vec2<double> v{0.0, 1.0};
            // take good steps until the poisoned evaluation, then check the failing one touched nothing
            odestep::status s = odestep::status::ok;
            vec2<double> x_before = x;
            vec2<double> v_before = v;
            for (int i = 0; i < 4 && s == odestep::status::ok; ++i) {
                x_before = x;
                v_before = v;
                s = stepper.step(force, x, v, 0.1 * i, 0.1);
            }
            INFO(doctest::String(name_of<S>()), ", evaluation ", poisoned);
            CHECK(s == odestep::status::non_finite);
            CHECK(same_bits(x, x_before));
            CHECK(same_bits(v, v_before));
        }
    });
}

TEST_CASE("newtonian: bad arguments to integrate leave x and v untouched") {
    vec2<double> x{1.0, 0.0};
    vec2<double> v{0.0, 1.0};
    odestep::beeman<vec2<double>> stepper;
    CHECK(odestep::integrate(stepper, kepler{}, x, v, 0.0, 1.0, 0.0).status == odestep::status::invalid_step);
    CHECK(odestep::integrate(stepper, kepler{}, x, v, 0.0, 1.0, -0.1).status == odestep::status::wrong_direction);
    CHECK(odestep::integrate(stepper, kepler{}, x, v, std::numeric_limits<double>::quiet_NaN(), 1.0, 0.1).status ==
          odestep::status::invalid_time);
    CHECK(x[0] == 1.0);
    CHECK(v[1] == 1.0);
}

TEST_CASE("newtonian: a velocity-dependent force works with the methods that accept one") {
    // Damped oscillator x'' = -x - 2 g x', g = 0.1: x = e^{-g t} (cos w t + (g / w) sin w t), w^2 = 1 - g^2.
    const double g = 0.1;
    const double w = std::sqrt(1 - g * g);
    auto damped = [g](double, const std::array<double, 1>& q, const std::array<double, 1>& p) {
        return std::array<double, 1>{-q[0] - 2 * g * p[0]};
    };
    const double t_end = 3.0;
    const double exact = std::exp(-g * t_end) * (std::cos(w * t_end) + g / w * std::sin(w * t_end));
    std::array<double, 1> x{1.0};
    std::array<double, 1> v{0.0};
    REQUIRE(odestep::integrate(odestep::newtonian_euler_richardson<std::array<double, 1>>{}, damped, x, v, 0.0, t_end,
                               0.001)
                .status == odestep::status::ok);
    CHECK(x[0] == doctest::Approx(exact).epsilon(1e-6));
    x = {1.0};
    v = {0.0};
    REQUIRE(odestep::integrate(odestep::predictor_corrector<std::array<double, 1>>{}, damped, x, v, 0.0, t_end, 0.001)
                .status == odestep::status::ok);
    CHECK(x[0] == doctest::Approx(exact).epsilon(1e-6));
}

// ---------------------------------------------------------------------------------------------------------
// Beeman with its history kept by the caller: step(a, x, v, hist, t, dt)

TEST_CASE("beeman, caller's history: exact under a constant force, and the history holds a_n and a_{n-1}") {
    // x'' = -g: Beeman's formulas with a_n = a_{n-1} = -g are x1 = x0 + v0 h - g h^2/2 and v1 = v0 - g h, and
    // its self-starting velocity Verlet step is the same, so after n steps x = x0 + v0 t - g t^2/2 and
    // v = v0 - g t, t = n h. h = 3/32 makes h^2/6 = 3/2048, h/6 = 1/64 and h/2 exact, and every intermediate
    // a dyadic rational of fewer than 53 bits: exact, with ==.
    using S = std::array<double, 1>;
    const double g = 9.75;  // 39/4
    std::size_t calls = 0;
    const odestep_test::counting<odestep_test::uniform_gravity<double>> gravity{{g}, &calls};
    const odestep::beeman<S> stepper;  // const: the caller keeps everything
    odestep::beeman<S>::history hist{};
    CHECK_FALSE(hist.started);
    S x{100.0};
    S v{12.5};
    const double h = 0.09375;
    for (int n = 1; n <= 64; ++n) {
        REQUIRE(stepper.step(gravity, x, v, hist, (n - 1) * h, h) == odestep::status::ok);
        const double t = n * h;
        CHECK(x[0] == 100.0 + 12.5 * t - g * t * t / 2.0);
        CHECK(v[0] == 12.5 - g * t);
        CHECK(hist.started);
        CHECK(hist.acc[0] == -g);
        CHECK(hist.acc_prev[0] == -g);
    }
    CHECK(calls == 65);  // two evaluations on the self-starting step, one on each of the other 63
}

TEST_CASE("beeman, caller's history: bit for bit the stepper-kept form's steps, restarts included") {
    std::size_t calls = 0;
    auto a = [&calls](double t, const vec2<double>& x) {
        ++calls;
        return kepler{}(t, x);
    };
    odestep::beeman<vec2<double>> kept;
    const odestep::beeman<vec2<double>> caller_form;
    odestep::beeman<vec2<double>>::history hist{};
    vec2<double> x{1.0, 0.0}, v{0.0, 1.0};
    vec2<double> y = x, w = v;
    const double dt = 0.01;
    for (int i = 0; i < 300; ++i) {
        if (i == 150) {  // a restart in both: the next step self-starts again
            kept.reset();
            hist = {};
        }
        REQUIRE(kept.step(a, x, v, i * dt, dt) == odestep::status::ok);
        REQUIRE(caller_form.step(a, y, w, hist, i * dt, dt) == odestep::status::ok);
        REQUIRE(same_bits(x, y));
        REQUIRE(same_bits(v, w));
        // hist.acc is the force at the new position (an independent evaluation, not counted)
        REQUIRE(same_bits(hist.acc, kepler{}(0.0, y)));
    }
    // each form: 2 evaluations on each of its 2 self-starting steps, 1 on the other 298
    CHECK(calls == 2 * (2 * 2 + 298));
    // the circular orbit x = (cos t, sin t) at t = 3, to Beeman's error (order 2, dt = 0.01: about 1e-5;
    // the order itself is tested above with the stepper-kept form, whose steps these are)
    CHECK(std::fabs(y[0] - std::cos(3.0)) < 1e-4);
    CHECK(std::fabs(y[1] - std::sin(3.0)) < 1e-4);
}

TEST_CASE(
    "beeman, caller's history: a NaN from any evaluation, or an overflow, leaves x, v and hist exactly as they were") {
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    const odestep::beeman<vec2<double>> stepper;
    // Poison the k-th evaluation over three steps: 1 and 2 hit the self-starting step, 3 and 4 the later
    // ones (which make one evaluation each).
    for (std::size_t poisoned = 1; poisoned <= 4; ++poisoned) {
        std::size_t calls = 0;
        auto a = [&calls, poisoned, qnan](double t, const vec2<double>& x) {
            ++calls;
            return calls == poisoned ? vec2<double>{x[0], qnan} : kepler{}(t, x);
        };
        vec2<double> x{1.0, 0.0}, v{0.0, 1.0};
        odestep::beeman<vec2<double>>::history hist{};
        odestep::status s = odestep::status::ok;
        vec2<double> x_before = x, v_before = v;
        odestep::beeman<vec2<double>>::history hist_before = hist;
        for (int i = 0; i < 3 && s == odestep::status::ok; ++i) {
            x_before = x;
            v_before = v;
            hist_before = hist;
            s = stepper.step(a, x, v, hist, 0.1 * i, 0.1);
        }
        INFO("evaluation ", poisoned);
        CHECK(s == odestep::status::non_finite);
        CHECK(same_bits(x, x_before));
        CHECK(same_bits(v, v_before));
        CHECK(same_bits(hist.acc, hist_before.acc));
        CHECK(same_bits(hist.acc_prev, hist_before.acc_prev));
        CHECK(hist.started == hist_before.started);
    }
    // No force; the drift x + dt v overflows to Inf on a continuing step.
    auto none = [](double, const vec2<double>&) { return vec2<double>{0.0, 0.0}; };
    vec2<double> x{1e308, 0.0}, v{1e308, 1.0};
    odestep::beeman<vec2<double>>::history hist{{0.0, 0.0}, {0.0, 0.0}, true};
    const vec2<double> x0 = x, v0 = v;
    CHECK(stepper.step(none, x, v, hist, 0.0, 10.0) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(v, v0));
    CHECK(hist.started);
}
