// SPDX-License-Identifier: BSL-1.0
// Symplectic splitting methods: traits, the schemes written out by hand, observed order, energy and
// angular momentum over 10^6 steps, time reversibility, the kept acceleration (first same as last),
// float, rollback and bad input.
#include <doctest/doctest.h>
#include <odestep/newtonian/splitting.hpp>
#include <odestep/odestep.hpp>

#include <algorithm>
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

using odestep_test::for_each_type;
using odestep_test::kepler;  // a = -x / |x|^3, GM = 1
using odestep_test::kepler_angular_momentum;
using odestep_test::kepler_energy;
using odestep_test::max_abs_difference;
using odestep_test::same_bits;
using odestep_test::splitting_methods;
using odestep_test::vec2;
using state = vec2<double>;
using state1 = std::array<double, 1>;

// Kepler with its calls counted.
using counting_kepler = odestep_test::counting<kepler>;

// The orbit of semi-major axis a = 1 and eccentricity e = 1/2 from perihelion (problems.hpp): period 2 pi,
// aphelion at t = pi, E = -1/2, L = sqrt(3)/2.
using orbit = odestep_test::eccentric_orbit;
constexpr double orbit_energy = orbit::energy<double>();
const double orbit_momentum = orbit::angular_momentum<double>();

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double qnan = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = 3.141592653589793238462643383279502884;

template <class M, class State = state>
using stepper_of = odestep::splitting<M, State>;

struct expected_traits {
    int order;
    std::size_t kicks;
    bool fsal;
    bool reversible;
};

// From the schemes as published (sources in symplectic.hpp): the number of kicks, whether the step
// begins and ends with a kick (first same as last), and whether the sequence is symmetric.
template <class M>
constexpr expected_traits published() {
    using namespace odestep::splittings;
    if constexpr (std::is_same_v<M, euler_cromer>)
        return {1, 1, false, false};
    else if constexpr (std::is_same_v<M, euler_cromer_drift_first>)
        return {1, 1, false, false};
    else if constexpr (std::is_same_v<M, velocity_verlet>)
        return {2, 2, true, true};
    else if constexpr (std::is_same_v<M, position_verlet>)
        return {2, 1, false, true};
    else if constexpr (std::is_same_v<M, forest_ruth>)
        return {4, 3, false, true};
    else if constexpr (std::is_same_v<M, yoshida6>)
        return {6, 7, false, true};
    else if constexpr (std::is_same_v<M, blanes_moan4>)
        return {4, 7, true, true};
    else
        return {0, 0, false, false};
}

// Drifts and kicks a step makes: the non-zero coefficients of the table.
template <class M>
constexpr std::size_t updates_per_step() {
    constexpr auto tab = M::template table<double>;
    std::size_t n = 0;
    for (std::size_t i = 0; i < tab.size; ++i) n += (tab.drift[i] != 0.0 ? 1U : 0U) + (tab.kick[i] != 0.0 ? 1U : 0U);
    return n;
}

// Kepler from perihelion to aphelion in `steps` steps of the method in T: the largest component error.
template <class M, class T>
T kepler_half_orbit_error(std::size_t steps) {
    stepper_of<M, vec2<T>> stepper;
    vec2<T> x = orbit::perihelion_x<T>();
    vec2<T> v = orbit::perihelion_v<T>();
    const T half_period = T(3.141592653589793238462643383279502884L);
    const auto r =
        odestep::integrate_n_steps(stepper, kepler{}, x, v, T(0), half_period / static_cast<T>(steps), steps);
    REQUIRE(r.status == odestep::status::ok);
    return max_abs_difference(x, orbit::aphelion_x<T>(), v, orbit::aphelion_v<T>());
}

// The step counts where each method's error is in its asymptotic regime and, at the finest, far above
// round-off (about 5e-14 here): found by tabulating the local slopes for N = 32 ... 32768. (Order 4 and 6
// reach round-off near N = 2048 and 1024.)
template <class M>
constexpr std::size_t kepler_coarsest_steps() {
    using namespace odestep::splittings;
    if constexpr (std::is_same_v<M, euler_cromer> || std::is_same_v<M, euler_cromer_drift_first>)
        return 2048;
    else if constexpr (std::is_same_v<M, velocity_verlet> || std::is_same_v<M, position_verlet>)
        return 128;
    else if constexpr (std::is_same_v<M, forest_ruth>)
        return 128;
    else if constexpr (std::is_same_v<M, blanes_moan4>)
        return 256;
    else
        return 64;  // yoshida6
}
template <class M>
constexpr std::size_t kepler_points() {
    return std::is_same_v<M, odestep::tables::blanes_moan4> ? 3 : 4;
}

// Runs `steps` steps forward with dt and `steps` back with -dt through integrate_n_steps.
template <class M>
state round_trip_error(std::size_t steps, double dt, double& v_error) {
    stepper_of<M> stepper;
    state x = orbit::perihelion_x<double>();
    state v = orbit::perihelion_v<double>();
    REQUIRE(odestep::integrate_n_steps(stepper, kepler{}, x, v, 0.0, dt, steps).status == odestep::status::ok);
    const double t_end = static_cast<double>(steps) * dt;
    REQUIRE(odestep::integrate_n_steps(stepper, kepler{}, x, v, t_end, -dt, steps).status == odestep::status::ok);
    v_error = std::max(std::fabs(v[0] - orbit::perihelion_v<double>()[0]),
                       std::fabs(v[1] - orbit::perihelion_v<double>()[1]));
    return {std::fabs(x[0] - orbit::perihelion_x<double>()[0]), std::fabs(x[1] - orbit::perihelion_x<double>()[1])};
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Traits and the schemes themselves

TEST_CASE("splitting: traits match the published schemes, and a step makes exactly the evaluations it says") {
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        using stepper = stepper_of<M>;
        constexpr expected_traits e = published<M>();
        INFO(doctest::String(M::name));
        CHECK(stepper::order == e.order);
        CHECK(stepper::stages == e.kicks);
        CHECK(stepper::rhs_evals_per_step == e.kicks);
        CHECK(stepper::rhs_evals_per_step == e.kicks);
        CHECK(stepper::first_same_as_last == e.fsal);
        CHECK(stepper::time_reversible == e.reversible);
        CHECK(stepper::symplectic);
        CHECK(stepper::self_starting);
        CHECK_FALSE(stepper::error_estimate);

        // The first step evaluates every kick; the second, from where the first ended, one fewer when the
        // last kick's acceleration is the next first kick's.
        stepper s;
        std::size_t calls = 0;
        state x = orbit::perihelion_x<double>();
        state v = orbit::perihelion_v<double>();
        REQUIRE(s.step(counting_kepler{{}, &calls}, x, v, 0.0, 0.01) == odestep::status::ok);
        CHECK(calls == e.kicks);
        calls = 0;
        REQUIRE(s.step(counting_kepler{{}, &calls}, x, v, 0.01, 0.01) == odestep::status::ok);
        CHECK(calls == e.kicks - (e.fsal ? 1U : 0U));
    });
}

