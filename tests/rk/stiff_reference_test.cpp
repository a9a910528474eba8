// SPDX-License-Identifier: BSL-1.0
// Host only (long runs): stiff problems against published reference solutions (Robertson to t = 1e11, Van der
// Pol with mu = 1000, HIRES), the order reduction on Prothero-Robinson, and the energy of a pendulum over 10^6
// steps of the symplectic implicit methods.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "support/stiff_problems.hpp"

namespace {

using odestep_test::state1;
using odestep_test::state3;
template <class T>
using state2 = std::array<T, 2>;
template <class T>
using state8 = std::array<T, 8>;

using odestep_test::hires;
using odestep_test::hires_at_end;
using odestep_test::van_der_pol;
using odestep_test::van_der_pol_at_2000;
using odestep_test::van_der_pol_jacobian;

template <std::size_t N>
double worst_relative(const std::array<double, N>& y, const std::array<double, N>& reference) {
    double worst = 0;
    for (std::size_t i = 0; i < N; ++i) worst = std::fmax(worst, std::fabs(y[i] / reference[i] - 1));
    return worst;
}

// The error at t = 10 on Prothero-Robinson (phi = sin) with steps 10 / n, n = n0, 2 n0, 4 n0, 8 n0, and the slope
// of its least-squares fit.
template <class Stepper>
double prothero_robinson_slope(double lambda, std::size_t n0) {
    std::array<double, 4> e{};
    const auto sys = odestep::with_jacobian(odestep_test::prothero_robinson<double>{lambda},
                                            odestep_test::prothero_robinson_jacobian<double>{lambda});
    for (std::size_t i = 0; i < 4; ++i) {
        const std::size_t n = n0 << i;
        state1<double> y{0.0};
        REQUIRE(odestep::integrate_n_steps(Stepper{}, sys, y, 0.0, 10.0 / double(n), n).status == odestep::status::ok);
        e[i] = std::fabs(y[0] - std::sin(10.0));
    }
    const double slope = odestep_test::fitted_order(e);
    MESSAGE("lambda " << lambda << ": errors " << e[0] << " ... " << e[3] << ", slope " << slope);
    return slope;
}

// The pendulum q'' = -sin q as y = (q, p), H = p^2 / 2 - cos q.
struct pendulum {
    void operator()(double, const state2<double>& y, state2<double>& d) const noexcept {
        d[0] = y[1];
        d[1] = -std::sin(y[0]);
    }
};
struct pendulum_jacobian {
    void operator()(double, const state2<double>& y, odestep::jacobian_t<state2<double>>& j) const noexcept {
        j[0] = {0, 1};
        j[1] = {-std::cos(y[0]), 0};
    }
};
double energy(const state2<double>& y) { return y[1] * y[1] / 2 - std::cos(y[0]); }

struct energy_record {
    double first = 0;  // largest |H - H0| over the first tenth of the run
    double last = 0;   // ... over the last tenth
};

template <class Stepper>
energy_record pendulum_energy(std::size_t steps, double h) {
    state2<double> y{1.5, 0.0};  // a wide swing: q0 = 1.5 rad
    const double h0 = energy(y);
    energy_record rec;
    std::size_t n = 0;
    const auto sys = odestep::with_jacobian(pendulum{}, pendulum_jacobian{});
    const auto r = odestep::integrate_n_steps(Stepper{}, sys, y, 0.0, h, steps, [&](double, const state2<double>& v) {
        const double e = std::fabs(energy(v) - h0);
        if (n < steps / 10) rec.first = std::fmax(rec.first, e);
        if (n >= steps - steps / 10) rec.last = std::fmax(rec.last, e);
        ++n;
    });
    REQUIRE(r.status == odestep::status::ok);
    return rec;
}

}  // namespace

