// SPDX-License-Identifier: BSL-1.0
// The DETEST problems with closed forms (Hull, Enright, Fellen & Sedgwick 1972, "Comparing numerical methods
// for ordinary differential equations", SIAM J. Numer. Anal. 9(4), 603-635), shared by the adaptive tests
// (detest_test.cpp: tolerance proportionality; bounds_test.cpp: the error bound of every pair and
// interpolant). Each closed form is written here in long double, independently of the library, and checked
// against f by central differences in detest_test.cpp. Each problem's `bound` is the factor of the tolerance
// detest_test.cpp allows DP 5(4), DOP853 and Cash-Karp (its comment there says why).
#ifndef ODESTEP_TESTS_ADAPTIVE_DETEST_PROBLEMS_HPP
#define ODESTEP_TESTS_ADAPTIVE_DETEST_PROBLEMS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace detest {

using ld = long double;

// The error bound's factor, error <= bound * tol, per problem. The controller keeps each step's local error
// estimate below tol (1 + |y|), and a pair propagating its higher order (all three here) commits a local error
// far below its estimate; the global error is the sum of the local ones carried by the flow.
//
// Classes A, B, C, E (decaying or bounded, non-expanding flows): the global error stays near the tolerance.
// The largest ratio measured over these problems, the three methods and 1e-3 .. 1e-10 is 7.6 (Cash-Karp on
// A3, whose exp(sin t) swings by a factor e^2 every period); 10 leaves a little room and no more.
inline constexpr double smooth_bound = 10.0;
// Class D (Kepler orbits): a local error changes the energy, hence the period, and the phase error grows
// linearly with t; near pericentre it is multiplied by the speed and acceleration there. An energy error dE
// changes the mean motion by 3 dE (a = -1 / 2E, n = a^(-3/2)), so after 20 time units the phase is off by
// about 60 dE, and near pericentre (acceleration 1 / (1 - e)^2: 1.2 for D1, 100 for D5) the velocity by
// 60 dE / (1 - e)^2. One local error of size tol at pericentre changes E by v dv + dr / r^2, up to
// 5 tol (D1) and 130 tol (D5). Hence ratios of 10^2..10^3 for D1 and 10^4..10^5 for D5 with any method that
// controls the error per step (measured: up to 860 for D1, DP 5(4) at 1e-3, and 1.5e5 for D5, DP 5(4) at
// 1e-5). The bounds are about twice and three times those; the proportionality itself is checked by the
// slope, which is the claim here.

inline const ld pi_ld = std::acos(ld(-1));

// ---------------------------------------------------------------------------------------------------------
// The problems. Each: n components, f templated on T, start<T>(), exact(t) in long double on [0, 20] (DETEST's
// interval for every problem used here). The closed forms are checked against f by central differences in
// the first test case.

// A1: y' = -y, y(0) = 1  =>  y = exp(-t).
struct a1 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = -y[0];
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {std::exp(-t)}; }
};

// A2: y' = -y^3 / 2, y(0) = 1  =>  y = 1 / sqrt(t + 1) (y^-2 = t + 1: d/dt y^-2 = -2 y^-3 y' = 1).
struct a2 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A2";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = -y[0] * y[0] * y[0] / T(2);
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {1 / std::sqrt(t + 1)}; }
};

// A3: y' = y cos t, y(0) = 1  =>  y = exp(sin t).
struct a3 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A3";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T t, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = y[0] * std::cos(t);
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {std::exp(std::sin(t))}; }
};

// A4: y' = (y / 4)(1 - y / 20), y(0) = 1  =>  the logistic curve y = 20 / (1 + 19 exp(-t / 4)).
struct a4 {
    static constexpr std::size_t n = 1;
    static constexpr const char* name = "A4";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 1>& y, std::array<T, 1>& d) const noexcept {
        d[0] = y[0] / T(4) * (T(1) - y[0] / T(20));
    }
    template <class T>
    static std::array<T, 1> start() noexcept {
        return {T(1)};
    }
    static std::array<ld, 1> exact(ld t) noexcept { return {20 / (1 + 19 * std::exp(-t / 4))}; }
};

// B2: y' = A y, A = [[-1, 1, 0], [1, -2, 1], [0, 1, -1]], y(0) = (2, 0, 1). A is symmetric with eigenpairs
// 0: (1, 1, 1), -1: (1, 0, -1), -3: (1, -2, 1); y(0) = (1, 1, 1) + (1, 0, -1) / 2 + (1, -2, 1) / 2, so
// y = (1, 1, 1) + exp(-t) (1, 0, -1) / 2 + exp(-3t) (1, -2, 1) / 2.
struct b2 {
    static constexpr std::size_t n = 3;
    static constexpr const char* name = "B2";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 3>& y, std::array<T, 3>& d) const noexcept {
        d[0] = -y[0] + y[1];
        d[1] = y[0] - T(2) * y[1] + y[2];
        d[2] = y[1] - y[2];
    }
    template <class T>
    static std::array<T, 3> start() noexcept {
        return {T(2), T(0), T(1)};
    }
    static std::array<ld, 3> exact(ld t) noexcept {
        const ld a = std::exp(-t) / 2;
        const ld b = std::exp(-3 * t) / 2;
        return {1 + a + b, 1 - 2 * b, 1 - a + b};
    }
};

