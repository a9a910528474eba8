// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: the right-hand sides. Each is written once, as a template over the scalar type and
// over anything indexable (std::array for odestep, the hand loops and Odeint; a plain pointer for GSL), so
// every variant of a case integrates exactly the same arithmetic.
#ifndef ODESTEP_BENCH_PROBLEMS_HPP
#define ODESTEP_BENCH_PROBLEMS_HPP

#include <array>
#include <cmath>

namespace bench {

/// Lorenz (1963): sigma = 10, rho = 28, beta = 8/3. Autonomous, 3 states.
template <class T, class In, class Out>
inline void lorenz(const In& y, Out& d) {
    d[0] = T(10) * (y[1] - y[0]);
    d[1] = y[0] * (T(28) - y[2]) - y[1];
    d[2] = y[0] * y[1] - (T(8) / T(3)) * y[2];
}

/// The planar three-body problem, G = 1, unit masses. y = (x1, y1, x2, y2, x3, y3, u1, v1, u2, v2, u3, v3):
/// positions then velocities, 12 states. Autonomous.
template <class T, class In, class Out>
inline void three_body(const In& y, Out& d) {
    const T dx01 = y[2] - y[0], dy01 = y[3] - y[1];
    const T dx02 = y[4] - y[0], dy02 = y[5] - y[1];
    const T dx12 = y[4] - y[2], dy12 = y[5] - y[3];
    const T r01 = dx01 * dx01 + dy01 * dy01;
    const T r02 = dx02 * dx02 + dy02 * dy02;
    const T r12 = dx12 * dx12 + dy12 * dy12;
    const T s01 = T(1) / (r01 * std::sqrt(r01));
    const T s02 = T(1) / (r02 * std::sqrt(r02));
    const T s12 = T(1) / (r12 * std::sqrt(r12));
    d[0] = y[6];
    d[1] = y[7];
    d[2] = y[8];
    d[3] = y[9];
    d[4] = y[10];
    d[5] = y[11];
    d[6] = dx01 * s01 + dx02 * s02;
    d[7] = dy01 * s01 + dy02 * s02;
    d[8] = dx12 * s12 - dx01 * s01;
    d[9] = dy12 * s12 - dy01 * s01;
    d[10] = -(dx02 * s02 + dx12 * s12);
    d[11] = -(dy02 * s02 + dy12 * s12);
}

/// Chenciner & Montgomery's figure-eight orbit (initial values from Simo): a periodic, linearly stable
/// three-body solution, so a short run is smooth and nothing comes close.
template <class T>
constexpr std::array<T, 12> figure_eight() {
    return {T(0.97000436L),
            T(-0.24308753L),
            T(0),
            T(0),
            T(-0.97000436L),
            T(0.24308753L),
            T(0.466203685L),
            T(0.43236573L),
            T(-0.93240737L),
            T(-0.86473146L),
            T(0.466203685L),
            T(0.43236573L)};
}

/// The harmonic oscillator x'' = -x as a first-order system (x, v). Its rhs is two moves and a negation,
/// so the integrator's own overhead dominates.
template <class T, class In, class Out>
inline void oscillator(const In& y, Out& d) {
    d[0] = y[1];
    d[1] = -y[0];
}

/// The planar Kepler problem with mu = 1: x'' = -x / |x|^3. A force of position alone, written into `a`.
template <class T, class In, class Out>
inline void kepler(const In& x, Out& a) {
    const T r2 = x[0] * x[0] + x[1] * x[1];
    const T s = T(1) / (r2 * std::sqrt(r2));
    a[0] = -x[0] * s;
    a[1] = -x[1] * s;
}

/// A pebble moving vertically against quadratic drag: y = (height, velocity), a = -g - (g / vt^2) v |v| with
/// g = 9.8 and terminal speed vt = 30. Autonomous, 2 states. The drag term has a jump in its second
/// derivative at v = 0 (the apex).
template <class T, class In, class Out>
inline void pebble(const In& y, Out& d) {
    const T g = T(9.8), k = T(9.8) / (T(30) * T(30));
    d[0] = y[1];
    d[1] = -g - k * y[1] * std::fabs(y[1]);
}

}  // namespace bench

#endif