TEST_CASE("velocity Verlet: one step of the oscillator is x + v h + a h^2/2 and v + (a0 + a1) h/2, by hand") {
    // x'' = -x. Written out: a0 = -x0, x1 = x0 + v0 h + a0 h^2/2, a1 = -x1, v1 = v0 + (a0 + a1) h/2. The
    // stepper computes the same numbers as v0 + h/2 a0 then x0 + h (that), so they agree to a rounding or
    // two (2 ULPs allowed).
    const double h = 0.1;
    const double x0 = 1.0;
    const double v0 = 0.5;
    const double a0 = -x0;
    const double x1 = x0 + v0 * h + a0 * h * h / 2.0;
    const double a1 = -x1;
    const double v1 = v0 + (a0 + a1) * h / 2.0;
    auto oscillator = [](double, const state1& x) { return state1{-x[0]}; };
    state1 x{x0};
    state1 v{v0};
    odestep::velocity_verlet<state1> stepper;
    REQUIRE(stepper.step(oscillator, x, v, 0.0, h) == odestep::status::ok);
    CHECK(std::fabs(x[0] - x1) <= 2 * eps * std::fabs(x1));
    CHECK(std::fabs(v[0] - v1) <= 2 * eps * std::fabs(v1));
    // x1 = 1 + 0.05 - 0.005 = 1.045, v1 = 0.5 - (1 + 1.045) 0.05 = 0.39775: the same, in decimals
    CHECK(x[0] == doctest::Approx(1.045).epsilon(1e-15));
    CHECK(v[0] == doctest::Approx(0.39775).epsilon(1e-15));
}

TEST_CASE("the first- and second-order splittings are, update for update, the formulas of their comments") {
    // A force of t and x, so that the time of each kick shows: a(t, x) = -x + t.
    auto force = [](double t, const state1& x) { return state1{-x[0] + t}; };
    const double t = 0.25;
    const double h = 0.1;
    const double x0 = 0.75;
    const double v0 = -0.5;
    SUBCASE("Euler-Cromer: v1 = v0 + h a(t, x0), x1 = x0 + h v1") {
        const double v1 = v0 + h * (-x0 + t);
        const double x1 = x0 + h * v1;
        state1 x{x0};
        state1 v{v0};
        REQUIRE(odestep::euler_cromer<state1>{}.step(force, x, v, t, h) == odestep::status::ok);
        CHECK(x[0] == x1);
        CHECK(v[0] == v1);
    }
    SUBCASE("drift first: x1 = x0 + h v0, v1 = v0 + h a(t + h, x1)") {
        const double x1 = x0 + h * v0;
        const double v1 = v0 + h * (-x1 + (t + h));
        state1 x{x0};
        state1 v{v0};
        REQUIRE(odestep::euler_cromer_drift_first<state1>{}.step(force, x, v, t, h) == odestep::status::ok);
        CHECK(x[0] == x1);
        CHECK(v[0] == v1);
    }
    SUBCASE("velocity Verlet: half kick at t, drift, half kick at t + h") {
        const double vh = v0 + h / 2 * (-x0 + t);
        const double x1 = x0 + h * vh;
        const double v1 = vh + h / 2 * (-x1 + (t + h));
        state1 x{x0};
        state1 v{v0};
        REQUIRE(odestep::velocity_verlet<state1>{}.step(force, x, v, t, h) == odestep::status::ok);
        CHECK(x[0] == x1);
        CHECK(v[0] == v1);
    }
    SUBCASE("position Verlet: half drift, kick at t + h/2, half drift") {
        const double xh = x0 + h / 2 * v0;
        const double v1 = v0 + h * (-xh + (t + h / 2));
        const double x1 = xh + h / 2 * v1;
        state1 x{x0};
        state1 v{v0};
        REQUIRE(odestep::position_verlet<state1>{}.step(force, x, v, t, h) == odestep::status::ok);
        CHECK(x[0] == x1);
        CHECK(v[0] == v1);
    }
}