// C1: the decay chain y1' = -y1, yi' = y(i-1) - yi (i = 2..9), y10' = y9, y(0) = (1, 0, ..., 0). By induction
// yi = t^(i-1) exp(-t) / (i-1)! for i <= 9 (the Poisson probabilities), and y10 = 1 - (y1 + ... + y9) (the
// sum of f is zero).
struct c1 {
    static constexpr std::size_t n = 10;
    static constexpr const char* name = "C1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T, const std::array<T, 10>& y, std::array<T, 10>& d) const noexcept {
        d[0] = -y[0];
        for (std::size_t i = 1; i < 9; ++i) d[i] = y[i - 1] - y[i];
        d[9] = y[8];
    }
    template <class T>
    static std::array<T, 10> start() noexcept {
        std::array<T, 10> y{};
        y[0] = T(1);
        return y;
    }
    static std::array<ld, 10> exact(ld t) noexcept {
        std::array<ld, 10> y{};
        ld term = std::exp(-t);  // t^k e^-t / k!, k = 0
        ld sum = 0;
        for (std::size_t k = 0; k < 9; ++k) {
            y[k] = term;
            sum += term;
            term *= t / static_cast<ld>(k + 1);
        }
        y[9] = 1 - sum;
        return y;
    }
};

// D1-D5: the Kepler problem x'' = -x / r^3 from (1 - e, 0) with velocity (0, sqrt((1 + e) / (1 - e))): an
// ellipse of semi-major axis 1 and eccentricity e (D1..D5: e = 0.1, 0.3, 0.5, 0.7, 0.9), period 2 pi. With
// the eccentric anomaly E from Kepler's equation E - e sin E = t (mean motion 1, pericentre at t = 0):
//   x = cos E - e, y = sqrt(1 - e^2) sin E, x' = -sin E / (1 - e cos E), y' = sqrt(1 - e^2) cos E / (1 - e cos E)
// (Danby, Fundamentals of Celestial Mechanics, ch. 6). E by Newton in long double from Danby's starter.
inline ld kepler_anomaly(ld e, ld mean) noexcept {
    const ld two_pi = 2 * pi_ld;
    const ld turns = std::floor(mean / two_pi + ld(0.5));
    const ld m = mean - turns * two_pi;  // in [-pi, pi]
    ld E = m + (m < 0 ? -ld(0.85) : ld(0.85)) * e;
    for (int i = 0; i < 60; ++i) {
        const ld step = (E - e * std::sin(E) - m) / (1 - e * std::cos(E));
        E -= step;
        if (std::fabs(step) <= 4 * std::numeric_limits<ld>::epsilon() * (1 + std::fabs(E))) break;
    }
    return E + turns * two_pi;
}

template <int Tenths>
struct kepler_d {
    static constexpr std::size_t n = 4;
    static constexpr const char* name = Tenths == 1   ? "D1"
                                        : Tenths == 3 ? "D2"
                                        : Tenths == 5 ? "D3"
                                        : Tenths == 7 ? "D4"
                                                      : "D5";
    static constexpr double bound = Tenths == 1 ? 2e3 : 5e5;
    template <class T>
    void operator()(T, const std::array<T, 4>& y, std::array<T, 4>& d) const noexcept {
        const T r2 = y[0] * y[0] + y[1] * y[1];
        const T r3 = r2 * std::sqrt(r2);
        d[0] = y[2];
        d[1] = y[3];
        d[2] = -y[0] / r3;
        d[3] = -y[1] / r3;
    }
    template <class T>
    static std::array<T, 4> start() noexcept {
        const ld e = ld(Tenths) / 10;
        return {static_cast<T>(1 - e), T(0), T(0), static_cast<T>(std::sqrt((1 + e) / (1 - e)))};
    }
    static std::array<ld, 4> exact(ld t) noexcept {
        const ld e = ld(Tenths) / 10;
        const ld E = kepler_anomaly(e, t);
        const ld s = std::sin(E);
        const ld c = std::cos(E);
        const ld b = std::sqrt(1 - e * e);
        const ld q = 1 - e * c;
        return {c - e, b * s, -s / q, b * c / q};
    }
};
using d1 = kepler_d<1>;
using d5 = kepler_d<9>;

// E1: y'' + y' / (t + 1) + (1 - 1 / (4 (t + 1)^2)) y = 0, Bessel's equation of order 1/2 in x = t + 1, with
// y(0) = J_{1/2}(1) and y'(0) = J_{1/2}'(1), so y = J_{1/2}(t + 1) = sqrt(2 / (pi x)) sin x (Abramowitz &
// Stegun 10.1.11). DETEST's initial values 0.6713967071418030, 0.09540051444747446 are these to 16 digits.
struct e1 {
    static constexpr std::size_t n = 2;
    static constexpr const char* name = "E1";
    static constexpr double bound = smooth_bound;
    template <class T>
    void operator()(T t, const std::array<T, 2>& y, std::array<T, 2>& d) const noexcept {
        const T x = t + T(1);
        d[0] = y[1];
        d[1] = -(y[1] / x + (T(1) - T(1) / (T(4) * x * x)) * y[0]);
    }
    template <class T>
    static std::array<T, 2> start() noexcept {
        const auto y = exact(0);
        return {static_cast<T>(y[0]), static_cast<T>(y[1])};
    }
    static std::array<ld, 2> exact(ld t) noexcept {
        const ld x = t + 1;
        const ld k = std::sqrt(2 / pi_ld);
        const ld r = std::sqrt(x);
        return {k * std::sin(x) / r, k * (std::cos(x) / r - std::sin(x) / (2 * x * r))};
    }
};

}  // namespace detest

#endif
