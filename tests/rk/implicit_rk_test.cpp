// SPDX-License-Identifier: BSL-1.0
// The implicit Runge-Kutta steppers: stability functions from their tables, observed order, closed forms
// (RC discharge), Robertson against its published values, the statuses of every failure with the state
// kept bit for bit, the published evaluation counts, and the driving and event loops, in float and double.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstring>
#include <limits>

#include "support/order_fit.hpp"
#include "support/stiff_problems.hpp"

namespace {

using odestep_test::state1;
using odestep_test::state3;
namespace tab = odestep::tables;

template <class T, std::size_t N>
bool same_bits(const std::array<T, N>& a, const std::array<T, N>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// ---- stability functions, from the tables, in complex long double (independent of the library's LU)

using cplx = std::complex<long double>;

// R(z) = 1 + z b^T (I - z A)^-1 1 (Hairer & Wanner, Solving ODE II, Sec. IV.3, (3.2)), by Gaussian elimination
// with partial pivoting on I - z A.
template <class Tag>
cplx stability(cplx z) {
    const auto& t = Tag::template table<long double>;
    constexpr std::size_t S = std::remove_reference_t<decltype(t)>::stages;
    std::array<std::array<cplx, S>, S> m{};
    std::array<cplx, S> x{};
    for (std::size_t i = 0; i < S; ++i) {
        for (std::size_t j = 0; j < S; ++j) m[i][j] = (i == j ? cplx(1) : cplx(0)) - z * t.a[i][j];
        x[i] = cplx(1);
    }
    for (std::size_t k = 0; k < S; ++k) {
        std::size_t p = k;
        for (std::size_t i = k + 1; i < S; ++i)
            if (std::abs(m[i][k]) > std::abs(m[p][k])) p = i;
        std::swap(m[k], m[p]);
        std::swap(x[k], x[p]);
        for (std::size_t i = k + 1; i < S; ++i) {
            const cplx l = m[i][k] / m[k][k];
            for (std::size_t j = k; j < S; ++j) m[i][j] -= l * m[k][j];
            x[i] -= l * x[k];
        }
    }
    for (std::size_t i = S; i-- > 0;) {
        for (std::size_t j = i + 1; j < S; ++j) x[i] -= m[i][j] * x[j];
        x[i] /= m[i][i];
    }
    cplx sum = 0;
    for (std::size_t i = 0; i < S; ++i) sum += t.b[i] * x[i];
    return cplx(1) + z * sum;
}

// The closed forms (Hairer & Wanner, Solving ODE II, Sec. IV.3-IV.6): backward Euler 1 / (1 - z); trapezoid and
// midpoint the (1,1) Pade approximation of e^z; Gauss with two stages the (2,2) Pade approximation; Radau IIA with
// three stages the (2,3) Pade approximation; an SDIRK of order p >= s the part of degree <= s of
// e^z (1 - gamma z)^s over (1 - gamma z)^s.
cplx backward_euler_r(cplx z) { return cplx(1) / (cplx(1) - z); }
cplx trapezoid_r(cplx z) { return (cplx(1) + z / 2.0L) / (cplx(1) - z / 2.0L); }
cplx gauss4_r(cplx z) { return (cplx(1) + z / 2.0L + z * z / 12.0L) / (cplx(1) - z / 2.0L + z * z / 12.0L); }
cplx radau5_r(cplx z) {
    return (cplx(1) + 2.0L * z / 5.0L + z * z / 20.0L) /
           (cplx(1) - 3.0L * z / 5.0L + 3.0L * z * z / 20.0L - z * z * z / 60.0L);
}
cplx sdirk3_r(cplx z) {
    const long double g = odestep::detail::alexander_gamma<long double>;
    const cplx p = cplx(1) + (1.0L - 3.0L * g) * z + (0.5L - 3.0L * g + 3.0L * g * g) * z * z +
                   (1.0L / 6.0L - 1.5L * g + 3.0L * g * g - g * g * g) * z * z * z;
    const cplx q = cplx(1) - g * z;
    return p / (q * q * q);
}
// SDIRK4 (s = 5, gamma = 1/4, order 4 < s): the part of degree <= 4 of e^z (1 - z/4)^5 (order 4), with no z^5
// term (R(infinity) = 0, the L-stability HW II Table 6.5 claims), over (1 - z/4)^5; sympy gives the same
// polynomial from the table's a and b: 1 - z/4 - z^2/8 + z^3/96 + 7 z^4/768.
cplx sdirk4_r(cplx z) {
    const cplx p = cplx(1) - z / 4.0L - z * z / 8.0L + z * z * z / 96.0L + 7.0L * z * z * z * z / 768.0L;
    const cplx q = cplx(1) - z / 4.0L;
    return p / (q * q * q * q * q);
}

template <class Tag, class Closed>
void stability_matches(Closed closed) {
    INFO(Tag::name);
    const cplx points[] = {cplx(-0.5L, 0), cplx(-3, 2), cplx(0.1L, 0.7L), cplx(-40, -15), cplx(0, 9)};
    for (const cplx z : points)
        CHECK(std::abs(stability<Tag>(z) - closed(z)) <= 64 * LDBL_EPSILON * (1 + std::abs(closed(z))));
}

// |R(iy)| <= 1 on the imaginary axis, y from 1e-3 to 1e8 (R(-iy) is the conjugate), and |R| <= 1 on a grid of
// the left half-plane up to |z| = 1e6 (so no pole lies there: with the axis, that is A-stability).
template <class Tag>
void a_stable() {
    INFO(Tag::name);
    long double worst_axis = 0;
    for (long double y = 1e-3L; y <= 1e8L; y *= 1.1L)
        worst_axis = std::max(worst_axis, std::abs(stability<Tag>(cplx(0, y))));
    CHECK(worst_axis <= 1 + 8 * LDBL_EPSILON);
    long double worst_plane = 0;
    for (long double x = 1e-2L; x <= 1e6L; x *= 1.5L)
        for (long double y = 0; y <= 1e6L; y = y * 1.5L + 1e-2L)
            worst_plane = std::max(worst_plane, std::abs(stability<Tag>(cplx(-x, y))));
    CHECK(worst_plane <= 1 + 8 * LDBL_EPSILON);
}

// ---- counting evaluations

template <class F>
struct counted {
    F f;
    std::size_t* calls;
    template <class T, class S>
    void operator()(T t, const S& y, S& d) const {
        ++*calls;
        f(t, y, d);
    }
};

// ---- the order on a smooth problem with a closed form

template <class Stepper>
double error_exp_sin(std::size_t steps) {
    using T = typename Stepper::value_type;
    Stepper stepper;
    state3<T> y{T(1), T(1), T(0)};
    const T t_end = T(10);
    const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
    const auto r = odestep::integrate_n_steps(stepper, sys, y, T(0), t_end / static_cast<T>(steps), steps);
    REQUIRE(r.status == odestep::status::ok);
    const double e0 = std::fabs(double(y[0]) - std::exp(std::sin(10.0)));
    const double e1 = std::fabs(double(y[1]) - std::cos(10.0));
    const double e2 = std::fabs(double(y[2]) - std::sin(10.0));
    return std::fmax(e0, std::fmax(e1, e2));
}

template <class Stepper>
double observed_order(std::size_t coarsest) {
    std::array<double, 4> errors{};
    for (std::size_t i = 0; i < 4; ++i) errors[i] = error_exp_sin<Stepper>(coarsest << i);
    MESSAGE("errors " << errors[0] << " ... " << errors[3]);
    return odestep_test::fitted_order(errors);
}

}  // namespace

TEST_CASE("implicit_rk: every table's stability function is its closed form (Pade approximations of e^z)") {
    stability_matches<tab::backward_euler>(backward_euler_r);
    stability_matches<tab::trapezoid>(trapezoid_r);
    stability_matches<tab::implicit_midpoint>(trapezoid_r);
    stability_matches<tab::gauss4>(gauss4_r);
    stability_matches<tab::sdirk3>(sdirk3_r);
    stability_matches<tab::radau_iia5>(radau5_r);
    stability_matches<tab::sdirk4>(sdirk4_r);
}

// The two slowest cases (about 1 s and 2 s on an emulated Cortex-M4F, where double is software) are in the
// "long" suite, which the emulated cores skip; everything else here runs there too.
TEST_CASE("implicit_rk: every method is A-stable: |R(z)| <= 1 on the imaginary axis and in the left half-plane" *
          doctest::test_suite("long")) {
    a_stable<tab::backward_euler>();
    a_stable<tab::trapezoid>();
    a_stable<tab::implicit_midpoint>();
    a_stable<tab::gauss4>();
    a_stable<tab::sdirk3>();
    a_stable<tab::radau_iia5>();
    a_stable<tab::sdirk4>();
}

TEST_CASE("implicit_rk: R(infinity) = 0 for the L-stable methods, |R(infinity)| = 1 for trapezoid, midpoint, Gauss") {
    // At z = -1e6: an L-stable R is O(1/z) (backward Euler 1e-6, SDIRK 2.9e-6, Radau IIA 3e-6), the others are
    // 1 - O(1/z) in magnitude (the trapezoid's (1 + z/2) / (1 - z/2) = -(1 - 4e-6)). Farther out, the formula
    // 1 + z b^T (I - zA)^-1 1 cancels to long double's rounding times |z|.
    const cplx far(-1e6L, 0);
    CHECK(std::abs(stability<tab::backward_euler>(far)) < 1e-5L);
    CHECK(std::abs(stability<tab::sdirk3>(far)) < 1e-5L);
    CHECK(std::abs(stability<tab::radau_iia5>(far)) < 1e-5L);
    CHECK(std::abs(stability<tab::sdirk4>(far)) < 1e-5L);
    // the stiff components are not damped, and the trapezoid and midpoint flip their sign every step
    CHECK(std::abs(std::abs(stability<tab::trapezoid>(far)) - 1) < 1e-5L);
    CHECK(stability<tab::trapezoid>(far).real() < 0);
    CHECK(std::abs(std::abs(stability<tab::implicit_midpoint>(far)) - 1) < 1e-5L);
    CHECK(stability<tab::implicit_midpoint>(far).real() < 0);
    CHECK(std::abs(std::abs(stability<tab::gauss4>(far)) - 1) < 2e-5L);  // 1 - 12/|z|
    CHECK(stability<tab::gauss4>(far).real() > 0);
    // and the tags' claims agree
    static_assert(tab::backward_euler::l_stable && tab::sdirk3::l_stable && tab::radau_iia5::l_stable);
    static_assert(!tab::trapezoid::l_stable && !tab::implicit_midpoint::l_stable && !tab::gauss4::l_stable);
}

TEST_CASE("implicit_rk: symplectic and time-reversible are computed from the tables as the theory says") {
    using s = state3<double>;
    // symplectic: the Gauss methods (implicit midpoint is Gauss with s = 1); symmetric: also the trapezoid
    static_assert(odestep::implicit_midpoint<s>::symplectic && odestep::gauss4<s>::symplectic);
    static_assert(!odestep::backward_euler<s>::symplectic && !odestep::trapezoid<s>::symplectic &&
                  !odestep::sdirk3<s>::symplectic && !odestep::radau_iia5<s>::symplectic);
    static_assert(odestep::implicit_midpoint<s>::time_reversible && odestep::gauss4<s>::time_reversible &&
                  odestep::trapezoid<s>::time_reversible);
    static_assert(!odestep::backward_euler<s>::time_reversible && !odestep::sdirk3<s>::time_reversible &&
                  !odestep::radau_iia5<s>::time_reversible);
    static_assert(odestep::check_stepper<odestep::radau_iia5<s>>() && odestep::check_stepper<odestep::gauss4<s>>() &&
                  odestep::check_stepper<odestep::backward_euler<s, odestep::fixed_newton<2>>>());
    static_assert(odestep::radau_iia5<s>::implicit && odestep::radau_iia5<s>::factorizations_per_step == 1);
    CHECK(odestep::radau_iia5<s>::iteration_matrix_size == 9);
    CHECK(odestep::sdirk3<s>::iteration_matrix_size == 3);
}

TEST_CASE("implicit_rk: every method shows its order on a smooth problem with a closed form" *
          doctest::test_suite("long")) {
    using s = state3<double>;
    // t in [0, 10]; the step counts keep every error in the asymptotic range and far above the Newton tolerance.
    CHECK(observed_order<odestep::backward_euler<s>>(1000) == doctest::Approx(1.0).epsilon(0.03));
    CHECK(observed_order<odestep::trapezoid<s>>(100) == doctest::Approx(2.0).epsilon(0.03));
    CHECK(observed_order<odestep::implicit_midpoint<s>>(100) == doctest::Approx(2.0).epsilon(0.03));
    CHECK(observed_order<odestep::sdirk3<s>>(100) == doctest::Approx(3.0).epsilon(0.03));
    CHECK(observed_order<odestep::gauss4<s>>(40) == doctest::Approx(4.0).epsilon(0.03));
    CHECK(observed_order<odestep::radau_iia5<s>>(40) == doctest::Approx(5.0).epsilon(0.04));
}

TEST_CASE("implicit_rk: float runs the same template and meets the double error to float round-off") {
    using sf = state3<float>;
    using sd = state3<double>;
    const double ef = error_exp_sin<odestep::radau_iia5<sf>>(40);
    const double ed = error_exp_sin<odestep::radau_iia5<sd>>(40);
    CHECK(std::fabs(ef - ed) < 2e-5);
    const double bf = error_exp_sin<odestep::backward_euler<sf>>(100);
    const double bd = error_exp_sin<odestep::backward_euler<sd>>(100);
    CHECK(std::fabs(bf - bd) < 2e-5 * std::fabs(bd) + 1e-5);
}

TEST_CASE("backward Euler on RC discharge at h/RC = 10: Q_n = Q0 / (1 + h/RC)^n to rounding") {
    // float: 30 steps (11^-30 = 5.7e-32 is still a normal float); double: 100 steps
    auto check = [](auto zero, std::size_t steps) {
        using T = decltype(zero);
        const T rc = T(0.002);
        const T h = T(10) * rc;
        state1<T> q{T(1)};
        const auto sys = odestep::with_jacobian(odestep_test::rc_circuit<T>{rc}, odestep_test::rc_jacobian<T>{rc});
        bool exact = true;
        T worst = T(0);
        auto observe = [&](T t, const state1<T>& y) {
            const long double n = std::round(static_cast<long double>(t / h));
            const long double expected = std::pow(1.0L + static_cast<long double>(h / rc), -n);
            const long double rel = std::fabs(static_cast<long double>(y[0]) / expected - 1.0L);
            worst = std::max(worst, static_cast<T>(rel));
            exact = exact && rel <= 8.0L * (n + 1) * static_cast<long double>(std::numeric_limits<T>::epsilon());
        };
        const auto r =
            odestep::integrate_n_steps(odestep::backward_euler<state1<T>>{}, sys, q, T(0), h, steps, observe);
        CHECK(r.status == odestep::status::ok);
        CHECK(exact);
        MESSAGE("worst relative error " << double(worst));
    };
    check(0.0f, 30);
    check(0.0, 100);
}

TEST_CASE("trapezoid on RC discharge at h/RC = 10: Q_n = Q0 ((1 - z/2) / (1 + z/2))^n = (-2/3)^n, sign flips") {
    auto check = [](auto zero, std::size_t steps) {
        using T = decltype(zero);
        const T rc = T(0.5);
        const T h = T(5);  // z = h / RC = 10
        state1<T> q{T(1)};
        const auto sys = odestep::with_jacobian(odestep_test::rc_circuit<T>{rc}, odestep_test::rc_jacobian<T>{rc});
        bool exact = true;
        auto observe = [&](T t, const state1<T>& y) {
            const long double n = std::round(static_cast<long double>(t / h));
            const long double expected = std::pow(-2.0L / 3.0L, n);
            exact = exact && std::fabs(static_cast<long double>(y[0]) / expected - 1.0L) <=
                                 8.0L * (n + 1) * static_cast<long double>(std::numeric_limits<T>::epsilon());
        };
        const auto r = odestep::integrate_n_steps(odestep::trapezoid<state1<T>>{}, sys, q, T(0), h, steps, observe);
        CHECK(r.status == odestep::status::ok);
        CHECK(exact);
        CHECK(q[0] * T(steps % 2 == 0 ? 1 : -1) > T(0));
    };
    check(0.0f, 60);
    check(0.0, 200);
}

TEST_CASE("implicit_rk: with a difference Jacobian, RC discharge is Q0 / (1 + h/RC)^n to the Newton tolerance") {
    const double rc = 0.002;
    const double h = 10 * rc;
    state1<double> q{1.0};
    const auto r = odestep::integrate_n_steps(odestep::backward_euler<state1<double>>{},
                                              odestep_test::rc_circuit<double>{rc}, q, 0.0, h, 100);
    REQUIRE(r.status == odestep::status::ok);
    CHECK(q[0] / std::pow(11.0, -100) == doctest::Approx(1.0).epsilon(1e-9));
}

TEST_CASE("implicit_rk: Robertson at t = 40 matches Hairer & Wanner's reference values, y1 + y2 + y3 = 1 kept") {
    // 20 steps in [0, 1e-5] and in each decade of t up to 10, then 20 in [10, 40]: 160 steps. The tolerances are the
    // methods' errors at these steps, about 1/3 of each bound; the invariant holds to rounding.
    auto run = [](const auto& stepper, double tolerance) {
        state3<double> y{1, 0, 0};
        const auto sys = odestep::with_jacobian(odestep_test::robertson{}, odestep_test::robertson_jacobian{});
        std::size_t steps = 0;
        const auto r = odestep_test::robertson_schedule(stepper, sys, y, 40.0, 20, &steps);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(steps == 160);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(y[i] / odestep_test::robertson_at_40[i] - 1) < tolerance);
        CHECK(std::fabs(y[0] + y[1] + y[2] - 1) < 1e-14);
    };
    run(odestep::backward_euler<state3<double>>{}, 3e-2);
    run(odestep::trapezoid<state3<double>>{}, 1e-3);
    run(odestep::sdirk3<state3<double>>{}, 2e-5);
    run(odestep::radau_iia5<state3<double>>{}, 2e-9);  // the reference's 10 digits are the limit
}

