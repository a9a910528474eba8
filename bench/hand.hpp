// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: the hand-written loops, the fastest a careful engineer writes without a library:
// named coefficients, loop-invariant products such as h/2 and h/6 hoisted, every loop over the components
// unrolled completely (BENCH_UNROLL) and the right-hand side inlined into the step (BENCH_HAND), at every
// -O, so that each is as fast as the same step written out in scalars; no copies beyond the one stage
// input, and no NaN/Inf check (odestep's check is what the comparison with these charges it for).
//
// Why unrolled and flattened (GCC 12.2, x86-64, callgrind instructions per step, Lorenz RK4): as plain
// `for` loops over std::array, GCC unrolls none of them at -O2 (180 instructions; unrolled: 101) and at -Os
// also calls the right-hand side out of line four times (204; unrolled alone: 185; unrolled and flattened:
// 98). -O3 unrolls and vectorizes plain loops by itself: there the rolled loops were up to 3 % faster for
// four cases (Lorenz RK4 97 against 101, DOPRI5 328/334, DOP853 2066/2106, RKF78 1948/1969) and slower for
// others (three-body RK4 400/387, AB4 111/85); one source serves all three levels.
// The three-body RK4 at -Os: 965 before, 684 now. The price is flash at -Os (RESULTS.md, code size).
//
// RK4 is the textbook y + h/6 (k1 + 2 (k2 + k3) + k4). DOPRI5 and DOP853 are written stage by stage as in
// E. Hairer's dopri5.f and dop853.f (Y1(I) = Y(I) + H*(A31*K1(I) + A32*K2(I)) and so on, same coefficients),
// except that they are stateless, like odestep's step: k1 is evaluated at the start of every step rather
// than carried over from the last stage of the step before (FSAL). RKF78 is written the same way; its
// eleventh stage feeds only the seventh-order solution, so the eighth-order step skips it. Velocity Verlet
// keeps the last acceleration in a variable of the caller's (first same as last), as any hand-written
// Verlet loop does: one evaluation of the force per step.
//
// The `*_checked` loops (the `hand_checked` rows) are the same loops written to give the guarantee odestep
// gives: the new state is computed into locals, tested for NaN and Inf, and only then written back; if any
// component is not finite (the right-hand side returned NaN or Inf, or the update overflowed) they return
// `non_finite` and leave the caller's x and v (or y), and a kept acceleration, exactly as they were. They
// return `ok` (0) otherwise. The arithmetic is the unchecked loop's, operation for operation. The sum that
// the test reads is taken after the loop that computes the new state, not inside it: with the loops
// unrolled that is as cheap or cheaper at every -O (three-body RK4 -O2: 414 against 645 fused; Lorenz RK4
// 110 against 111, -Os 104 against 105; Lorenz AB4 -O2 94.5 against 96.5).
#ifndef ODESTEP_BENCH_HAND_HPP
#define ODESTEP_BENCH_HAND_HPP

#include <array>
#include <cstddef>
#include <limits>

/// Before every loop over the components: unrolled completely (up to 16 components) at every -O.
#define BENCH_UNROLL _Pragma("GCC unroll 16")
/// A hand-written step function: every call in it inlined (the right-hand side, the RK4 start of the Adams
/// loops), as in the step written out by hand, also at -Os where GCC would call a right-hand side used four
/// times out of line.
#define BENCH_HAND [[gnu::flatten]] inline

