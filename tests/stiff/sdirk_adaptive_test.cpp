// SPDX-License-Identifier: BSL-1.0
// Host only: the error-controlled SDIRK pair (odestep::sdirk_adaptive with tables::sdirk4, sdirk4_substeps, the
// free-running loops) from the natural initial conditions of the stiff test problems, against published or
// independently computed references, and its failures. The table's order conditions and stability function are
// checked with the other tables' (tests/tables/order_conditions_test.cpp, tests/rk/implicit_rk_test.cpp).
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/counting.hpp"
#include "support/order_fit.hpp"
#include "support/stiff_engine_checks.hpp"
#include "support/stiff_problems.hpp"

namespace {

using odestep_test::state2;
using odestep_test::state3;
using S3 = state3<double>;
using engine3 = odestep::sdirk_adaptive<odestep::tables::sdirk4, S3>;

// Robertson at t = 40 from (1, 0, 0): SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-12, atol=1e-20, exact
// Jacobian), as in tests/stiff/radau5_test.cpp (Hairer & Wanner's ten digits agree to their last digit).
constexpr std::array<double, 3> robertson_40{0.7158270687194083, 9.185534764557791e-06, 0.28416374574583075};

template <std::size_t N>
double worst_relative(const std::array<double, N>& y, const std::array<double, N>& reference) {
    double worst = 0;
    for (std::size_t i = 0; i < N; ++i) worst = std::fmax(worst, std::fabs(y[i] / reference[i] - 1));
    return worst;
}

static_assert(odestep::check_stepper<odestep::sdirk4_substeps<S3>>());
static_assert(engine3::order == 4 && engine3::estimate_order == 4 && engine3::stages == 5);
// the published bounds: per attempt f at a point, the difference Jacobian (3) and 5 stages at the cap of 7
static_assert(engine3::rhs_evals_per_attempt == 1 + 3 + 5 * 7);
static_assert(odestep::sdirk4_substeps<S3>::rhs_evals_per_step == 2 + 1000 * (1 + 3 + 5 * 7));
static_assert(odestep::sdirk4_substeps<S3>::newton_iterations_per_step == 1000 * 7);

TEST_CASE("sdirk4: Robertson from (1, 0, 0) to 40, free-running: error <= 10 rtol, slope near 1, Jacobians reused") {
    std::size_t calls = 0;
    const auto sys = odestep::with_jacobian(odestep_test::counted(odestep_test::robertson{}, &calls),
                                            odestep_test::robertson_jacobian{});
    const std::array<double, 3> rtols{1e-4, 1e-6, 1e-8};
    std::array<double, 3> errors{};
    for (std::size_t k = 0; k < 3; ++k) {
        calls = 0;
        engine3 engine(odestep::tolerances<S3>::uniform(rtols[k], rtols[k] * 1e-6));
        S3 y{1, 0, 0};
        REQUIRE(odestep::integrate_adaptive(engine, sys, y, 0.0, 40.0).status == odestep::status::ok);
        errors[k] = worst_relative(y, robertson_40);
        MESSAGE("rtol " << rtols[k] << ": worst relative error " << errors[k] << ", f " << calls << ", accepted "
                        << engine.accepted_steps() << ", rejected " << engine.rejected_steps() << ", Jacobians "
                        << engine.jacobian_evaluations() << ", LU " << engine.decompositions() << ", Newton iterations "
                        << engine.newton_iterations());
        CHECK(errors[k] <= 10 * rtols[k]);
        // the targets: Jacobians <= 0.4 per accepted step, factorizations <= 1.2 per step
        const double steps = double(engine.accepted_steps() + engine.rejected_steps());
        CHECK(double(engine.jacobian_evaluations()) <= 0.4 * double(engine.accepted_steps()));
        CHECK(double(engine.decompositions()) <= 1.2 * steps);
    }
    const double slope = odestep_test::log_log_slope(rtols, errors);
    MESSAGE("slope of the error against rtol: " << slope);
    CHECK(slope >= 0.7);
    CHECK(slope <= 1.3);
}

TEST_CASE("sdirk4_substeps: Robertson from (1, 0, 0) on a 0.1 grid to 40, every interval ok, error <= 10 rtol") {
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    for (double rtol : {1e-4, 1e-6, 1e-8}) {
        odestep::sdirk4_substeps<S3> stepper(odestep::tolerances<S3>::uniform(rtol, rtol * 1e-6));
        S3 y{1, 0, 0};
        double mass = 0;
        const auto r = odestep::integrate(stepper, sys, y, 0.0, 40.0, 0.1, [&](double, const S3& u) {
            mass = std::fmax(mass, std::fabs(u[0] + u[1] + u[2] - 1));
        });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.steps == 400);
        const double err = worst_relative(y, robertson_40);
        MESSAGE("rtol " << rtol << ": worst relative error " << err << ", accepted "
                        << stepper.engine().accepted_steps() << ", rejected " << stepper.engine().rejected_steps());
        CHECK(err <= 10 * rtol);
        CHECK(mass < 1e-12);  // y1 + y2 + y3 = 1, a linear invariant every Runge-Kutta method keeps
    }
}

