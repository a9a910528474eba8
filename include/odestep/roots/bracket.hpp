// SPDX-License-Identifier: BSL-1.0
// odestep: bracketing root finders (bisection, Illinois, Anderson-Bjorck, Brent, ITP), used by the event
// loop to narrow a sign change of an event function down to a time bracket.
#ifndef ODESTEP_ROOTS_BRACKET_HPP
#define ODESTEP_ROOTS_BRACKET_HPP

#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "../detail/ops.hpp"
#include "../state.hpp"

namespace odestep {

/// The result of narrowing a bracket: f(a) < 0 <= f(b), a < b.
template <class T>
struct root_bracket {
    T a;                      ///< the last point strictly on the negative side
    T fa;                     ///< f(a) < 0
    T b;                      ///< the first point on the non-negative side
    T fb;                     ///< f(b) >= 0 (may be exactly 0)
    std::size_t evaluations;  ///< calls of f made
    bool converged;           ///< b - a <= tol was reached within the cap
    bool failed;              ///< f returned NaN or Inf: the search stopped at once; a, b are the last valid bracket
};

// Every finder below is a type with
//
//     template <class T, class F>
//     static constexpr root_bracket<T> narrow(F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap);
//     template <class T>
//     static constexpr std::size_t worst_case_evaluations(T width, T tol);
//
// narrow's preconditions (the caller's): a < b, fa < 0 <= fb, tol > 0, all finite, and b - a finite.
// It calls f only at points strictly inside the bracket of the moment, at most `cap` times, and stops as
// soon as b - a <= tol (no call at all when that holds on entry). f(x) < 0 moves a to x, anything else
// (an exact zero, -0 included) moves b to x; after a zero at b the search goes on from the left until a is
// within tol of it. A NaN or +-Inf from f stops the search: failed = true and the bracket before that
// call. If tol is below the spacing of T at the root the search stops, unconverged, at two adjacent
// values (no point lies strictly between them). f is called as an lvalue with a T and must return T.
//
// worst_case_evaluations(b - a, tol) bounds the calls narrow makes when it converges (0 when
// width <= tol, SIZE_MAX for an infinite width or tol <= 0). The bounds count halvings in exact
// arithmetic; a midpoint rounded to T halves the width only up to half an ULP, which matters only when
// tol is within a few ULPs of the bracket's points.

namespace detail {

template <class T, class F>
inline constexpr bool nothrow_bracket_call_v = noexcept(T(std::declval<F&>()(std::declval<T>())));

/// ceil(log2(width / tol)) written as a count of halvings (std::log2 is not constexpr in C++17): the
/// number of bisection steps that take a bracket of that width down to tol.
template <class T>
constexpr std::size_t halvings(T width, T tol) noexcept {
    if (!(width > tol)) return 0;
    // (not is_finite: Inf * 0 is not a constant expression for g++)
    if (!(tol > T(0)) || !(width <= std::numeric_limits<T>::max())) return std::numeric_limits<std::size_t>::max();
    std::size_t n = 0;
    while (width > tol) {
        width /= T(2);
        ++n;
    }
    return n;
}

/// The point where the secant through (a, fa) and (b, fb), fa < 0 <= fb, crosses zero, interpolated from
/// the end with the smaller |f| (the more accurate side). Written as an endpoint plus a fraction of the
/// width in [0, 1], so nothing overflows for finite f; NaN if fb - fa is zero (scaled values underflowed).
template <class T>
ODESTEP_INLINE constexpr T false_position(T a, T fa, T b, T fb) noexcept {
    const T width = b - a;
    const T span = fb - fa;
    return -fa < fb ? a + width * (-fa / span) : b - width * (fb / span);
}

/// The loop every finder shares. Rule proposes a point, narrow_with evaluates f there and keeps the
/// bracket. A proposal that is not strictly inside (a, b) (or is NaN) is replaced by the midpoint; when
/// no midpoint lies strictly inside, the search stops.
///
/// Rules with `paced` set (the secant family: Illinois, Anderson-Bjorck, Brent) are also held to half of
/// bisection's rate: after n >= 1 calls the width must be at most w0 / 2^floor((n - 1) / 2) (w0 the initial
/// width), and while it is not, the next point is the midpoint. No step widens the bracket and a midpoint
/// halves it, so by induction the width after n >= 2 calls is at most w0 / 2^floor((n - 2) / 2): the search
/// converges within 2 n_b + 2 calls, n_b being bisection's count. (A stricter rule, "two steps of the
/// rule's own must halve the bracket or the next is a midpoint", breaks the Illinois cycle of two steps on
/// one side and then a jump across: on x^2 - 2 and e^x - 3 in double it took Illinois from 9 and 10 calls
/// to 19 and 21, Anderson-Bjorck from 7 and 8 to 19 and 21, and helped nowhere, so it is not used.)
///
/// Always inlined, as is each finder's narrow: the event loop's location has exactly one call of it, and
/// inlined there the bracket, the rule's state and f (a lambda over the re-step's buffers) live in the
/// location's own frame instead of a frame and a copied closure of their own (Cortex-M4F, RK4 with one event
/// whose action changes the state: 640 bytes of stack per tick otherwise, 488 inlined, float at -Os).
template <class T, class F, class Rule>
ODESTEP_INLINE constexpr root_bracket<T> narrow_with(F& f, T a, T fa, T b, T fb, T tol, std::size_t cap,
                                                     Rule rule) noexcept(nothrow_bracket_call_v<T, F>) {
    static_assert(is_scalar_v<T>, "odestep: the root finders work in float, double or long double");
    static_assert(std::is_invocable_v<F&, T>, "odestep: a root finder's f must be callable as f(T)");
    root_bracket<T> r{a, fa, b, fb, 0, false, false};
    T pace = b - a;  // w0 / 2^floor((n - 1) / 2) after n >= 1 calls
    bool force_midpoint = false;
    while (r.b - r.a > tol && r.evaluations < cap) {
        const T width = r.b - r.a;
        const T midpoint = r.a + width / T(2);
        if (!(r.a < midpoint && midpoint < r.b)) break;  // a and b are adjacent in T: tol is out of reach
        T x = midpoint;
        bool own = false;
        if (!force_midpoint) {
            const T proposal = rule.propose(r, tol, midpoint);
            if (r.a < proposal && proposal < r.b) {  // false for NaN
                x = proposal;
                own = true;
            }
        }
        const T fx = f(x);
        ++r.evaluations;
        if (!is_finite(fx)) {
            r.failed = true;
            return r;
        }
        if (fx < T(0)) {
            r.a = x;
            r.fa = fx;
        } else {
            r.b = x;
            r.fb = fx;
        }
        rule.accept(r, x, fx, own);
        if constexpr (Rule::paced) {
            if (r.evaluations > 1 && r.evaluations % 2 == 1) pace /= T(2);
            force_midpoint = r.b - r.a > pace;
        }
    }
    r.converged = r.b - r.a <= tol;
    return r;
}

/// The bound of the paced secant family: 2 n + 2 calls, n = bisection's count (see narrow_with).
template <class T>
constexpr std::size_t secant_family_worst_case(T width, T tol) noexcept {
    const std::size_t n = halvings(width, tol);
    if (n == 0) return 0;
    if (n > (std::numeric_limits<std::size_t>::max() - 2) / 2) return std::numeric_limits<std::size_t>::max();
    return 2 * n + 2;
}

// What Illinois, Anderson-Bjorck and Brent share: the pace rule's worst case.
struct paced_secant_family {
    /// The most calls of f `narrow` makes on a bracket of this width to reach tol (no cap).
    template <class T>
    static constexpr std::size_t worst_case_evaluations(T width, T tol) noexcept {
        return secant_family_worst_case(width, tol);
    }
};

template <class T>
struct bisection_rule {
    static constexpr bool paced = false;
    constexpr T propose(const root_bracket<T>&, T, T midpoint) const noexcept { return midpoint; }
    constexpr void accept(const root_bracket<T>&, T, T, bool) const noexcept {}
};

/// Regula falsi on working copies of f(a), f(b): when the new point falls on the same side as the point
/// before it, the value at the end that stayed is scaled down, by 1/2 (Illinois) or by
/// m = 1 - f(x) / f(previous point), 1/2 when m <= 0 (Anderson-Bjorck), so that the next secant reaches
/// past the root and both ends move. b counts as the point before the first (the papers' x2; for the event
/// loop it is the newer end). A point within tol/2 of an end is moved to tol/2 from it (as Brent does),
/// so that a secant that has found the root closes the bracket with one more call. After a forced midpoint
/// the working values restart from the true ones.
template <class T, bool Anderson_Bjorck>
struct false_position_rule {
    static constexpr bool paced = true;
    T ga, gb;            // working values at a and b
    T f_last;            // f at the last point
    bool last_negative;  // the last point was on the negative side (it is a)

