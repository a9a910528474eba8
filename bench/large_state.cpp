// SPDX-License-Identifier: BSL-1.0
// Large states (issue 27 item 1): RK4, Dormand-Prince 5(4) with its estimate and velocity Verlet at N = 2 .. 10,000 components, float and double,
// against a plain and a checked hand loop written so that GCC vectorizes them, on right-hand sides that
// vectorize themselves (y' = -k y; x'' = -w^2 x), so that the stepper's own loops are what is measured.
// Not a harness case (harness.hpp is one State per binary); run by `scripts/bench.sh --large`:
//   check        every variant 40 steps from the same start: same-method variants agree with odestep to
//                round-off, and every variant with the closed form to the method's truncation error
//   count        each variant's steps bracketed by Callgrind client requests (valgrind --tool=callgrind
//                --collect-atstart=no '--toggle-collect=large_*'): one dump per variant, size and type
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include <valgrind/callgrind.h>

#include <odestep/odestep.hpp>

#define LARGE_STEP __attribute__((noipa))
// The hand loops unrolled as bench/hand.hpp's (and odestep's, ODESTEP_STEP_UNROLL) are: at -O2 GCC 12
// unrolls nothing by itself, and at N = 8 the rolled loops cost up to twice the instructions.
#define LARGE_UNROLL _Pragma("GCC unroll 16")

namespace {

template <class T, std::size_t N>
using state = std::array<T, N>;

constexpr double decay_k = 0.5;    // y' = -k y
constexpr double spring_w2 = 4.0;  // x'' = -w^2 x

template <class T, std::size_t N>
struct decay {
    void operator()(T, const state<T, N>& y, state<T, N>& d) const noexcept {
        for (std::size_t i = 0; i < N; ++i) d[i] = T(-decay_k) * y[i];
    }
};
// Both forms of a force of position: odestep takes the in-place one where a callable offers both
// (system.hpp), as the hand loops do.
template <class T, std::size_t N>
struct spring {
    state<T, N> operator()(T, const state<T, N>& x) const noexcept {
        state<T, N> a;
        for (std::size_t i = 0; i < N; ++i) a[i] = T(-spring_w2) * x[i];
        return a;
    }
    void operator()(T, const state<T, N>& x, state<T, N>& a) const noexcept {
        for (std::size_t i = 0; i < N; ++i) a[i] = T(-spring_w2) * x[i];
    }
};

// The hand loops' finiteness test, written to vectorize: x is NaN or Inf exactly when its exponent bits
// are all ones, and then (bits & E) + (the exponent's lowest bit) carries into the sign bit; for any other
// x it does not. An OR of those sums over the components (integer AND, ADD, OR: no float reduction, no
// compare) has the sign bit set iff some component is not finite.
template <class T>
using bits_t = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
template <class T, std::size_t N>
inline bits_t<T> nonfinite_bits(bits_t<T> acc, const state<T, N>& a) noexcept {
    using U = bits_t<T>;
    constexpr int mant = std::numeric_limits<T>::digits - 1;  // 23 or 52
    constexpr U lowest = U(1) << mant;
    constexpr U exponent = ((U(1) << (sizeof(T) * 8 - 1)) - 1) & ~(lowest - 1);
    for (std::size_t i = 0; i < N; ++i) {
        U b;
        std::memcpy(&b, &a[i], sizeof b);
        acc |= (b & exponent) + lowest;
    }
    return acc;
}
template <class T>
inline bool bits_finite(bits_t<T> acc) noexcept {
    return (acc >> (sizeof(T) * 8 - 1)) == 0;
}

// ---- RK4: y' = -k y ----
template <class T, std::size_t N>
LARGE_STEP int large_rk4_odestep(state<T, N>& y, T t, T h) {
    return static_cast<int>(odestep::rk4<state<T, N>>{}.step(decay<T, N>{}, y, t, h));
}
template <class T, std::size_t N>
LARGE_STEP int large_rk4_odestep_unchecked(state<T, N>& y, T t, T h) {
    return static_cast<int>(odestep::unchecked_t<odestep::rk4<state<T, N>>>{}.step(decay<T, N>{}, y, t, h));
}
// Textbook RK4, one loop per stage input, h/2 and h/6 hoisted, the last loop updating y in place.
template <class T, std::size_t N>
LARGE_STEP int large_rk4_hand(state<T, N>& __restrict y, T t, T h) {
    const decay<T, N> f;
    const T h2 = h * T(0.5), h6 = h / T(6);
    state<T, N> k1, k2, k3, k4, in;
    f(t, y, k1);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h2 * k1[i];
    f(t + h2, in, k2);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h2 * k2[i];
    f(t + h2, in, k3);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h * k3[i];
    f(t + h, in, k4);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) y[i] += h6 * (k1[i] + T(2) * (k2[i] + k3[i]) + k4[i]);
    return 0;
}
// The same with odestep's guarantee: the new y into a local, tested (nonfinite_bits), copied to y only if
// every component is finite; else 1 and y untouched. (All four stages have non-zero weights, so a
// non-finite stage makes the new y non-finite: the new y alone is tested, as odestep does.)
template <class T, std::size_t N>
LARGE_STEP int large_rk4_hand_checked(state<T, N>& __restrict y, T t, T h) {
    const decay<T, N> f;
    const T h2 = h * T(0.5), h6 = h / T(6);
    state<T, N> k1, k2, k3, k4, in;
    f(t, y, k1);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h2 * k1[i];
    f(t + h2, in, k2);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h2 * k2[i];
    f(t + h2, in, k3);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h * k3[i];
    f(t + h, in, k4);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) in[i] = y[i] + h6 * (k1[i] + T(2) * (k2[i] + k3[i]) + k4[i]);
    if (!bits_finite<T>(nonfinite_bits<T, N>(0, in))) return 1;
    y = in;
    return 0;
}

