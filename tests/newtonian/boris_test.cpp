// SPDX-License-Identifier: BSL-1.0
// The Boris pushers: exact norm conservation of the rotation, the gyro-phase and gyroradius in closed form,
// the E x B drift, order 2, the half-step convention for v, volume preservation and time reversibility,
// the relativistic variant, float, and NaN rollback.
#include <doctest/doctest.h>
#include <odestep/newtonian/boris.hpp>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <utility>

#include "support/compare.hpp"
#include "support/order_fit.hpp"

namespace {

template <class T>
using vec3 = std::array<T, 3>;
using v3 = vec3<double>;

using odestep_test::fitted_order;
using odestep_test::max_abs_difference;
using odestep_test::same_bits;

template <class T>
T norm(const vec3<T>& a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// E = e y-hat, B = b z-hat: with e = 0 a pure magnetic field, with e != 0 the crossed fields.
template <class T>
struct crossed {
    T e;
    T b;
    void operator()(T, const vec3<T>&, vec3<T>& E, vec3<T>& B) const noexcept {
        E = {T(0), e, T(0)};
        B = {T(0), T(0), b};
    }
};

// A uniform E and no B (writes only E: B is zeroed by the stepper).
struct constant_e {
    v3 e;
    void operator()(double, const v3&, v3& E, v3&) const noexcept { E = e; }
};

// Smooth, non-uniform and time-dependent fields, all six components non-trivial.
struct nonuniform {
    template <class T>
    void operator()(T t, const vec3<T>& x, vec3<T>& E, vec3<T>& B) const noexcept {
        E = {T(-0.2) * x[0], T(0.1) * std::sin(x[1]), T(0.05) * std::cos(t)};
        B = {T(0.1) * x[1], T(0.2) + T(0.05) * x[2], T(1) + T(0.3) * x[0] * x[0]};
    }
};

// The exact motion in E = e y-hat, B = b z-hat with charge-to-mass ratio qm (F. F. Chen, Introduction to
// Plasma Physics and Controlled Fusion, section 2.2; any plasma text): the drift is w = e / b along x, and
// in the drifting frame v' = v - w x-hat turns at omega = qm b, clockwise for qm b > 0:
// v'_x + i v'_y = zeta0 exp(-i omega t), so x + i y = x0 + i y0 + w t + i zeta0 (exp(-i omega t) - 1) / omega,
// and z = z0 + v_z t.
struct exact_crossed {
    double qm, e, b;
    v3 x0, v0;
    void at(double t, v3& x, v3& v) const {
        const double w = e / b;
        const double omega = qm * b;
        const std::complex<double> zeta0(v0[0] - w, v0[1]);
        const std::complex<double> turn = std::exp(std::complex<double>(0.0, -omega * t));
        const std::complex<double> orbit = std::complex<double>(0.0, 1.0) * zeta0 * (turn - 1.0) / omega;
        const std::complex<double> vel = zeta0 * turn;
        x = {x0[0] + w * t + orbit.real(), x0[1] + orbit.imag(), x0[2] + v0[2] * t};
        v = {w + vel.real(), vel.imag(), v0[2]};
    }
};

// The angle from a to b about z (in the x-y plane), in (-pi, pi].
double turn_angle(const v3& a, const v3& b) { return std::atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]); }