TEST_CASE("implicit_rk: Robertson in float with a difference Jacobian reaches t = 40 to float accuracy") {
    state3<float> y{1.0f, 0.0f, 0.0f};
    const auto r =
        odestep_test::robertson_schedule(odestep::radau_iia5<state3<float>>{}, odestep_test::robertson{}, y, 40.0f, 20);
    REQUIRE(r.status == odestep::status::ok);
    for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(double(y[i]) / odestep_test::robertson_at_40[i] - 1) < 1e-3);
}

TEST_CASE("implicit_rk: a NaN from f, at the start or inside the iteration, is non_finite with y kept bit for bit") {
    auto check = [](auto stepper) {
        using S = typename decltype(stepper)::state_type;
        using T = typename S::value_type;
        const T nan = std::numeric_limits<T>::quiet_NaN();
        // NaN at once
        S y{T(1), T(0.5), T(0.25)};
        const S before = y;
        auto poison = [nan](T, const S&) { return S{nan, T(0), T(0)}; };
        CHECK(stepper.step(poison, y, T(0), T(0.1)) == odestep::status::non_finite);
        CHECK(same_bits(y, before));
        // finite at y, NaN once the iterate moves off it (an Inf in the middle component)
        auto later = [&before](T, const S& v) {
            return v[0] == before[0] ? S{T(-1), T(0), T(0)} : S{T(0), std::numeric_limits<T>::infinity(), T(0)};
        };
        const auto sys = odestep::with_jacobian(later, [](T, const S&, odestep::jacobian_t<S>& j) { j = {}; });
        CHECK(stepper.step(sys, y, T(0), T(0.1)) == odestep::status::non_finite);
        CHECK(same_bits(y, before));
    };
    check(odestep::backward_euler<state3<double>>{});
    check(odestep::trapezoid<state3<float>>{});
    check(odestep::sdirk3<state3<double>>{});
    check(odestep::gauss4<state3<float>>{});
    check(odestep::radau_iia5<state3<double>>{});
    check(odestep::radau_iia5<state3<double>, odestep::fixed_newton<3>>{});
}

