// SPDX-License-Identifier: BSL-1.0
// The step's derivative Phi = d y_{n+1} / d y_n (sensitivity/transition.hpp): on y' = A y against the
// stability polynomials computed here from the published tables; on Lorenz, the pendulum and Kepler against
// central differences of the plain step, with the O(eps^2) convergence of the differences shown over a sweep;
// the product of the steps' Phi against the differences of a whole run; Phi^T J Phi = J for the splitting
// methods; bad input and the roll-back.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "sensitivity/helpers.hpp"
#include "support/compare.hpp"
#include "support/methods.hpp"
#include "support/problems.hpp"

namespace {

using odestep_test::same_bits;

using namespace sensitivity_test;  // NOLINT: the shared matrices, problems and difference check

// ---- linear systems: Phi = R(h A)

// A non-normal 3 x 3 matrix with a rotation and decay (no structure the step could exploit).
const mat<double, 3> A3{{{-1.0, 2.0, 0.5}, {-0.3, -2.0, 1.0}, {0.2, 0.4, -0.5}}};

template <class T, std::size_t N>
auto linear_system(const mat<T, N>& a) {
    using S = std::array<T, N>;
    auto f = [&a](T, const S& y) {
        S d{};
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t j = 0; j < N; ++j) d[i] += a[i][j] * y[j];
        return d;
    };
    auto jac = [&a](T, const S&, odestep::jacobian_t<S>& J) { J = a; };
    return odestep::with_jacobian(std::move(f), std::move(jac));  // moved in: locals held by reference would dangle
}

// sum_k gamma_k (hA)^k for k = 0 .. K, gamma from the caller.
template <std::size_t K, class T, std::size_t N>
mat<T, N> matrix_polynomial(const std::array<long double, K + 1>& gamma, const mat<T, N>& a, T h) {
    mat<T, N> ha{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) ha[i][j] = h * a[i][j];
    mat<T, N> power = identity<T, N>();
    mat<T, N> sum{};
    for (std::size_t k = 0; k <= K; ++k) {
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t j = 0; j < N; ++j) sum[i][j] += static_cast<T>(gamma[k]) * power[i][j];
        power = product(power, ha);
    }
    return sum;
}

template <class Stepper, class T, std::size_t N>
mat<T, N> phi_of_linear(const mat<T, N>& a, T h) {
    auto sys = linear_system(a);
    std::array<T, N> y{};
    y[0] = T(1);
    mat<T, N> phi{};
    REQUIRE(Stepper{}.step(sys, y, phi, T(0), h) == odestep::status::ok);
    return phi;
}