namespace bench::hand {

/// The checked loops' return codes.
constexpr int ok = 0;
constexpr int non_finite = 1;

/// Every component finite, tested one by one: the slow path of finite_state. -max <= c <= max, which NaN
/// fails too: compares with two constants, which leave c in its register (std::isfinite's |c| <= max masks
/// a copy of c, and keeping those copies alive costs the fast path register moves: 1 to 2 instructions per
/// step at -O2). The array is taken by value: a 2-component state then travels in registers, where by
/// reference GCC at -Os keeps the new state on the stack for this call, fast path included (3 more in
/// kepler_verlet).
template <class T, std::size_t N>
inline bool each_finite(std::array<T, N> a) {
    constexpr T big = std::numeric_limits<T>::max();
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        if (!(a[i] >= -big && a[i] <= big)) return false;
    return true;
}

/// The finiteness test of a new state, given s, the sum of the components it tests, and the arrays that
/// hold them. z = s - s is exactly 0 when s is finite and NaN when s is NaN or +-Inf, which it is as soon as
/// one component is NaN or Inf (NaN propagates; an Inf stays Inf or meets the opposite Inf and gives NaN);
/// z == z is false only for NaN. So a subtraction, a compare of z with itself and a branch, after the
/// additions that form s (after the loop that computes the new state), prove every
/// component finite. Only when the test fails, because a component is not finite or because finite
/// components summed past the largest finite value, is each component tested on its own. Measured (GCC 12,
/// instructions per step, the seven hand_checked cases at -O2 and -Os, with the loops not yet unrolled) against std::isfinite on every
/// component, no sum: that costs 3 to 7 instructions more per step on the Kepler steps that test x alone,
/// the oscillator and Lorenz, 16 to 23 in kepler_verlet, 58 to 71 on the three-body problem. Always
/// inlined, as it would be written by hand: GCC at -Os makes a function called from two places a call (the
/// first step of beeman_checked is velocity_verlet_checked), and values live across a call spill.
template <class T, std::size_t... N>
[[gnu::always_inline]] inline bool finite_state(T s, const std::array<T, N>&... parts) {
    const T z = s - s;
    return z == z || (each_finite(parts) && ...);
}

/// a[0] + a[1] + ... + a[N-1], left to right: the s of finite_state.
template <class T, std::size_t N>
inline T sum(const std::array<T, N>& a) {
    T s = a[0];
    BENCH_UNROLL
    for (std::size_t i = 1; i < N; ++i) s += a[i];
    return s;
}

/// Classic RK4: y <- y + h/6 (k1 + 2 (k2 + k3) + k4). f(t, y, dydt).
template <class T, std::size_t N, class F>
BENCH_HAND void rk4(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, k3, k4, yt;
    const T h2 = h * T(0.5);
    const T h6 = h * (T(1) / T(6));
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k1[i];
    f(t + h2, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k2[i];
    f(t + h2, yt, k3);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k3[i];
    f(t + h, yt, k4);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h6 * (k1[i] + T(2) * (k2[i] + k3[i]) + k4[i]);
}

/// rk4, checked: the same stages, the new state computed into the stage input yt (free after the last
/// stage), its sum taken after that loop, tested, then copied into y. Written out rather than built on
/// rk4 or on a stages function shared with it: either changes GCC's code for the unchecked rk4 (inlining
/// and IPA decisions) by an instruction or two, and the `hand` rows are the reference.
template <class T, std::size_t N, class F>
BENCH_HAND int rk4_checked(F f, std::array<T, N>& y, T t, T h) {
    std::array<T, N> k1, k2, k3, k4, yt;
    const T h2 = h * T(0.5);
    const T h6 = h * (T(1) / T(6));
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k1[i];
    f(t + h2, yt, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h2 * k2[i];
    f(t + h2, yt, k3);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h * k3[i];
    f(t + h, yt, k4);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yt[i] = y[i] + h6 * (k1[i] + T(2) * (k2[i] + k3[i]) + k4[i]);
    if (!finite_state(sum(yt), yt)) return non_finite;
    y = yt;
    return ok;
}

/// Dormand-Prince 5(4) with its error estimate, as dopri5.f: the fifth-order solution is the seventh
/// stage's input, and err = h (e1 k1 + e3 k3 + ... + e7 k7) with e = b - bhat. Checked (the
/// `hand_checked` row): the new y, the estimate and k2 (weight 0 in both, so it reaches neither; a NaN
/// there must fail the step as in odestep) summed and tested, y and err written only if finite; returns 0
/// or non_finite. Unchecked: always 0.
template <bool Checked = false, std::size_t N, class F>
BENCH_HAND int dopri5(F f, std::array<double, N>& y, double t, double h, std::array<double, N>& err_out) {
    constexpr double c2 = 0.2, c3 = 0.3, c4 = 0.8, c5 = 8.0 / 9.0;
    constexpr double a21 = 0.2;
    constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
    constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                     a65 = -5103.0 / 18656.0;
    constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0, a75 = -2187.0 / 6784.0,
                     a76 = 11.0 / 84.0;
    constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                     e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
    std::array<double, N> k1, k2, k3, k4, k5, k6, k7, y1, e;
    std::array<double, N>& err = Checked ? e : err_out;
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

/// DOP853's eighth-order step (12 stages), as dop853.f, coefficients to the digits published there.
/// Checked (`hand_checked`): the new y into a local, it and k2 to k5 (weight 0: they reach y only through
/// later stages' inputs) summed and tested, y written only if finite; returns 0 or non_finite.
template <bool Checked = false, std::size_t N, class F>
BENCH_HAND int dop853(F f, std::array<double, N>& y, double t, double h) {
    constexpr double c2 = 0.526001519587677318785587544488e-01, c3 = 0.789002279381515978178381316732e-01,
                     c4 = 0.118350341907227396726757197510e+00, c5 = 0.281649658092772603273242802490e+00,
                     c6 = 0.333333333333333333333333333333e+00, c7 = 0.25e+00,
                     c8 = 0.307692307692307692307692307692e+00, c9 = 0.651282051282051282051282051282e+00,
                     c10 = 0.6e+00, c11 = 0.857142857142857142857142857142e+00;
    constexpr double a21 = 5.26001519587677318785587544488e-2;
    constexpr double a31 = 1.97250569845378994544595329183e-2, a32 = 5.91751709536136983633785987549e-2;
    constexpr double a41 = 2.95875854768068491816892993775e-2, a43 = 8.87627564304205475450678981324e-2;
    constexpr double a51 = 2.41365134159266685502369798665e-1, a53 = -8.84549479328286085344864962717e-1,
                     a54 = 9.24834003261792003115737966543e-1;
    constexpr double a61 = 3.7037037037037037037037037037e-2, a64 = 1.70828608729473871279604482173e-1,
                     a65 = 1.25467687566822425016691814123e-1;
    constexpr double a71 = 3.7109375e-2, a74 = 1.70252211019544039314978060272e-1,
                     a75 = 6.02165389804559606850219397283e-2, a76 = -1.7578125e-2;
    constexpr double a81 = 3.70920001185047927108779319836e-2, a84 = 1.70383925712239993810214054705e-1,
                     a85 = 1.07262030446373284651809199168e-1, a86 = -1.53194377486244017527936158236e-2,
                     a87 = 8.27378916381402288758473766002e-3;
    constexpr double a91 = 6.24110958716075717114429577812e-1, a94 = -3.36089262944694129406857109825e0,
                     a95 = -8.68219346841726006818189891453e-1, a96 = 2.75920996994467083049415600797e1,
                     a97 = 2.01540675504778934086186788979e1, a98 = -4.34898841810699588477366255144e1;
    constexpr double a101 = 4.77662536438264365890433908527e-1, a104 = -2.48811461997166764192642586468e0,
                     a105 = -5.90290826836842996371446475743e-1, a106 = 2.12300514481811942347288949897e1,
                     a107 = 1.52792336328824235832596922938e1, a108 = -3.32882109689848629194453265587e1,
                     a109 = -2.03312017085086261358222928593e-2;
    constexpr double a111 = -9.3714243008598732571704021658e-1, a114 = 5.18637242884406370830023853209e0,
                     a115 = 1.09143734899672957818500254654e0, a116 = -8.14978701074692612513997267357e0,
                     a117 = -1.85200656599969598641566180701e1, a118 = 2.27394870993505042818970056734e1,
                     a119 = 2.49360555267965238987089396762e0, a1110 = -3.0467644718982195003823669022e0;
    constexpr double a121 = 2.27331014751653820792359768449e0, a124 = -1.05344954667372501984066689879e1,
                     a125 = -2.00087205822486249909675718444e0, a126 = -1.79589318631187989172765950534e1,
                     a127 = 2.79488845294199600508499808837e1, a128 = -2.85899827713502369474065508674e0,
                     a129 = -8.87285693353062954433549289258e0, a1210 = 1.23605671757943030647266201528e1,
                     a1211 = 6.43392746015763530355970484046e-1;
    constexpr double b1 = 5.42937341165687622380535766363e-2, b6 = 4.45031289275240888144113950566e0,
                     b7 = 1.89151789931450038304281599044e0, b8 = -5.8012039600105847814672114227e0,
                     b9 = 3.1116436695781989440891606237e-1, b10 = -1.52160949662516078556178806805e-1,
                     b11 = 2.01365400804030348374776537501e-1, b12 = 4.47106157277725905176885569043e-2;
    std::array<double, N> k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k11, k12, y1;
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, y1, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    f(t + c3 * h, y1, k3);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a41 * k1[i] + a43 * k3[i]);
    f(t + c4 * h, y1, k4);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a51 * k1[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + c5 * h, y1, k5);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a61 * k1[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + c6 * h, y1, k6);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a71 * k1[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    f(t + c7 * h, y1, k7);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a81 * k1[i] + a84 * k4[i] + a85 * k5[i] + a86 * k6[i] + a87 * k7[i]);
    f(t + c8 * h, y1, k8);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a91 * k1[i] + a94 * k4[i] + a95 * k5[i] + a96 * k6[i] + a97 * k7[i] + a98 * k8[i]);
    f(t + c9 * h, y1, k9);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a101 * k1[i] + a104 * k4[i] + a105 * k5[i] + a106 * k6[i] + a107 * k7[i] + a108 * k8[i] +
                            a109 * k9[i]);
    f(t + c10 * h, y1, k10);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a111 * k1[i] + a114 * k4[i] + a115 * k5[i] + a116 * k6[i] + a117 * k7[i] + a118 * k8[i] +
                            a119 * k9[i] + a1110 * k10[i]);
    f(t + c11 * h, y1, k11);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a121 * k1[i] + a124 * k4[i] + a125 * k5[i] + a126 * k6[i] + a127 * k7[i] + a128 * k8[i] +
                            a129 * k9[i] + a1210 * k10[i] + a1211 * k11[i]);
    f(t + h, y1, k12);
    if constexpr (Checked) {
        BENCH_UNROLL
        for (std::size_t i = 0; i < N; ++i)
            y1[i] = y[i] + h * (b1 * k1[i] + b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] + b10 * k10[i] +
                                b11 * k11[i] + b12 * k12[i]);
        if (!finite_state(sum(y1) + sum(k2) + sum(k3) + sum(k4) + sum(k5), y1, k2, k3, k4, k5)) return non_finite;
        y = y1;
        return ok;
    }
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y[i] += h * (b1 * k1[i] + b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] + b10 * k10[i] + b11 * k11[i] +
                     b12 * k12[i]);
    return ok;
}