// ---- Dormand-Prince 5(4) with its error estimate: y' = -k y ----
template <class T, std::size_t N>
LARGE_STEP int large_dp54_odestep(state<T, N>& y, state<T, N>& err, T t, T h) {
    return static_cast<int>(odestep::dormand_prince54<state<T, N>>{}.step(decay<T, N>{}, y, t, h, err));
}
template <class T, std::size_t N>
LARGE_STEP int large_dp54_odestep_unchecked(state<T, N>& y, state<T, N>& err, T t, T h) {
    return static_cast<int>(
        odestep::unchecked_t<odestep::dormand_prince54<state<T, N>>>{}.step(decay<T, N>{}, y, t, h, err));
}
// As dopri5.f (E. Hairer's coefficients, as bench/hand.hpp's dopri5), in T: the fifth-order solution is the
// seventh stage's input, err = h sum e_i k_i. Checked: y1, err and k2 (weight zero in both rows, so only
// the test sees it) tested by nonfinite_bits, y and err written only if all are finite.
template <bool Checked, class T, std::size_t N>
inline int dp54_hand(state<T, N>& __restrict y, state<T, N>& __restrict err_out, T t, T h) {
    const decay<T, N> f;
    const T c2 = T(0.2), c3 = T(0.3), c4 = T(0.8), c5 = T(8.0 / 9.0);
    const T a21 = T(0.2);
    const T a31 = T(3.0 / 40.0), a32 = T(9.0 / 40.0);
    const T a41 = T(44.0 / 45.0), a42 = T(-56.0 / 15.0), a43 = T(32.0 / 9.0);
    const T a51 = T(19372.0 / 6561.0), a52 = T(-25360.0 / 2187.0), a53 = T(64448.0 / 6561.0), a54 = T(-212.0 / 729.0);
    const T a61 = T(9017.0 / 3168.0), a62 = T(-355.0 / 33.0), a63 = T(46732.0 / 5247.0), a64 = T(49.0 / 176.0),
            a65 = T(-5103.0 / 18656.0);
    const T a71 = T(35.0 / 384.0), a73 = T(500.0 / 1113.0), a74 = T(125.0 / 192.0), a75 = T(-2187.0 / 6784.0),
            a76 = T(11.0 / 84.0);
    const T e1 = T(71.0 / 57600.0), e3 = T(-71.0 / 16695.0), e4 = T(71.0 / 1920.0), e5 = T(-17253.0 / 339200.0),
            e6 = T(22.0 / 525.0), e7 = T(-1.0 / 40.0);
    state<T, N> k1, k2, k3, k4, k5, k6, k7, y1, e;
    state<T, N>& err = Checked ? e : err_out;
    f(t, y, k1);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, y1, k2);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
    f(t + c3 * h, y1, k3);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
    f(t + c4 * h, y1, k4);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) y1[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
    f(t + c5 * h, y1, k5);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
    f(t + h, y1, k6);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        y1[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
    f(t + h, y1, k7);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i)
        err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
    if constexpr (Checked) {
        if (!bits_finite<T>(nonfinite_bits<T, N>(nonfinite_bits<T, N>(nonfinite_bits<T, N>(0, y1), err), k2))) return 1;
        err_out = err;
    }
    y = y1;
    return 0;
}
template <class T, std::size_t N>
LARGE_STEP int large_dp54_hand(state<T, N>& __restrict y, state<T, N>& __restrict err, T t, T h) {
    return dp54_hand<false, T, N>(y, err, t, h);
}
template <class T, std::size_t N>
LARGE_STEP int large_dp54_hand_checked(state<T, N>& __restrict y, state<T, N>& __restrict err, T t, T h) {
    return dp54_hand<true, T, N>(y, err, t, h);
}