TEST_CASE("sdirk4_substeps: Robertson with a difference Jacobian (f alone) on a 0.1 grid to 40") {
    odestep::sdirk4_substeps<S3> stepper(odestep::tolerances<S3>::uniform(1e-6, 1e-12));
    S3 y{1, 0, 0};
    REQUIRE(odestep::integrate(stepper, odestep_test::robertson{}, y, 0.0, 40.0, 0.1).status == odestep::status::ok);
    CHECK(worst_relative(y, robertson_40) <= 1e-5);
}

TEST_CASE("sdirk4: the published bound holds: f evaluations <= start + attempts x rhs_evals_per_attempt") {
    // difference Jacobians (f alone), so every path that evaluates f is taken
    std::size_t calls = 0;
    auto f = odestep_test::counted(odestep_test::robertson{}, &calls);
    for (double rtol : {1e-3, 1e-6}) {
        calls = 0;
        engine3 engine(odestep::tolerances<S3>::uniform(rtol, rtol * 1e-6));
        S3 y{1, 0, 0};
        REQUIRE(odestep::integrate_adaptive(engine, f, y, 0.0, 40.0).status == odestep::status::ok);
        const auto attempts = engine.accepted_steps() + engine.rejected_steps();
        MESSAGE("rtol " << rtol << ": f " << calls << " in " << attempts << " attempts, "
                        << engine.jacobian_evaluations() << " Jacobians");
        CHECK(calls <= 1 + engine3::rhs_evals_to_start + attempts * engine3::rhs_evals_per_attempt);
        CHECK(engine.newton_iterations() <= attempts * engine3::stages * engine3::max_newton_iterations);
        CHECK(engine.decompositions() <= attempts * engine3::decompositions_per_attempt);
    }
}

TEST_CASE("sdirk4_substeps: float Robertson at rtol 1e-3 on a 0.1 grid to 40, within 1e-2") {
    using F3 = state3<float>;
    odestep::sdirk4_substeps<F3> stepper(odestep::tolerances<F3>::uniform(1e-3f, 1e-9f));
    F3 y{1, 0, 0};
    const auto r = odestep::integrate(stepper, odestep_test::robertson{}, y, 0.0f, 40.0f, 0.1f);
    REQUIRE(r.status == odestep::status::ok);
    double worst = 0;
    for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(double(y[i]) / robertson_40[i] - 1));
    MESSAGE("float: worst relative error " << worst);
    CHECK(worst <= 1e-2);
}

TEST_CASE("sdirk4_substeps: Van der Pol mu = 1000 from (2, 0) on a 0.1 grid to 2000, |y1| <= 2.1 throughout") {
    // reference at 2000: the Test Set for IVP Solvers, problem VDPOL (support/stiff_problems.hpp)
    const auto sys = odestep::with_jacobian(odestep_test::van_der_pol{}, odestep_test::van_der_pol_jacobian{});
    using S2 = state2<double>;
    for (double rtol : {1e-4, 1e-6}) {
        odestep::sdirk4_substeps<S2> stepper(odestep::tolerances<S2>::uniform(rtol, rtol));
        S2 y{2, 0};
        double largest = 0;
        const auto r = odestep::integrate(stepper, sys, y, 0.0, 2000.0, 0.1,
                                          [&](double, const S2& u) { largest = std::fmax(largest, std::fabs(u[0])); });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(largest <= 2.1);
        const double err = worst_relative(y, odestep_test::van_der_pol_at_2000);
        MESSAGE("rtol " << rtol << ": worst relative error at 2000 " << err << ", accepted "
                        << stepper.engine().accepted_steps() << ", rejected " << stepper.engine().rejected_steps());
        CHECK(err <= 10 * rtol);
    }
}

TEST_CASE("sdirk4_substeps: exp(sin t) on a 1.0 grid to 20: error <= 100 rtol over the grid") {
    // a smooth problem with a closed-form solution (support/problems.hpp)
    (void)odestep_test::check_exp_sin_on_grid<odestep::sdirk4_substeps>(std::array<double, 3>{1e-4, 1e-6, 1e-8});
}