/// Runge-Kutta-Fehlberg 7(8), the eighth-order solution only (Fehlberg 1968, NASA TR R-287, Table X).
/// Stage 11 feeds only the seventh-order solution and is skipped: 12 evaluations. Checked (`hand_checked`):
/// the new y into a local, it and k1 to k5 (weight 0) summed and tested, y written only if finite; returns 0
/// or non_finite.
template <bool Checked = false, std::size_t N, class F>
BENCH_HAND int rkf78(F f, std::array<double, N>& y, double t, double h) {
    constexpr double c2 = 2.0 / 27.0, c3 = 1.0 / 9.0, c4 = 1.0 / 6.0, c5 = 5.0 / 12.0, c6 = 0.5, c7 = 5.0 / 6.0,
                     c8 = 1.0 / 6.0, c9 = 2.0 / 3.0, c10 = 1.0 / 3.0;
    constexpr double a21 = 2.0 / 27.0;
    constexpr double a31 = 1.0 / 36.0, a32 = 1.0 / 12.0;
    constexpr double a41 = 1.0 / 24.0, a43 = 1.0 / 8.0;
    constexpr double a51 = 5.0 / 12.0, a53 = -25.0 / 16.0, a54 = 25.0 / 16.0;
    constexpr double a61 = 1.0 / 20.0, a64 = 1.0 / 4.0, a65 = 1.0 / 5.0;
    constexpr double a71 = -25.0 / 108.0, a74 = 125.0 / 108.0, a75 = -65.0 / 27.0, a76 = 125.0 / 54.0;
    constexpr double a81 = 31.0 / 300.0, a85 = 61.0 / 225.0, a86 = -2.0 / 9.0, a87 = 13.0 / 900.0;
    constexpr double a91 = 2.0, a94 = -53.0 / 6.0, a95 = 704.0 / 45.0, a96 = -107.0 / 9.0, a97 = 67.0 / 90.0, a98 = 3.0;
    constexpr double a101 = -91.0 / 108.0, a104 = 23.0 / 108.0, a105 = -976.0 / 135.0, a106 = 311.0 / 54.0,
                     a107 = -19.0 / 60.0, a108 = 17.0 / 6.0, a109 = -1.0 / 12.0;
    constexpr double a121 = 3.0 / 205.0, a126 = -6.0 / 41.0, a127 = -3.0 / 205.0, a128 = -3.0 / 41.0, a129 = 3.0 / 41.0,
                     a1210 = 6.0 / 41.0;
    constexpr double a131 = -1777.0 / 4100.0, a134 = -341.0 / 164.0, a135 = 4496.0 / 1025.0, a136 = -289.0 / 82.0,
                     a137 = 2193.0 / 4100.0, a138 = 51.0 / 82.0, a139 = 33.0 / 164.0, a1310 = 12.0 / 41.0, a1312 = 1.0;
    constexpr double b6 = 34.0 / 105.0, b7 = 9.0 / 35.0, b8 = 9.0 / 35.0, b9 = 9.0 / 280.0, b10 = 9.0 / 280.0,
                     b12 = 41.0 / 840.0, b13 = 41.0 / 840.0;
    std::array<double, N> k1, k2, k3, k4, k5, k6, k7, k8, k9, k10, k12, k13, y1;
    f(t, y, k1);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, y1, k2);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    f(t + c3 * h, y1, k3);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a41 * k1[i] + a43 * k3[i]);
    f(t + c4 * h, y1, k4);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a51 * k1[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + c5 * h, y1, k5);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a61 * k1[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + c6 * h, y1, k6);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a71 * k1[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    f(t + c7 * h, y1, k7);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a81 * k1[i] + a85 * k5[i] + a86 * k6[i] + a87 * k7[i]);
    f(t + c8 * h, y1, k8);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a91 * k1[i] + a94 * k4[i] + a95 * k5[i] + a96 * k6[i] + a97 * k7[i] + a98 * k8[i]);
    f(t + c9 * h, y1, k9);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a101 * k1[i] + a104 * k4[i] + a105 * k5[i] + a106 * k6[i] + a107 * k7[i] + a108 * k8[i] +
                            a109 * k9[i]);
    f(t + c10 * h, y1, k10);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a121 * k1[i] + a126 * k6[i] + a127 * k7[i] + a128 * k8[i] + a129 * k9[i] + a1210 * k10[i]);
    f(t, y1, k12);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a131 * k1[i] + a134 * k4[i] + a135 * k5[i] + a136 * k6[i] + a137 * k7[i] + a138 * k8[i] +
                            a139 * k9[i] + a1310 * k10[i] + a1312 * k12[i]);
    f(t + h, y1, k13);
    if constexpr (Checked) {
        BENCH_UNROLL
        for (std::size_t i = 0; i < N; ++i)
            y1[i] = y[i] + h * (b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] + b10 * k10[i] + b12 * k12[i] +
                                b13 * k13[i]);
        if (!finite_state(sum(y1) + sum(k1) + sum(k2) + sum(k3) + sum(k4) + sum(k5), y1, k1, k2, k3, k4, k5))
            return non_finite;
        y = y1;
        return ok;
    }
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y[i] += h * (b6 * k6[i] + b7 * k7[i] + b8 * k8[i] + b9 * k9[i] + b10 * k10[i] + b12 * k12[i] + b13 * k13[i]);
    return ok;
}