TEST_CASE(
    "transition: on y' = A y, Phi is the published stability polynomial R(hA) of Euler, Heun, RK4 and "
    "Dormand-Prince 5(4)") {
    using state = std::array<double, 3>;
    const double h = 0.1;  // |hA| about 0.3: every power up to the 6th is above round-off
    // R(z) = sum_k gamma_k z^k. Euler: 1 + z; Heun (order 2, 2 stages): 1 + z + z^2/2; RK4 (order 4, 4
    // stages): the Taylor polynomial of e^z to z^4 (Hairer, Norsett & Wanner, Solving ODE I, Sec. IV.2);
    // Dormand-Prince 5(4), stepping with the 5th order: the Taylor polynomial to z^5 plus z^6 / 600, and no
    // z^7 term since b_7 = 0 (Hairer & Wanner, Solving ODE II, Sec. IV.2, the stability function of DOPRI5).
    const std::array<long double, 2> euler{1.0L, 1.0L};
    const std::array<long double, 3> heun{1.0L, 1.0L, 0.5L};
    const std::array<long double, 5> rk4{1.0L, 1.0L, 1.0L / 2, 1.0L / 6, 1.0L / 24};
    const std::array<long double, 8> dp5{1.0L, 1.0L, 1.0L / 2, 1.0L / 6, 1.0L / 24, 1.0L / 120, 1.0L / 600, 0.0L};
    const double tol = 16 * std::numeric_limits<double>::epsilon();
    CHECK(max_difference(phi_of_linear<odestep::euler_transition<state>>(A3, h), matrix_polynomial<1>(euler, A3, h)) <=
          tol);
    CHECK(max_difference(phi_of_linear<odestep::heun_transition<state>>(A3, h), matrix_polynomial<2>(heun, A3, h)) <=
          tol);
    CHECK(max_difference(phi_of_linear<odestep::rk4_transition<state>>(A3, h), matrix_polynomial<4>(rk4, A3, h)) <=
          tol);
    CHECK(max_difference(phi_of_linear<odestep::dormand_prince54_transition<state>>(A3, h),
                         matrix_polynomial<7>(dp5, A3, h)) <= tol);
    // The 1/600 is the table's own: b^T A^5 1 of Dormand-Prince, summed here in long double from the table.
    const auto& tab = odestep::tables::dormand_prince54::table<long double>;
    std::array<long double, 7> v{};
    for (auto& x : v) x = 1.0L;
    for (int power = 0; power < 5; ++power) {
        std::array<long double, 7> w{};
        for (std::size_t i = 0; i < 7; ++i)
            for (std::size_t j = 0; j < 7; ++j) w[i] += tab.a[i][j] * v[j];
        v = w;
    }
    long double gamma6 = 0.0L;
    for (std::size_t i = 0; i < 7; ++i) gamma6 += tab.b[i] * v[i];
    CHECK(std::fabs(gamma6 - 1.0L / 600) < 1e-15L);
}

TEST_CASE(
    "transition: on y' = A y, Phi is R(hA) with R's coefficients b^T A^(k-1) 1 from the table, for every "
    "explicit table") {
    // The stability polynomial of an explicit table is R(z) = 1 + sum_k (b^T A^(k-1) 1) z^k (Hairer & Wanner,
    // Solving ODE II, Sec. IV.2, eq. (2.5) expanded), computed here in long double from the published table:
    // a route (scalar coefficients, then matrix powers) that shares nothing with the stepper's stage loop.
    using state = std::array<double, 3>;
    const double h = 0.1;
    odestep_test::for_each_method([&](auto m) {
        using M = decltype(m);
        const auto& tab = M::template table<long double>;
        constexpr std::size_t S = std::remove_const_t<std::remove_reference_t<decltype(tab)>>::stages;
        std::array<long double, S + 1> gamma{};
        gamma[0] = 1.0L;
        std::array<long double, S> v{};
        for (auto& x : v) x = 1.0L;
        for (std::size_t k = 1; k <= S; ++k) {
            for (std::size_t i = 0; i < S; ++i) gamma[k] += tab.b[i] * v[i];
            std::array<long double, S> w{};
            for (std::size_t i = 0; i < S; ++i)
                for (std::size_t j = 0; j < S; ++j) w[i] += tab.a[i][j] * v[j];
            v = w;
        }
        const auto phi = phi_of_linear<odestep::explicit_rk_transition<M, state>>(A3, h);
        INFO(M::name);
        CHECK(max_difference(phi, matrix_polynomial<S>(gamma, A3, h)) <= 32 * std::numeric_limits<double>::epsilon());
    });
}

TEST_CASE(
    "transition: in float, RK4's Phi on y' = A y is R(hA) to float round-off, and the state is the plain step's") {
    using state = std::array<float, 3>;
    mat<float, 3> a{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) a[i][j] = static_cast<float>(A3[i][j]);
    const std::array<long double, 5> rk4{1.0L, 1.0L, 1.0L / 2, 1.0L / 6, 1.0L / 24};
    const auto phi = phi_of_linear<odestep::rk4_transition<state>>(a, 0.1f);
    CHECK(max_difference(phi, matrix_polynomial<4>(rk4, a, 0.1f)) <= 16 * std::numeric_limits<float>::epsilon());
}