TEST_CASE("the tables' coefficients: Forest-Ruth's gamma, Yoshida's w and Blanes-Moan's a, b as published") {
    using odestep::tables::blanes_moan4;
    using odestep::tables::forest_ruth;
    using odestep::tables::yoshida6;
    // gamma = 1 / (2 - 2^(1/3)) = 1.3512071919596576340... (Forest & Ruth 1990, eq. 4.8)
    constexpr auto fr = forest_ruth::table<long double>;
    const long double gamma = 1.0L / (2.0L - std::cbrt(2.0L));
    CHECK(std::fabs(fr.kick[0] - gamma) <= 4 * std::numeric_limits<long double>::epsilon());
    CHECK(std::fabs(fr.kick[1] - (1.0L - 2.0L * gamma)) <= 8 * std::numeric_limits<long double>::epsilon());
    CHECK(fr.drift[0] == fr.kick[0] / 2);
    CHECK(static_cast<double>(fr.kick[0]) == doctest::Approx(1.3512071919596576).epsilon(1e-15));
    // Yoshida 1990, Table 1, solution A, as printed (15 digits): the w here round to them.
    constexpr auto y6 = yoshida6::table<double>;
    CHECK(y6.kick[0] == doctest::Approx(0.784513610477560).epsilon(5e-15));  // w3
    CHECK(y6.kick[1] == doctest::Approx(0.235573213359357).epsilon(5e-15));  // w2
    CHECK(y6.kick[2] == doctest::Approx(-1.17767998417887).epsilon(5e-15));  // w1
    CHECK(y6.kick[3] == doctest::Approx(1.31518632068391).epsilon(5e-15));   // w0 = 1 - 2 (w1 + w2 + w3)
    CHECK(y6.drift[0] == y6.kick[0] / 2);
    // Blanes & Moan 2002, Table 3, SRKN_6^b.
    constexpr auto bm = blanes_moan4::table<double>;
    CHECK(bm.kick_first);
    CHECK(bm.kick[0] == 0.0829844064174052);
    CHECK(bm.drift[0] == 0.245298957184271);
    CHECK(bm.kick[1] == 0.396309801498368);
    CHECK(bm.drift[1] == 0.604872665711080);
    CHECK(bm.kick[2] == -0.0390563049223486);
    CHECK(bm.drift[2] == doctest::Approx(-0.350171622895351).epsilon(1e-15));  // 1/2 - (a1 + a2)
    CHECK(bm.kick[3] == doctest::Approx(0.1195241940131508).epsilon(1e-15));   // 1 - 2 (b1 + b2 + b3)
}

// ---------------------------------------------------------------------------------------------------------
// Order

TEST_CASE(
    "every splitting reaches its nominal order on the Kepler problem, perihelion to aphelion (slope within 0.2)") {
    // Half an orbit of e = 1/2 from perihelion ends at aphelion, where the state is known in closed form
    // (eccentric_orbit in support/problems.hpp). Not a whole orbit: there the first-order methods' O(h) error cancels (the O(h)
    // term of their modified Hamiltonian, +-v.grad(V)/2 = +-(dV/dt)/2, averages to zero over an orbit) and
    // they show slope 2.00.
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        constexpr int order = stepper_of<M>::order;
        constexpr std::size_t points = kepler_points<M>();
        std::array<double, 4> errors{};
        for (std::size_t i = 0; i < points; ++i)
            errors[i] = kepler_half_orbit_error<M, double>(kepler_coarsest_steps<M>() << i);
        const double slope = odestep_test::fitted_order(errors, points);
        const auto local = odestep_test::local_slopes(errors, points);
        INFO(doctest::String(M::name), ": errors ", errors[0], " ", errors[1], " ", errors[2], " ", errors[3],
             "; local slopes ", local[0], " ", local[1], " ", local[2]);
        MESSAGE(doctest::String(M::name), ": order ", order, ", fitted slope ", slope,
                " (N = ", kepler_coarsest_steps<M>(), " to ", kepler_coarsest_steps<M>() << (points - 1), ", error ",
                errors[0], " to ", errors[points - 1], ")");
        CHECK(std::fabs(slope - order) < 0.2);
        CHECK(errors[points - 1] > 1e-13);  // above round-off
    });
}

TEST_CASE(
    "every splitting evaluates its kicks at the times its drifts have reached: the forced oscillator keeps the order") {
    // x'' = -x + cos 2t, x(0) = 1, v(0) = 0: x = 4/3 cos t - 1/3 cos 2t, v = -4/3 sin t + 2/3 sin 2t. A force
    // of t as well as x: a kick at the wrong time costs the order (all kicks at t would leave order 1).
    auto forced = [](double t, const state1& x) { return state1{-x[0] + std::cos(2 * t)}; };
    const double t_end = 3.0;
    const double x_exact = 4.0 / 3.0 * std::cos(t_end) - std::cos(2 * t_end) / 3.0;
    const double v_exact = -4.0 / 3.0 * std::sin(t_end) + 2.0 / 3.0 * std::sin(2 * t_end);
    for_each_type<splitting_methods>([&](auto method) {
        using M = decltype(method);
        using stepper = stepper_of<M, state1>;
        constexpr int order = stepper::order;
        // Asymptotic and above round-off (tabulated for N = 8 ... 8192).
        const std::size_t coarsest = order == 1 ? 256 : order == 2 ? 64 : order == 4 ? 32 : 16;
        std::array<double, 4> errors{};
        for (std::size_t i = 0; i < 4; ++i) {
            stepper s;
            state1 x{1.0};
            state1 v{0.0};
            const std::size_t n = coarsest << i;
            REQUIRE(odestep::integrate_n_steps(s, forced, x, v, 0.0, t_end / static_cast<double>(n), n).status ==
                    odestep::status::ok);
            errors[i] = std::max(std::fabs(x[0] - x_exact), std::fabs(v[0] - v_exact));
        }
        const double slope = odestep_test::fitted_order(errors, 4);
        INFO(doctest::String(M::name), ": errors ", errors[0], " ", errors[1], " ", errors[2], " ", errors[3]);
        MESSAGE(doctest::String(M::name), ": forced oscillator, fitted slope ", slope);
        CHECK(std::fabs(slope - order) < 0.2);
        CHECK(errors[3] > 1e-13);
    });
}

TEST_CASE("Blanes-Moan SRKN6b: at the cost of Forest-Ruth, an error smaller by more than 100") {
    // Six evaluations per step against three: N Blanes-Moan steps cost what 2N Forest-Ruth steps cost.
    // Measured on the half orbit: 1.5e-10 against 8.3e-8 (N = 256), a factor 550.
    const double bm = kepler_half_orbit_error<odestep::tables::blanes_moan4, double>(256);
    const double fr = kepler_half_orbit_error<odestep::tables::forest_ruth, double>(512);
    MESSAGE("same cost: Blanes-Moan ", bm, ", Forest-Ruth ", fr, ", ratio ", fr / bm);
    CHECK(bm * 100 < fr);
}

// ---------------------------------------------------------------------------------------------------------
// Long runs: 10^6 steps of each method (about a second in all at -O2). In the "long" suite, so that the
// emulated Cortex-M run can leave them out (doctest -tse=long).