/// Velocity Verlet for x'' = a(x), with the acceleration at x kept between steps in `acc` (the caller sets
/// it to a(x0) before the first step), written kick-drift-kick: v_half = v + h/2 a, x <- x + h v_half,
/// a_new = a(x), v <- v_half + h/2 a_new. One evaluation per step, and three multiply-adds per component
/// (the form x + h v + h^2/2 a, then v + h/2 (a + a_new), takes five operations and two more constants:
/// kepler_verlet checked, x86-64 -O2, 58 instructions a step against 52 kick-drift-kick). f(t, x, acc).
template <class T, std::size_t N, class F>
BENCH_HAND void velocity_verlet(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, T t, T h) {
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

/// velocity_verlet, checked: the same updates into locals xn, vn, an; x, v and acc written only if the new
/// x and v are finite. a_new need not be tested: v_new = v_half + h/2 a_new is NaN or Inf whenever a_new is
/// (h/2 times an Inf is Inf, or NaN for h = 0). x_new must be: the force may map a non-finite x to a finite
/// acceleration. On failure x, v and acc are untouched.
template <class T, std::size_t N, class F>
BENCH_HAND int velocity_verlet_checked(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, T t, T h) {
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

// The rest of the Newtonian family, for x'' = a(t, x) with the force f(t, x, acc) written into acc: each
// update in place, its coefficient times h hoisted, one loop over the components per update (a kick and
// the drift after it share one).

/// Euler-Cromer (symplectic Euler, kick then drift): v <- v + h a(t, x), then x <- x + h v with the new v.
/// One evaluation per step, nothing kept.
template <class T, std::size_t N, class F>
BENCH_HAND void euler_cromer(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    std::array<T, N> acc;
    f(t, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += h * acc[i];
        x[i] += h * v[i];
    }
}

/// euler_cromer, checked: the same updates into locals xn, vn, written to x and v only if finite.
/// The step ends with a drift x += c v_new, so x_new[i] is finite only if v_new[i] is (c v_new[i] is NaN or
/// Inf for a NaN or Inf v_new[i], even for c = 0): testing x_new tests the whole new state.
template <class T, std::size_t N, class F>
BENCH_HAND int euler_cromer_checked(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    std::array<T, N> acc, xn, vn;
    f(t, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] = v[i] + h * acc[i];
        xn[i] = x[i] + h * vn[i];
    }
    if (!finite_state(sum(xn), xn)) return non_finite;
    x = xn;
    v = vn;
    return ok;
}

/// Position Verlet (leapfrog, drift-kick-drift): x <- x + h/2 v, v <- v + h a(t + h/2, x), x <- x + h/2 v.
/// One evaluation per step, nothing kept.
template <class T, std::size_t N, class F>
BENCH_HAND void position_verlet(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    const T h2 = h * T(0.5);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) x[i] += h2 * v[i];
    std::array<T, N> acc;
    f(t + h2, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += h * acc[i];
        x[i] += h2 * v[i];
    }
}