    constexpr T propose(const root_bracket<T>& r, T tol, T) const noexcept {
        T x = false_position(r.a, ga, r.b, gb);
        const T margin = tol / T(2);
        if (x < r.a + margin) {
            x = r.a + margin;
        } else if (x > r.b - margin) {
            x = r.b - margin;
        }
        return x;  // NaN stays NaN: the caller bisects
    }

    constexpr void accept(const root_bracket<T>& r, T, T fx, bool own) noexcept {
        const bool negative = fx < T(0);
        if (!own) {
            ga = r.fa;
            gb = r.fb;
        } else if (negative == last_negative) {
            T m = T(0.5);
            if constexpr (Anderson_Bjorck) {
                if (f_last != T(0)) {
                    const T k = T(1) - fx / f_last;
                    if (k > T(0)) m = k;
                }
            }
            if (negative) {
                gb *= m;
            } else {
                ga *= m;
            }
        }
        if (negative) {
            ga = fx;
        } else {
            gb = fx;
        }
        f_last = fx;
        last_negative = negative;
    }
};

/// Brent's procedure zero, step for step, on its own names: b the point with the smaller |f|, c the other
/// end of the bracket, a the previous b; d the last step and e the one before. Inverse quadratic
/// interpolation through a, b, c (the secant when a == c), accepted only if it lands within 3/4 of the way
/// from b to c and moves less than half of e, else the midpoint; steps shorter than tol/2 become tol/2
/// towards c. Brent's own 2 eps |b| term is left out: the shared loop replaces a point that rounds onto
/// an end with the midpoint. Brent stops at f(b) == 0; here the search goes on with the step tol/2 from b
/// towards c.
template <class T>
struct brent_rule {
    static constexpr bool paced = true;
    T a, fa, b, fb, c, fc, d, e;