TEST_CASE("10^6 steps of the Kepler orbit: the energy error stays bounded, with no drift, and L is kept to round-off" *
          doctest::test_suite("long")) {
    // dt = 2 pi / 1000 for the first- and second-order methods (1000 orbits), 2 pi / 200 for the fourth-
    // and sixth-order ones (5000 orbits; at 2 pi / 1000 Yoshida's energy error is round-off alone).
    //
    // No drift: the largest |E - E0| over the last tenth of the run is at most 1.1 times that over the first
    // tenth, plus round-off growth: each step rounds 2 to 15 updates of x and v, each moving E by an ULP or
    // so, independently, so round-off walks like sqrt(steps) (Brouwer's law); allowed 64 ULPs of E0 times
    // sqrt(10^6) = 7e-12. A method with secular drift fails this at once (the RK4 test below).
    //
    // Angular momentum: x cross v is exactly invariant under every drift (x + c v) and every kick (v + c x,
    // a central force), so L changes only by the rounding of each update, about an ULP of |x||v| (at most
    // 1.2 L on this orbit) and independent from update to update: a random walk, bounded here by
    // 2 sqrt(updates) ULPs of L, updates = steps times the updates per step.
    constexpr std::size_t steps = 1000000;
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        using stepper = stepper_of<M>;
        const double dt = stepper::order <= 2 ? 2 * pi / 1000 : 2 * pi / 200;
        // Measured (g++ 12, x86-64): the largest relative energy error over the run, times 1.5.
        const double energy_bound = [] {
            using namespace odestep::splittings;
            if constexpr (std::is_same_v<M, euler_cromer> || std::is_same_v<M, euler_cromer_drift_first>)
                return 1.4e-2;  // 9.1e-3
            else if constexpr (std::is_same_v<M, velocity_verlet>)
                return 1.6e-4;  // 1.07e-4
            else if constexpr (std::is_same_v<M, position_verlet>)
                return 3.8e-5;  // 2.5e-5
            else if constexpr (std::is_same_v<M, forest_ruth>)
                return 1.4e-5;  // 9.2e-6
            else if constexpr (std::is_same_v<M, yoshida6>)
                return 6e-9;  // 4.0e-9
            else
                return 4.2e-9;  // Blanes-Moan: 2.8e-9
        }();
        const double updates = static_cast<double>(updates_per_step<M>());
        stepper s;
        state x = orbit::perihelion_x<double>();
        state v = orbit::perihelion_v<double>();
        double first = 0, last = 0, worst_l = 0;
        std::size_t seen = 0;
        const auto r = odestep::integrate_n_steps(
            s, kepler{}, x, v, 0.0, dt, steps, [&](double, const state& xs, const state& vs) {
                const double e = std::fabs(kepler_energy(xs, vs) - orbit_energy);
                if (seen <= steps / 10) first = std::max(first, e);
                if (seen >= steps - steps / 10) last = std::max(last, e);
                worst_l = std::max(worst_l, std::fabs(kepler_angular_momentum(xs, vs) - orbit_momentum));
                ++seen;
            });
        REQUIRE(r.status == odestep::status::ok);
        const double roundoff = 64 * eps * std::fabs(orbit_energy) * std::sqrt(static_cast<double>(steps));
        const double l_ulps = worst_l / (eps * orbit_momentum);
        const double l_bound = 2 * std::sqrt(updates * static_cast<double>(steps));
        MESSAGE(doctest::String(M::name), ": relative energy error, first tenth ", first / 0.5, ", last tenth ",
                last / 0.5, " (ratio ", last / first, "); |L - L0| ", l_ulps, " ULPs (bound ", l_bound, ")");
        CHECK(std::max(first, last) / std::fabs(orbit_energy) < energy_bound);
        CHECK(last <= 1.1 * first + roundoff);
        CHECK(l_ulps <= l_bound);
    });
}

TEST_CASE("10^6 steps of the Kepler orbit: the drift check does catch a method that drifts (classic RK4)" *
          doctest::test_suite("long")) {
    // The same orbit, the same dt = 2 pi / 1000 and the same criterion, with RK4 on the first-order system:
    // its energy error grows linearly, the last tenth's is about 10 times the first tenth's.
    using y4 = std::array<double, 4>;
    auto f = [](double, const y4& y) {
        const state a = kepler{}(0.0, state{y[0], y[1]});
        return y4{y[2], y[3], a[0], a[1]};
    };
    constexpr std::size_t steps = 1000000;
    y4 y{0.5, 0.0, 0.0, std::sqrt(3.0)};
    double first = 0, last = 0;
    std::size_t seen = 0;
    const auto r =
        odestep::integrate_n_steps(odestep::rk4<y4>{}, f, y, 0.0, 2 * pi / 1000, steps, [&](double, const y4& s) {
            const double e = std::fabs(kepler_energy(state{s[0], s[1]}, state{s[2], s[3]}) - orbit_energy);
            if (seen <= steps / 10) first = std::max(first, e);
            if (seen >= steps - steps / 10) last = std::max(last, e);
            ++seen;
        });
    REQUIRE(r.status == odestep::status::ok);
    const double roundoff = 64 * eps * std::fabs(orbit_energy) * std::sqrt(static_cast<double>(steps));
    MESSAGE("RK4: relative energy error, first tenth ", first / 0.5, ", last tenth ", last / 0.5);
    CHECK(last > 1.1 * first + roundoff);
}

// ---------------------------------------------------------------------------------------------------------
// Time reversibility

TEST_CASE(
    "the symmetric splittings retrace their steps: 100 steps with dt, then 100 with -dt, end within 4 ULPs of the "
    "start") {
    // In exact arithmetic the step with -dt undoes the step with dt update by update; what is left is the
    // rounding of 200 steps. Measured: at most 2.3 ULPs of |v0| = sqrt(3) (Forest-Ruth; a tenth of the orbit,
    // through perihelion). The first-order methods are not symmetric: they miss by about 1e-2, which shows
    // the test can fail.
    const double dt = 2 * pi / 1000;
    const double scale = std::sqrt(3.0);  // the largest component of the state
    for_each_type<splitting_methods>([&](auto method) {
        using M = decltype(method);
        double v_error = 0;
        const state x_error = round_trip_error<M>(100, dt, v_error);
        const double worst = std::max({x_error[0], x_error[1], v_error}) / (eps * scale);
        INFO(doctest::String(M::name), ": ", worst, " ULPs");
        if constexpr (stepper_of<M>::time_reversible) {
            MESSAGE(doctest::String(M::name), ": back at the start within ", worst, " ULPs");
            CHECK(worst <= 4.0);
        } else {
            CHECK(worst > 1e10);
        }
    });
}

