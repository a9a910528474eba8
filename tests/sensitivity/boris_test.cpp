// SPDX-License-Identifier: BSL-1.0
// The Boris step's derivative (sensitivity/boris.hpp): det Phi = 1 and the velocity block a rotation in uniform
// fields (the closed form of the step); Phi against central differences of the plain step in a non-uniform
// field, O(eps^2) over a sweep of eps; the composition over several steps against the differences of the run;
// NaN in a field Jacobian rolled back. The relativistic pusher's the same way (at |u| = 1.66 c), with its
// non-relativistic limit and |u| kept by the rotation in a magnetic field.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "sensitivity/helpers.hpp"
#include "support/compare.hpp"

namespace {

using namespace sensitivity_test;  // NOLINT: the shared matrices
using odestep_test::same_bits;

template <class T>
using vec = std::array<T, 3>;

// The determinant by Gaussian elimination with partial pivoting (independent of the code under test).
template <class T, std::size_t N>
T determinant(mat<T, N> a) {
    T det = T(1);
    for (std::size_t c = 0; c < N; ++c) {
        std::size_t p = c;
        for (std::size_t r = c + 1; r < N; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
        if (p != c) {
            std::swap(a[p], a[c]);
            det = -det;
        }
        det *= a[c][c];
        for (std::size_t r = c + 1; r < N; ++r) {
            const T m = a[r][c] / a[c][c];
            for (std::size_t k = c; k < N; ++k) a[r][k] -= m * a[c][k];
        }
    }
    return det;
}

// Uniform fields.
struct uniform {
    template <class T>
    void operator()(T, const vec<T>&, vec<T>& E, vec<T>& B) const {
        E = {T(0.3), T(-0.2), T(0.1)};
        B = {T(0.4), T(0.7), T(-1.1)};
    }
};
struct uniform_jacobian {
    template <class T>
    void operator()(T, const vec<T>&, mat<T, 3>&, mat<T, 3>&) const {}  // zero: left as given
};

// Non-uniform fields and their Jacobians by hand.
struct field {
    template <class T>
    void operator()(T, const vec<T>& x, vec<T>& E, vec<T>& B) const {
        E = {T(-0.5) * x[0] + T(0.1) * x[1] * x[2], T(0.3) * std::sin(x[1]), T(0.2) * x[0] * x[0]};
        B = {T(0.1) * x[1], T(0.2) + T(0.05) * x[2] * x[2], T(1) + T(0.3) * x[0]};
    }
};
struct field_jacobian {
    template <class T>
    void operator()(T, const vec<T>& x, mat<T, 3>& ex, mat<T, 3>& bx) const {
        ex = {{{T(-0.5), T(0.1) * x[2], T(0.1) * x[1]},
               {T(0), T(0.3) * std::cos(x[1]), T(0)},
               {T(0.4) * x[0], T(0), T(0)}}};
        bx = {{{T(0), T(0.1), T(0)}, {T(0), T(0), T(0.1) * x[2]}, {T(0.3), T(0), T(0)}}};
    }
};

// Central differences of n plain Boris steps from (x, v): column j = (run(z + e e_j) - run(z - e e_j)) / (2 e).
template <class F, class T>
mat<T, 6> run_difference(F f, T qm, const vec<T>& x, const vec<T>& v, T dt, int n, T e) {
    mat<T, 6> d{};
    const odestep::boris<vec<T>> pusher(qm);
    for (std::size_t j = 0; j < 6; ++j) {
        std::array<vec<T>, 2> px{x, v};
        std::array<vec<T>, 2> mx{x, v};
        px[j / 3][j % 3] += e;
        mx[j / 3][j % 3] -= e;
        for (int k = 0; k < n; ++k) {
            const T t = T(k) * dt;
            REQUIRE(pusher.step(f, px[0], px[1], t, dt) == odestep::status::ok);
            REQUIRE(pusher.step(f, mx[0], mx[1], t, dt) == odestep::status::ok);
        }
        for (std::size_t i = 0; i < 6; ++i) d[i][j] = (px[i / 3][i % 3] - mx[i / 3][i % 3]) / (T(2) * e);
    }
    return d;
}

const vec<double> x0{0.4, -0.3, 0.8};
const vec<double> v0{0.6, 0.2, -0.5};

}  // namespace

static_assert(odestep::boris_transition<vec<double>>::order == 2);
static_assert(odestep::is_field_jacobian_v<field_jacobian, vec<double>>);

TEST_CASE("boris_transition: in uniform fields det Phi = 1 and Phi is [[I, dt R], [0, R]] with R orthogonal") {
    // Uniform fields: v_{n+1/2} = R v_{n-1/2} + c with R the Boris rotation, x_{n+1} = x_n + dt v_{n+1/2}, so Phi
    // is block upper triangular with det Phi = det R = 1 (Qin et al. 2013).
    const double dt = 0.3;
    const odestep::boris_transition<vec<double>> step(-1.7);
    vec<double> x = x0;
    vec<double> v = v0;
    odestep::phase_matrix_t<vec<double>> phi{};
    REQUIRE(step.step(uniform{}, uniform_jacobian{}, x, v, phi, 0.0, dt) == odestep::status::ok);
    CHECK(std::fabs(determinant(phi) - 1.0) < 1e-14);
    mat<double, 3> r{};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            r[i][j] = phi[3 + i][3 + j];
            CHECK(phi[i][j] == (i == j ? 1.0 : 0.0));                          // dx/dx = I
            CHECK(phi[3 + i][j] == 0.0);                                       // dv/dx = 0
            CHECK(std::fabs(phi[i][3 + j] - dt * phi[3 + i][3 + j]) < 1e-15);  // dx/dv = dt R
        }
    CHECK(max_difference(product(transpose(r), r), identity<double, 3>()) < 1e-14);
    // The rotation leaves tau = h B fixed: R tau = tau (the axis; Birdsall & Langdon 4-3).
    const double h = -1.7 * dt / 2;
    const vec<double> tau{h * 0.4, h * 0.7, h * -1.1};
    for (std::size_t i = 0; i < 3; ++i)
        CHECK(std::fabs(r[i][0] * tau[0] + r[i][1] * tau[1] + r[i][2] * tau[2] - tau[i]) < 1e-15);
}