// ---- velocity Verlet: x'' = -w^2 x, the acceleration at x kept by the caller ----
template <class T, std::size_t N>
LARGE_STEP int large_vv_odestep(state<T, N>& x, state<T, N>& v, state<T, N>& acc, T t, T h) {
    return static_cast<int>(odestep::velocity_verlet<state<T, N>>{}.step(spring<T, N>{}, x, v, acc, t, h));
}
template <class T, std::size_t N>
LARGE_STEP int large_vv_odestep_unchecked(state<T, N>& x, state<T, N>& v, state<T, N>& acc, T t, T h) {
    return static_cast<int>(
        odestep::unchecked_t<odestep::velocity_verlet<state<T, N>>>{}.step(spring<T, N>{}, x, v, acc, t, h));
}
// Kick-drift-kick in place, as bench/hand.hpp's velocity_verlet, with the force in place.
template <class T, std::size_t N>
LARGE_STEP int large_vv_hand(state<T, N>& __restrict x, state<T, N>& __restrict v, state<T, N>& __restrict acc, T t,
                             T h) {
    const spring<T, N> a;
    const T h2 = h * T(0.5);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        v[i] += h2 * acc[i];
        x[i] += h * v[i];
    }
    a(t + h, x, acc);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) v[i] += h2 * acc[i];
    return 0;
}
// The same into locals, x and v tested (the new acceleration need not be: v is non-finite whenever it is),
// x, v and acc written only if finite.
template <class T, std::size_t N>
LARGE_STEP int large_vv_hand_checked(state<T, N>& __restrict x, state<T, N>& __restrict v, state<T, N>& __restrict acc,
                                     T t, T h) {
    const spring<T, N> a;
    const T h2 = h * T(0.5);
    state<T, N> xn, vn, an;
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) {
        vn[i] = v[i] + h2 * acc[i];
        xn[i] = x[i] + h * vn[i];
    }
    a(t + h, xn, an);
    LARGE_UNROLL
    for (std::size_t i = 0; i < N; ++i) vn[i] += h2 * an[i];
    if (!bits_finite<T>(nonfinite_bits<T, N>(nonfinite_bits<T, N>(0, xn), vn))) return 1;
    x = xn;
    v = vn;
    acc = an;
    return 0;
}

// ---- the driver ----
template <class T>
const char* type_name() {
    return sizeof(T) == 4 ? "float" : "double";
}