    constexpr T propose(const root_bracket<T>&, T tol, T) noexcept {
        if (abs_value(fc) < abs_value(fb)) {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        const T half_tol = tol / T(2);
        const T m = (c - b) / T(2);
        const T nudge = m > T(0) ? half_tol : -half_tol;
        if (fb == T(0)) {
            d = m;
            e = m;
            return b + nudge;
        }
        if (abs_value(e) < half_tol || abs_value(fa) <= abs_value(fb)) {
            d = m;
            e = m;
        } else {
            T s = fb / fa;
            T p = T(0);
            T q = T(0);
            if (a == c) {
                p = T(2) * m * s;
                q = T(1) - s;
            } else {
                q = fa / fc;
                const T t = fb / fc;
                p = s * (T(2) * m * q * (q - t) - (b - a) * (t - T(1)));
                q = (q - T(1)) * (t - T(1)) * (s - T(1));
            }
            if (p > T(0)) {
                q = -q;
            } else {
                p = -p;
            }
            s = e;
            e = d;
            if (T(2) * p < T(3) * m * q - abs_value(half_tol * q) && p < abs_value(T(0.5) * s * q)) {
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        }
        return b + (abs_value(d) > half_tol ? d : nudge);
    }

    constexpr void accept(const root_bracket<T>&, T x, T fx, bool own) noexcept {
        if (!own) {  // the loop bisected instead: book it as Brent's own bisection
            d = x - b;
            e = d;
        }
        a = b;
        fa = fb;
        b = x;
        fb = fx;
        if ((fb < T(0)) == (fc < T(0))) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
    }
};

/// One ITP step (interpolate, truncate, project), in the paper's notation with eps = tol / 2:
/// x_f the regula falsi point, delta = kappa1 (b - a)^kappa2, x_t = x_f moved delta towards the midpoint
/// (the midpoint itself if that is closer), then x_t projected onto the interval of radius
/// r = eps 2^(n_max - j) - (b - a) / 2 around the midpoint, n_max = n_1/2 + n0. With n0 = 1,
/// eps 2^(n_max - j) = tol 2^(n_1/2 - j), held as `reach` and halved after every call. r is never taken
/// below 0 (rounding could make it so after more calls than the bound), which leaves the midpoint.
/// delta is never taken below tol / 2: near the end kappa1 (b - a)^2 falls below the spacing of T, x_t
/// then rounds onto x_f or onto an end, and after an exact zero at b (x_f = b) every point would be the
/// midpoint (on x - cos x in double that cost 22 extra calls). The projection, which alone carries the
/// bound, is unchanged.
template <class T>
struct itp_rule {
    static constexpr bool paced = false;
    T width0;  // kappa1 = 0.2 / width0
    T reach;   // tol 2^(n_1/2 - j)

    constexpr T propose(const root_bracket<T>& r, T tol, T midpoint) const noexcept {
        const T width = r.b - r.a;
        const T xf = false_position(r.a, r.fa, r.b, r.fb);
        T delta = T(0.2) * (width / width0) * width;  // kappa1 (b - a)^2, kappa1 = 0.2 / width0
        if (delta < tol / T(2)) delta = tol / T(2);
        T radius = reach - width / T(2);
        if (!(radius > T(0))) radius = T(0);
        const T gap = midpoint - xf;  // sigma = sign(gap)
        T xt = midpoint;
        if (delta <= abs_value(gap)) xt = gap > T(0) ? xf + delta : xf - delta;  // false for NaN
        if (abs_value(xt - midpoint) <= radius) return xt;
        return gap > T(0) ? midpoint - radius : midpoint + radius;
    }

    constexpr void accept(const root_bracket<T>&, T, T, bool) noexcept { reach /= T(2); }
};

}  // namespace detail

/// Bisection: the midpoint a + (b - a) / 2 every time. The optimal worst case among bracketing methods,
/// and no better than it on any function: ceil(log2(width / tol)) calls.
struct bisection {
    /// The most calls of f `narrow` makes on a bracket of this width to reach tol (no cap).
    template <class T>
    static constexpr std::size_t worst_case_evaluations(T width, T tol) noexcept {
        return detail::halvings(width, tol);
    }