// Runs the crossed-field problem with the Boris pusher in T: stagger, n steps, synchronize; the largest
// error in x and in v at t_end against the closed form.
template <class T>
void boris_crossed_errors(const exact_crossed& ex, double t_end, std::size_t n, double& ex_err, double& ev_err) {
    const odestep::boris<vec3<T>> pusher(static_cast<T>(ex.qm));
    const crossed<T> fields{static_cast<T>(ex.e), static_cast<T>(ex.b)};
    const T dt = static_cast<T>(t_end / static_cast<double>(n));
    vec3<T> x{static_cast<T>(ex.x0[0]), static_cast<T>(ex.x0[1]), static_cast<T>(ex.x0[2])};
    vec3<T> v{static_cast<T>(ex.v0[0]), static_cast<T>(ex.v0[1]), static_cast<T>(ex.v0[2])};
    REQUIRE(pusher.stagger(fields, x, v, T(0), dt) == odestep::status::ok);
    const auto r = odestep::integrate_n_steps(pusher, fields, x, v, T(0), dt, n);
    REQUIRE(r.status == odestep::status::ok);
    REQUIRE(pusher.synchronize(fields, x, v, r.t, dt) == odestep::status::ok);
    v3 xe, ve;
    ex.at(static_cast<double>(r.t), xe, ve);
    const v3 xd{static_cast<double>(x[0]), static_cast<double>(x[1]), static_cast<double>(x[2])};
    const v3 vd{static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
    ex_err = max_abs_difference(xd, xe);
    ev_err = max_abs_difference(vd, ve);
}

// The 6x6 Jacobian determinant of a map z -> F(z) of (x, v) by central differences, in long double, by
// Gaussian elimination with partial pivoting.
template <class Map>
long double jacobian_determinant(Map&& map, const std::array<long double, 6>& z, long double delta) {
    std::array<std::array<long double, 6>, 6> J{};
    for (std::size_t j = 0; j < 6; ++j) {
        std::array<long double, 6> zp = z, zm = z;
        zp[j] += delta;
        zm[j] -= delta;
        const std::array<long double, 6> fp = map(zp), fm = map(zm);
        for (std::size_t i = 0; i < 6; ++i) J[i][j] = (fp[i] - fm[i]) / (2 * delta);
    }
    long double det = 1;
    for (std::size_t c = 0; c < 6; ++c) {
        std::size_t p = c;
        for (std::size_t r = c + 1; r < 6; ++r)
            if (std::fabs(J[r][c]) > std::fabs(J[p][c])) p = r;
        if (p != c) {
            std::swap(J[p], J[c]);
            det = -det;
        }
        det *= J[c][c];
        for (std::size_t r = c + 1; r < 6; ++r) {
            const long double f = J[r][c] / J[c][c];
            for (std::size_t k = c; k < 6; ++k) J[r][k] -= f * J[c][k];
        }
    }
    return det;
}

constexpr double qnan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// Traits

static_assert(odestep::boris<v3>::order == 2);
static_assert(odestep::boris<v3>::rhs_evals_per_step == 1 && odestep::boris<v3>::rhs_evals_per_step == 1);
static_assert(!odestep::boris<v3>::symplectic && odestep::boris<v3>::volume_preserving);
static_assert(odestep::boris<v3>::time_reversible && !odestep::boris<v3>::self_starting);
static_assert(odestep::boris_relativistic<vec3<float>>::order == 2);
static_assert(odestep::boris_relativistic<vec3<float>>::rhs_evals_per_step == 1);
static_assert(odestep::boris_relativistic<vec3<float>>::rhs_evals_per_step == 1);
static_assert(!odestep::boris_relativistic<vec3<float>>::symplectic);
static_assert(odestep::boris_relativistic<vec3<float>>::volume_preserving);
static_assert(odestep::boris_relativistic<vec3<float>>::time_reversible);
static_assert(!odestep::boris_relativistic<vec3<float>>::self_starting);
static_assert(std::is_same_v<odestep::boris<vec3<float>>::value_type, float>);
static_assert(odestep::is_em_fields_v<crossed<double>, v3>);
static_assert(!odestep::is_em_fields_v<constant_e, vec3<float>>);

TEST_CASE("boris: a step makes exactly one field evaluation, and stagger and synchronize one each") {
    std::size_t calls = 0;
    auto counting = [&calls](double, const v3&, v3&, v3& B) {
        ++calls;
        B = {0.0, 0.0, 1.0};
    };
    const odestep::boris<v3> pusher;
    CHECK(pusher.charge_to_mass() == 1.0);
    v3 x{0, 0, 0}, v{1, 0, 0};
    REQUIRE(pusher.stagger(counting, x, v, 0.0, 0.1) == odestep::status::ok);
    CHECK(calls == 1);
    REQUIRE(odestep::integrate_n_steps(pusher, counting, x, v, 0.0, 0.1, 10).status == odestep::status::ok);
    CHECK(calls == 11);
    REQUIRE(pusher.synchronize(counting, x, v, 1.0, 0.1) == odestep::status::ok);
    CHECK(calls == 12);
}

// ---------------------------------------------------------------------------------------------------------
// The pure magnetic field

TEST_CASE("boris: in a pure magnetic field |v| is conserved to round-off over 10^5 steps, in double and float") {
    // The rotation is exact in norm: only rounding changes |v|, by about an ULP per step in no preferred
    // direction, so after N steps by about sqrt(N) ULPs; the bound allows 2 sqrt(N) eps.
    const std::size_t n = 100000;
    {
        const odestep::boris<v3> pusher;
        const crossed<double> fields{0.0, 1.0};
        v3 x{0, 0, 0}, v{1.0, 0.0, 0.3};
        REQUIRE(pusher.stagger(fields, x, v, 0.0, 0.1) == odestep::status::ok);
        const double n0 = norm(v);
        double worst = 0;
        const auto r = odestep::integrate_n_steps(
            pusher, fields, x, v, 0.0, 0.1, n,
            [&](double, const v3&, const v3& vh) { worst = std::fmax(worst, std::fabs(norm(vh) / n0 - 1)); });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(worst <= 2 * std::sqrt(static_cast<double>(n)) * std::numeric_limits<double>::epsilon());
        MESSAGE("double: largest relative change of |v| over 1e5 steps ", worst);
    }
    {
        using f3 = vec3<float>;
        const odestep::boris<f3> pusher;
        const crossed<float> fields{0.0f, 1.0f};
        f3 x{0, 0, 0}, v{1.0f, 0.0f, 0.3f};
        REQUIRE(pusher.stagger(fields, x, v, 0.0f, 0.1f) == odestep::status::ok);
        const float n0 = norm(v);
        float worst = 0;
        const auto r = odestep::integrate_n_steps(
            pusher, fields, x, v, 0.0f, 0.1f, n,
            [&](float, const f3&, const f3& vh) { worst = std::fmax(worst, std::fabs(norm(vh) / n0 - 1.0f)); });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(worst <= 2.0f * std::sqrt(static_cast<float>(n)) * std::numeric_limits<float>::epsilon());
        MESSAGE("float: largest relative change of |v| over 1e5 steps ", static_cast<double>(worst));
    }
}

TEST_CASE("boris: the gyro-phase advances by exactly 2 atan(omega_c dt / 2) per step, clockwise for q B > 0") {
    // The rotation is the Cayley transform (I - K)^-1 (I + K) of the skew matrix K of tau = (q/m) B dt/2
    // (K v = v x tau): a rotation by the angle a with tan(a/2) = |tau|, so 2 atan(omega_c dt / 2), short of
    // omega_c dt by (omega_c dt)^3 / 12 + O(dt^5) per step (the series of atan).
    for (double qm : {2.0, -2.0}) {
        INFO("q/m = ", qm);
        const double b = 0.75, dt = 0.1, omega = qm * b;  // omega_c = |q/m| B = 1.5
        const odestep::boris<v3> pusher(qm);
        const crossed<double> fields{0.0, b};
        v3 x{0, 0, 0}, v{0.6, -0.8, 0.25};
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        const v3 v_start = v;
        const std::size_t n = 1000;
        const double per_step = -2 * std::atan(omega * dt / 2);  // clockwise (negative) for q/m B > 0
        // Each step's angle minus the closed form, summed: small terms, so the sum adds no rounding of its own.
        double deviation = 0, worst = 0;
        v3 before = v;
        const auto r =
            odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, n, [&](double t, const v3&, const v3& vh) {
                if (t == 0.0) return;  // the observer's first call is the initial state
                const double d = turn_angle(before, vh) - per_step;
                deviation += d;
                worst = std::fmax(worst, std::fabs(d));
                before = vh;
            });
        REQUIRE(r.status == odestep::status::ok);
        // every step within a few ULPs of the angle (0.15: ULP 2.8e-17), and no drift: 1000 steps, 1e-13
        CHECK(worst <= 1e-15);
        CHECK(std::fabs(deviation) <= 1e-13);
        const double phase = static_cast<double>(n) * per_step + deviation;
        CHECK(std::fabs(turn_angle(v_start, v) -
                        std::remainder(static_cast<double>(n) * per_step, 2 * std::acos(-1.0))) <= 1e-12);
        // v_z, along B, is untouched; and the phase lags omega_c t by n (omega_c dt)^3 / 12 to O(dt^5)
        CHECK(v[2] == v_start[2]);
        const double lag = std::fabs(phase) - std::fabs(omega) * static_cast<double>(n) * dt;
        CHECK(lag == doctest::Approx(-static_cast<double>(n) * std::pow(std::fabs(omega) * dt, 3) / 12).epsilon(0.01));
    }
}