TEST_CASE("implicit_rk: a NaN or Inf in the system's Jacobian is singular_matrix with y kept bit for bit") {
    auto check = [](auto stepper) {
        using S = typename decltype(stepper)::state_type;
        using T = typename S::value_type;
        S y{T(1), T(0.5), T(0.25)};
        const S before = y;
        auto f = [](T, const S& v) { return S{-v[0], -v[1], -v[2]}; };
        auto bad = [](T, const S&, odestep::jacobian_t<S>& j) {
            j = {};
            j[1][2] = std::numeric_limits<T>::quiet_NaN();
        };
        CHECK(stepper.step(odestep::with_jacobian(f, bad), y, T(0), T(0.1)) == odestep::status::singular_matrix);
        CHECK(same_bits(y, before));
        auto huge = [](T, const S&, odestep::jacobian_t<S>& j) {
            j = {};
            j[0][0] = std::numeric_limits<T>::infinity();
        };
        CHECK(stepper.step(odestep::with_jacobian(f, huge), y, T(0), T(0.1)) == odestep::status::singular_matrix);
        CHECK(same_bits(y, before));
    };
    check(odestep::backward_euler<state3<double>>{});
    check(odestep::sdirk3<state3<float>>{});
    check(odestep::gauss4<state3<double>>{});
    check(odestep::radau_iia5<state3<float>>{});
}