template <class T, std::size_t N>
double rel_diff(const state<T, N>& a, const state<T, N>& b) {
    double m = 0;
    for (std::size_t i = 0; i < N; ++i) {
        const double d = std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
        m = d > m || d != d ? d : m;
    }
    return m;  // every component is of order 1
}

template <class T, std::size_t N>
struct rk4_case {
    using S = state<T, N>;
    using fn = int (*)(S&, T, T);
    static constexpr const char* keys[] = {"odestep", "odestep_unchecked", "hand", "hand_checked"};
    static constexpr fn fns[] = {large_rk4_odestep<T, N>, large_rk4_odestep_unchecked<T, N>, large_rk4_hand<T, N>,
                                 large_rk4_hand_checked<T, N>};
    static S start() {
        S y;
        for (std::size_t i = 0; i < N; ++i) y[i] = T(1) + T(static_cast<float>(i % 97) / 97.0f);
        return y;
    }
    static int run(fn f, S& y, int steps, T h) {
        int bad = 0;
        for (int s = 0; s < steps; ++s) bad |= f(y, static_cast<T>(s) * h, h);
        return bad;
    }
    static int check() {
        const T h = T(0.01);
        const int steps = 40;
        const double same_tol = sizeof(T) == 4 ? 1e-5 : 1e-12;
        const double method_tol = sizeof(T) == 4 ? 1e-5 : 1e-9;  // RK4 at kh = 0.005: 1e-12 relative
        S ref = start();
        for (std::size_t i = 0; i < N; ++i)
            ref[i] = static_cast<T>(static_cast<double>(ref[i]) * std::exp(-decay_k * 0.4));  // y0 e^{-k t}
        S y0{};
        int failures = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            S y = start();
            const int bad = run(fns[k], y, steps, h);
            if (k == 0) y0 = y;
            const double d_ref = rel_diff(y, ref), d_same = rel_diff(y, y0);
            const bool ok = bad == 0 && d_ref <= method_tol && d_same <= same_tol;
            failures += !ok;
            std::printf("CHECK\trk4\t%s\t%zu\t%s\t%s\tvs_exact=%.2e vs_odestep=%.2e\n", type_name<T>(), N, keys[k],
                        ok ? "ok" : "FAIL", d_ref, d_same);
        }
        // The guarantee: a step whose result is not finite leaves y as it was (checked variants only).
        for (std::size_t k : {std::size_t(0), std::size_t(3)}) {
            S y = start();
            y[N / 2] = std::numeric_limits<T>::infinity();
            const S before = y;
            const int st = fns[k](y, T(0), h);
            const bool ok = st != 0 && std::memcmp(&y, &before, sizeof y) == 0;
            failures += !ok;
            std::printf("CHECK\trk4\t%s\t%zu\t%s\t%s\tnon-finite step refused, y untouched\n", type_name<T>(), N,
                        keys[k], ok ? "ok" : "FAIL");
        }
        return failures;
    }
    static void count(int steps) {
        for (std::size_t k = 0; k < 4; ++k) {
            S y = start();
            run(fns[k], y, 2, T(0.01));
            y = start();
            CALLGRIND_ZERO_STATS;
            run(fns[k], y, steps, T(0.01));
            char name[96];
            std::snprintf(name, sizeof name, "rk4 %s %zu %s %d", type_name<T>(), N, keys[k], steps);
            CALLGRIND_DUMP_STATS_AT(name);
        }
    }
};