TEST_CASE(
    "boris: the orbit in a uniform B is a circle of radius |v_perp| (1 + (omega_c dt/2)^2) / omega_c, second order in "
    "dt") {
    // With v_{n+1/2} turning by theta = 2 atan(omega_c dt/2) at constant speed |v_{1/2}| = |v_perp| sqrt(1 +
    // (omega_c dt/2)^2) (staggered from v_0), the points x_n are the vertices of chords of length dt |v_{1/2}|
    // subtending theta: radius dt |v_{1/2}| / (2 sin(theta/2)) = |v_perp| (1 + (omega_c dt/2)^2) / omega_c.
    // The exact gyroradius is |v_perp| / omega_c (omega_c = |q/m| B).
    const double b = 2.0, omega = b;  // q/m = 1
    const v3 v0{0.3, 0.4, 0.1};
    const double exact_radius = 0.5 / omega;  // |v_perp| = 0.5
    std::array<double, 2> rel_error{};
    for (std::size_t k = 0; k < 2; ++k) {
        const double dt = 0.1 / static_cast<double>(1 + k);  // 0.1, then 0.05
        const odestep::boris<v3> pusher;
        const crossed<double> fields{0.0, b};
        v3 x{1.0, -2.0, 0.5}, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        std::array<v3, 2000> xs{};
        xs[0] = x;
        const auto r = odestep::integrate_n_steps(
            pusher, fields, x, v, 0.0, dt, xs.size() - 1,
            [&, i = std::size_t{0}](double, const v3& xn, const v3&) mutable { xs[i++] = xn; });
        REQUIRE(r.status == odestep::status::ok);
        // The circle through the first three points (circumcentre in the x-y plane) ...
        const double ax = xs[0][0], ay = xs[0][1], bx = xs[1][0], by = xs[1][1], cx = xs[2][0], cy = xs[2][1];
        const double d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
        const double ux =
            ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d;
        const double uy =
            ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d;
        // ... holds every later point, at the closed-form radius
        const double radius = 0.5 * (1 + (omega * dt / 2) * (omega * dt / 2)) / omega;
        double worst = 0;
        for (const v3& p : xs) worst = std::fmax(worst, std::fabs(std::hypot(p[0] - ux, p[1] - uy) - radius));
        CHECK(worst <= 1e-12);
        rel_error[k] = radius / exact_radius - 1;
        // and it is centred (closed form, as the radius) at x_0 + (1 + (omega_c dt/2)^2) (v_0 x z-hat) / omega_c,
        // the exact guiding centre x_0 + (v_0 x z-hat) / omega_c = x_0 + (0.2, -0.15) moved out by the same factor
        CHECK(std::fabs(ux - (1.0 + 0.2 * (1 + (omega * dt / 2) * (omega * dt / 2)))) <= 1e-12);
        CHECK(std::fabs(uy - (-2.0 - 0.15 * (1 + (omega * dt / 2) * (omega * dt / 2)))) <= 1e-12);
    }
    // second order: the radius error (omega_c dt / 2)^2 quarters when dt halves
    CHECK(rel_error[0] == doctest::Approx(0.01));
    CHECK(rel_error[0] / rel_error[1] == doctest::Approx(4.0).epsilon(1e-9));
}

// ---------------------------------------------------------------------------------------------------------
// Crossed fields

TEST_CASE("boris: in crossed fields the guiding centre drifts at E x B / B^2 = (E/B) x-hat") {
    // E = 0.5 y-hat, B = 1 z-hat, q = m = 1: the drift is 0.5 along x. In the frame moving at E/B the
    // electric force cancels (E + w x B = 0), and the Boris step sees exactly that: v - w x-hat turns by
    // theta = 2 atan(omega_c dt/2) per step on a circle of radius R_B = |v'_perp| (1 + (omega_c dt/2)^2) /
    // omega_c, so the average velocity over a time T is E/B up to the orbit's diameter over T, 2 R_B / T.
    const double e = 0.5, b = 1.0, w = e / b;
    const crossed<double> fields{e, b};
    const odestep::boris<v3> pusher;
    SUBCASE("over a whole number of Boris gyro-periods the displacement is (E/B) t to round-off") {
        // dt = 2 tan(pi / 40) / omega_c makes theta = 2 pi / 40: the orbit closes every 40 steps.
        const double dt = 2 * std::tan(std::acos(-1.0) / 40) / b;
        v3 x{0, 0, 0}, v{0, 0, 0.2};  // from rest across the fields: a cycloid
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        const std::size_t n = 40 * 250;
        const auto r = odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, n);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(std::fabs(x[0] / r.t - w) <= 1e-12);
        CHECK(std::fabs(x[1]) <= 1e-10);
        CHECK(std::fabs(x[2] - 0.2 * r.t) <= 1e-10);
        REQUIRE(pusher.synchronize(fields, x, v, r.t, dt) == odestep::status::ok);
        CHECK(max_abs_difference(v, v3{0, 0, 0.2}) <= 1e-12);  // back at rest (across B) after whole periods
    }
    SUBCASE(
        "with any dt, the average velocity over many gyro-periods is E/B within the orbit's diameter over the time") {
        const double dt = 0.1;
        const v3 v0{-1.0, 0.7, 0.0};
        v3 x{0, 0, 0}, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        const std::size_t n = 10000;  // t = 1000, about 159 gyro-periods
        double y_min = 0, y_max = 0;
        const auto r =
            odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, n, [&](double, const v3& xn, const v3&) {
                y_min = std::fmin(y_min, xn[1]);
                y_max = std::fmax(y_max, xn[1]);
            });
        REQUIRE(r.status == odestep::status::ok);
        const double v_perp = std::hypot(v0[0] - w, v0[1]);
        const double radius = v_perp * (1 + (b * dt / 2) * (b * dt / 2)) / b;
        const double average = x[0] / r.t;
        CHECK(std::fabs(average - w) <= 2 * radius / r.t);
        CHECK(std::fabs(x[1] - 0.0) <= 2 * radius);
        // the orbit across the drift spans its diameter, within the sampling of the circle
        CHECK((y_max - y_min) / 2 == doctest::Approx(radius).epsilon(1e-4));
        MESSAGE("average velocity ", average, " against E/B = ", w, " (allowed ", 2 * radius / r.t, ")");
    }
}