/// position_verlet, checked: the same updates into locals xn, vn, written to x and v only if finite.
/// The step ends with a drift x += c v_new, so x_new[i] is finite only if v_new[i] is (c v_new[i] is NaN or
/// Inf for a NaN or Inf v_new[i], even for c = 0): testing x_new tests the whole new state.
template <class T, std::size_t N, class F>
BENCH_HAND int position_verlet_checked(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    const T h2 = h * T(0.5);
    std::array<T, N> xn, vn, acc;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) xn[i] = x[i] + h2 * v[i];
    f(t + h2, xn, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] = v[i] + h * acc[i];
        xn[i] += h2 * vn[i];
    }
    if (!finite_state(sum(xn), xn)) return non_finite;
    x = xn;
    v = vn;
    return ok;
}

/// Forest-Ruth's coefficients (forest_ruth below), shared by forest_ruth and forest_ruth_checked: d the
/// drifts', k the kicks', c the kicks' times, each a fraction of h.
template <class T>
struct forest_ruth_coefficients {
    static constexpr long double cbrt2 = 1.259921049894873164767210607278228350570L;  // 2^(1/3)
    static constexpr long double gamma = 1.0L / (2.0L - cbrt2);
    static constexpr T d_outer = T(gamma / 2.0L), d_inner = T((1.0L - gamma) / 2.0L);
    static constexpr T k_outer = T(gamma), k_inner = T(1.0L - 2.0L * gamma);
    static constexpr T c1 = d_outer, c2 = d_outer + d_inner, c3 = d_outer + d_inner + d_inner;
};

