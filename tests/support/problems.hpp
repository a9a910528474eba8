// SPDX-License-Identifier: BSL-1.0
// The test problems more than one test uses, each with its closed-form solution (or known states) and where
// that comes from. Every problem but arenstorf is a template in the value type: float, double and long double.
#ifndef ODESTEP_TESTS_SUPPORT_PROBLEMS_HPP
#define ODESTEP_TESTS_SUPPORT_PROBLEMS_HPP

#include <array>
#include <cmath>
#include <cstddef>

namespace odestep_test {

/// Two components: a plane position or velocity, or the oscillator's (y, y').
template <class T>
using vec2 = std::array<T, 2>;
/// Three components: exp_sin's state.
template <class T>
using state3 = std::array<T, 3>;

// ---------------------------------------------------------------------------------------------------------
// First-order systems y' = f(t, y)

/// The restricted three-body problem of the Arenstorf orbit (HNW I, Sec. II.0, eq. (0.1); the driver of
/// Hairer's DOPRI5): y1'' = y1 + 2 y2' - mu' (y1 + mu) / D1 - mu (y1 - mu') / D2,
/// y2'' = y2 - 2 y1' - mu' y2 / D1 - mu y2 / D2, D1 = ((y1 + mu)^2 + y2^2)^(3/2), D2 = ((y1 - mu')^2 +
/// y2^2)^(3/2), mu' = 1 - mu, as a first-order system in (y1, y2, y1', y2'). From start() the solution is
/// periodic with the period below, so y(period) = y(0) is the reference. Double only (Hairer's figures).
struct arenstorf {
    using state = std::array<double, 4>;
    static constexpr double mu = 0.012277471;
    static constexpr double period = 17.0652165601579625588917206249;
    static constexpr state start() noexcept { return {0.994, 0.0, 0.0, -2.00158510637908252240537862224}; }
    void operator()(double, const state& y, state& d) const noexcept {
        const double mp = 1.0 - mu;
        double d1 = (y[0] + mu) * (y[0] + mu) + y[1] * y[1];
        d1 *= std::sqrt(d1);
        double d2 = (y[0] - mp) * (y[0] - mp) + y[1] * y[1];
        d2 *= std::sqrt(d2);
        d[0] = y[2];
        d[1] = y[3];
        d[2] = y[0] + 2.0 * y[3] - mp * (y[0] + mu) / d1 - mu * (y[0] - mp) / d2;
        d[3] = y[1] - 2.0 * y[2] - mp * y[1] / d1 - mu * y[1] / d2;
    }
};

/// A nonlinear autonomous system with a bounded closed-form solution:
///   y0' = y0 y1,  y1' = -y2,  y2' = y1,  y(0) = (1, 1, 0)  =>  y1 = cos t, y2 = sin t, y0 = exp(sin t)
/// (y1'' = -y1 with y1(0) = 1, y1'(0) = 0; then y0' = exp(sin t) cos t = y0 y1, checked by differentiation).
/// Over many periods the truncation error grows linearly with time and round-off only like the square root
/// of the step count, which leaves room to see order 8 in double.
struct exp_sin {
    /// f, in place.
    template <class T>
    void operator()(T, const state3<T>& y, state3<T>& dydt) const noexcept {
        dydt[0] = y[0] * y[1];
        dydt[1] = -y[2];
        dydt[2] = y[1];
    }
    /// y(0) = (1, 1, 0).
    template <class T>
    static state3<T> start() noexcept {
        return {T(1), T(1), T(0)};
    }
    /// The solution at t, computed in T: (exp(sin t), cos t, sin t).
    template <class T>
    static state3<T> exact(T t) noexcept {
        return {std::exp(std::sin(t)), std::cos(t), std::sin(t)};
    }
};

/// The harmonic oscillator as a first-order system, y0' = y1, y1' = -y0: from (1, 0), y = (cos t, -sin t).
struct harmonic {
    /// f, in place.
    template <class T>
    void operator()(T, const vec2<T>& y, vec2<T>& dydt) const noexcept {
        dydt[0] = y[1];
        dydt[1] = -y[0];
    }
};

// ---------------------------------------------------------------------------------------------------------
// Newton's equations x'' = a(t, x)

/// The spring a = -x, component by component (x'' = -x: x = x0 cos t + v0 sin t).
struct spring {
    /// a(t, x) = -x.
    template <class T, std::size_t N>
    std::array<T, N> operator()(T, const std::array<T, N>& x) const noexcept {
        std::array<T, N> a{};
        for (std::size_t i = 0; i < N; ++i) a[i] = -x[i];
        return a;
    }
};

/// Uniform gravity x'' = -g in every component: x = x0 + v0 t - g t^2 / 2, v = v0 - g t. Every method of
/// order 2 or more that is exact for a constant force reproduces it, to rounding; with g, x0, v0 and the step
/// dyadic rationals of few bits, to the last bit.
template <class T>
struct uniform_gravity {
    T g;  ///< the acceleration is -g