// ---- nonlinear systems: Phi against central differences of the plain step

TEST_CASE(
    "transition: on Lorenz, the pendulum and Kepler, Phi is the limit of central differences of the plain "
    "step, their error falling as e^2") {
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    const std::array<double, 3> y0{1.0, 2.0, 20.0};
    check_against_differences<odestep::rk4<std::array<double, 3>>, odestep::rk4_transition<std::array<double, 3>>>(
        lz, y0, 0.0, 0.02, 0.4);
    check_against_differences<odestep::dormand_prince54<std::array<double, 3>>,
                              odestep::dormand_prince54_transition<std::array<double, 3>>>(lz, y0, 0.0, 0.02, 0.4);
    check_against_differences<odestep::fehlberg78<std::array<double, 3>>,
                              odestep::explicit_rk_transition<odestep::tables::fehlberg78, std::array<double, 3>>>(
        lz, y0, 0.0, 0.02, 0.4);
    auto pd = odestep::with_jacobian(pendulum{}, pendulum_jacobian{});
    check_against_differences<odestep::rk4<std::array<double, 2>>, odestep::rk4_transition<std::array<double, 2>>>(
        pd, std::array<double, 2>{2.0, 0.5}, 0.0, 0.3, 0.2);
    check_against_differences<odestep::midpoint<std::array<double, 2>>,
                              odestep::explicit_rk_transition<odestep::tables::midpoint, std::array<double, 2>>>(
        pd, std::array<double, 2>{2.0, 0.5}, 0.0, 0.3, 0.2);
    auto kp = odestep::with_jacobian(kepler4{}, kepler4_jacobian{});
    check_against_differences<odestep::rk4<std::array<double, 4>>, odestep::rk4_transition<std::array<double, 4>>>(
        kp, std::array<double, 4>{1.0, 0.2, -0.3, 1.1}, 0.0, 0.1, 0.1);
}

// ---- composition: the run's derivative

TEST_CASE("transition: the product of the steps' Phi is the derivative of the whole run, and propagate gives it") {
    using state = std::array<double, 3>;
    auto lz = odestep::with_jacobian(lorenz{}, lorenz_jacobian{});
    const state y0{1.0, 2.0, 20.0};
    const double dt = 0.01;
    const int steps = 20;
    odestep::rk4_transition<state> st;
    state y = y0;
    state z = y0;
    mat<double, 3> prod = identity<double, 3>();
    mat<double, 3> s = identity<double, 3>();
    for (int n = 0; n < steps; ++n) {
        const double t = n * dt;
        mat<double, 3> phi{};
        REQUIRE(st.step(lz, y, phi, t, dt) == odestep::status::ok);
        prod = product(phi, prod);
        REQUIRE(st.propagate(lz, z, s, t, dt) == odestep::status::ok);
    }
    CHECK(same_bits(y, z));
    CHECK(max_difference(prod, s) <= 1e-12 * max_entry(prod));
    // The run by the plain stepper, differentiated by central differences: its error is O(e^2) (about
    // 1e-5 relative at e = 1e-3 here), far above round-off.
    mat<double, 3> run{};
    const double e = 1e-3;
    for (std::size_t j = 0; j < 3; ++j) {
        state plus = y0;
        state minus = y0;
        plus[j] += e;
        minus[j] -= e;
        REQUIRE(odestep::integrate_n_steps(odestep::rk4<state>{}, lz, plus, 0.0, dt, steps).status ==
                odestep::status::ok);
        REQUIRE(odestep::integrate_n_steps(odestep::rk4<state>{}, lz, minus, 0.0, dt, steps).status ==
                odestep::status::ok);
        for (std::size_t i = 0; i < 3; ++i) run[i][j] = (plus[i] - minus[i]) / (2 * e);
    }
    CHECK(max_difference(prod, run) <= 1e-5 * max_entry(prod));
    // A sensitivity with fewer columns than N: the same columns.
    std::array<std::array<double, 1>, 3> col{{{1.0}, {0.0}, {0.0}}};
    state w = y0;
    for (int n = 0; n < steps; ++n) REQUIRE(st.propagate(lz, w, col, n * dt, dt) == odestep::status::ok);
    for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(col[i][0] - s[i][0]) <= 1e-12 * max_entry(s));
}

