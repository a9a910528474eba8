// SPDX-License-Identifier: BSL-1.0
// The shared test helpers themselves: every test leans on them, so each is checked here against a closed form
// or a case worked by hand.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/methods.hpp"
#include "support/order_fit.hpp"
#include "support/problems.hpp"
#include "support/type_list.hpp"

namespace {

using odestep_test::state3;
using odestep_test::vec2;

template <int Id>
struct tag {
    static constexpr int id = Id;
};

// The central difference (y(t + d) - y(t - d)) / (2 d) of a closed form, in long double: an independent
// derivative to hold f(t, y(t)) against.
template <class Exact>
state3<long double> central_difference(Exact&& exact, long double t, long double d) {
    const state3<long double> a = exact(t + d), b = exact(t - d);
    return {(a[0] - b[0]) / (2 * d), (a[1] - b[1]) / (2 * d), (a[2] - b[2]) / (2 * d)};
}

}  // namespace

TEST_CASE("support: same_bits tells -0 from +0 and a NaN from a number, and sees equal NaNs as the same") {
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    CHECK(odestep_test::same_bits(vec2<double>{1.0, 0.0}, vec2<double>{1.0, 0.0}));
    CHECK_FALSE(odestep_test::same_bits(vec2<double>{1.0, 0.0}, vec2<double>{1.0, -0.0}));
    CHECK_FALSE(odestep_test::same_bits(vec2<double>{1.0, 0.0}, vec2<double>{1.0, qnan}));
    CHECK(odestep_test::same_bits(vec2<double>{qnan, 2.0}, vec2<double>{qnan, 2.0}));
    CHECK_FALSE(odestep_test::same_bits(vec2<float>{1.0f, 2.0f}, vec2<float>{1.0f, std::nextafter(2.0f, 3.0f)}));
}

TEST_CASE("support: max_abs_difference is the largest component difference, and NaN when any is NaN") {
    CHECK(odestep_test::max_abs_difference(state3<double>{1.0, 2.0, 3.0}, state3<double>{1.0, 2.5, 2.0}) == 1.0);
    CHECK(odestep_test::max_abs_difference(vec2<float>{-1.0f, 0.0f}, vec2<float>{1.0f, 0.0f}) == 2.0f);
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(odestep_test::max_abs_difference(vec2<double>{qnan, 1.0}, vec2<double>{0.0, 5.0})));
    CHECK(std::isnan(odestep_test::max_abs_difference(vec2<double>{0.0, 1.0}, vec2<double>{0.0, qnan})));
    // position and velocity together: the larger of the two, NaN from either side
    const vec2<double> zero{0.0, 0.0};
    CHECK(odestep_test::max_abs_difference(vec2<double>{0.25, 0.0}, zero, vec2<double>{0.0, -0.5}, zero) == 0.5);
    CHECK(odestep_test::max_abs_difference(vec2<double>{0.75, 0.0}, zero, vec2<double>{0.0, -0.5}, zero) == 0.75);
    CHECK(std::isnan(odestep_test::max_abs_difference(vec2<double>{qnan, 0.0}, zero, vec2<double>{1.0, 0.0}, zero)));
    CHECK(std::isnan(odestep_test::max_abs_difference(vec2<double>{1.0, 0.0}, zero, vec2<double>{qnan, 0.0}, zero)));
}

TEST_CASE("support: fitted_order recovers the exponent of e = C h^p, and local_slopes each halving's") {
    // e_i = 3 (h0 / 2^i)^2.5 with h0 = 1: log e is exactly linear in log h with slope 2.5.
    std::array<double, 4> errors{};
    for (std::size_t i = 0; i < errors.size(); ++i) errors[i] = 3.0 * std::pow(0.5, 2.5 * static_cast<double>(i));
    CHECK(odestep_test::fitted_order(errors) == doctest::Approx(2.5).epsilon(1e-12));
    // only the first count points enter: a wild last point changes nothing
    errors[3] = 1.0;
    CHECK(odestep_test::fitted_order(errors, 3) == doctest::Approx(2.5).epsilon(1e-12));
    // e = 1, 1/4, 1/32, 1/32: local slopes 2, 3, 0
    const auto local = odestep_test::local_slopes(std::array<double, 4>{1.0, 0.25, 0.03125, 0.03125});
    CHECK(local[0] == doctest::Approx(2.0).epsilon(1e-15));
    CHECK(local[1] == doctest::Approx(3.0).epsilon(1e-15));
    CHECK(local[2] == 0.0);
    // with count = 3 the slope past the last point used is left 0
    CHECK(odestep_test::local_slopes(std::array<double, 4>{1.0, 0.5, 0.25, 8.0}, 3)[2] == 0.0);
}

TEST_CASE("support: counting counts every call, passes the result through and keeps the system form") {
    std::size_t calls = 0;
    const odestep_test::counting<odestep_test::exp_sin> f{{}, &calls};
    static_assert(odestep::is_inplace_system_v<decltype(f), state3<double>>);
    static_assert(!odestep::is_returning_system_v<decltype(f), state3<double>>);
    static_assert(noexcept(f(0.0, std::declval<const state3<double>&>(), std::declval<state3<double>&>())));
    state3<double> y{1.0, 1.0, 0.0};
    REQUIRE(odestep::integrate_n_steps(odestep::rk4<state3<double>>{}, f, y, 0.0, 0.1, 10).status ==
            odestep::status::ok);
    CHECK(calls == 40);  // four stages per step
    // a returning acceleration, counted through a copy: the copy counts into the same counter
    calls = 0;
    const auto a = odestep_test::counted(odestep_test::kepler{}, &calls);
    const auto copy = a;
    const vec2<double> at = copy(0.0, vec2<double>{2.0, 0.0});
    CHECK(calls == 1);
    CHECK(at[0] == -0.25);  // -x / |x|^3 at x = (2, 0)
    CHECK(at[1] == 0.0);
}