TEST_CASE("boris_transition: in a non-uniform field Phi matches central differences of the step to O(eps^2)") {
    const double dt = 0.2;
    const double qm = 1.3;
    const odestep::boris_transition<vec<double>> step(qm);
    vec<double> x = x0;
    vec<double> v = v0;
    odestep::phase_matrix_t<vec<double>> phi{};
    REQUIRE(step.step(field{}, field_jacobian{}, x, v, phi, 0.0, dt) == odestep::status::ok);
    // The new state is the plain step's, bit for bit.
    vec<double> px = x0;
    vec<double> pv = v0;
    REQUIRE(odestep::boris<vec<double>>(qm).step(field{}, px, pv, 0.0, dt) == odestep::status::ok);
    CHECK(same_bits(px, x));
    CHECK(same_bits(pv, v));
    // Volume preserving in any field: each sub-update has det 1 (see the header).
    CHECK(std::fabs(determinant(phi) - 1.0) < 1e-14);
    // The difference's error is e^2/6 times a third derivative plus round-off: each halving of e divides it
    // by 3 to 5 while truncation dominates (a wrong Phi levels out).
    double e = 1e-2;
    double previous = max_difference(run_difference(field{}, qm, x0, v0, dt, 1, e), phi);
    for (int halving = 0; halving < 3; ++halving) {
        e /= 2;
        const double error = max_difference(run_difference(field{}, qm, x0, v0, dt, 1, e), phi);
        INFO("e = " << e << ", error " << error << ", previous " << previous);
        CHECK(previous / error > 3.0);
        CHECK(previous / error < 5.0);
        previous = error;
    }
}