template <class T, std::size_t N>
struct dp54_case {
    using S = state<T, N>;
    using fn = int (*)(S&, S&, T, T);
    static constexpr const char* keys[] = {"odestep", "odestep_unchecked", "hand", "hand_checked"};
    static constexpr fn fns[] = {large_dp54_odestep<T, N>, large_dp54_odestep_unchecked<T, N>, large_dp54_hand<T, N>,
                                 large_dp54_hand_checked<T, N>};
    static int run(fn f, S& y, S& err, int steps, T h) {
        int bad = 0;
        for (int s = 0; s < steps; ++s) bad |= f(y, err, static_cast<T>(s) * h, h);
        return bad;
    }
    // The new y checked as RK4's (the estimate is of the order of round-off here, so not compared).
    static int check() {
        const T h = T(0.01);
        const int steps = 40;
        const double same_tol = sizeof(T) == 4 ? 1e-5 : 1e-12;
        const double method_tol = sizeof(T) == 4 ? 1e-5 : 1e-9;
        S ref = rk4_case<T, N>::start();
        for (std::size_t i = 0; i < N; ++i)
            ref[i] = static_cast<T>(static_cast<double>(ref[i]) * std::exp(-decay_k * 0.4));
        S y0{};
        int failures = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            S y = rk4_case<T, N>::start(), err{};
            const int bad = run(fns[k], y, err, steps, h);
            if (k == 0) y0 = y;
            const double d_ref = rel_diff(y, ref), d_same = rel_diff(y, y0);
            const bool ok = bad == 0 && d_ref <= method_tol && d_same <= same_tol;
            failures += !ok;
            std::printf("CHECK\tdp54\t%s\t%zu\t%s\t%s\tvs_exact=%.2e vs_odestep=%.2e\n", type_name<T>(), N, keys[k],
                        ok ? "ok" : "FAIL", d_ref, d_same);
        }
        for (std::size_t k : {std::size_t(0), std::size_t(3)}) {
            S y = rk4_case<T, N>::start(), err{};
            y[N / 2] = std::numeric_limits<T>::infinity();
            const S before = y, err_before = err;
            const int st = fns[k](y, err, T(0), h);
            const bool ok =
                st != 0 && std::memcmp(&y, &before, sizeof y) == 0 && std::memcmp(&err, &err_before, sizeof err) == 0;
            failures += !ok;
            std::printf("CHECK\tdp54\t%s\t%zu\t%s\t%s\tnon-finite step refused, y and err untouched\n", type_name<T>(),
                        N, keys[k], ok ? "ok" : "FAIL");
        }
        return failures;
    }
    static void count(int steps) {
        for (std::size_t k = 0; k < 4; ++k) {
            S y = rk4_case<T, N>::start(), err{};
            run(fns[k], y, err, 2, T(0.01));
            y = rk4_case<T, N>::start();
            CALLGRIND_ZERO_STATS;
            run(fns[k], y, err, steps, T(0.01));
            char name[96];
            std::snprintf(name, sizeof name, "dp54 %s %zu %s %d", type_name<T>(), N, keys[k], steps);
            CALLGRIND_DUMP_STATS_AT(name);
        }
    }
};