/// Forest-Ruth (Forest & Ruth 1990), the fourth-order triple jump of position Verlet: drift gamma/2,
/// kick gamma, drift (1 - gamma)/2, kick 1 - 2 gamma, drift (1 - gamma)/2, kick gamma, drift gamma/2,
/// gamma = 1 / (2 - 2^(1/3)). The coefficients are computed in long double from 2^(1/3) to 40 digits and
/// rounded once to T, as odestep's detail::splitting_coefficients does; the time of each kick is the
/// drift coefficients before it, summed in T. Three evaluations per step, nothing kept.
template <class T, std::size_t N, class F>
BENCH_HAND void forest_ruth(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    using coefficients = forest_ruth_coefficients<T>;
    constexpr T d_outer = coefficients::d_outer, d_inner = coefficients::d_inner;
    constexpr T k_outer = coefficients::k_outer, k_inner = coefficients::k_inner;
    constexpr T c1 = coefficients::c1, c2 = coefficients::c2, c3 = coefficients::c3;
    const T hd_outer = d_outer * h, hd_inner = d_inner * h, hk_outer = k_outer * h, hk_inner = k_inner * h;
    std::array<T, N> acc;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) x[i] += hd_outer * v[i];
    f(t + c1 * h, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += hk_outer * acc[i];
        x[i] += hd_inner * v[i];
    }
    f(t + c2 * h, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += hk_inner * acc[i];
        x[i] += hd_inner * v[i];
    }
    f(t + c3 * h, x, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += hk_outer * acc[i];
        x[i] += hd_outer * v[i];
    }
}

/// forest_ruth, checked: the same seven updates into locals xn, vn, written to x and v only if finite.
/// The step ends with a drift x += c v_new, so x_new[i] is finite only if v_new[i] is (c v_new[i] is NaN or
/// Inf for a NaN or Inf v_new[i], even for c = 0): testing x_new tests the whole new state.
template <class T, std::size_t N, class F>
BENCH_HAND int forest_ruth_checked(F f, std::array<T, N>& x, std::array<T, N>& v, T t, T h) {
    using c = forest_ruth_coefficients<T>;
    const T hd_outer = c::d_outer * h, hd_inner = c::d_inner * h, hk_outer = c::k_outer * h, hk_inner = c::k_inner * h;
    std::array<T, N> xn, vn, acc;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) xn[i] = x[i] + hd_outer * v[i];
    f(t + c::c1 * h, xn, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] = v[i] + hk_outer * acc[i];
        xn[i] += hd_inner * vn[i];
    }
    f(t + c::c2 * h, xn, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] += hk_inner * acc[i];
        xn[i] += hd_inner * vn[i];
    }
    f(t + c::c3 * h, xn, acc);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] += hk_outer * acc[i];
        xn[i] += hd_outer * vn[i];
    }
    if (!finite_state(sum(xn), xn)) return non_finite;
    x = xn;
    v = vn;
    return ok;
}