TEST_CASE("boris: observed order 2 on the exact crossed-field motion (step halving, x and v)") {
    // The trochoid of exact_crossed, with q/m = -1.5 (so omega_c = 1.5, counter-clockwise), to t = 10.
    const exact_crossed ex{-1.5, 0.4, 1.0, v3{0.1, -0.2, 0.3}, v3{0.8, -0.3, 0.5}};
    std::array<double, 5> ex_errors{}, ev_errors{};
    for (std::size_t k = 0; k < ex_errors.size(); ++k) {
        boris_crossed_errors<double>(ex, 10.0, std::size_t{50} << k, ex_errors[k], ev_errors[k]);
    }
    const double px = fitted_order(ex_errors), pv = fitted_order(ev_errors);
    MESSAGE("observed order: x ", px, ", v ", pv, "; x error at dt = 0.2: ", ex_errors[0]);
    CHECK(std::fabs(px - 2.0) <= 0.2);
    CHECK(std::fabs(pv - 2.0) <= 0.2);
}

// ---------------------------------------------------------------------------------------------------------
// Which time v belongs to

TEST_CASE(
    "boris: v lags x by half a step; in a uniform E the staggered leapfrog is exact, and the observer sees v(t - "
    "dt/2)") {
    // B = 0 and E uniform: x'' = a = (q/m) E. The leapfrog's velocity kick a dt then drift v_{n+1/2} dt is
    // exact for a constant force, provided v starts at t0 - dt/2. All numbers below are dyadic, so every
    // operation is exact and the comparisons are ==.
    const double qm = 2.0, dt = 0.125;
    const constant_e fields{v3{0.5, -0.25, 1.0}};
    const v3 a{1.0, -0.5, 2.0};  // (q/m) E
    const v3 x0{0.0, 1.0, 2.0}, v0{1.0, 0.5, -1.0};
    const odestep::boris<v3> pusher(qm);
    auto exact_x = [&](double t, std::size_t i) { return x0[i] + v0[i] * t + a[i] * t * t / 2; };
    auto exact_v = [&](double t, std::size_t i) { return v0[i] + a[i] * t; };

    SUBCASE("staggered: x(t_n) exact, v = v(t_n - dt/2) exact, and synchronize gives v(t_n)") {
        v3 x = x0, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        for (std::size_t i = 0; i < 3; ++i) CHECK(v[i] == exact_v(-dt / 2, i));
        std::size_t seen = 0, wrong = 0;
        const auto r =
            odestep::integrate(pusher, fields, x, v, 0.0, 8.0, dt, [&](double t, const v3& xn, const v3& vh) {
                for (std::size_t i = 0; i < 3; ++i)
                    if (xn[i] != exact_x(t, i) || vh[i] != exact_v(t - dt / 2, i)) ++wrong;
                ++seen;
            });
        REQUIRE(r.status == odestep::status::ok);
        CHECK(seen == 65);
        CHECK(wrong == 0);
        REQUIRE(pusher.synchronize(fields, x, v, r.t, dt) == odestep::status::ok);
        for (std::size_t i = 0; i < 3; ++i) CHECK(v[i] == exact_v(8.0, i));
    }
    SUBCASE("not staggered: v(t0) read as v(t0 - dt/2) shifts x by exactly a t dt / 2, a first-order error") {
        v3 x = x0, v = v0;
        const auto r = odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, 64);
        REQUIRE(r.status == odestep::status::ok);
        for (std::size_t i = 0; i < 3; ++i) CHECK(x[i] == exact_x(8.0, i) + a[i] * 8.0 * dt / 2);
    }
    SUBCASE("a shortened last step keeps v dt/2 behind and costs x exactly -a h (dt - h) / 2, at most |a| dt^2 / 8") {
        // t1 = 1.0625 = 8.5 dt: eight steps of dt and a last one of h = dt/2. With v = v(t_n - dt/2), the last
        // step gives v(t_n - dt/2) + a h = v(t1 - dt/2) and x_n + h (v(t_n) + a (h - dt/2)), against the exact
        // x_n + h v(t_n) + a h^2 / 2.
        v3 x = x0, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        const auto r = odestep::integrate(pusher, fields, x, v, 0.0, 1.0625, dt);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.steps == 9);
        const double h = dt / 2;
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(x[i] == exact_x(1.0625, i) - a[i] * h * (dt - h) / 2);
            CHECK(v[i] == exact_v(1.0625 - dt / 2, i));
        }
    }
}

TEST_CASE("boris: stagger and synchronize are each other's inverse, for both pushers, in any field") {
    const nonuniform fields;
    const v3 x{0.3, -0.7, 0.2}, v0{0.9, -0.4, 0.6};
    for (double dt : {0.1, -0.25}) {
        INFO("dt = ", dt);
        {
            const odestep::boris<v3> pusher(-1.7);
            v3 v = v0;
            REQUIRE(pusher.stagger(fields, x, v, 0.4, dt) == odestep::status::ok);
            CHECK(max_abs_difference(v, v0) > 1e-3);
            REQUIRE(pusher.synchronize(fields, x, v, 0.4, dt) == odestep::status::ok);
            CHECK(max_abs_difference(v, v0) <= 1e-15);
        }
        {
            const odestep::boris_relativistic<v3> pusher(-1.7, 1.5);
            v3 u = v0;
            REQUIRE(pusher.stagger(fields, x, u, 0.4, dt) == odestep::status::ok);
            CHECK(max_abs_difference(u, v0) > 1e-3);
            REQUIRE(pusher.synchronize(fields, x, u, 0.4, dt) == odestep::status::ok);
            CHECK(max_abs_difference(u, v0) <= 1e-15);
        }
    }
}