template <class T, std::size_t N>
struct vv_case {
    using S = state<T, N>;
    using fn = int (*)(S&, S&, S&, T, T);
    static constexpr const char* keys[] = {"odestep", "odestep_unchecked", "hand", "hand_checked"};
    static constexpr fn fns[] = {large_vv_odestep<T, N>, large_vv_odestep_unchecked<T, N>, large_vv_hand<T, N>,
                                 large_vv_hand_checked<T, N>};
    static void start(S& x, S& v, S& acc) {
        for (std::size_t i = 0; i < N; ++i) {
            x[i] = T(1) + T(static_cast<float>(i % 89) / 89.0f);
            v[i] = T(0);
        }
        spring<T, N>{}(T(0), x, acc);
    }
    static int run(fn f, S& x, S& v, S& acc, int steps, T h) {
        int bad = 0;
        for (int s = 0; s < steps; ++s) bad |= f(x, v, acc, static_cast<T>(s) * h, h);
        return bad;
    }
    static int check() {
        const T h = T(0.01);
        const int steps = 40;
        const double same_tol = sizeof(T) == 4 ? 1e-5 : 1e-12;
        // Velocity Verlet's global error on the oscillator, w = 2, h = 0.01 to t = 0.4: about
        // (w h)^2 w t / 24 |x0| = 1.3e-5 of the amplitude (amplitudes up to 2): 1e-4 leaves a margin.
        const double method_tol = 1e-4;
        S ref, v_ref, scratch;
        start(ref, v_ref, scratch);
        const double w = std::sqrt(spring_w2);
        for (std::size_t i = 0; i < N; ++i) ref[i] = static_cast<T>(static_cast<double>(ref[i]) * std::cos(w * 0.4));
        S x0{};
        int failures = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            S x, v, acc;
            start(x, v, acc);
            const int bad = run(fns[k], x, v, acc, steps, h);
            if (k == 0) x0 = x;
            const double d_ref = rel_diff(x, ref), d_same = rel_diff(x, x0);
            const bool ok = bad == 0 && d_ref <= method_tol && d_same <= same_tol;
            failures += !ok;
            std::printf("CHECK\tvv\t%s\t%zu\t%s\t%s\tvs_exact=%.2e vs_odestep=%.2e\n", type_name<T>(), N, keys[k],
                        ok ? "ok" : "FAIL", d_ref, d_same);
        }
        for (std::size_t k : {std::size_t(0), std::size_t(3)}) {
            S x, v, acc;
            start(x, v, acc);
            v[N / 2] = std::numeric_limits<T>::infinity();
            const S xb = x, vb = v, ab = acc;
            const int st = fns[k](x, v, acc, T(0), h);
            const bool ok = st != 0 && std::memcmp(&x, &xb, sizeof x) == 0 && std::memcmp(&v, &vb, sizeof v) == 0 &&
                            std::memcmp(&acc, &ab, sizeof acc) == 0;
            failures += !ok;
            std::printf("CHECK\tvv\t%s\t%zu\t%s\t%s\tnon-finite step refused, x, v, acc untouched\n", type_name<T>(), N,
                        keys[k], ok ? "ok" : "FAIL");
        }
        return failures;
    }
    static void count(int steps) {
        for (std::size_t k = 0; k < 4; ++k) {
            S x, v, acc;
            start(x, v, acc);
            run(fns[k], x, v, acc, 2, T(0.01));
            start(x, v, acc);
            CALLGRIND_ZERO_STATS;
            run(fns[k], x, v, acc, steps, T(0.01));
            char name[96];
            std::snprintf(name, sizeof name, "vv %s %zu %s %d", type_name<T>(), N, keys[k], steps);
            CALLGRIND_DUMP_STATS_AT(name);
        }
    }
};

template <class T, std::size_t N>
int one(bool counting) {
    // Enough steps that the count is exact per step at every size, few enough for Callgrind at N = 10,000.
    const int steps = N >= 1000 ? 4 : 64;
#ifdef LARGE_ONLY_VV
    // LARGE_ONLY_VV: velocity Verlet alone (a quicker build while working on the Newtonian steppers).
    if (counting) {
        vv_case<T, N>::count(steps);
        return 0;
    }
    return vv_case<T, N>::check();
#endif
    if (counting) {
        rk4_case<T, N>::count(steps);
        dp54_case<T, N>::count(steps);
        vv_case<T, N>::count(steps);
        return 0;
    }
    return rk4_case<T, N>::check() + dp54_case<T, N>::check() + vv_case<T, N>::check();
}

// LARGE_ONLY_N=n builds one size alone (scripts/perf_gate.sh: N = 1000 at -O2, a few seconds to compile).
template <class T>
int all_sizes(bool counting) {
#ifdef LARGE_ONLY_N
    return one<T, LARGE_ONLY_N>(counting);
#endif
    return one<T, 2>(counting) + one<T, 8>(counting) + one<T, 64>(counting) + one<T, 192>(counting) +
           one<T, 1000>(counting) + one<T, 10000>(counting);
}

}  // namespace

int main(int argc, char** argv) {
    const bool counting = argc > 1 && std::strcmp(argv[1], "count") == 0;
    if (argc > 1 && !counting && std::strcmp(argv[1], "check") != 0) {
        std::fprintf(stderr, "usage: %s check | count\n", argv[0]);
        return 2;
    }
    const int failures = all_sizes<float>(counting) + all_sizes<double>(counting);
    return failures == 0 ? 0 : 1;
}