// ---- splitting methods

template <std::size_t N>
mat<double, 2 * N> symplectic_j() {
    mat<double, 2 * N> j{};
    for (std::size_t i = 0; i < N; ++i) {
        j[i][N + i] = 1.0;
        j[N + i][i] = -1.0;
    }
    return j;
}

struct kepler_hessian_j {
    void operator()(double, const std::array<double, 2>& x, mat<double, 2>& J) const { J = kepler_hessian(x); }
};
struct pendulum_a {
    std::array<double, 1> operator()(double, const std::array<double, 1>& x) const { return {-std::sin(x[0])}; }
};
struct pendulum_dadx {
    void operator()(double, const std::array<double, 1>& x, mat<double, 1>& J) const { J = {{{-std::cos(x[0])}}}; }
};

// ---- parameters: the augmented system

TEST_CASE(
    "transition: the derivative with respect to a parameter, by the augmented system (y, k)' = (f, 0), is the "
    "closed form of the run") {
    // y' = -k y with the parameter k as a state component with zero derivative; s = d (y, k) / dk starts at
    // (0, 1) and propagate carries it. The Jacobian of the augmented f, [[-k, -y], [0, 0]], holds df/dk; it
    // comes here from dual numbers (f written once as a template). The runs' closed forms:
    //   RK4: y_n = R(-kh)^n y_0, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, so dy_n/dk = -n h R^(n-1) R'(-kh) y_0;
    //   backward Euler: y_n = y_0 / (1 + kh)^n, so dy_n/dk = -n h y_0 / (1 + kh)^(n+1).
    using state = std::array<double, 2>;  // y, k
    auto decay = odestep::with_dual_jacobian([](double, const auto& y) {
        using S = std::decay_t<decltype(y[0])>;
        return std::array<S, 2>{-y[1] * y[0], S(0.0)};
    });
    const double k = 0.7;
    const double h = 0.1;
    const double y0 = 2.0;
    const int n = 30;
    const double z = -k * h;
    const double r = 1 + z + z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
    const double dr = 1 + z + z * z / 2 + z * z * z / 6;  // R'(z)
    const double rk4_expected = -n * h * std::pow(r, n - 1) * dr * y0;
    const double be_expected = -n * h * y0 / std::pow(1 + k * h, n + 1);
    SUBCASE("RK4") {
        state y{y0, k};
        std::array<std::array<double, 1>, 2> s{{{0.0}, {1.0}}};
        for (int i = 0; i < n; ++i)
            REQUIRE(odestep::rk4_transition<state>{}.propagate(decay, y, s, i * h, h) == odestep::status::ok);
        CHECK(std::fabs(y[0] - std::pow(r, n) * y0) <= 1e-14);
        CHECK(std::fabs(s[0][0] - rk4_expected) <= 1e-13);
        CHECK(s[1][0] == 1.0);
    }
    SUBCASE("backward Euler") {
        state y{y0, k};
        std::array<std::array<double, 1>, 2> s{{{0.0}, {1.0}}};
        for (int i = 0; i < n; ++i)
            REQUIRE(odestep::backward_euler_transition<state>{}.propagate(decay, y, s, i * h, h) ==
                    odestep::status::ok);
        CHECK(std::fabs(y[0] - y0 / std::pow(1 + k * h, n)) <= 1e-10);
        CHECK(std::fabs(s[0][0] - be_expected) <= 1e-9);
        CHECK(std::fabs(s[1][0] - 1.0) <= 1e-15);
    }
}