TEST_CASE(
    "boris: time reversible: stagger, N steps and synchronize forward, then the same with -dt, return to the start") {
    // The map on synchronized (x_n, v_n) is a half kick, a drift and the inverse half kick: symmetric, so
    // the run with -dt from (x_N, v_N) retraces it. Round-off only: 1000 steps, each about 1e-16.
    const nonuniform fields;
    const v3 x0{0.3, -0.7, 0.2}, v0{0.9, -0.4, 0.6};
    const double dt = 0.05;
    const std::size_t n = 1000;
    auto there_and_back = [&](const auto& pusher, double tolerance) {
        v3 x = x0, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        const auto r = odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, n);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(pusher.synchronize(fields, x, v, r.t, dt) == odestep::status::ok);
        CHECK(max_abs_difference(x, x0) > 1.0);  // it went somewhere
        REQUIRE(pusher.stagger(fields, x, v, r.t, -dt) == odestep::status::ok);
        const auto back = odestep::integrate_n_steps(pusher, fields, x, v, r.t, -dt, n);
        REQUIRE(back.status == odestep::status::ok);
        REQUIRE(pusher.synchronize(fields, x, v, back.t, -dt) == odestep::status::ok);
        CHECK(std::fabs(back.t) <= 1e-13);
        CHECK(max_abs_difference(x, x0) <= tolerance);
        CHECK(max_abs_difference(v, v0) <= tolerance);
    };
    there_and_back(odestep::boris<v3>(1.3), 1e-12);
    there_and_back(odestep::boris_relativistic<v3>(1.3, 2.0), 1e-12);
}

TEST_CASE(
    "boris: volume preserving: the step's Jacobian determinant in (x, v) is 1 in a non-uniform field, where RK4's is "
    "not") {
    // Each stage of the step has determinant 1 (Qin et al. 2013): the E kicks and the drift are shears, and
    // the rotation, at fixed x, is orthogonal; for the relativistic pusher the rotation angle depends on |u|
    // only, which it keeps, so it too preserves volume (Higuera & Cary 2017). Central differences in long
    // double with delta = cbrt(eps), which balances truncation (about delta^2) against rounding (about
    // eps / delta): errors near eps^(2/3), 2e-13 in x87 long double and 4e-11 where long double is double
    // (ARM EABI), both well below 1e-9.
    using z6 = std::array<long double, 6>;
    using l3 = vec3<long double>;
    const nonuniform fields;
    const z6 z{0.3L, -0.7L, 0.2L, 0.9L, -0.4L, 0.6L};
    const long double dt = 0.3L, delta = std::cbrt(std::numeric_limits<long double>::epsilon());
    auto as_map = [&](const auto& pusher) {
        return [&fields, &pusher, dt](const z6& s) {
            l3 x{s[0], s[1], s[2]}, v{s[3], s[4], s[5]};
            REQUIRE(pusher.step(fields, x, v, 0.1L, dt) == odestep::status::ok);
            return z6{x[0], x[1], x[2], v[0], v[1], v[2]};
        };
    };
    const odestep::boris<l3> pusher(1.3L);
    const odestep::boris_relativistic<l3> relativistic(1.3L, 1.5L);
    const long double det = jacobian_determinant(as_map(pusher), z, delta);
    const long double det_rel = jacobian_determinant(as_map(relativistic), z, delta);
    CHECK(std::fabs(det - 1) <= 1e-9L);
    CHECK(std::fabs(det_rel - 1) <= 1e-9L);
    // The map on synchronized (x_n, v_n) (stagger, step, synchronize) is not volume preserving in a
    // non-uniform B: stagger's Jacobian is det(I - [tau x]) = 1 + |tau(x_n)|^2 and synchronize's is its inverse
    // at x_{n+1}, so its determinant is (1 + |tau(x_n)|^2) / (1 + |tau(x_{n+1})|^2), as boris.hpp says.
    auto tau2 = [&](long double t, const l3& at) {
        l3 E, B;
        fields(t, at, E, B);
        const long double h = 1.3L * dt / 2;
        return h * h * (B[0] * B[0] + B[1] * B[1] + B[2] * B[2]);
    };
    auto synchronized_map = [&](const z6& s) {
        l3 x{s[0], s[1], s[2]}, v{s[3], s[4], s[5]};
        REQUIRE(pusher.stagger(fields, x, v, 0.1L, dt) == odestep::status::ok);
        REQUIRE(pusher.step(fields, x, v, 0.1L, dt) == odestep::status::ok);
        REQUIRE(pusher.synchronize(fields, x, v, 0.1L + dt, dt) == odestep::status::ok);
        return z6{x[0], x[1], x[2], v[0], v[1], v[2]};
    };
    const long double det_sync = jacobian_determinant(synchronized_map, z, delta);
    const z6 z1 = synchronized_map(z);
    const long double expected_sync =
        (1 + tau2(0.1L, l3{z[0], z[1], z[2]})) / (1 + tau2(0.1L + dt, l3{z1[0], z1[1], z1[2]}));
    CHECK(std::fabs(det_sync - expected_sync) <= 1e-9L);
    CHECK(std::fabs(expected_sync - 1) > 1e-3L);
    // The same test tells a method that is not volume preserving: RK4 on the same equations.
    auto lorentz = [&fields](long double t, const z6& s, z6& d) {
        l3 E, B;
        fields(t, l3{s[0], s[1], s[2]}, E, B);
        d = {s[3],
             s[4],
             s[5],
             1.3L * (E[0] + s[4] * B[2] - s[5] * B[1]),
             1.3L * (E[1] + s[5] * B[0] - s[3] * B[2]),
             1.3L * (E[2] + s[3] * B[1] - s[4] * B[0])};
    };
    const long double det_rk4 = jacobian_determinant(
        [&](const z6& s) {
            z6 y = s;
            REQUIRE(odestep::rk4<z6>{}.step(lorentz, y, 0.1L, dt) == odestep::status::ok);
            return y;
        },
        z, delta);
    CHECK(std::fabs(det_rk4 - 1) > 1e-6L);
    MESSAGE("|det - 1|: boris ", static_cast<double>(std::fabs(det - 1)), ", relativistic ",
            static_cast<double>(std::fabs(det_rel - 1)), ", rk4 ", static_cast<double>(std::fabs(det_rk4 - 1)));
}