// ---------------------------------------------------------------------------------------------------------
// First same as last: the kept acceleration

TEST_CASE("velocity Verlet: one evaluation per step after the first, stepping by hand or through integrate") {
    std::size_t calls = 0;
    counting_kepler a{{}, &calls};
    const double dt = 2 * pi / 1000;
    SUBCASE("step by step, t advanced by the caller") {
        odestep::velocity_verlet<state> stepper;
        state x = orbit::perihelion_x<double>();
        state v = orbit::perihelion_v<double>();
        double t = 0.0;
        for (int i = 0; i < 1000; ++i) {
            REQUIRE(stepper.step(a, x, v, t, dt) == odestep::status::ok);
            t += dt;
        }
        CHECK(calls == 1001);
    }
    SUBCASE("integrate, whose t0 + i dt differs from the step's t + dt in the last bit about a third of the time") {
        odestep::velocity_verlet<state> stepper;
        state x = orbit::perihelion_x<double>();
        state v = orbit::perihelion_v<double>();
        REQUIRE(odestep::integrate(stepper, a, x, v, 0.0, 2 * pi, dt).status == odestep::status::ok);
        CHECK(calls == 1001);
    }
    SUBCASE("Blanes-Moan: six per step after the first seven") {
        odestep::blanes_moan4<state> stepper;
        state x = orbit::perihelion_x<double>();
        state v = orbit::perihelion_v<double>();
        REQUIRE(odestep::integrate_n_steps(stepper, a, x, v, 0.0, dt, 100).status == odestep::status::ok);
        CHECK(calls == 7 + 99 * 6);
    }
}

TEST_CASE(
    "velocity Verlet: after reset(), for another x object, or at another time, the acceleration is evaluated afresh") {
    std::size_t calls = 0;
    counting_kepler a{{}, &calls};
    const double dt = 0.01;
    odestep::velocity_verlet<state> stepper;
    state x = orbit::perihelion_x<double>();
    state v = orbit::perihelion_v<double>();
    REQUIRE(stepper.step(a, x, v, 0.0, dt) == odestep::status::ok);
    REQUIRE(calls == 2);

    calls = 0;
    stepper.reset();
    REQUIRE(stepper.step(a, x, v, dt, dt) == odestep::status::ok);
    CHECK(calls == 2);

    calls = 0;
    state y = x;  // the same values in another object
    state w = v;
    REQUIRE(stepper.step(a, y, w, 2 * dt, dt) == odestep::status::ok);
    CHECK(calls == 2);
    calls = 0;
    REQUIRE(stepper.step(a, x, v, 2 * dt, dt) == odestep::status::ok);  // the kept one is y's now
    CHECK(calls == 2);

    calls = 0;
    REQUIRE(stepper.step(a, x, v, 5.0, dt) == odestep::status::ok);  // not the time it ended at (3 dt)
    CHECK(calls == 2);
    calls = 0;
    REQUIRE(stepper.step(a, x, v, 5.0 + dt, dt) == odestep::status::ok);
    CHECK(calls == 1);
}

TEST_CASE(
    "velocity Verlet: after a step at an infinite time, or one whose end time overflows, the next evaluates afresh") {
    // A force of position alone takes a step at t = +Inf without complaint. The time that step ends at is
    // not finite, so no later time continues it (the allowance around it is not finite either).
    std::size_t calls = 0;
    auto none = [&calls](double, const state&) {
        ++calls;
        return state{0.0, 0.0};
    };
    const double inf = std::numeric_limits<double>::infinity();
    const double big = std::numeric_limits<double>::max();
    odestep::velocity_verlet<state> stepper;
    state x{1.0, 0.0};
    state v{0.0, 0.0};
    REQUIRE(stepper.step(none, x, v, inf, 0.01) == odestep::status::ok);
    calls = 0;
    REQUIRE(stepper.step(none, x, v, 0.0, 0.01) == odestep::status::ok);
    CHECK(calls == 2);
    calls = 0;
    REQUIRE(stepper.step(none, x, v, inf, 0.01) == odestep::status::ok);
    CHECK(calls == 2);
    calls = 0;
    REQUIRE(stepper.step(none, x, v, big, big) == odestep::status::ok);  // ends at big + big = +Inf
    calls = 0;
    REQUIRE(stepper.step(none, x, v, 5.0, 0.01) == odestep::status::ok);
    CHECK(calls == 2);
    calls = 0;
    REQUIRE(stepper.step(none, x, v, 5.01, 0.01) == odestep::status::ok);  // an ordinary continuation again
    CHECK(calls == 1);
}