TEST_CASE("implicit_rk: a singular iteration matrix I - h gamma J is singular_matrix with y kept bit for bit") {
    // f(y) = y with J = I: backward Euler at h = 1 has I - h J = 0, and the implicit midpoint at h = 2 too.
    auto f = [](double, const state1<double>& y) { return y; };
    auto identity = [](double, const state1<double>&, odestep::jacobian_t<state1<double>>& j) { j[0][0] = 1.0; };
    state1<double> y{3.0};
    const state1<double> before = y;
    CHECK(odestep::backward_euler<state1<double>>{}.step(odestep::with_jacobian(f, identity), y, 0.0, 1.0) ==
          odestep::status::singular_matrix);
    CHECK(same_bits(y, before));
    CHECK(odestep::implicit_midpoint<state1<double>>{}.step(odestep::with_jacobian(f, identity), y, 0.0, 2.0) ==
          odestep::status::singular_matrix);
    CHECK(same_bits(y, before));
    // and by differences: f(y) = y / h gives J = 1 / h to rounding, not exactly, so it is factored; the exact
    // singular case above is the one the factorization must catch.
}

TEST_CASE("implicit_rk: Newton that does not converge within its cap is no_convergence, y kept bit for bit") {
    // y' = -y^3, y(0) = 1, backward Euler with h = 100: the solution of y1 + 100 y1^3 = 1 is y1 = 0.2, where the
    // residual's derivative is 13, but the Jacobian frozen at y0 = 1 gives 301: simplified Newton contracts by
    // 1 - 13/301 = 0.957 per iteration, far too slowly for 10 iterations.
    auto f = [](double, const state1<double>& y) { return state1<double>{-y[0] * y[0] * y[0]}; };
    auto j = [](double, const state1<double>& y, odestep::jacobian_t<state1<double>>& m) {
        m[0][0] = -3 * y[0] * y[0];
    };
    std::size_t calls = 0;
    auto counting = [&](double t, const state1<double>& y) {
        ++calls;
        return f(t, y);
    };
    state1<double> y{1.0};
    const state1<double> before = y;
    using be = odestep::backward_euler<state1<double>>;
    CHECK(be{}.step(odestep::with_jacobian(counting, j), y, 0.0, 100.0) == odestep::status::no_convergence);
    CHECK(same_bits(y, before));
    CHECK(calls == be::rhs_evals_with_jacobian);  // the worst case, reached: 10 iterations
    // by differences, the same, and the published worst case is exactly what it cost
    calls = 0;
    CHECK(be{}.step(counting, y, 0.0, 100.0) == odestep::status::no_convergence);
    CHECK(calls == be::rhs_evals_per_step);
    CHECK(same_bits(y, before));
    // a wrong Jacobian (of the wrong sign) makes the iteration diverge: abandoned before the cap
    auto wrong = [](double, const state1<double>& v, odestep::jacobian_t<state1<double>>& m) {
        m[0][0] = 3 * v[0] * v[0];
    };
    calls = 0;
    CHECK(be{}.step(odestep::with_jacobian(counting, wrong), y, 0.0, 1.0) == odestep::status::no_convergence);
    CHECK(calls < be::rhs_evals_with_jacobian);
    CHECK(same_bits(y, before));
    // with 1000 iterations allowed it converges (in about 550) to y1 = 0.2 (0.2 + 100 0.008 = 1)
    CHECK(odestep::backward_euler<state1<double>, odestep::newton<1000>>{}.step(odestep::with_jacobian(f, j), y, 0.0,
                                                                                100.0) == odestep::status::ok);
    CHECK(y[0] == doctest::Approx(0.2).epsilon(1e-9));
}