TEST_CASE("boris: integrate is bitwise the same as calling step by hand at t0 + i dt") {
    const nonuniform fields;
    const odestep::boris<v3> pusher(0.8);
    v3 xa{0.3, -0.7, 0.2}, va{0.9, -0.4, 0.6};
    v3 xb = xa, vb = va;
    const auto r = odestep::integrate(pusher, fields, xa, va, 0.0, 2.0, 0.25);
    REQUIRE(r.status == odestep::status::ok);
    for (int i = 0; i < 8; ++i) REQUIRE(pusher.step(fields, xb, vb, 0.25 * i, 0.25) == odestep::status::ok);
    CHECK(same_bits(xa, xb));
    CHECK(same_bits(va, vb));
}

// ---------------------------------------------------------------------------------------------------------
// Relativistic

TEST_CASE(
    "boris_relativistic: in a pure B, |u| (so gamma) is conserved to round-off and the gyration frequency is omega_c / "
    "gamma") {
    // c = 2 and |u| = 2.6: gamma = sqrt(1 + 2.6^2 / 4) = 1.64 (v = 0.79 c). The rotation angle per step is
    // 2 atan(omega_c dt / (2 gamma)) exactly (tau = (q/m) B dt / (2 gamma)), omega_c dt / gamma to O(dt^3).
    const double qm = 1.0, b = 3.0, c = 2.0, dt = 0.02;
    const odestep::boris_relativistic<v3> pusher(qm, c);
    CHECK(pusher.charge_to_mass() == qm);
    CHECK(pusher.speed_of_light() == c);
    const crossed<double> fields{0.0, b};
    v3 x{0, 0, 0}, u{2.4, 0.0, 1.0};
    REQUIRE(pusher.stagger(fields, x, u, 0.0, dt) == odestep::status::ok);
    const double u0 = norm(u), gamma = pusher.gamma(u);
    const std::size_t n = 100000;
    const double per_step = -2 * std::atan(qm * b * dt / (2 * gamma));
    double worst = 0, deviation = 0;  // as in the non-relativistic test: each step's angle minus per_step
    v3 before = u;
    const auto r = odestep::integrate_n_steps(pusher, fields, x, u, 0.0, dt, n, [&](double t, const v3&, const v3& uh) {
        worst = std::fmax(worst, std::fabs(norm(uh) / u0 - 1));
        if (t == 0.0) return;  // the observer's first call is the initial state
        deviation += turn_angle(before, uh) - per_step;
        before = uh;
    });
    REQUIRE(r.status == odestep::status::ok);
    CHECK(worst <= 2 * std::sqrt(static_cast<double>(n)) * std::numeric_limits<double>::epsilon());
    CHECK(std::fabs(pusher.gamma(u) / gamma - 1) <=
          2 * std::sqrt(static_cast<double>(n)) * std::numeric_limits<double>::epsilon());
    // The angle depends on |u| through gamma, and |u| wanders by round-off (up to 2 sqrt(n) eps, checked
    // above), so each step's angle may be off by that relative amount: n |per_step| 2 sqrt(n) eps = 5e-10.
    CHECK(std::fabs(deviation) <= static_cast<double>(n) * std::fabs(per_step) * 2 * std::sqrt(static_cast<double>(n)) *
                                      std::numeric_limits<double>::epsilon());
    const double phase = static_cast<double>(n) * per_step + deviation;
    // the frequency of the physical particle, omega_c / gamma(u_0) with u_0 = 2.6: a relative difference
    // of O(dt^2), from 2 atan(x/2) = x - x^3/12 and from |u_{1/2}| = |u_0| sqrt(1 + |tau|^2)
    const double gamma0 = std::sqrt(1 + (2.4 * 2.4 + 1.0) / (c * c));
    const double frequency = std::fabs(phase) / r.t;
    CHECK(frequency == doctest::Approx(qm * b / gamma0).epsilon(1e-3));
    CHECK(std::fabs(frequency / (qm * b / gamma0) - 1) > 1e-6);  // but not exactly
    MESSAGE("relativistic gyration: measured ", frequency, ", omega_c / gamma = ", qm * b / gamma0);
}