TEST_CASE("stiff references: Robertson to t = 1e11 against the Test Set's reference, 20 steps per decade") {
    const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
    auto run = [&](const auto& stepper, double tolerance) {
        state3<double> y{1, 0, 0};
        std::size_t steps = 0;
        REQUIRE(odestep_test::robertson_schedule(stepper, sys, y, 1e11, 20, &steps).status == odestep::status::ok);
        CHECK(steps == 17 * 20);
        const double worst = worst_relative(y, odestep_test::robertson_at_1e11);
        MESSAGE("largest relative error " << worst);
        CHECK(worst < tolerance);
        CHECK(std::fabs(y[0] + y[1] + y[2] - 1) < 1e-14);
    };
    // measured: 1.5e-6, 4.0e-10, 9.6e-4, 0.12 (each step is 45 % of the time it starts at)
    run(odestep::radau_iia5<state3<double>>{}, 5e-6);
    run(odestep::rodas3<state3<double>>{}, 1e-8);
    run(odestep::sdirk3<state3<double>>{}, 3e-3);
    run(odestep::backward_euler<state3<double>>{}, 0.3);
}

TEST_CASE("stiff references: Van der Pol with mu = 1000 at t = 2000 against the Test Set's reference") {
    // Fixed steps per phase: 0.1 on the slow branches, 1e-4 across the two jumps (at t = (3/2 - ln 2) mu = 807
    // and twice that, to leading order; the jumps take about 1e-2). Through a jump the solution's derivative reaches
    // 1e3, and a Jacobian frozen at the step's start converges only for steps that resolve it.
    const auto sys = odestep::with_jacobian(van_der_pol{}, van_der_pol_jacobian{});
    auto run = [&](const auto& stepper, double tolerance) {
        state2<double> y{2, 0};
        const double bounds[] = {0, 806, 808, 1612, 1616, 2000};
        std::size_t steps = 0;
        for (std::size_t p = 0; p < 5; ++p) {
            const auto r = odestep::integrate(stepper, sys, y, bounds[p], bounds[p + 1], p % 2 == 1 ? 1e-4 : 0.1);
            REQUIRE(r.status == odestep::status::ok);
            steps += r.steps;
        }
        const double worst = worst_relative(y, van_der_pol_at_2000);
        MESSAGE(steps << " steps, largest relative error " << worst);
        CHECK(worst < tolerance);
    };
    run(odestep::radau_iia5<state2<double>>{}, 1e-6);
    run(odestep::rodas3<state2<double>>{}, 1e-3);
}

TEST_CASE("stiff references: HIRES at t = 321.8122 against the Test Set's reference") {
    auto run = [](const auto& stepper, double dt, double tolerance) {
        state8<double> y{1, 0, 0, 0, 0, 0, 0, 0.0057};
        const auto r = odestep::integrate(stepper, hires{}, y, 0.0, 321.8122, dt);
        REQUIRE(r.status == odestep::status::ok);
        const double worst = worst_relative(y, hires_at_end);
        MESSAGE("dt " << dt << ", largest relative error " << worst);
        CHECK(worst < tolerance);
    };
    // Jacobians by differences. With dt = 0.1 the initial transient needs more than 7 simplified Newton
    // iterations for backward Euler (the Jacobian at t = 0 does not see the 280 y6 y8 reaction start): newton<15>.
    run(odestep::radau_iia5<state8<double>>{}, 0.01, 1e-11);
    run(odestep::radau_iia5<state8<double>, odestep::newton<10>>{}, 0.1, 1e-6);
    run(odestep::sdirk3<state8<double>>{}, 0.01, 1e-7);
    run(odestep::rodas3<state8<double>>{}, 0.01, 1e-6);
    run(odestep::rodas3<state8<double>>{}, 0.1, 1e-3);
    run(odestep::backward_euler<state8<double>>{}, 0.01, 2e-3);
    run(odestep::backward_euler<state8<double>, odestep::newton<15>>{}, 0.1, 2e-2);
}