/// Beeman's algorithm, with a_n in `acc` and a_{n-1} in `acc_prev` kept in the caller's variables:
///   x <- x + h v + h^2/6 (4 a_n - a_{n-1}),  a_{n+1} = a(t + h, x),  v <- v + h/6 (2 a_{n+1} + 5 a_n - a_{n-1}).
/// The caller sets acc = a(x0) and started = false before a run: the run's first step, which has no
/// a_{n-1}, is one velocity Verlet step (above), as odestep's beeman self-starts. One evaluation per step.
template <class T, std::size_t N, class F>
BENCH_HAND void beeman(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, std::array<T, N>& acc_prev,
                       bool& started, T t, T h) {
    if (!started) {
        started = true;
        acc_prev = acc;
        velocity_verlet(f, x, v, acc, t, h);
        return;
    }
    const T hh6 = h * h * (T(1) / T(6));
    const T h6 = h * (T(1) / T(6));
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) x[i] += h * v[i] + hh6 * (T(4) * acc[i] - acc_prev[i]);
    std::array<T, N> acc_new;
    f(t + h, x, acc_new);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) v[i] += h6 * (T(2) * acc_new[i] + T(5) * acc[i] - acc_prev[i]);
    acc_prev = acc;
    acc = acc_new;
}

/// beeman, checked: the same arithmetic into locals xn, vn, an; x, v, acc and acc_prev written only if the
/// new x and v are finite (a_new needs no test: v_new is NaN or Inf whenever it is, as in
/// velocity_verlet_checked). The first step is velocity_verlet_checked. On failure x, v, acc, acc_prev and
/// started are untouched. Returns 0 or non_finite.
template <class T, std::size_t N, class F>
BENCH_HAND int beeman_checked(F f, std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc,
                              std::array<T, N>& acc_prev, bool& started, T t, T h) {
    if (!started) {
        const std::array<T, N> a0 = acc;
        if (velocity_verlet_checked(f, x, v, acc, t, h) != ok) return non_finite;
        acc_prev = a0;
        started = true;
        return ok;
    }
    const T hh6 = h * h * (T(1) / T(6));
    const T h6 = h * (T(1) / T(6));
    std::array<T, N> xn, vn, an;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) xn[i] = x[i] + (h * v[i] + hh6 * (T(4) * acc[i] - acc_prev[i]));
    f(t + h, xn, an);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) vn[i] = v[i] + h6 * (T(2) * an[i] + T(5) * acc[i] - acc_prev[i]);
    if (!finite_state(sum(xn) + sum(vn), xn, vn)) return non_finite;
    x = xn;
    v = vn;
    acc_prev = acc;
    acc = an;
    return ok;
}

/// The derivatives a hand-written Adams-Bashforth 4 loop keeps: f of the last three steps, newest first
/// (past[0] = f_{n-1}, past[1] = f_{n-2}, past[2] = f_{n-3}), shifted down as a block after each step, so
/// that every read is at a fixed place (a ring of three costs the index arithmetic and the selects of its
/// three places on every step), and how many are known (below three, the step is RK4's, out of line:
/// adams_start). Lorenz AB4 checked, x86-64 -O2: 94.5 instructions a step with the ring and the start
/// inline, 76.2 now.
template <class T, std::size_t N>
struct ab4_history {
    std::array<std::array<T, N>, 3> past;
    int known = 0;
};

/// The history after a step: f_n in front, the others one place down (the oldest dropped).
template <class T, std::size_t N>
[[gnu::always_inline]] inline void shift_in(ab4_history<T, N>& hist, const std::array<T, N>& fn) {
    hist.past[2] = hist.past[1];
    hist.past[1] = hist.past[0];
    hist.past[0] = fn;
}

/// The first three steps of the Adams loops: RK4, and f(t, y) recorded (evaluated once more than RK4's own
/// evaluations, the first three steps only, as odestep's adams starts). Out of line, as a careful engineer
/// keeps a rare path: inlined, its stages' frame is every step's. Checked: f(t, y) tested too (only the
/// history reads it), and on failure y and hist untouched.
template <bool Checked, class T, std::size_t N, class F>
[[gnu::noinline]] int adams_start(F f, std::array<T, N>& y, ab4_history<T, N>& hist, T t, T h) {
    std::array<T, N> fn;
    f(t, y, fn);
    if constexpr (Checked) {
        std::array<T, N> yn = y;
        if (rk4_checked(f, yn, t, h) != ok || !finite_state(sum(fn), fn)) return non_finite;
        y = yn;
    } else {
        rk4(f, y, t, h);
    }
    shift_in(hist, fn);
    ++hist.known;
    return ok;
}