TEST_CASE("boris_relativistic: observed order 2 on the exact helix in a uniform B") {
    // u_perp turns at omega_c / gamma; x_perp + i y_perp = i zeta0 (exp(-i omega_c t / gamma) - 1) / omega_c
    // with zeta0 = u_x + i u_y at t = 0 (for q/m b > 0), and z = u_z t / gamma.
    const double qm = 1.0, b = 3.0, c = 2.0, t_end = 5.0;
    const v3 u0{2.4, 0.0, 1.0};
    const double gamma = std::sqrt(1 + (u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2]) / (c * c));
    const double omega = qm * b / gamma;
    const std::complex<double> zeta0(u0[0], u0[1]);
    const std::complex<double> orbit =
        std::complex<double>(0, 1) * zeta0 * (std::exp(std::complex<double>(0, -omega * t_end)) - 1.0) / (qm * b);
    const std::complex<double> u_perp = zeta0 * std::exp(std::complex<double>(0, -omega * t_end));
    const v3 x_exact{orbit.real(), orbit.imag(), u0[2] * t_end / gamma};
    const v3 u_exact{u_perp.real(), u_perp.imag(), u0[2]};
    std::array<double, 5> ex{}, eu{};
    const odestep::boris_relativistic<v3> pusher(qm, c);
    const crossed<double> fields{0.0, b};
    for (std::size_t k = 0; k < ex.size(); ++k) {
        const std::size_t n = std::size_t{100} << k;
        const double dt = t_end / static_cast<double>(n);
        v3 x{0, 0, 0}, u = u0;
        REQUIRE(pusher.stagger(fields, x, u, 0.0, dt) == odestep::status::ok);
        const auto r = odestep::integrate_n_steps(pusher, fields, x, u, 0.0, dt, n);
        REQUIRE(r.status == odestep::status::ok);
        REQUIRE(pusher.synchronize(fields, x, u, r.t, dt) == odestep::status::ok);
        ex[k] = max_abs_difference(x, x_exact);
        eu[k] = max_abs_difference(u, u_exact);
    }
    const double px = fitted_order(ex), pu = fitted_order(eu);
    MESSAGE("relativistic observed order: x ", px, ", u ", pu);
    CHECK(std::fabs(px - 2.0) <= 0.2);
    CHECK(std::fabs(pu - 2.0) <= 0.2);
}

TEST_CASE("boris_relativistic: at small velocities it agrees with the non-relativistic pusher to O(v^2 / c^2)") {
    // Crossed fields (E = 0.5, B = 1, speeds up to about 1.2), the same dt and start, to t = 20. The
    // difference comes from gamma - 1 = |v|^2 / (2 c^2) + O(c^-4): it shrinks 100-fold for c 10 times larger.
    const crossed<double> fields{0.5, 1.0};
    const double dt = 0.05;
    const std::size_t n = 400;
    const v3 v0{-0.3, 0.6, 0.2};
    auto run = [&](const auto& pusher) {
        v3 x{0, 0, 0}, v = v0;
        REQUIRE(pusher.stagger(fields, x, v, 0.0, dt) == odestep::status::ok);
        REQUIRE(odestep::integrate_n_steps(pusher, fields, x, v, 0.0, dt, n).status == odestep::status::ok);
        return x;
    };
    const v3 classical = run(odestep::boris<v3>(1.0));
    std::array<double, 2> diff{};
    const double cs[2] = {100.0, 1000.0};
    for (std::size_t k = 0; k < 2; ++k)
        diff[k] = max_abs_difference(run(odestep::boris_relativistic<v3>(1.0, cs[k])), classical);
    // The main effect: the gyration at omega_c / gamma, with gamma - 1 <= v_max^2 / (2 c^2), slips the phase
    // by omega_c t v_max^2 / (2 c^2) on the gyroradius R = 1 (|v - E/B x-hat| = |(-0.8, 0.6)| = 1, omega_c = 1);
    // v_max = |(0.5 + 1, 0, 0.2)| = 1.52 (drift plus gyration, and v_z). The bound is twice that, for the
    // smaller changes to the drift and the E kick: omega_c t R (v_max / c)^2 = 4.6e-3 at c = 100.
    const double omega_c = 1.0, t_end = 20.0, radius = 1.0, v_max = 1.52;
    CHECK(diff[0] <= omega_c * t_end * radius * (v_max / cs[0]) * (v_max / cs[0]));
    CHECK(diff[0] / diff[1] == doctest::Approx(100.0).epsilon(0.01));
    MESSAGE("relativistic - classical: ", diff[0], " at c = 100, ", diff[1], " at c = 1000");
}

// ---------------------------------------------------------------------------------------------------------
// float

TEST_CASE("boris: float runs give the double result to within float round-off, for both pushers") {
    // 400 steps on the crossed-field trochoid to t = 20: the float error is the double (truncation) error
    // plus float round-off. Each step rounds x (|x| <= 11, where half a float ULP is 4.8e-7) in no preferred
    // direction, so after 400 steps by about sqrt(400) x 4.8e-7 = 1e-5; the bound allows 4 times that.
    const exact_crossed ex{1.0, 0.5, 1.0, v3{0.0, 0.0, 0.0}, v3{-0.3, 0.6, 0.2}};
    double xd = 0, vd = 0, xf = 0, vf = 0;
    boris_crossed_errors<double>(ex, 20.0, 400, xd, vd);
    boris_crossed_errors<float>(ex, 20.0, 400, xf, vf);
    const double allowed = 4 * std::sqrt(400.0) * 4.8e-7;
    CHECK(std::fabs(xf - xd) <= allowed);
    CHECK(std::fabs(vf - vd) <= allowed);
    CHECK(xd > 50 * allowed);  // the truncation error is far larger: the comparison has teeth
    MESSAGE("double error ", xd, ", float error ", xf, " (x), ", vd, " and ", vf, " (v)");

    // relativistic, pure B (the helix), float against double
    using f3 = vec3<float>;
    const odestep::boris_relativistic<f3> pf(1.0f, 2.0f);
    const odestep::boris_relativistic<v3> pd(1.0, 2.0);
    f3 x_f{0, 0, 0}, u_f{2.4f, 0.0f, 1.0f};
    v3 x_d{0, 0, 0}, u_d{static_cast<double>(2.4f), 0.0, 1.0};
    const crossed<float> ff{0.0f, 3.0f};
    const crossed<double> fd{0.0, 3.0};
    REQUIRE(pf.stagger(ff, x_f, u_f, 0.0f, 0.0125f) == odestep::status::ok);
    REQUIRE(pd.stagger(fd, x_d, u_d, 0.0, 0.0125) == odestep::status::ok);
    REQUIRE(odestep::integrate_n_steps(pf, ff, x_f, u_f, 0.0f, 0.0125f, 400).status == odestep::status::ok);
    REQUIRE(odestep::integrate_n_steps(pd, fd, x_d, u_d, 0.0, 0.0125, 400).status == odestep::status::ok);
    // Float round-off again: per step about half an ULP of |u| = 2.6 (1.2e-7), a sqrt(n) walk to 2.4e-6, plus
    // the rounding of tau (relative 6e-8), the same every step, which shifts the phase linearly: n theta 6e-8
    // = 400 x 0.023 x 6e-8 = 5.5e-7 on a gyroradius below 1. About 3e-6 in all; the bound allows 1e-5.
    const v3 xf_d{static_cast<double>(x_f[0]), static_cast<double>(x_f[1]), static_cast<double>(x_f[2])};
    const v3 uf_d{static_cast<double>(u_f[0]), static_cast<double>(u_f[1]), static_cast<double>(u_f[2])};
    CHECK(max_abs_difference(xf_d, x_d) <= 1e-5);
    CHECK(max_abs_difference(uf_d, u_d) <= 1e-5);
    MESSAGE("relativistic float - double: x ", max_abs_difference(xf_d, x_d), ", u ", max_abs_difference(uf_d, u_d));
    CHECK(std::fabs(norm(u_f) / static_cast<float>(norm(u_d)) - 1.0f) <= 64 * std::numeric_limits<float>::epsilon());
}