TEST_CASE("boris_transition: the product of 8 steps' Phi is propagate's and matches the differences of the run") {
    const double dt = 0.15;
    const double qm = 0.9;
    const odestep::boris_transition<vec<double>> step(qm);
    vec<double> x = x0;
    vec<double> v = v0;
    vec<double> y = x0;
    vec<double> w = v0;
    mat<double, 6> product_of_steps = identity<double, 6>();
    odestep::sensitivity_matrix<double, 6, 6> s = identity<double, 6>();
    for (int k = 0; k < 8; ++k) {
        const double t = k * dt;
        mat<double, 6> phi{};
        REQUIRE(step.step(field{}, field_jacobian{}, x, v, phi, t, dt) == odestep::status::ok);
        product_of_steps = product(phi, product_of_steps);
        REQUIRE(step.propagate(field{}, field_jacobian{}, y, w, s, t, dt) == odestep::status::ok);
    }
    CHECK(same_bits(x, y));
    CHECK(max_difference(product_of_steps, s) < 1e-13);
    CHECK(std::fabs(determinant(s) - 1.0) < 1e-13);
    // Central differences of the 8-step run, e = 1e-5: error e^2 |third derivative| / 6 plus round-off, 1e-9.
    CHECK(max_difference(run_difference(field{}, qm, x0, v0, dt, 8, 1e-5), s) < 1e-8);
    // A 2-column sensitivity: the first two columns of Phi.
    odestep::sensitivity_matrix<double, 6, 2> s2{};
    s2[0][0] = 1.0;
    s2[4][1] = 1.0;
    vec<double> a = x0;
    vec<double> b = v0;
    REQUIRE(step.propagate(field{}, field_jacobian{}, a, b, s2, 0.0, dt) == odestep::status::ok);
    mat<double, 6> phi1{};
    vec<double> c = x0;
    vec<double> d = v0;
    REQUIRE(step.step(field{}, field_jacobian{}, c, d, phi1, 0.0, dt) == odestep::status::ok);
    for (std::size_t i = 0; i < 6; ++i) {
        CHECK(s2[i][0] == phi1[i][0]);
        CHECK(s2[i][1] == phi1[i][4]);
    }
}

TEST_CASE("boris_transition: float stays float and agrees with the double Phi") {
    const odestep::boris_transition<vec<float>> step(1.3f);
    vec<float> x{0.4f, -0.3f, 0.8f};
    vec<float> v{0.6f, 0.2f, -0.5f};
    odestep::phase_matrix_t<vec<float>> phi{};
    REQUIRE(step.step(field{}, field_jacobian{}, x, v, phi, 0.0f, 0.2f) == odestep::status::ok);
    const odestep::boris_transition<vec<double>> step_d(1.3);
    vec<double> xd = x0;
    vec<double> vd = v0;
    mat<double, 6> phid{};
    REQUIRE(step_d.step(field{}, field_jacobian{}, xd, vd, phid, 0.0, 0.2) == odestep::status::ok);
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) CHECK(std::fabs(double(phi[i][j]) - phid[i][j]) < 1e-5);
}