TEST_CASE("velocity Verlet: results with the kept acceleration are bit for bit those of a reset before every step") {
    SUBCASE("Kepler through integrate_n_steps") {
        odestep::velocity_verlet<state> kept;
        odestep::velocity_verlet<state> fresh;
        state x1 = orbit::perihelion_x<double>(), v1 = orbit::perihelion_v<double>();
        state x2 = x1, v2 = v1;
        REQUIRE(odestep::integrate_n_steps(kept, kepler{}, x1, v1, 0.0, 2 * pi / 1000, 5000).status ==
                odestep::status::ok);
        const double dt = 2 * pi / 1000;
        for (std::size_t i = 0; i < 5000; ++i) {
            fresh.reset();
            REQUIRE(fresh.step(kepler{}, x2, v2, static_cast<double>(i) * dt, dt) == odestep::status::ok);
        }
        CHECK(same_bits(x1, x2));
        CHECK(same_bits(v1, v2));
    }
    SUBCASE("a force of t and x, stepped with t += dt (the kept time is then exactly the next step's)") {
        auto forced = [](double t, const state& x) {
            const state g = kepler{}(t, x);
            return state{g[0] + 0.01 * std::cos(t), g[1]};
        };
        odestep::blanes_moan4<state> kept;
        odestep::blanes_moan4<state> fresh;
        state x1 = orbit::perihelion_x<double>(), v1 = orbit::perihelion_v<double>();
        state x2 = x1, v2 = v1;
        double t = 0.0;
        const double dt = 2 * pi / 200;
        for (int i = 0; i < 1000; ++i) {
            REQUIRE(kept.step(forced, x1, v1, t, dt) == odestep::status::ok);
            fresh.reset();
            REQUIRE(fresh.step(forced, x2, v2, t, dt) == odestep::status::ok);
            t += dt;
        }
        CHECK(same_bits(x1, x2));
        CHECK(same_bits(v1, v2));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Scalars

TEST_CASE("every splitting works in float: its error is its double error to within float round-off") {
    // Kepler half orbit at each method's coarsest step count of the order test. Round-off in float: a few
    // ULPs of the state (|x|, |v| <= 2) per step, growing at most like the step count: 4 N eps_float
    // (measured: at most 0.4 N eps_float).
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        const std::size_t n = kepler_coarsest_steps<M>();
        const double err_double = kepler_half_orbit_error<M, double>(n);
        const double err_float = static_cast<double>(kepler_half_orbit_error<M, float>(n));
        const double roundoff =
            4.0 * static_cast<double>(n) * static_cast<double>(std::numeric_limits<float>::epsilon());
        INFO(doctest::String(M::name), ": float error ", err_float, ", double error ", err_double, ", allowance ",
             roundoff);
        CHECK(std::fabs(err_float - err_double) <= roundoff);
    });
}

TEST_CASE("float, double and long double steppers come from the same template and agree") {
    std::array<float, 2> xf{0.5f, 0.0f}, vf{0.0f, std::sqrt(3.0f)};
    state xd = orbit::perihelion_x<double>(), vd = orbit::perihelion_v<double>();
    std::array<long double, 2> xl{0.5L, 0.0L}, vl{0.0L, std::sqrt(3.0L)};
    REQUIRE(
        odestep::integrate(odestep::velocity_verlet<std::array<float, 2>>{}, kepler{}, xf, vf, 0.0f, 1.0f, 0.0078125f)
            .status == odestep::status::ok);
    REQUIRE(odestep::integrate(odestep::velocity_verlet<state>{}, kepler{}, xd, vd, 0.0, 1.0, 0.0078125).status ==
            odestep::status::ok);
    REQUIRE(odestep::integrate(odestep::velocity_verlet<std::array<long double, 2>>{}, kepler{}, xl, vl, 0.0L, 1.0L,
                               0.0078125L)
                .status == odestep::status::ok);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(std::fabs(static_cast<double>(xf[i]) - xd[i]) <=
              128 * 4 * static_cast<double>(std::numeric_limits<float>::epsilon()));
        CHECK(std::fabs(static_cast<long double>(xd[i]) - xl[i]) <= 128 * 4 * static_cast<long double>(eps));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Rollback and bad input

TEST_CASE("a NaN from any evaluation of any splitting leaves x and v exactly as they were") {
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        using stepper = stepper_of<M>;
        for (std::size_t poisoned = 1; poisoned <= stepper::rhs_evals_per_step; ++poisoned) {
            std::size_t calls = 0;
            auto a = [&calls, poisoned](double t, const state& x) {
                ++calls;
                return calls == poisoned ? state{qnan, x[0]} : kepler{}(t, x);
            };
            stepper s;
            state x = orbit::perihelion_x<double>();
            state v = orbit::perihelion_v<double>();
            const state x0 = x, v0 = v;
            INFO(doctest::String(M::name), ", evaluation ", poisoned);
            CHECK(s.step(a, x, v, 0.0, 0.01) == odestep::status::non_finite);
            CHECK(same_bits(x, x0));
            CHECK(same_bits(v, v0));
        }
    });
}

TEST_CASE("a step that overflows is rolled back, for every splitting") {
    // No force; the drift x + dt v overflows to Inf.
    auto none = [](double, const state&) { return state{0.0, 0.0}; };
    for_each_type<splitting_methods>([&](auto method) {
        using M = decltype(method);
        stepper_of<M> s;
        state x{1e308, 0.0};
        state v{1e308, 1.0};
        const state x0 = x, v0 = v;
        INFO(doctest::String(M::name));
        CHECK(s.step(none, x, v, 0.0, 10.0) == odestep::status::non_finite);
        CHECK(same_bits(x, x0));
        CHECK(same_bits(v, v0));
    });
}

TEST_CASE("a failed step does not poison the kept acceleration: the retry is the step a fresh stepper takes") {
    // Velocity Verlet and Blanes-Moan, warm (one good step taken), then a step whose last evaluation is NaN.
    auto check = [](auto kept, auto fresh, std::size_t per_step) {
        std::size_t calls = 0;
        bool poison = false;
        auto a = [&](double t, const state& x) {
            ++calls;
            return poison && calls == per_step ? state{x[0], qnan} : kepler{}(t, x);
        };
        state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
        const double dt = 0.01;
        REQUIRE(kept.step(a, x, v, 0.0, dt) == odestep::status::ok);
        const state x1 = x, v1 = v;
        calls = 0;
        poison = true;
        CHECK(kept.step(a, x, v, dt, dt) == odestep::status::non_finite);
        CHECK(calls == per_step);
        CHECK(same_bits(x, x1));
        CHECK(same_bits(v, v1));
        poison = false;
        calls = 0;
        REQUIRE(kept.step(a, x, v, dt, dt) == odestep::status::ok);
        CHECK(calls == per_step);  // the kept one still serves: it belongs to x1, which is still x
        state y = x1, w = v1;
        REQUIRE(fresh.step(a, y, w, dt, dt) == odestep::status::ok);
        CHECK(same_bits(x, y));
        CHECK(same_bits(v, w));
    };
    check(odestep::velocity_verlet<state>{}, odestep::velocity_verlet<state>{}, 1);
    check(odestep::blanes_moan4<state>{}, odestep::blanes_moan4<state>{}, 6);
}