TEST_CASE("implicit_rk: the tolerance is validated, and a refused one changes nothing") {
    odestep::radau_iia5<state3<double>> stepper;
    const auto before = stepper.tolerance();
    CHECK(before.relative == doctest::Approx(std::pow(2.0, -39)).epsilon(1e-12));
    CHECK(odestep::newton_tolerance<float>{}.relative == std::pow(2.0f, -17.0f));
    CHECK(stepper.set_tolerance({-1e-9, 1e-9}) == odestep::status::invalid_tolerance);
    CHECK(stepper.set_tolerance({1e-9, 0.0}) == odestep::status::invalid_tolerance);
    CHECK(stepper.set_tolerance({std::numeric_limits<double>::quiet_NaN(), 1e-9}) ==
          odestep::status::invalid_tolerance);
    CHECK(stepper.set_tolerance({1e-9, std::numeric_limits<double>::infinity()}) == odestep::status::invalid_tolerance);
    CHECK(stepper.tolerance().relative == before.relative);
    CHECK(stepper.tolerance().absolute == before.absolute);
    CHECK(stepper.set_tolerance({0.0, 1e-6}) == odestep::status::ok);
    CHECK(stepper.tolerance().absolute == 1e-6);
}

TEST_CASE("implicit_rk: the evaluations per step are the published ones: exact with fixed_newton, bounded otherwise") {
    using s = state3<double>;
    // the published counts: Jacobian by differences N (+ f(t, y) unless the first stage is it), iterations at the cap
    static_assert(odestep::backward_euler<s>::rhs_evals_per_step == 3 + 1 + 10);
    static_assert(odestep::trapezoid<s>::rhs_evals_per_step == 3 + 1 + 10);  // the explicit stage is f(t, y)
    static_assert(odestep::sdirk3<s>::rhs_evals_per_step == 3 + 1 + 3 * 10);
    static_assert(odestep::radau_iia5<s>::rhs_evals_per_step == 3 + 1 + 3 * 10);
    static_assert(odestep::gauss4<s, odestep::fixed_newton<2>>::rhs_evals_per_step == 3 + 1 + 2 * 2);
    static_assert(odestep::radau_iia5<s>::rhs_evals_for<
                      odestep::system_with_jacobian<odestep_test::robertson, odestep_test::robertson_jacobian>> ==
                  3 * 10);
    auto check_fixed = [](auto stepper) {
        using St = decltype(stepper);
        std::size_t calls = 0;
        std::size_t jacobians = 0;
        const counted<odestep_test::robertson> f{{}, &calls};
        auto j = [&](double t, const s& y, odestep::jacobian_t<s>& m) {
            ++jacobians;
            odestep_test::robertson_jacobian{}(t, y, m);
        };
        s y{1, 1e-5, 0};
        for (int n = 0; n < 5; ++n) {
            calls = 0;
            REQUIRE(stepper.step(f, y, 1e-3 * n, 1e-3) == odestep::status::ok);
            CHECK(calls == St::rhs_evals_per_step);
            calls = 0;
            jacobians = 0;
            REQUIRE(stepper.step(odestep::with_jacobian(f, j), y, 1e-3 * n, 1e-3) == odestep::status::ok);
            CHECK(calls == St::rhs_evals_with_jacobian);
            CHECK(jacobians == 1);
        }
    };
    check_fixed(odestep::backward_euler<s, odestep::fixed_newton<2>>{});
    check_fixed(odestep::trapezoid<s, odestep::fixed_newton<3>>{});
    check_fixed(odestep::sdirk3<s, odestep::fixed_newton<2>>{});
    check_fixed(odestep::gauss4<s, odestep::fixed_newton<1>>{});
    check_fixed(odestep::radau_iia5<s, odestep::fixed_newton<3>>{});
    // converging: a linear system with its exact Jacobian takes two iterations (the second update is rounding)
    std::size_t calls = 0;
    auto lin = [&](double, const state1<double>& q) {
        ++calls;
        return state1<double>{-q[0]};
    };
    auto lin_j = [](double, const state1<double>&, odestep::jacobian_t<state1<double>>& m) { m[0][0] = -1; };
    state1<double> q{1};
    REQUIRE(odestep::radau_iia5<state1<double>>{}.step(odestep::with_jacobian(lin, lin_j), q, 0.0, 0.5) ==
            odestep::status::ok);
    CHECK(calls == 3 * 2);
    CHECK(q[0] == doctest::Approx(static_cast<double>(radau5_r(cplx(-0.5L)).real())).epsilon(1e-14));
}