TEST_CASE("sdirk4: integrate_times interpolates by cubic Hermite: exact for y' = 3 t^2, 100 rtol on exp(sin t)") {
    SUBCASE("y = t^3: the pair integrates it exactly (B(4)) and the slopes are exact, so the cubic is") {
        using S1 = std::array<double, 1>;
        auto f = [](double t, const S1&) { return S1{3 * t * t}; };
        odestep::sdirk_adaptive<odestep::tables::sdirk4, S1> engine(odestep::tolerances<S1>::uniform(1e-6, 1e-6));
        engine.set_step_size(0.7);  // a few long steps, so most times fall inside one
        std::array<double, 9> times{0.1, 0.35, 0.5, 0.9, 1.3, 1.75, 2.2, 2.6, 3.0};
        S1 y{0};
        double worst = 0;
        const auto r = odestep::integrate_times(engine, f, y, 0.0, times, [&](double t, const S1& u) {
            worst = std::fmax(worst, std::fabs(u[0] - t * t * t));
        });
        REQUIRE(r.status == odestep::status::ok);
        MESSAGE("worst error " << worst << " in " << r.steps << " steps");
        CHECK(r.steps < times.size());
        CHECK(worst <= 1e-12);
    }
    SUBCASE("exp(sin t) at 0.05 spacing to 20") {
        const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
        std::array<double, 400> times{};
        for (std::size_t i = 0; i < times.size(); ++i) times[i] = 0.05 * double(i + 1);
        for (double rtol : {1e-4, 1e-6, 1e-8}) {
            engine3 engine(odestep::tolerances<S3>::uniform(rtol, rtol));
            S3 y = odestep_test::exp_sin::start<double>();
            double worst = 0;
            std::size_t seen = 0;
            const auto r = odestep::integrate_times(engine, sys, y, 0.0, times, [&](double t, const S3& u) {
                const S3 x = odestep_test::exp_sin::exact(t);
                for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(u[i] - x[i]));
                ++seen;
            });
            REQUIRE(r.status == odestep::status::ok);
            CHECK(seen == times.size());
            MESSAGE("rtol " << rtol << ": largest error at the times " << worst << " (" << r.steps << " steps)");
            CHECK(worst <= 100 * rtol);
        }
    }
}

TEST_CASE("sdirk4_substeps: Prothero-Robinson with lambda = -1e6 on a 0.1 grid, exact sin t") {
    // y' = lambda (y - sin t) + cos t, y(0) = 0: y = sin t (support/stiff_problems.hpp), a closed form
    using S1 = std::array<double, 1>;
    const auto sys = odestep::with_jacobian(odestep_test::prothero_robinson<double>{-1e6},
                                            odestep_test::prothero_robinson_jacobian<double>{-1e6});
    for (double rtol : {1e-4, 1e-6, 1e-8}) {
        odestep::sdirk4_substeps<S1> stepper(odestep::tolerances<S1>::uniform(rtol, rtol));
        S1 y{0};
        double worst = 0;
        REQUIRE(odestep::integrate(stepper, sys, y, 0.0, 10.0, 0.1, [&](double t, const S1& u) {
                    worst = std::fmax(worst, std::fabs(u[0] - std::sin(t)));
                }).status == odestep::status::ok);
        MESSAGE("rtol " << rtol << ": largest error " << worst);
        CHECK(worst <= 10 * rtol);
    }
}

// ---- failures: a clear status, y bit for bit as it was

TEST_CASE("sdirk4_substeps: NaN from f, NaN in the Jacobian, the attempt cap and bad settings leave y bit for bit") {
    SUBCASE("f gives NaN past t = 1.05: non_finite on the interval that reaches it") {
        odestep_test::check_nan_past_a_time<odestep::sdirk4_substeps>();
    }
    SUBCASE("f gives NaN at the start: non_finite, nothing changed") {
        auto f = [](double, const S3&, S3& d) { d = {std::numeric_limits<double>::quiet_NaN(), 0, 0}; };
        odestep::sdirk4_substeps<S3> stepper;
        S3 y{1, 0, 0};
        const S3 before = y;
        CHECK(stepper.step(f, y, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(odestep::detail::same_values(y, before));
    }
    SUBCASE("a Jacobian with NaN: singular_matrix") { odestep_test::check_nan_jacobian<odestep::sdirk4_substeps>(); }
    SUBCASE("the attempt cap: substep_limit, y as given") {
        odestep_test::check_attempt_cap<odestep::sdirk4_substeps, 4>();
    }
    SUBCASE("bad settings are refused before anything is evaluated") {
        odestep_test::check_bad_newton_settings<odestep::sdirk4_substeps>();
    }
}

}  // namespace