TEST_CASE("Prothero-Robinson: full order at lambda = -1, reduced to the stage order at lambda = -1e6") {
    // y' = lambda (y - sin t) + cos t on [0, 10]. At lambda = -1e6 every step has |h lambda| >= 1.25e4. A stiffly
    // accurate method's error is then about e_s^T A^-1 Delta / (h lambda), Delta_i = O(h^(q+1)) the stages'
    // quadrature errors (q the stage order): O(h^q / |lambda|), tiny but of order q. A method with |R(oo)| = 1
    // (Gauss, midpoint, trapezoid) does not damp the stage errors: O(h^q) with q = 2 (Gauss 2, trapezoid 2) or
    // the midpoint's 2 from its alternating sign (Hairer & Wanner, Solving ODE II, Sec. IV.15). The same steps for
    // both lambdas, except Radau IIA at lambda = -1, which starts at 0.5 so that its finest error (1e-11) stays
    // clear of the Newton tolerance.
    using s = state1<double>;
    CHECK(prothero_robinson_slope<odestep::backward_euler<s>>(-1, 100) == doctest::Approx(1).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::backward_euler<s>>(-1e6, 100) == doctest::Approx(1).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::trapezoid<s>>(-1, 100) == doctest::Approx(2).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::trapezoid<s>>(-1e6, 100) == doctest::Approx(2).epsilon(0.1));
    CHECK(prothero_robinson_slope<odestep::implicit_midpoint<s>>(-1, 100) == doctest::Approx(2).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::implicit_midpoint<s>>(-1e6, 100) == doctest::Approx(2).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::gauss4<s>>(-1, 50) == doctest::Approx(4).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::gauss4<s>>(-1e6, 50) == doctest::Approx(2).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::sdirk3<s>>(-1, 100) == doctest::Approx(3).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::sdirk3<s>>(-1e6, 100) == doctest::Approx(1).epsilon(0.12));
    CHECK(prothero_robinson_slope<odestep::radau_iia5<s>>(-1, 20) == doctest::Approx(5).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::radau_iia5<s>>(-1e6, 40) == doctest::Approx(3).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::rodas3<s>>(-1, 100) == doctest::Approx(3).epsilon(0.05));
    CHECK(prothero_robinson_slope<odestep::rodas3<s>>(-1e6, 100) == doctest::Approx(1).epsilon(0.12));
}

TEST_CASE("pendulum: the energy of implicit midpoint and Gauss 4 stays bounded over 10^6 steps, Radau IIA drifts") {
    // h = 0.1, q0 = 1.5: 10^6 steps is 1.6e4 periods. A symplectic method's energy error oscillates with a bounded
    // amplitude (Hairer, Lubich & Wanner, Geometric Numerical Integration, Thm. IX.8.1): the largest error of the
    // last tenth of the run is that of the first tenth. Radau IIA (not symplectic, L-stable) loses energy steadily.
    const std::size_t steps = 1000000;
    const auto mid = pendulum_energy<odestep::implicit_midpoint<state2<double>>>(steps, 0.1);
    MESSAGE("implicit midpoint: |H - H0| <= " << mid.first << " (first tenth), " << mid.last << " (last tenth)");
    CHECK(mid.first < 1e-2);
    CHECK(mid.last < 1.05 * mid.first);
    const auto gauss = pendulum_energy<odestep::gauss4<state2<double>>>(steps, 0.1);
    MESSAGE("Gauss 4: |H - H0| <= " << gauss.first << " (first tenth), " << gauss.last << " (last tenth)");
    CHECK(gauss.first < 1e-5);
    CHECK(gauss.last < 1.05 * gauss.first);
    const auto radau = pendulum_energy<odestep::radau_iia5<state2<double>>>(steps / 10, 0.1);
    MESSAGE("Radau IIA (10^5 steps): |H - H0| <= " << radau.first << " (first tenth), " << radau.last
                                                   << " (last tenth)");
    CHECK(radau.last > 5 * radau.first);
}