TEST_CASE("implicit_rk: fixed_newton<1> on a linear system with its exact Jacobian is the exact implicit step") {
    // One Newton step from Z = 0 with the exact Jacobian solves a linear stage equation: R(-h/RC) per step.
    const double rc = 0.25;
    state1<double> q{1.0};
    const auto sys =
        odestep::with_jacobian(odestep_test::rc_circuit<double>{rc}, odestep_test::rc_jacobian<double>{rc});
    REQUIRE(
        odestep::integrate_n_steps(odestep::sdirk3<state1<double>, odestep::fixed_newton<1>>{}, sys, q, 0.0, 1.0, 10)
            .status == odestep::status::ok);
    CHECK(q[0] == doctest::Approx(static_cast<double>(std::pow(sdirk3_r(cplx(-4.0L)).real(), 10.0L))).epsilon(1e-12));
}

TEST_CASE("implicit_rk: integrate lands on t1 with a shortened last step, integrate_n_steps counts its steps") {
    const double rc = 1.0;
    const auto sys =
        odestep::with_jacobian(odestep_test::rc_circuit<double>{rc}, odestep_test::rc_jacobian<double>{rc});
    state1<double> q{1.0};
    std::size_t observed = 0;
    const auto r = odestep::integrate(odestep::backward_euler<state1<double>>{}, sys, q, 0.0, 1.0, 0.3,
                                      [&](double, const state1<double>&) { ++observed; });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(r.steps == 4);
    CHECK(observed == 5);
    CHECK(q[0] == doctest::Approx(1 / (1.3 * 1.3 * 1.3 * 1.1)).epsilon(1e-13));  // three steps of 0.3, one of 0.1
    const auto bad = odestep::integrate(odestep::backward_euler<state1<double>>{}, sys, q, 0.0, 1.0, 0.0);
    CHECK(bad.status == odestep::status::invalid_step);
}