// ---------------------------------------------------------------------------------------------------------
// NaN and Inf

namespace {
// Puts `bad` into component `which` (0-2: E, 3-5: B) from call number `at` on.
template <class T>
struct poisoned {
    T bad;
    std::size_t which;
    std::size_t at;
    std::size_t* calls;
    void operator()(T, const vec3<T>&, vec3<T>& E, vec3<T>& B) const noexcept {
        E = {T(0.1), T(0.5), T(-0.2)};
        B = {T(0.3), T(-0.1), T(1)};
        if ((*calls)++ >= at) (which < 3 ? E[which] : B[which - 3]) = bad;
    }
};

template <class Pusher, class T>
void check_rollback(const Pusher& pusher, T bad) {
    for (std::size_t which = 0; which < 6; ++which) {
        INFO("component ", which, " (E: 0-2, B: 3-5) = ", static_cast<double>(bad));
        std::size_t calls = 0;
        const poisoned<T> fields{bad, which, 0, &calls};
        const vec3<T> x0{T(0.5), T(-1), T(2)}, v0{T(0.25), T(0.75), T(-0.5)};
        vec3<T> x = x0, v = v0;
        CHECK(pusher.step(fields, x, v, T(0), T(0.1)) == odestep::status::non_finite);
        CHECK(same_bits(x, x0));
        CHECK(same_bits(v, v0));
        CHECK(pusher.stagger(fields, x, v, T(0), T(0.1)) == odestep::status::non_finite);
        CHECK(same_bits(v, v0));
        CHECK(pusher.synchronize(fields, x, v, T(0), T(0.1)) == odestep::status::non_finite);
        CHECK(same_bits(v, v0));
        // in a run: the fields go bad at the 6th step; the caller keeps the state after 5 good steps
        calls = 0;
        const poisoned<T> late{bad, which, 5, &calls};
        vec3<T> xr = x0, vr = v0;
        const auto r = odestep::integrate_n_steps(pusher, late, xr, vr, T(0), T(0.1), 10);
        CHECK(r.status == odestep::status::non_finite);
        CHECK(r.steps == 5);
        std::size_t clean_calls = 0;
        const poisoned<T> clean{bad, which, 1000, &clean_calls};
        vec3<T> xc = x0, vc = v0;
        REQUIRE(odestep::integrate_n_steps(pusher, clean, xc, vc, T(0), T(0.1), 5).status == odestep::status::ok);
        CHECK(same_bits(xr, xc));
        CHECK(same_bits(vr, vc));
    }
}
}  // namespace

TEST_CASE(
    "boris: a NaN or Inf in any field component leaves x and v exactly as they were, both pushers, float and double") {
    for (double bad : {qnan, inf, -inf}) {
        check_rollback(odestep::boris<v3>(1.5), bad);
        check_rollback(odestep::boris_relativistic<v3>(1.5, 3.0), bad);
        check_rollback(odestep::boris<vec3<float>>(1.5f), static_cast<float>(bad));
        check_rollback(odestep::boris_relativistic<vec3<float>>(1.5f, 3.0f), static_cast<float>(bad));
    }
}

TEST_CASE("boris: finite fields whose result overflows are rolled back too, including a B so large |tau|^2 overflows") {
    const vec3<double> x0{0.5, -1, 2}, v0{0.25, 0.75, -0.5};
    // |tau|^2 = (1e200 * 0.05)^2 overflows: s would be 0 and the step a silent no-rotation
    auto huge_b = [](double, const v3&, v3&, v3& B) { B = {0.0, 0.0, 1e200}; };
    auto huge_e = [](double, const v3&, v3& E, v3&) { E = {1e308, 1e308, 0.0}; };
    const odestep::boris<v3> pusher;
    const odestep::boris_relativistic<v3> relativistic(1.0, 1e160);  // |u|^2 / c^2 overflows only for |u| > 1e300
    for (int which = 0; which < 2; ++which) {
        v3 x = x0, v = v0;
        if (which == 0) {
            CHECK(pusher.step(huge_b, x, v, 0.0, 0.1) == odestep::status::non_finite);
            CHECK(pusher.synchronize(huge_b, x, v, 0.0, 0.1) == odestep::status::non_finite);
            CHECK(relativistic.step(huge_b, x, v, 0.0, 0.1) == odestep::status::non_finite);
        } else {
            CHECK(pusher.step(huge_e, x, v, 0.0, 100.0) == odestep::status::non_finite);
            CHECK(relativistic.step(huge_e, x, v, 0.0, 100.0) == odestep::status::non_finite);
        }
        CHECK(same_bits(x, x0));
        CHECK(same_bits(v, v0));
    }
    // relativistic: |u|^2 overflowing makes gamma = Inf, which would freeze x; it is caught
    const odestep::boris_relativistic<v3> slow_light(1.0, 1.0);
    v3 x = x0, u{1e200, 1e200, 0.0};
    const v3 u_before = u;
    auto none = [](double, const v3&, v3&, v3&) {};
    CHECK(slow_light.step(none, x, u, 0.0, 0.1) == odestep::status::non_finite);
    CHECK(same_bits(x, x0));
    CHECK(same_bits(u, u_before));
}