    /// a(t, x) = -g.
    template <std::size_t N>
    std::array<T, N> operator()(T, const std::array<T, N>&) const noexcept {
        std::array<T, N> a{};
        for (std::size_t i = 0; i < N; ++i) a[i] = -g;
        return a;
    }
};

/// Kepler's problem in the plane with GM = 1: a = -x / |x|^3.
struct kepler {
    /// a(t, x) = -k x with k = 1 / r^3: both components scaled by one rounded k, so a stays parallel to x
    /// to one rounding per component. (The figures measured in splitting_test.cpp, energy and |L - L0| over
    /// 10^6 steps, were taken with this rounding.)
    template <class T>
    vec2<T> operator()(T, const vec2<T>& x) const noexcept {
        const T r2 = x[0] * x[0] + x[1] * x[1];
        const T r = std::sqrt(r2);
        const T k = T(1) / (r2 * r);
        return {-k * x[0], -k * x[1]};
    }
};

/// Kepler's energy |v|^2 / 2 - 1 / |x| (GM = 1), conserved along every orbit.
template <class T>
T kepler_energy(const vec2<T>& x, const vec2<T>& v) {
    return (v[0] * v[0] + v[1] * v[1]) / T(2) - T(1) / std::sqrt(x[0] * x[0] + x[1] * x[1]);
}

/// Kepler's angular momentum x0 v1 - x1 v0, conserved along every orbit.
template <class T>
T kepler_angular_momentum(const vec2<T>& x, const vec2<T>& v) {
    return x[0] * v[1] - x[1] * v[0];
}

/// Kepler's circular orbit from x = (1, 0), v = (0, 1) (v^2 = 1/r): x = (cos t, sin t), nonlinear, with a
/// closed form at every t.
struct circular_orbit {
    /// x(0) = (1, 0).
    template <class T>
    static vec2<T> start_x() noexcept {
        return {T(1), T(0)};
    }
    /// v(0) = (0, 1).
    template <class T>
    static vec2<T> start_v() noexcept {
        return {T(0), T(1)};
    }
    /// x(t) = (cos t, sin t), in T.
    template <class T>
    static vec2<T> x_at(T t) noexcept {
        return {std::cos(t), std::sin(t)};
    }
    /// v(t) = (-sin t, cos t), in T.
    template <class T>
    static vec2<T> v_at(T t) noexcept {
        return {-std::sin(t), std::cos(t)};
    }
};

/// Kepler's orbit of semi-major axis a = 1 and eccentricity e = 1/2, from perihelion (any mechanics text, e.g.
/// Goldstein, Classical Mechanics, ch. 3): r = a (1 - e) = 1/2, and by vis-viva v^2 = 2/r - 1/a = 3. Its
/// period is 2 pi, its energy E = -1/(2a) = -1/2 and its angular momentum L = sqrt(a (1 - e^2)) = sqrt(3)/2.
/// Half a period later it is at aphelion, r = a (1 + e) = 3/2, moving at sqrt(2/r - 1/a) = 1/sqrt(3) in -y
/// (L = 3/2 * 1/sqrt(3) = sqrt(3)/2 again).
struct eccentric_orbit {
    /// x at perihelion (t = 0): (1/2, 0).
    template <class T>
    static vec2<T> perihelion_x() noexcept {
        return {T(1) / T(2), T(0)};
    }
    /// v at perihelion: (0, sqrt 3).
    template <class T>
    static vec2<T> perihelion_v() noexcept {
        return {T(0), std::sqrt(T(3))};
    }
    /// x at aphelion (t = pi): (-3/2, 0).
    template <class T>
    static vec2<T> aphelion_x() noexcept {
        return {T(-3) / T(2), T(0)};
    }
    /// v at aphelion: (0, -1/sqrt 3).
    template <class T>
    static vec2<T> aphelion_v() noexcept {
        return {T(0), -std::sqrt(T(1) / T(3))};
    }
    /// E = -1/2.
    template <class T>
    static constexpr T energy() noexcept {
        return T(-0.5);
    }
    /// L = sqrt(3)/2.
    template <class T>
    static T angular_momentum() noexcept {
        return std::sqrt(T(3)) / T(2);
    }
};

}  // namespace odestep_test

#endif