TEST_CASE("bad input through integrate leaves x and v untouched and observes nothing") {
    struct case_t {
        double t0, t1, dt;
        odestep::status expected;
    };
    const case_t cases[] = {
        {0.0, 1.0, 0.0, odestep::status::invalid_step},
        {0.0, 1.0, qnan, odestep::status::invalid_step},
        {0.0, 1.0, std::numeric_limits<double>::infinity(), odestep::status::invalid_step},
        {0.0, 1.0, -0.1, odestep::status::wrong_direction},
        {1.0, 0.0, 0.1, odestep::status::wrong_direction},
        {qnan, 1.0, 0.1, odestep::status::invalid_time},
    };
    for_each_type<splitting_methods>([&](auto method) {
        using M = decltype(method);
        for (const case_t& c : cases) {
            std::size_t calls = 0;
            std::size_t observed = 0;
            stepper_of<M> s;
            state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
            const state x0 = x, v0 = v;
            const auto r = odestep::integrate(s, counting_kepler{{}, &calls}, x, v, c.t0, c.t1, c.dt,
                                              [&](double, const state&, const state&) { ++observed; });
            INFO(doctest::String(M::name), ": t0 ", c.t0, ", t1 ", c.t1, ", dt ", c.dt);
            CHECK(r.status == c.expected);
            CHECK(r.steps == 0);
            CHECK(calls == 0);
            CHECK(observed == 0);
            CHECK(same_bits(x, x0));
            CHECK(same_bits(v, v0));
        }
        std::size_t calls = 0;
        stepper_of<M> s;
        state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
        const state x0 = x, v0 = v;
        const auto r = odestep::integrate_n_steps(s, counting_kepler{{}, &calls}, x, v, 0.0, 0.0, 10);
        CHECK(r.status == odestep::status::invalid_step);
        CHECK(calls == 0);
        CHECK(same_bits(x, x0));
        CHECK(same_bits(v, v0));
    });
}

TEST_CASE("a NaN mid-run through integrate stops at the last good state, at the time integrate reports") {
    std::size_t calls = 0;
    auto a = [&calls](double t, const state& x) {
        ++calls;
        return calls == 11 ? state{qnan, qnan} : kepler{}(t, x);  // in step 10 (1 + 1 per step before)
    };
    odestep::velocity_verlet<state> stepper;
    state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
    state x_seen{}, v_seen{};
    const auto r = odestep::integrate(stepper, a, x, v, 0.0, 1.0, 0.01, [&](double, const state& xs, const state& vs) {
        x_seen = xs;
        v_seen = vs;
    });
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.steps == 9);
    CHECK(r.t == 9.0 * 0.01);
    CHECK(same_bits(x, x_seen));
    CHECK(same_bits(v, v_seen));
}

// ---------------------------------------------------------------------------------------------------------
// Compile-time facts

static_assert(std::is_same_v<odestep::leapfrog<state>, odestep::velocity_verlet<state>>,
              "leapfrog (kick-drift-kick) is velocity Verlet");
static_assert(odestep::velocity_verlet<std::array<float, 3>>::rhs_evals_per_step == 2);
static_assert(odestep::position_verlet<std::array<float, 3>>::rhs_evals_per_step == 1);
static_assert(std::is_same_v<odestep::yoshida6<std::array<float, 3>>::value_type, float>);
// The stateless tables keep nothing, and their step is const: one object serves any number of states.
static_assert(sizeof(odestep::position_verlet<state>) == 1);
static_assert(sizeof(odestep::yoshida6<state>) == 1);
static_assert(std::is_same_v<decltype(std::declval<const odestep::forest_ruth<state>&>().step(
                                 kepler{}, std::declval<state&>(), std::declval<state&>(), 0.0, 0.1)),
                             odestep::status>);
// Every table passes its compile-time checks in every scalar.
static_assert(odestep::is_consistent(odestep::tables::yoshida6::table<float>));
static_assert(odestep::is_consistent(odestep::tables::blanes_moan4::table<long double>));
static_assert(odestep::is_consistent(odestep::tables::forest_ruth::table<float>));

TEST_CASE(
    "velocity Verlet keeps its acceleration far from t = 0 too: 20000 steps from t0 = -1000 cost 20001 evaluations") {
    // integrate_n_steps' t0 + i dt and the stepper's t + dt differ by more than an ULP of dt at |t| ~ 1000.
    using S = std::array<double, 2>;
    std::size_t calls = 0;
    auto spring = [&calls](double, const S& q) {
        ++calls;
        return S{-q[0], -q[1]};
    };
    odestep::velocity_verlet<S> stepper;
    S x{1.0, 0.0};
    S v{0.0, 1.0};
    REQUIRE(odestep::integrate_n_steps(stepper, spring, x, v, -1000.0, 0.1, 20000).status == odestep::status::ok);
    CHECK(calls == 20001);
}

// ---------------------------------------------------------------------------------------------------------
// First same as last, the acceleration kept by the caller: step(a, x, v, acc, t, dt)

namespace {
template <class S, class = void>
struct has_caller_acceleration_step : std::false_type {};
template <class S>
struct has_caller_acceleration_step<
    S, std::void_t<decltype(std::declval<const S&>().step(kepler{}, std::declval<state&>(), std::declval<state&>(),
                                                          std::declval<state&>(), 0.0, 0.0))>> : std::true_type {};
}  // namespace

TEST_CASE("the caller-kept acceleration form exists exactly for the first-same-as-last tables, and is const") {
    for_each_type<splitting_methods>([](auto method) {
        using M = decltype(method);
        INFO(doctest::String(M::name));
        CHECK(has_caller_acceleration_step<stepper_of<M>>::value == published<M>().fsal);
    });
}