    /// Narrows [a, b] (f(a) fa < 0 <= fb = f(b)) until b - a <= tol or cap calls of f were made.
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(
        F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap) noexcept(detail::nothrow_bracket_call_v<T, F>) {
        return detail::narrow_with(f, a, fa, b, fb, tol, cap, detail::bisection_rule<T>{});
    }
};

/// The Illinois method: regula falsi that halves the value kept at an end when the new point falls on the
/// same side as the one before (Dowell & Jarratt, "A modified regula falsi method for computing the root
/// of an equation", BIT 11 (1971) 168-174; order 3^(1/3) ~ 1.44 per call at a simple root). Safeguarded:
/// at most 2 n + 2 calls, n = bisection's count.
struct illinois : detail::paced_secant_family {
    /// Narrows [a, b] (f(a) fa < 0 <= fb = f(b)) until b - a <= tol or cap calls of f were made.
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(
        F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap) noexcept(detail::nothrow_bracket_call_v<T, F>) {
        return detail::narrow_with(f, a, fa, b, fb, tol, cap, detail::false_position_rule<T, false>{fa, fb, fb, false});
    }
};

/// The Anderson-Bjorck method: as Illinois, but the kept value is scaled by m = 1 - f(x) / f(previous
/// point) (1/2 when m <= 0), which is what makes the next secant land near the root on a smooth function
/// (Anderson & Bjorck, "A new high order method of regula falsi type for computing a root of an
/// equation", BIT 13 (1973) 253-264). Safeguarded: at most 2 n + 2 calls, n = bisection's count.
struct anderson_bjorck : detail::paced_secant_family {
    /// Narrows [a, b] (f(a) fa < 0 <= fb = f(b)) until b - a <= tol or cap calls of f were made.
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(
        F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap) noexcept(detail::nothrow_bracket_call_v<T, F>) {
        return detail::narrow_with(f, a, fa, b, fb, tol, cap, detail::false_position_rule<T, true>{fa, fb, fb, false});
    }
};

/// Brent's method: inverse quadratic interpolation and secant steps with Brent's own bisection test
/// (R. P. Brent, "Algorithms for Minimization without Derivatives", Prentice-Hall 1973, chapter 4,
/// procedure zero). Brent's test alone allows about n^2 calls; with the loop's pace rule at most
/// 2 n + 2, n = bisection's count.
struct brent : detail::paced_secant_family {
    /// Narrows [a, b] (f(a) fa < 0 <= fb = f(b)) until b - a <= tol or cap calls of f were made.
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(
        F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap) noexcept(detail::nothrow_bracket_call_v<T, F>) {
        // Brent's start: b the newer end, c = a the other, d = e = b - a.
        return detail::narrow_with(f, a, fa, b, fb, tol, cap, detail::brent_rule<T>{a, fa, b, fb, a, fa, b - a, b - a});
    }
};

/// The ITP method (interpolate, truncate, project): a regula falsi point pulled towards the midpoint and
/// kept within a radius of it that shrinks so that the method never needs more than n_1/2 + n0 calls,
/// n_1/2 = bisection's count (I. F. D. Oliveira & R. H. C. Takahashi, "An Enhancement of the Bisection
/// Method Average Performance Preserving Minmax Optimality", ACM TOMS 47(1) (2020), article 5). The
/// parameters are those the paper suggests: kappa1 = 0.2 / (b - a) of the initial bracket, kappa2 = 2,
/// n0 = 1: at most one call more than bisection.
struct itp {
    /// The most calls of f `narrow` makes on a bracket of this width to reach tol (no cap).
    template <class T>
    static constexpr std::size_t worst_case_evaluations(T width, T tol) noexcept {
        const std::size_t n = detail::halvings(width, tol);
        if (n == 0 || n == std::numeric_limits<std::size_t>::max()) return n;
        return n + 1;  // n0 = 1
    }

    /// Narrows [a, b] (f(a) fa < 0 <= fb = f(b)) until b - a <= tol or cap calls of f were made.
    template <class T, class F>
    [[nodiscard]] ODESTEP_INLINE static constexpr root_bracket<T> narrow(
        F&& f, T a, T fa, T b, T fb, T tol, std::size_t cap) noexcept(detail::nothrow_bracket_call_v<T, F>) {
        // reach = tol 2^(n_1/2): the least tol 2^k >= b - a (k = 0 when the loop will make no call). Doubling
        // is exact; `reach > 0` guards a tol <= 0 against looping forever.
        const T width = b - a;
        T reach = tol;
        while (reach < width && reach > T(0)) reach *= T(2);
        return detail::narrow_with(f, a, fa, b, fb, tol, cap, detail::itp_rule<T>{width, reach});
    }
};

}  // namespace odestep

#endif