TEST_CASE("implicit_rk: the event loop locates a crossing of the backward Euler trajectory at its closed form") {
    // Q' = -Q, RC = 1, h = 0.25: Q_n = 0.8^n. Q crosses 1/2 in step 4 (Q_3 = 0.512, Q_4 = 0.4096). The event loop
    // re-steps from t_3 with s < h, and one backward Euler step of s gives Q_3 / (1 + s): it reaches 1/2 at
    // s = Q_3 / (1/2) - 1 = 0.024, so at t = 0.774. The state at the event is the integrator's own just before.
    const auto sys =
        odestep::with_jacobian(odestep_test::rc_circuit<double>{1.0}, odestep_test::rc_jacobian<double>{1.0});
    auto half = [](double, const state1<double>& q) { return q[0] - 0.5; };
    state1<double> q{1.0};
    const auto r =
        odestep::integrate(odestep::backward_euler<state1<double>>{}, sys, q, 0.0, 2.0, 0.25,
                           odestep::watch(odestep::make_event<state1<double>>(half, odestep::direction::falling)));
    CHECK(r.status == odestep::status::stopped_by_event);
    CHECK(r.t == doctest::Approx(0.774).epsilon(1e-12));
    CHECK(q[0] >= 0.5);
    CHECK(q[0] - 0.5 < 1e-12);
    // the per-tick loop, as a control loop would run it: ticks of 0.25, the event in the fourth
    state1<double> p{1.0};
    auto loop = odestep::make_event_stepper(
        odestep::radau_iia5<state1<double>>{},
        odestep::watch(odestep::make_event<state1<double>>(half, odestep::direction::falling, odestep::record)));
    REQUIRE(loop.start(0.0, 0.25, p) == odestep::status::ok);
    std::size_t fired_at = 0;
    for (std::size_t n = 1; n <= 8; ++n) {
        const auto tick = loop.tick(sys, p);
        REQUIRE(tick.status == odestep::status::ok);
        if (tick.fired > 0 && fired_at == 0) fired_at = n;
    }
    CHECK(fired_at == 3);  // Radau IIA is nearly exact: e^-t = 1/2 at t = 0.693, in the third tick
    CHECK(p[0] == doctest::Approx(std::exp(-2.0)).epsilon(1e-6));
}