TEST_CASE("splitting transition: velocity Verlet's Phi on x'' = -w^2 x is its published transfer matrix") {
    // Velocity Verlet on the oscillator: x1 = (1 - h^2 w^2/2) x0 + h v0, v1 = -h w^2 (1 - h^2 w^2/4) x0 +
    // (1 - h^2 w^2/2) v0 (Hairer, Lubich & Wanner, Geometric Numerical Integration, Sec. I.5; written out
    // from x1 = x0 + h v0 + h^2/2 a0, v1 = v0 + h/2 (a0 + a1)).
    using state = std::array<double, 1>;
    const double w2 = 4.0;
    const double h = 0.3;
    auto a = odestep::with_jacobian([w2](double, const state& x) { return state{-w2 * x[0]}; },
                                    [w2](double, const state&, mat<double, 1>& J) { J = {{{-w2}}}; });
    state x{0.7};
    state v{-0.2};
    odestep::phase_matrix_t<state> phi{};
    REQUIRE(odestep::velocity_verlet_transition<state>{}.step(a, x, v, phi, 0.0, h) == odestep::status::ok);
    const double c = 1 - h * h * w2 / 2;
    const mat<double, 2> expected{{{c, h}, {-h * w2 * (1 - h * h * w2 / 4), c}}};
    CHECK(max_difference(phi, expected) <= 4 * std::numeric_limits<double>::epsilon());
}

template <class Method>
void check_splitting(double h) {
    using state = std::array<double, 2>;
    auto a = odestep::with_jacobian(odestep_test::kepler{}, kepler_hessian_j{});
    const state x0{1.0, 0.2};
    const state v0{-0.3, 1.1};
    state x = x0;
    state v = v0;
    odestep::phase_matrix_t<state> phi{};
    odestep::splitting_transition<Method, state> st;
    REQUIRE(st.step(a, x, v, phi, 0.0, h) == odestep::status::ok);
    // The state is the plain (fresh) splitting stepper's, bit for bit.
    state px = x0;
    state pv = v0;
    odestep::splitting<Method, state> plain;
    REQUIRE(plain.step(a, px, pv, 0.0, h) == odestep::status::ok);
    CHECK(same_bits(px, x));
    CHECK(same_bits(pv, v));
    // Symplectic: Phi^T J Phi = J to round-off (HLW, Def. VI.2.2).
    const auto j = symplectic_j<2>();
    CHECK(max_difference(product(transpose(phi), product(j, phi)), j) <=
          64 * std::numeric_limits<double>::epsilon() * max_entry(phi) * max_entry(phi));
    // Central differences of the plain step over a sweep: the error falls as e^2 (as for the RK steps).
    auto differences = [&](double e) {
        mat<double, 4> d{};
        for (std::size_t col = 0; col < 4; ++col) {
            state xp = x0, vp = v0, xm = x0, vm = v0;
            (col < 2 ? xp[col] : vp[col - 2]) += e;
            (col < 2 ? xm[col] : vm[col - 2]) -= e;
            odestep::splitting<Method, state> s1;
            odestep::splitting<Method, state> s2;
            REQUIRE(s1.step(a, xp, vp, 0.0, h) == odestep::status::ok);
            REQUIRE(s2.step(a, xm, vm, 0.0, h) == odestep::status::ok);
            for (std::size_t i = 0; i < 2; ++i) {
                d[i][col] = (xp[i] - xm[i]) / (2 * e);
                d[2 + i][col] = (vp[i] - vm[i]) / (2 * e);
            }
        }
        return d;
    };
    double e = 0.1;
    double previous = max_difference(differences(e), phi);
    for (int halving = 0; halving < 3; ++halving) {
        e /= 2;
        const double error = max_difference(differences(e), phi);
        INFO(Method::name << ": e = " << e << ", error " << error << ", previous " << previous);
        CHECK(previous / error > 3.0);
        CHECK(previous / error < 5.0);
        previous = error;
    }
}

