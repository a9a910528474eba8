// SPDX-License-Identifier: BSL-1.0
// The hand loops of the emulated Cortex-M4F table (bench/m4f/steppers.cpp) that bench/hand.hpp does not have:
// forward Euler, the explicit midpoint rule and Heun's method, and Dormand-Prince 5(4) with its error
// estimate in any T (hand.hpp's dopri5 is written in double). Written as hand.hpp's are (see its header
// comment): the right-hand side inlined into the step (BENCH_HAND), every loop over the components unrolled
// (BENCH_UNROLL), h times a coefficient hoisted, no copy beyond the one stage input. The `_checked` forms give
// odestep's guarantee with hand.hpp's test (finite_state): the new state into locals, summed after the loop
// that computes it, tested, written back only if finite; a stage whose weight is zero in every result (the
// midpoint rule's k1, Dormand-Prince's k2) is summed and tested too, as odestep tests it. They return
// bench::hand::ok (0) or bench::hand::non_finite and leave y (and err) as they were on failure.
#ifndef ODESTEP_BENCH_M4F_HAND_MORE_HPP
#define ODESTEP_BENCH_M4F_HAND_MORE_HPP

#include <array>
#include <cstddef>

#include "hand.hpp"

namespace bench::m4f_hand {

using bench::hand::finite_state;
using bench::hand::non_finite;
using bench::hand::ok;
using bench::hand::sum;

/// Forward Euler: y <- y + h f(t, y).
template <class T, std::size_t N, class F>
BENCH_HAND void euler(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1;
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h * k1[i];
}

/// euler, checked.
template <class T, std::size_t N, class F>
BENCH_HAND int euler_checked(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, yn;
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yn[i] = y[i] + h * k1[i];
    if (!finite_state(sum(yn), yn)) return non_finite;
    y = yn;
    return ok;
}

/// Explicit midpoint rule: k1 = f(t, y), k2 = f(t + h/2, y + h/2 k1), y <- y + h k2.
template <class T, std::size_t N, class F>
BENCH_HAND void midpoint(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, yt;
    const T h2 = h * T(0.5);
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k1[i];
    f(t + h2, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h * k2[i];
}

/// midpoint, checked: the new y and k1 (weight 0: it reaches y only through k2's input) summed and tested.
template <class T, std::size_t N, class F>
BENCH_HAND int midpoint_checked(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, yt;
    const T h2 = h * T(0.5);
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k1[i];
    f(t + h2, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k2[i];
    if (!finite_state(sum(yt) + sum(k1), yt, k1)) return non_finite;
    y = yt;
    return ok;
}

/// Heun's method (explicit trapezoidal rule): k1 = f(t, y), k2 = f(t + h, y + h k1), y <- y + h/2 (k1 + k2).
template <class T, std::size_t N, class F>
BENCH_HAND void heun(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, yt;
    const T h2 = h * T(0.5);
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k1[i];
    f(t + h, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h2 * (k1[i] + k2[i]);
}

/// heun, checked.
template <class T, std::size_t N, class F>
BENCH_HAND int heun_checked(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, yt;
    const T h2 = h * T(0.5);
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k1[i];
    f(t + h, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * (k1[i] + k2[i]);
    if (!finite_state(sum(yt), yt)) return non_finite;
    y = yt;
    return ok;
}

/// Velocity Verlet written kick-drift-kick, the acceleration at x kept by the caller in `acc` (a(x0) before
/// the first step): v_half = v + h/2 acc, x <- x + h v_half, acc <- a(x), v <- v_half + h/2 acc. One
/// evaluation and six multiply-adds per component pair, fewer operations than bench/hand.hpp's
/// x + h v + h^2/2 a form (the same method; the results differ by round-off).
template <class T, std::size_t N, class F>
BENCH_HAND void velocity_verlet_kdk(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, T t, T h) {
    const T h2 = h * T(0.5);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += h2 * acc[i];
        x[i] += h * v[i];
    }
    f(t + h, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) v[i] += h2 * acc[i];
}

/// velocity_verlet_kdk, checked: the same updates into locals; x, v and acc written only if the new x and v
/// are finite (the new acceleration needs no test: v_new is not finite when it is not, as in hand.hpp's
/// velocity_verlet_checked).
template <class T, std::size_t N, class F>
BENCH_HAND int velocity_verlet_kdk_checked(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, T t,
                                           T h) {
    const T h2 = h * T(0.5);
    std::array<T, N> xn, vn, an;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] = v[i] + h2 * acc[i];
        xn[i] = x[i] + h * vn[i];
    }
    f(t + h, xn, an);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) vn[i] += h2 * an[i];
    if (!finite_state(sum(xn) + sum(vn), xn, vn)) return non_finite;
    x = xn;
    v = vn;
    acc = an;
    return ok;
}

/// Dormand-Prince 5(4) with its error estimate, stage by stage as E. Hairer's dopri5.f (the coefficients of
/// Dormand & Prince 1980, J. Comput. Appl. Math. 6, 19-26), stateless like odestep's step (k1 evaluated
/// in every step, no first-same-as-last): the fifth-order solution is the seventh stage's input, and
/// err = h (e1 k1 + e3 k3 + ... + e7 k7), e = b - bhat (y_{n+1} - yhat_{n+1}, odestep's sign). Checked:
/// the new y, the estimate and k2 (weight 0 in both) summed and tested, y and err written only if finite.
/// The same stages as bench/hand.hpp's dopri5<double>, in T.
template <bool Checked, class T, std::size_t N, class F>
BENCH_HAND int dopri5(F f, std::array<T, N>& y, T t, T h, std::array<T, N>& err_out) {
    constexpr T c2 = T(0.2), c3 = T(0.3), c4 = T(0.8), c5 = T(8) / T(9);
    constexpr T a21 = T(0.2);
    constexpr T a31 = T(3) / T(40), a32 = T(9) / T(40);
    constexpr T a41 = T(44) / T(45), a42 = T(-56) / T(15), a43 = T(32) / T(9);
    constexpr T a51 = T(19372) / T(6561), a52 = T(-25360) / T(2187), a53 = T(64448) / T(6561), a54 = T(-212) / T(729);
    constexpr T a61 = T(9017) / T(3168), a62 = T(-355) / T(33), a63 = T(46732) / T(5247), a64 = T(49) / T(176),
                a65 = T(-5103) / T(18656);
    constexpr T a71 = T(35) / T(384), a73 = T(500) / T(1113), a74 = T(125) / T(192), a75 = T(-2187) / T(6784),
                a76 = T(11) / T(84);
    constexpr T e1 = T(71) / T(57600), e3 = T(-71) / T(16695), e4 = T(71) / T(1920), e5 = T(-17253) / T(339200),
                e6 = T(22) / T(525), e7 = T(-1) / T(40);
    std::array<T, N> k1, k2, k3, k4, k5, k6, k7, y1, e;
    std::array<T, N>& err = Checked ? e : err_out;
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, y1, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    f(t + c3 * h, y1, k3);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    f(t + c4 * h, y1, k4);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + c5 * h, y1, k5);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + h, y1, k6);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    f(t + h, y1, k7);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
    if constexpr (Checked) {
        if (!finite_state(sum(y1) + sum(err) + sum(k2), y1, err, k2)) return non_finite;
        err_out = err;
    }
    y = y1;
    return ok;
}

}  // namespace bench::m4f_hand

#endif