TEST_CASE(
    "velocity Verlet, caller's acceleration: exact under a constant force, and acc is a(t + dt, x) after each step") {
    // x'' = -g: velocity Verlet is exact for a constant acceleration (x1 = x0 + v0 h - g h^2/2 and
    // v1 = v0 - g h are its own formulas), so after n steps x = x0 + v0 t - g t^2/2 and v = v0 - g t,
    // t = n h, to rounding. Numbers chosen so that every intermediate is a dyadic rational: exact.
    using S = std::array<double, 1>;
    const double g = 9.75;  // 39/4
    std::size_t calls = 0;
    const odestep_test::counting<odestep_test::uniform_gravity<double>> gravity{{g}, &calls};
    const odestep::velocity_verlet<S> stepper;  // const: the caller keeps everything
    S x{100.0};
    S v{12.5};
    S acc{-g};  // a(t0, x0), evaluated by the caller
    const double h = 0.125;
    for (int n = 1; n <= 64; ++n) {
        REQUIRE(stepper.step(gravity, x, v, acc, (n - 1) * h, h) == odestep::status::ok);
        const double t = n * h;
        CHECK(x[0] == 100.0 + 12.5 * t - g * t * t / 2.0);
        CHECK(v[0] == 12.5 - g * t);
        CHECK(acc[0] == -g);
    }
    CHECK(calls == 64);  // one evaluation per step, the first step included (acc came from the caller)
}

TEST_CASE("the caller-kept form takes, bit for bit, the kept form's steps: velocity Verlet and Blanes-Moan on Kepler") {
    auto check = [](auto kept, auto per_step_evals) {
        using stepper_type = decltype(kept);
        std::size_t calls = 0;
        counting_kepler a{{}, &calls};
        const stepper_type explicit_form{};
        state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
        state y = x, w = v;
        state acc = kepler{}(0.0, y);  // a(t0, x0), not counted
        const double dt = 2 * pi / 500;
        for (int i = 0; i < 250; ++i) {  // half an orbit
            REQUIRE(kept.step(a, x, v, i * dt, dt) == odestep::status::ok);
            REQUIRE(explicit_form.step(a, y, w, acc, i * dt, dt) == odestep::status::ok);
            REQUIRE(same_bits(x, y));
            REQUIRE(same_bits(v, w));
            // acc is the force at the new position (an independent evaluation)
            REQUIRE(same_bits(acc, kepler{}(0.0, y)));
        }
        // the kept form: per_step + 1 on its first step; the caller's form: per_step every step
        CHECK(calls == (per_step_evals + 1) + 249 * per_step_evals + 250 * per_step_evals);
        // at aphelion, to the method's error (velocity Verlet: 2.7e-4 measured by the bench case with 1000
        // steps per orbit, so about 4 times that with 500 (order 2); Blanes-Moan far below)
        CHECK(max_abs_difference(y, orbit::aphelion_x<double>(), w, orbit::aphelion_v<double>()) < 2e-3);
    };
    check(odestep::velocity_verlet<state>{}, std::size_t{1});
    check(odestep::blanes_moan4<state>{}, std::size_t{6});
}

TEST_CASE("the caller-kept form: a NaN from any evaluation, or an overflow, leaves x, v and acc exactly as they were") {
    auto check = [](auto stepper, std::size_t per_step) {
        for (std::size_t poisoned = 1; poisoned <= per_step; ++poisoned) {
            std::size_t calls = 0;
            auto a = [&calls, poisoned](double t, const state& x) {
                ++calls;
                return calls == poisoned ? state{x[0], qnan} : kepler{}(t, x);
            };
            state x = orbit::perihelion_x<double>(), v = orbit::perihelion_v<double>();
            state acc = kepler{}(0.0, x);
            const state x0 = x, v0 = v, acc0 = acc;
            INFO("evaluation ", poisoned);
            CHECK(stepper.step(a, x, v, acc, 0.0, 0.01) == odestep::status::non_finite);
            CHECK(same_bits(x, x0));
            CHECK(same_bits(v, v0));
            CHECK(same_bits(acc, acc0));
        }
        // No force; the drift x + dt v overflows to Inf.
        auto none = [](double, const state&) { return state{0.0, 0.0}; };
        state x{1e308, 0.0}, v{1e308, 1.0}, acc{0.0, 0.0};
        const state x0 = x, v0 = v, acc0 = acc;
        CHECK(stepper.step(none, x, v, acc, 0.0, 10.0) == odestep::status::non_finite);
        CHECK(same_bits(x, x0));
        CHECK(same_bits(v, v0));
        CHECK(same_bits(acc, acc0));
    };
    check(odestep::velocity_verlet<state>{}, 1);
    check(odestep::blanes_moan4<state>{}, 6);
}

TEST_CASE(
    "a step ending with a drift tests x alone: a velocity gone non-finite in the last kick still fails the step") {
    // Euler-Cromer, position Verlet, Forest-Ruth and Yoshida end with x <- x + h v: a v of +-Inf or NaN
    // makes that x non-finite (IEEE 754: finite + +-Inf is +-Inf, 0 * Inf is NaN), so the step's
    // finiteness test looks at x only. Each case below makes v non-finite and x's own arithmetic finite.
    const double inf = std::numeric_limits<double>::infinity();
    auto huge = [](double, const state&) { return state{1e308, -1e308}; };    // v overflows with dt = 10
    auto infinite = [inf](double, const state&) { return state{inf, 0.0}; };  // Inf from the force
    auto not_a_number = [](double, const state&) { return state{0.0, qnan}; };
    auto check = [&](auto stepper, const char* name) {
        INFO(name);
        static_assert(!decltype(stepper)::first_same_as_last);
        auto run = [&](auto force, double dt) {
            state x{1.0, 2.0};
            state v{1e308, -1e308};
            const state x0 = x, v0 = v;
            CHECK(stepper.step(force, x, v, 0.0, dt) == odestep::status::non_finite);
            CHECK(same_bits(x, x0));
            CHECK(same_bits(v, v0));
        };
        run(huge, 10.0);
        run(infinite, 0.5);
        run(infinite, 0.0);  // h = 0: v + 0 Inf is NaN, x + 0 NaN is NaN
        run(not_a_number, 0.5);
        run(not_a_number, 1e-320);  // h v underflows for every finite v; NaN stays NaN
    };
    check(odestep::euler_cromer<state>{}, "Euler-Cromer");
    check(odestep::position_verlet<state>{}, "position Verlet");
    check(odestep::forest_ruth<state>{}, "Forest-Ruth");
    check(odestep::yoshida6<state>{}, "Yoshida 6");
}