TEST_CASE("support: for_each_type visits every type of the list once, in order") {
    int visited[4] = {0, 0, 0, 0};
    int next = 0;
    odestep_test::for_each_type<std::tuple<tag<2>, tag<0>, tag<3>>>([&](auto t) { visited[next++] = decltype(t)::id; });
    CHECK(next == 3);
    CHECK(visited[0] == 2);
    CHECK(visited[1] == 0);
    CHECK(visited[2] == 3);
    // the family lists: 14 Runge-Kutta tables, 5 Adams, 7 splittings, 7 + 7 Newtonian steppers, 5 finders
    CHECK(std::tuple_size_v<odestep_test::all_methods> == 14);
    CHECK(std::tuple_size_v<odestep_test::adams_methods> == 5);
    CHECK(std::tuple_size_v<odestep_test::splitting_methods> == 7);
    CHECK(std::tuple_size_v<odestep_test::newtonian_steppers<vec2<double>>> == 14);
    CHECK(std::tuple_size_v<odestep_test::root_finders> == 5);
    CHECK(std::is_same_v<std::tuple_element_t<7, odestep_test::newtonian_steppers<vec2<double>>>,
                         odestep::euler_cromer<vec2<double>>>);
    CHECK(std::is_same_v<std::tuple_element_t<4, odestep_test::adams_steppers<vec2<double>>>,
                         odestep::adams_bashforth_moulton4<vec2<double>>>);
}

TEST_CASE("support: exp_sin and harmonic: f at the closed form is the closed form's derivative") {
    // Central differences with d = 1e-5 in long double: truncation d^2/6 |y'''| < 1e-10, far below 1e-8.
    for (const long double t : {0.0L, 0.7L, 2.0L, -3.5L, 20.0L}) {
        state3<long double> f{};
        odestep_test::exp_sin{}(t, odestep_test::exp_sin::exact(t), f);
        const state3<long double> d =
            central_difference([](long double s) { return odestep_test::exp_sin::exact(s); }, t, 1e-5L);
        INFO("t = ", static_cast<double>(t));
        for (std::size_t i = 0; i < 3; ++i) CHECK(static_cast<double>(std::fabs(f[i] - d[i])) < 1e-8);
        // harmonic from (1, 0): y = (cos t, -sin t), y' = (-sin t, -cos t)
        vec2<long double> g{};
        odestep_test::harmonic{}(t, vec2<long double>{std::cos(t), -std::sin(t)}, g);
        CHECK(g[0] == -std::sin(t));
        CHECK(g[1] == -std::cos(t));
    }
    CHECK(odestep_test::same_bits(odestep_test::exp_sin::start<float>(), odestep_test::exp_sin::exact(0.0f)));
}

TEST_CASE("support: the Kepler orbits: the circular one feels -x, the eccentric one has E = -1/2, L = sqrt(3)/2") {
    for (const double t : {0.0, 1.0, 2.5, -4.0}) {
        const vec2<double> x = odestep_test::circular_orbit::x_at(t);
        const vec2<double> a = odestep_test::kepler{}(t, x);
        INFO("t = ", t);
        CHECK(a[0] == doctest::Approx(-x[0]).epsilon(1e-15));  // r = 1: a = -x, the centripetal |v|^2 / r = 1
        CHECK(a[1] == doctest::Approx(-x[1]).epsilon(1e-15));
        CHECK(odestep_test::kepler_energy(x, odestep_test::circular_orbit::v_at(t)) == doctest::Approx(-0.5));
    }
    using orbit = odestep_test::eccentric_orbit;
    const double e_peri = odestep_test::kepler_energy(orbit::perihelion_x<double>(), orbit::perihelion_v<double>());
    const double e_aph = odestep_test::kepler_energy(orbit::aphelion_x<double>(), orbit::aphelion_v<double>());
    CHECK(e_peri == doctest::Approx(orbit::energy<double>()).epsilon(1e-15));
    CHECK(e_aph == doctest::Approx(orbit::energy<double>()).epsilon(1e-15));
    CHECK(odestep_test::kepler_angular_momentum(orbit::perihelion_x<double>(), orbit::perihelion_v<double>()) ==
          doctest::Approx(std::sqrt(3.0) / 2.0).epsilon(1e-15));
    CHECK(odestep_test::kepler_angular_momentum(orbit::aphelion_x<double>(), orbit::aphelion_v<double>()) ==
          doctest::Approx(orbit::angular_momentum<double>()).epsilon(1e-15));
    // the spring and uniform gravity, by hand
    CHECK(odestep_test::same_bits(odestep_test::spring{}(0.0f, std::array<float, 3>{1.0f, -2.0f, 0.0f}),
                                  std::array<float, 3>{-1.0f, 2.0f, -0.0f}));
    CHECK(odestep_test::uniform_gravity<double>{9.75}(0.0, std::array<double, 1>{5.0})[0] == -9.75);
}