/// Four-step Adams-Bashforth, y <- y + h/24 (55 f_n - 59 f_{n-1} + 37 f_{n-2} - 9 f_{n-3}) with f_n = f(t, y)
/// evaluated here and the others kept in `hist`: one evaluation per step. While fewer than three are known
/// the step is adams_start's.
template <class T, std::size_t N, class F>
BENCH_HAND void adams_bashforth4(F f, std::array<T, N>& y, ab4_history<T, N>& hist, T t, T h) {
    if (__builtin_expect(hist.known < 3, 0)) {
        adams_start<false>(f, y, hist, t, h);
        return;
    }
    std::array<T, N> fn;
    f(t, y, fn);
    const T h24 = h * (T(1) / T(24));
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y[i] += h24 * (T(55) * fn[i] - T(59) * hist.past[0][i] + T(37) * hist.past[1][i] - T(9) * hist.past[2][i]);
    shift_in(hist, fn);
}

/// adams_bashforth4, checked: the new state into a local, its sum tested, then written with the
/// history; f_n needs no test of its own once the formula uses it (55 h/24 times a NaN or Inf is not
/// finite, nor is a sum with it). On failure y and hist are untouched.
template <class T, std::size_t N, class F>
BENCH_HAND int adams_bashforth4_checked(F f, std::array<T, N>& y, ab4_history<T, N>& hist, T t, T h) {
    if (__builtin_expect(hist.known < 3, 0)) return adams_start<true>(f, y, hist, t, h);
    std::array<T, N> fn;
    f(t, y, fn);
    std::array<T, N> yn;
    const T h24 = h * (T(1) / T(24));
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        yn[i] =
            y[i] + h24 * (T(55) * fn[i] - T(59) * hist.past[0][i] + T(37) * hist.past[1][i] - T(9) * hist.past[2][i]);
    if (!finite_state(sum(yn), yn)) return non_finite;
    y = yn;
    shift_in(hist, fn);
    return ok;
}

/// Adams-Bashforth-Moulton 4 in PECE mode, the history as adams_bashforth4's: predict
/// p = y + h/24 (55 f_n - 59 f_{n-1} + 37 f_{n-2} - 9 f_{n-3}), evaluate f(t + h, p), correct
/// y <- y + h/24 (9 f(t + h, p) + 19 f_n - 5 f_{n-1} + f_{n-2}). Two evaluations per step once started.
template <class T, std::size_t N, class F>
BENCH_HAND void adams_bashforth_moulton4(F f, std::array<T, N>& y, ab4_history<T, N>& hist, T t, T h) {
    if (__builtin_expect(hist.known < 3, 0)) {
        adams_start<false>(f, y, hist, t, h);
        return;
    }
    std::array<T, N> fn;
    f(t, y, fn);
    const std::array<T, N>& f1 = hist.past[0];
    const std::array<T, N>& f2 = hist.past[1];
    const std::array<T, N>& f3 = hist.past[2];
    const T h24 = h * (T(1) / T(24));
    std::array<T, N> p, fp;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        p[i] = y[i] + h24 * (T(55) * fn[i] - T(59) * f1[i] + T(37) * f2[i] - T(9) * f3[i]);
    f(t + h, p, fp);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h24 * (T(9) * fp[i] + T(19) * fn[i] - T(5) * f1[i] + f2[i]);
    shift_in(hist, fn);
}

/// adams_bashforth_moulton4, checked as adams_bashforth4_checked: the corrected y into a local, its sum
/// tested (f(t + h, p) and f_n enter it with non-zero weights), then written with the history.
template <class T, std::size_t N, class F>
BENCH_HAND int adams_bashforth_moulton4_checked(F f, std::array<T, N>& y, ab4_history<T, N>& hist, T t, T h) {
    if (__builtin_expect(hist.known < 3, 0)) return adams_start<true>(f, y, hist, t, h);
    std::array<T, N> fn;
    f(t, y, fn);
    const std::array<T, N>& f1 = hist.past[0];
    const std::array<T, N>& f2 = hist.past[1];
    const std::array<T, N>& f3 = hist.past[2];
    const T h24 = h * (T(1) / T(24));
    std::array<T, N> p, fp, yn;
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        p[i] = y[i] + h24 * (T(55) * fn[i] - T(59) * f1[i] + T(37) * f2[i] - T(9) * f3[i]);
    f(t + h, p, fp);
    BENCH_UNROLL
    for (std::size_t i = 0; i < N; ++i) yn[i] = y[i] + h24 * (T(9) * fp[i] + T(19) * fn[i] - T(5) * f1[i] + f2[i]);
    if (!finite_state(sum(yn), yn)) return non_finite;
    y = yn;
    shift_in(hist, fn);
    return ok;
}

}  // namespace bench::hand

#endif