TEST_CASE(
    "splitting transition: Verlet, Forest-Ruth and Yoshida on Kepler: Phi^T J Phi = J, and Phi is the limit "
    "of the plain step's differences") {
    check_splitting<odestep::tables::velocity_verlet>(0.2);
    check_splitting<odestep::tables::forest_ruth>(0.2);
    check_splitting<odestep::tables::yoshida6>(0.2);
    check_splitting<odestep::tables::euler_cromer>(0.2);
}

TEST_CASE("splitting transition: propagate over a run is the product of the steps' Phi, and det Phi = 1") {
    using state = std::array<double, 1>;
    auto a = odestep::with_jacobian(pendulum_a{}, pendulum_dadx{});
    state x{2.0};
    state v{0.1};
    state px = x;
    state pv = v;
    odestep::forest_ruth_transition<state> st;
    mat<double, 2> prod = identity<double, 2>();
    std::array<std::array<double, 2>, 2> s = identity<double, 2>();
    for (int n = 0; n < 50; ++n) {
        mat<double, 2> phi{};
        REQUIRE(st.step(a, x, v, phi, n * 0.1, 0.1) == odestep::status::ok);
        CHECK(std::fabs(phi[0][0] * phi[1][1] - phi[0][1] * phi[1][0] - 1.0) < 1e-14);
        prod = product(phi, prod);
        REQUIRE(st.propagate(a, px, pv, s, n * 0.1, 0.1) == odestep::status::ok);
    }
    CHECK(max_difference(prod, s) <= 1e-12 * max_entry(prod));
    CHECK(std::fabs(prod[0][0] * prod[1][1] - prod[0][1] * prod[1][0] - 1.0) < 1e-11);
}

// ---- bad input