TEST_CASE("boris_transition: NaN in a field Jacobian is non_finite with x, v and Phi untouched") {
    const odestep::boris_transition<vec<double>> step;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto bad_jacobian = [nan](double, const vec<double>&, mat<double, 3>&, mat<double, 3>& bx) { bx[1][2] = nan; };
    vec<double> x = x0;
    vec<double> v = v0;
    mat<double, 6> phi = identity<double, 6>();
    phi[2][5] = 7.0;
    const mat<double, 6> before = phi;
    CHECK(step.step(field{}, bad_jacobian, x, v, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(v, v0));
    CHECK(max_difference(phi, before) == 0.0);
    // A NaN field: the plain step's own failure, the same status.
    auto bad_field = [nan](double, const vec<double>&, vec<double>& E, vec<double>&) { E[0] = nan; };
    CHECK(step.step(bad_field, field_jacobian{}, x, v, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(v, v0));
    CHECK(max_difference(phi, before) == 0.0);
}

// ---- the relativistic pusher (boris_relativistic_transition)

namespace {

// Central differences of n plain relativistic Boris steps from (x, u), as run_difference.
template <class F, class T>
mat<T, 6> relativistic_run_difference(F f, T qm, T c, const vec<T>& x, const vec<T>& u, T dt, int n, T e) {
    mat<T, 6> d{};
    const odestep::boris_relativistic<vec<T>> pusher(qm, c);
    for (std::size_t j = 0; j < 6; ++j) {
        std::array<vec<T>, 2> px{x, u};
        std::array<vec<T>, 2> mx{x, u};
        px[j / 3][j % 3] += e;
        mx[j / 3][j % 3] -= e;
        for (int k = 0; k < n; ++k) {
            const T t = T(k) * dt;
            REQUIRE(pusher.step(f, px[0], px[1], t, dt) == odestep::status::ok);
            REQUIRE(pusher.step(f, mx[0], mx[1], t, dt) == odestep::status::ok);
        }
        for (std::size_t i = 0; i < 6; ++i) d[i][j] = (px[i / 3][i % 3] - mx[i / 3][i % 3]) / (T(2) * e);
    }
    return d;
}

// u = gamma v at relativistic speed: |u| = 1.66 c with c = 1, gamma = 1.94, so both Lorentz factors and their
// derivatives are far from the non-relativistic limit.
const vec<double> u0{1.2, 0.8, -0.9};

}  // namespace

static_assert(odestep::boris_relativistic_transition<vec<double>>::order == 2);

TEST_CASE("boris_relativistic_transition: Phi matches central differences of the step to O(eps^2), det Phi = 1") {
    const double dt = 0.2;
    const double qm = 1.3;
    const double c = 1.0;
    const odestep::boris_relativistic_transition<vec<double>> step(qm, c);
    vec<double> x = x0;
    vec<double> u = u0;
    odestep::phase_matrix_t<vec<double>> phi{};
    REQUIRE(step.step(field{}, field_jacobian{}, x, u, phi, 0.0, dt) == odestep::status::ok);
    // The new state is the plain step's, bit for bit.
    vec<double> px = x0;
    vec<double> pu = u0;
    REQUIRE(odestep::boris_relativistic<vec<double>>(qm, c).step(field{}, px, pu, 0.0, dt) == odestep::status::ok);
    CHECK(same_bits(px, x));
    CHECK(same_bits(pu, u));
    // Volume preserving for fields of x (derived in the header: a shift, a rotation about B by an angle of
    // |u-| alone, a shift, then a shear; Higuera & Cary 2017).
    CHECK(std::fabs(determinant(phi) - 1.0) < 1e-14);
    // The differences' error is e^2/6 times a third derivative plus round-off: each halving divides it by 3 to
    // 5 while truncation dominates (a Phi without the Lorentz factors' derivatives levels out).
    double e = 1e-2;
    double previous = max_difference(relativistic_run_difference(field{}, qm, c, x0, u0, dt, 1, e), phi);
    for (int halving = 0; halving < 3; ++halving) {
        e /= 2;
        const double error = max_difference(relativistic_run_difference(field{}, qm, c, x0, u0, dt, 1, e), phi);
        INFO("e = " << e << ", error " << error << ", previous " << previous);
        CHECK(previous / error > 3.0);
        CHECK(previous / error < 5.0);
        previous = error;
    }
}

TEST_CASE("boris_relativistic_transition: in uniform fields the momentum block keeps |u| and dx/dx = I") {
    // Uniform fields, E = 0: u_{n+1/2} is the rotation of u about B by an angle of |u| alone, so |u| is kept:
    // d|u_{n+1/2}|^2 / du = 2 u_{n+1/2}^T (du_{n+1/2} / du) equals 2 u^T. x enters nothing but the drift.
    struct magnetic {
        void operator()(double, const vec<double>&, vec<double>&, vec<double>& B) const { B = {0.4, 0.7, -1.1}; }
    };
    const double dt = 0.3;
    const odestep::boris_relativistic_transition<vec<double>> step(-1.7, 1.0);
    vec<double> x = x0;
    vec<double> u = u0;
    odestep::phase_matrix_t<vec<double>> phi{};
    REQUIRE(step.step(magnetic{}, uniform_jacobian{}, x, u, phi, 0.0, dt) == odestep::status::ok);
    CHECK(std::fabs(determinant(phi) - 1.0) < 1e-14);
    for (std::size_t j = 0; j < 3; ++j) {
        double grad = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(phi[i][j] == (i == j ? 1.0 : 0.0));  // dx/dx = I
            CHECK(phi[3 + i][j] == 0.0);               // du/dx = 0
            grad += 2.0 * u[i] * phi[3 + i][3 + j];
        }
        CHECK(std::fabs(grad - 2.0 * u0[j]) < 1e-14);
    }
}

TEST_CASE("boris_relativistic_transition: as c grows Phi becomes the non-relativistic boris_transition's") {
    // gamma = sqrt(1 + |u|^2 / c^2) = 1 to the rounding of double for c = 1e100: the relativistic step and its
    // derivative are then the non-relativistic ones (boris_transition, checked above against its closed form).
    const double dt = 0.2;
    const double qm = 1.3;
    vec<double> x = x0;
    vec<double> u = v0;
    odestep::phase_matrix_t<vec<double>> phi{};
    REQUIRE(odestep::boris_relativistic_transition<vec<double>>(qm, 1e100).step(field{}, field_jacobian{}, x, u, phi,
                                                                                0.0, dt) == odestep::status::ok);
    vec<double> y = x0;
    vec<double> v = v0;
    odestep::phase_matrix_t<vec<double>> phi_newton{};
    REQUIRE(odestep::boris_transition<vec<double>>(qm).step(field{}, field_jacobian{}, y, v, phi_newton, 0.0, dt) ==
            odestep::status::ok);
    CHECK(same_bits(x, y));
    CHECK(same_bits(u, v));
    CHECK(max_difference(phi, phi_newton) < 1e-15);
}

TEST_CASE("boris_relativistic_transition: the product of 8 steps' Phi is propagate's and the run's differences") {
    const double dt = 0.15;
    const double qm = 0.9;
    const double c = 1.5;
    const odestep::boris_relativistic_transition<vec<double>> step(qm, c);
    vec<double> x = x0;
    vec<double> u = u0;
    vec<double> y = x0;
    vec<double> w = u0;
    mat<double, 6> product_of_steps = identity<double, 6>();
    odestep::sensitivity_matrix<double, 6, 6> s = identity<double, 6>();
    for (int k = 0; k < 8; ++k) {
        const double t = k * dt;
        mat<double, 6> phi{};
        REQUIRE(step.step(field{}, field_jacobian{}, x, u, phi, t, dt) == odestep::status::ok);
        product_of_steps = product(phi, product_of_steps);
        REQUIRE(step.propagate(field{}, field_jacobian{}, y, w, s, t, dt) == odestep::status::ok);
    }
    CHECK(same_bits(x, y));
    CHECK(same_bits(u, w));
    CHECK(max_difference(product_of_steps, s) < 1e-13);
    CHECK(std::fabs(determinant(s) - 1.0) < 1e-13);
    // Central differences of the 8-step run, e = 1e-5: error e^2 |third derivative| / 6 plus round-off.
    CHECK(max_difference(relativistic_run_difference(field{}, qm, c, x0, u0, dt, 8, 1e-5), s) < 1e-8);
}

TEST_CASE("boris_relativistic_transition: float stays float and agrees with the double Phi") {
    const odestep::boris_relativistic_transition<vec<float>> step(1.3f, 1.0f);
    vec<float> x{0.4f, -0.3f, 0.8f};
    vec<float> u{1.2f, 0.8f, -0.9f};
    odestep::phase_matrix_t<vec<float>> phi{};
    REQUIRE(step.step(field{}, field_jacobian{}, x, u, phi, 0.0f, 0.2f) == odestep::status::ok);
    const odestep::boris_relativistic_transition<vec<double>> step_d(1.3, 1.0);
    vec<double> xd{double(0.4f), double(-0.3f), double(0.8f)};
    vec<double> ud{double(1.2f), double(0.8f), double(-0.9f)};
    mat<double, 6> phid{};
    REQUIRE(step_d.step(field{}, field_jacobian{}, xd, ud, phid, 0.0, double(0.2f)) == odestep::status::ok);
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) CHECK(std::fabs(double(phi[i][j]) - phid[i][j]) < 1e-5);
}

TEST_CASE("boris_relativistic_transition: NaN in a field Jacobian is non_finite with x, u and Phi untouched") {
    const odestep::boris_relativistic_transition<vec<double>> step(1.0, 2.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto bad_jacobian = [nan](double, const vec<double>&, mat<double, 3>& ex, mat<double, 3>&) { ex[2][0] = nan; };
    vec<double> x = x0;
    vec<double> u = u0;
    mat<double, 6> phi = identity<double, 6>();
    phi[2][5] = 7.0;
    const mat<double, 6> before = phi;
    CHECK(step.step(field{}, bad_jacobian, x, u, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(u, u0));
    CHECK(max_difference(phi, before) == 0.0);
    // A momentum whose |u|^2 overflows: the plain step's own failure, the same status.
    vec<double> huge{1e200, 0.0, 0.0};
    const vec<double> huge0 = huge;
    CHECK(step.step(field{}, field_jacobian{}, x, huge, phi, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(huge, huge0));
    CHECK(max_difference(phi, before) == 0.0);
}