TEST_CASE("implicit_rk: Radau IIA 5's estimating step gives RADAU5's estimate, of local order 4, and the plain step") {
    using s3 = state3<double>;
    using stepper = odestep::radau_iia5<s3>;
    static_assert(stepper::error_estimate && stepper::embedded_order == 3);
    static_assert(stepper::rhs_evals_per_error_step == stepper::rhs_evals_per_step);
    static_assert(!odestep::sdirk3<s3>::error_estimate && !odestep::backward_euler<s3>::error_estimate);
    // one step of exp(sin t) (support/problems.hpp) from t = 0.3 with h = 0.2 / 2^k: |err| ~ C h^4
    const auto sys = odestep::with_jacobian(odestep_test::exp_sin{}, odestep_test::exp_sin_jacobian{});
    std::array<double, 4> errs{};
    std::array<double, 4> hs{};
    for (std::size_t k = 0; k < 4; ++k) {
        hs[k] = 0.2 / double(1u << k);
        s3 y = odestep_test::exp_sin::exact(0.3);
        s3 plain = y;
        s3 err{};
        REQUIRE(stepper{}.step(sys, y, 0.3, hs[k], err) == odestep::status::ok);
        REQUIRE(stepper{}.step(sys, plain, 0.3, hs[k]) == odestep::status::ok);
        CHECK(std::memcmp(&y, &plain, sizeof y) == 0);
        errs[k] = std::sqrt(err[0] * err[0] + err[1] * err[1] + err[2] * err[2]);
    }
    const double slope = odestep_test::log_log_slope(hs, errs);
    MESSAGE("Radau IIA 5 estimate: " << errs[0] << " ... " << errs[3] << ", slope " << slope);
    CHECK(slope > 3.7);
    CHECK(slope < 4.3);
}

TEST_CASE("implicit_rk: a Newton matrix whose first pivot is zero is solved with a row interchange") {
    // y' = J y with J = [[1/(h g), 1], [1, 0]] (g the stage's diagonal coefficient): the iteration matrix
    // I - h g J has a zero in its top-left corner, so LU without pivoting divides by zero, while with partial
    // pivoting it is an ordinary, well-conditioned 2x2 system. The expected values are that system solved by
    // hand (Cramer's rule; every number is exact in binary), each in the block below.
    using s2 = std::array<double, 2>;
    const auto linear = [](double j00) {
        return odestep::with_jacobian(
            [j00](double, const s2& y) {
                return s2{j00 * y[0] + y[1], y[0]};
            },
            [j00](double, const s2&, odestep::jacobian_t<s2>& j) {
                j = {{{j00, 1.0}, {1.0, 0.0}}};
            });
    };
    {
        // Backward Euler (g = 1), h = 1/2, J00 = 2: (I - h J) y1 = y0 is [[0, -1/2], [-1/2, 1]] y1 = (1, 1), so
        // y1[1] = -2 and y1[0] = -2 (1 - y1[1]) = -6.
        s2 y{1.0, 1.0};
        CHECK(odestep::backward_euler<s2>{}.step(linear(2.0), y, 0.0, 0.5) == odestep::status::ok);
        CHECK(y[0] == doctest::Approx(-6.0).epsilon(1e-12));
        CHECK(y[1] == doctest::Approx(-2.0).epsilon(1e-12));
    }
    {
        // The trapezoid (g = 1/2), h = 1/2, J00 = 4: (I - h/2 J) y1 = (I + h/2 J) y0 is
        // [[0, -1/4], [-1/4, 1]] y1 = (1, 1) + (1/4) (5, 1) = (9/4, 5/4), so y1[1] = -9 and
        // y1[0] = -4 (5/4 - y1[1]) = -41.
        s2 y{1.0, 1.0};
        CHECK(odestep::trapezoid<s2>{}.step(linear(4.0), y, 0.0, 0.5) == odestep::status::ok);
        CHECK(y[0] == doctest::Approx(-41.0).epsilon(1e-12));
        CHECK(y[1] == doctest::Approx(-9.0).epsilon(1e-12));
    }
}