TEST_CASE("transition: a NaN in J, a non-finite state or an overflowing Phi is non_finite with y and Phi untouched") {
    using state = std::array<double, 2>;
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    auto f = [](double, const state& y) { return state{y[1], -y[0]}; };
    const state y0{0.5, -0.25};
    mat<double, 2> phi0{{{3.0, 4.0}, {5.0, 6.0}}};
    odestep::rk4_transition<state> st;
    SUBCASE("NaN in J") {
        auto sys = odestep::with_jacobian(f, [qnan](double, const state&, mat<double, 2>& J) {
            J = {{{0.0, 1.0}, {-1.0, qnan}}};
        });
        state y = y0;
        mat<double, 2> phi = phi0;
        CHECK(st.step(sys, y, phi, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
        std::array<std::array<double, 2>, 2> s = phi0;
        CHECK(st.propagate(sys, y, s, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(same_bits(s, phi0));
    }
    SUBCASE("NaN in J at a later stage only") {
        auto sys = odestep::with_jacobian(f, [qnan](double t, const state&, mat<double, 2>& J) {
            J = {{{0.0, 1.0}, {-1.0, t > 0.0 ? qnan : 0.0}}};
        });
        state y = y0;
        mat<double, 2> phi = phi0;
        CHECK(st.step(sys, y, phi, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
    SUBCASE("a finite state with an overflowing Phi") {
        auto sys = odestep::with_jacobian(f, [](double, const state&, mat<double, 2>& J) {
            J = {{{1e300, 1e300}, {1e300, 1e300}}};
        });
        state y = y0;
        mat<double, 2> phi = phi0;
        CHECK(st.step(sys, y, phi, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
    SUBCASE("a non-finite state") {
        auto sys = odestep::with_jacobian(
            [](double, const state&) {
                return state{std::numeric_limits<double>::infinity(), 0.0};
            },
            [](double, const state&, mat<double, 2>& J) { J = {}; });
        state y = y0;
        mat<double, 2> phi = phi0;
        CHECK(st.step(sys, y, phi, 0.0, 0.1) == odestep::status::non_finite);
        CHECK(same_bits(y, y0));
        CHECK(same_bits(phi, phi0));
    }
    SUBCASE("unchecked: the same arithmetic, written as it comes") {
        auto sys = odestep::with_jacobian(f, [](double, const state&, mat<double, 2>& J) {
            J = {{{0.0, 1.0}, {-1.0, 0.0}}};
        });
        state y = y0;
        state yc = y0;
        mat<double, 2> phi{};
        mat<double, 2> phic{};
        CHECK(odestep::explicit_rk_transition<odestep::tables::rk4, state, odestep::unchecked>{}.step(
                  sys, y, phi, 0.0, 0.1) == odestep::status::ok);
        CHECK(st.step(sys, yc, phic, 0.0, 0.1) == odestep::status::ok);
        CHECK(same_bits(y, yc));
        CHECK(same_bits(phi, phic));
    }
}

TEST_CASE("splitting transition: a NaN in da/dx is non_finite with x, v and Phi untouched") {
    using state = std::array<double, 1>;
    const double qnan = std::numeric_limits<double>::quiet_NaN();
    auto a = odestep::with_jacobian(pendulum_a{}, [qnan](double, const state&, mat<double, 1>& J) { J = {{{qnan}}}; });
    const state x0{1.0};
    const state v0{0.5};
    state x = x0;
    state v = v0;
    mat<double, 2> phi0{{{3.0, 4.0}, {5.0, 6.0}}};
    mat<double, 2> phi = phi0;
    CHECK(odestep::velocity_verlet_transition<state>{}.step(a, x, v, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(v, v0));
    CHECK(same_bits(phi, phi0));
}

}  // namespace

// ---- a force of position and velocity, a(t, x, v)

TEST_CASE("splitting transition: velocity Verlet with a damped force a = -w^2 x - c v is K D K to round-off") {
    // The splitting evaluates a(t, x, v) at each kick with the velocity before it, so kick by h/2:
    // v <- v + h/2 (-w^2 x - c v), K = [[1, 0], [-h w^2 / 2, 1 - h c / 2]]; drift by h: D = [[1, h], [0, 1]];
    // Phi = K D K (the method written out, HLW Sec. I.5 with the damping in the kicks).
    using state = std::array<double, 1>;
    const double w2 = 4.0;
    const double c = 0.6;
    const double h = 0.3;
    auto a = odestep::with_velocity_jacobian(
        [w2, c](double, const state& x, const state& v) { return state{-w2 * x[0] - c * v[0]}; },
        [w2, c](double, const state&, const state&, mat<double, 1>& ax, mat<double, 1>& av) {
            ax[0][0] = -w2;
            av[0][0] = -c;
        });
    state x{0.7};
    state v{-0.2};
    odestep::phase_matrix_t<state> phi{};
    REQUIRE(odestep::velocity_verlet_transition<state>{}.step(a, x, v, phi, 0.0, h) == odestep::status::ok);
    state px{0.7};
    state pv{-0.2};
    odestep::velocity_verlet<state> plain;
    REQUIRE(plain.step(a, px, pv, 0.0, h) == odestep::status::ok);
    CHECK(same_bits(px, x));
    CHECK(same_bits(pv, v));
    const mat<double, 2> k{{{1.0, 0.0}, {-h * w2 / 2, 1 - h * c / 2}}};
    const mat<double, 2> d{{{1.0, h}, {0.0, 1.0}}};
    const mat<double, 2> expected = product(k, product(d, k));
    CHECK(max_difference(phi, expected) <= 4 * std::numeric_limits<double>::epsilon());
    // Not symplectic: det Phi = (1 - h c / 2)^2, not 1.
    CHECK(std::fabs(phi[0][0] * phi[1][1] - phi[0][1] * phi[1][0] - (1 - h * c / 2) * (1 - h * c / 2)) < 1e-15);
}

namespace {
// A nonlinear force of position and velocity in 2-D, and its Jacobians by hand.
struct dragged {
    template <class T>
    std::array<T, 2> operator()(T, const std::array<T, 2>& x, const std::array<T, 2>& v) const {
        return {-std::sin(x[0]) - T(0.2) * v[0] * v[0] * v[0] + T(0.1) * v[1],
                -x[1] * x[1] * x[1] - T(0.4) * v[1] + T(0.2) * x[0] * v[0]};
    }
};
struct dragged_jacobian {
    template <class T>
    void operator()(T, const std::array<T, 2>& x, const std::array<T, 2>& v, mat<T, 2>& ax, mat<T, 2>& av) const {
        ax = {{{-std::cos(x[0]), T(0)}, {T(0.2) * v[0], T(-3) * x[1] * x[1]}}};
        av = {{{T(-0.6) * v[0] * v[0], T(0.1)}, {T(0.2) * x[0], T(-0.4)}}};
    }
};
// Central differences of one plain splitting step in (x, v).
template <class Method>
mat<double, 4> splitting_difference(const std::array<double, 2>& x, const std::array<double, 2>& v, double h,
                                    double e) {
    mat<double, 4> out{};
    for (std::size_t j = 0; j < 4; ++j) {
        std::array<std::array<double, 2>, 2> p{x, v};
        std::array<std::array<double, 2>, 2> m{x, v};
        p[j / 2][j % 2] += e;
        m[j / 2][j % 2] -= e;
        REQUIRE(odestep::splitting<Method, std::array<double, 2>>{}.step(dragged{}, p[0], p[1], 0.0, h) ==
                odestep::status::ok);
        REQUIRE(odestep::splitting<Method, std::array<double, 2>>{}.step(dragged{}, m[0], m[1], 0.0, h) ==
                odestep::status::ok);
        for (std::size_t i = 0; i < 4; ++i) out[i][j] = (p[i / 2][i % 2] - m[i / 2][i % 2]) / (2 * e);
    }
    return out;
}
template <class Method>
void check_velocity_force(double h) {
    using state = std::array<double, 2>;
    const state x0{0.8, -0.5};
    const state v0{0.3, 0.9};
    state x = x0;
    state v = v0;
    odestep::phase_matrix_t<state> phi{};
    REQUIRE(odestep::splitting_transition<Method, state>{}.step(
                odestep::with_velocity_jacobian(dragged{}, dragged_jacobian{}), x, v, phi, 0.0, h) ==
            odestep::status::ok);
    // The error of the differences falls as e^2 over the sweep (ratios 3 to 5 per halving).
    double e = 1e-2;
    double previous = max_difference(splitting_difference<Method>(x0, v0, h, e), phi);
    for (int halving = 0; halving < 3; ++halving) {
        e /= 2;
        const double error = max_difference(splitting_difference<Method>(x0, v0, h, e), phi);
        INFO("e = " << e << ", error " << error << ", previous " << previous);
        CHECK(previous / error > 3.0);
        CHECK(previous / error < 5.0);
        previous = error;
    }
}
}  // namespace

TEST_CASE("splitting transition: with a(t, x, v) Phi matches central differences to O(eps^2)") {
    SUBCASE("velocity Verlet") { check_velocity_force<odestep::tables::velocity_verlet>(0.2); }
    SUBCASE("Forest-Ruth") { check_velocity_force<odestep::tables::forest_ruth>(0.2); }
}

TEST_CASE("splitting transition: a NaN in da/dv is non_finite with x, v and Phi untouched") {
    using state = std::array<double, 2>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto bad = odestep::with_velocity_jacobian(
        dragged{}, [nan](double, const state&, const state&, mat<double, 2>&, mat<double, 2>& av) { av[1][0] = nan; });
    state x{0.8, -0.5};
    state v{0.3, 0.9};
    mat<double, 4> phi = identity<double, 4>();
    CHECK(odestep::velocity_verlet_transition<state>{}.step(bad, x, v, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, state{0.8, -0.5}));
    CHECK(same_bits(v, state{0.3, 0.9}));
    CHECK(max_difference(phi, identity<double, 4>()) == 0.0);
}
