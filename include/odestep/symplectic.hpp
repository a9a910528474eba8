// odestep: symplectic splitting (composition) methods for Newton's equations x'' = a(t, x), driven by
// constexpr coefficient tables, and the table library.
#ifndef ODESTEP_SYMPLECTIC_HPP
#define ODESTEP_SYMPLECTIC_HPP

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "newtonian.hpp"
#include "state.hpp"
#include "status.hpp"
#include "tableau.hpp"

namespace odestep {

/// A splitting method for x' = v, v' = a(t, x): the exact flows of the two halves, the drift
/// x <- x + h v (v fixed) and the kick v <- v + h a(t, x) (x fixed), composed with M coefficients each:
///
///     kick first:   for i = 1..M:  v <- v + b_i dt a(t + c_i dt, x);   x <- x + a_i dt v
///     drift first:  for i = 1..M:  x <- x + a_i dt v;   v <- v + b_i dt a(t + c_i dt, x)
///
/// with a = `drift`, b = `kick`, and c_i, the time of kick i, the sum of the drift coefficients applied
/// before it (time advances with the drifts). A zero coefficient is an update that is not made. Each flow
/// is symplectic when a depends on t and x only, so every such composition is symplectic; it is
/// symmetric (time-reversible) when the sequence of updates reads the same backwards.
template <class T, std::size_t M>
struct splitting_table {
    using value_type = T;
    static constexpr std::size_t size = M;

    bool kick_first = true;
    std::array<T, M> drift{};  // a_i
    std::array<T, M> kick{};   // b_i
    int order = 0;
    bool time_reversible = false;  // claimed; is_consistent checks it against the sequence
};

namespace detail {

// Update k of the sequence (k = 0 .. 2M-1): kick first, the even ones are kicks; drift first, the odd ones.
template <class T, std::size_t M>
constexpr bool is_kick_update(const splitting_table<T, M>& tab, std::size_t k) noexcept {
    return (k % 2 == 0) == tab.kick_first;
}
template <class T, std::size_t M>
constexpr T update_coefficient(const splitting_table<T, M>& tab, std::size_t k) noexcept {
    return is_kick_update(tab, k) ? tab.kick[k / 2] : tab.drift[k / 2];
}
template <class T, std::size_t M>
constexpr std::size_t first_update(const splitting_table<T, M>& tab) noexcept {
    for (std::size_t k = 0; k < 2 * M; ++k)
        if (update_coefficient(tab, k) != T(0)) return k;
    return 2 * M;
}
template <class T, std::size_t M>
constexpr std::size_t last_update(const splitting_table<T, M>& tab) noexcept {
    for (std::size_t k = 2 * M; k-- > 0;)
        if (update_coefficient(tab, k) != T(0)) return k;
    return 2 * M;
}

/// The updates made, in order, are the same read backwards (same kind, same coefficient, exactly): then
/// the step with -dt undoes the step with dt, update by update.
template <class T, std::size_t M>
constexpr bool is_palindrome(const splitting_table<T, M>& tab) noexcept {
    const std::size_t first = first_update(tab);
    const std::size_t last = last_update(tab);
    if (first > last || last >= 2 * M) return false;
    for (std::size_t i = 0; first + i <= last; ++i) {
        const std::size_t k = first + i;
        const std::size_t mirror = last - i;
        if (is_kick_update(tab, k) != is_kick_update(tab, mirror)) return false;
        if (update_coefficient(tab, k) != update_coefficient(tab, mirror)) return false;
    }
    return true;
}

}  // namespace detail

/// The drift coefficients and the kick coefficients each sum to 1 (to a few rounding errors of T), the
/// order is given, and the table is time-reversible exactly when it claims so.
template <class T, std::size_t M>
constexpr bool is_consistent(const splitting_table<T, M>& tab) noexcept {
    return detail::sums_to(tab.drift, M, T(1)) && detail::sums_to(tab.kick, M, T(1)) && tab.order >= 1 &&
           tab.time_reversible == detail::is_palindrome(tab);
}

namespace detail {

// What the stepper needs to know of a table, at compile time.
template <class Method, class T>
struct splitting_plan {
    static constexpr auto tab = Method::template table<T>;
    using table_type = std::remove_const_t<decltype(tab)>;
    static constexpr std::size_t M = table_type::size;
    static constexpr std::size_t updates = 2 * M;
    static constexpr std::size_t first = first_update(tab);
    static constexpr std::size_t last = last_update(tab);

    static constexpr bool is_kick(std::size_t k) noexcept { return is_kick_update(tab, k); }
    static constexpr T coefficient(std::size_t k) noexcept { return update_coefficient(tab, k); }

    static constexpr std::size_t count_kicks() noexcept {
        std::size_t n = 0;
        for (std::size_t k = 0; k < updates; ++k) n += (is_kick(k) && coefficient(k) != T(0)) ? 1U : 0U;
        return n;
    }
    static constexpr std::size_t kicks = count_kicks();

    /// First same as last: the step begins with a kick at x_n and ends with a kick at x_{n+1}, so the
    /// acceleration of the last kick of one step is that of the first kick of the next.
    static constexpr bool fsal = kicks >= 2 && first < updates && is_kick(first) && is_kick(last);

    /// A drift (a kick) with a coefficient not zero comes before update k.
    static constexpr bool drift_before(std::size_t k) noexcept {
        for (std::size_t j = 0; j < k; ++j)
            if (!is_kick(j) && coefficient(j) != T(0)) return true;
        return false;
    }
    static constexpr bool kick_before(std::size_t k) noexcept {
        for (std::size_t j = 0; j < k; ++j)
            if (is_kick(j) && coefficient(j) != T(0)) return true;
        return false;
    }

    /// c for update k: the drift coefficients before it, summed.
    static constexpr T time_fraction(std::size_t k) noexcept {
        T c = T(0);
        for (std::size_t j = 0; j < k; ++j)
            if (!is_kick(j)) c += coefficient(j);
        return c;
    }
};

// The cached acceleration of a first-same-as-last method: a(t, *x), valid while the next step starts on
// the same position object at that time (detail::continuation, as the history-keeping steppers use).
template <class State, bool Fsal>
struct splitting_cache {};
template <class State>
struct splitting_cache<State, true> {
    State acceleration{};
    continuation<State> next{};
};

}  // namespace detail

/// A step of a symplectic splitting method for x'' = a(t, x) from the table `Method::table<T>`, with
/// position and velocity as two states, advanced in place.
///
/// The sequence of drifts and kicks is unrolled at compile time: a zero coefficient emits nothing. The
/// force must be of position alone, `State a(T t, const State& x)` (a velocity-dependent force does not
/// compile): only then is each kick an exact, symplectic flow.
///
/// First same as last (velocity Verlet, leapfrog, Blanes-Moan): the acceleration of a step's last kick,
/// a(t + dt, x_{n+1}), is kept with that time and the address of the x it belongs to, and serves as the
/// first kick's acceleration of the next step when that step is called with the same x object at the
/// same time. "The same time" allows the rounding of the run's times (detail::continuation): `integrate`
/// calls step n+1 at t0 + (n+1) dt from its counter, which differs from the fl(t + dt) of step n in the
/// last bits about one step in three. (For a force that depends on t, the kept value is then a at a time a few ULPs off.)
/// Velocity Verlet thus costs one evaluation of a per step, stepping forward or back (-dt). A failed step
/// keeps the acceleration it had. What the stepper cannot see is a change made to x between two steps,
/// or to the force itself (a parameter of the functor, a control input): call `reset()` after changing x
/// or v outside the stepper (an event, a correction, a new initial state in the same object) or changing
/// the force, and the next step evaluates afresh. One stepper can step several states, correctly, but
/// each step then evaluates afresh: give each state its own stepper. The other tables keep no state at
/// all, and their step is const.
template <class Method, class State>
class splitting {
public:
    using state_type = State;
    using value_type = value_type_t<State>;
    using method_type = Method;

private:
    using T = value_type;
    using plan = detail::splitting_plan<Method, T>;
    static_assert(is_consistent(plan::tab),
                  "odestep: the table's drift or kick coefficients do not sum to 1, or its time_reversible claim "
                  "does not match its sequence of updates");
    static_assert(plan::kicks >= 1, "odestep: a splitting table needs at least one kick");
    static constexpr std::size_t N = state_traits<State>::size;
    static constexpr bool fsal = plan::fsal;
    static constexpr bool ends_with_kick = plan::is_kick(plan::last);
    // The first update is a kick that evaluates the force (not a kept acceleration): see advance.
    static constexpr bool lazy_velocity = plan::is_kick(plan::first) && !fsal;

public:
    static constexpr int order = plan::tab.order;
    /// Kicks per step.
    static constexpr std::size_t stages = plan::kicks;
    /// Evaluations of a in one step, the most it makes (first same as last: the first step, or the first
    /// after reset(); the others make one fewer).
    static constexpr std::size_t accelerations_per_step = plan::kicks;
    static constexpr std::size_t rhs_evals_per_step = plan::kicks;
    static constexpr bool first_same_as_last = fsal;
    static constexpr bool symplectic = true;
    static constexpr bool time_reversible = plan::tab.time_reversible;
    static constexpr bool self_starting = true;
    static constexpr bool error_estimate = false;

    /// (x, v) <- (x, v)(t + dt). On `status::non_finite` x and v are left exactly as they were.
    template <class Accel, bool F = fsal, std::enable_if_t<!F, int> = 0>
    [[nodiscard]] status step(Accel&& a, State& x, State& v, T t, T dt) const {
        return advance(a, x, v, t, dt, nullptr, nullptr);
    }

    /// As above; the acceleration of the last kick is kept for the next step (not when the step fails).
    template <class Accel, bool F = fsal, std::enable_if_t<F, int> = 0>
    [[nodiscard]] status step(Accel&& a, State& x, State& v, T t, T dt) {
        const bool hit = cache_.next.at(t, x);
        if (!hit) {
            cache_.next.clear();  // until a step succeeds, the kept value belongs to no step
            cache_.acceleration = detail::acceleration(a, t, x);
        }
        State last;
        const status s = advance(a, x, v, t, dt, &cache_.acceleration, &last);
        if (s == status::ok) {
            assign(cache_.acceleration, last);  // evaluated at t + dt, where the next step starts
            cache_.next.expect(t, dt, x, hit);
        }
        return s;
    }

    /// The first-same-as-last step for a caller who keeps the acceleration, as a hand-written loop does:
    /// on entry `acc` is a(t, x) (evaluate it once, `acc = a(t0, x0)`, before the first step; again after
    /// changing x outside the stepper); on status::ok it is a(t + dt, x) of the new x, the next step's
    /// entry value. The stepper keeps and checks nothing, so this form has no continuation test: one
    /// evaluation of a per step, always, and the step is const (one stepper serves any number of states).
    /// On status::non_finite x, v and acc are left exactly as they were. acc is an object of its own (not
    /// x or v).
    template <class Accel, bool F = fsal, std::enable_if_t<F, int> = 0>
    [[nodiscard]] status step(Accel&& a, State& x, State& v, State& acc, T t, T dt) const {
        State last;
        const status s = advance(a, x, v, t, dt, &acc, &last);
        if (s == status::ok) assign(acc, last);
        return s;
    }

    /// Forgets the kept acceleration, so the next step evaluates a afresh. Call it after changing x or v
    /// outside the stepper, or the force. A no-op for the tables that keep nothing.
    constexpr void reset() noexcept {
        if constexpr (fsal) cache_.next.clear();
    }

private:
    detail::splitting_cache<State, fsal> cache_{};

    // The step: the splitting of x' = v, v' = a(t, x) into the drift (x' = v, v' = 0) and the kick (x' = 0,
    // v' = a(t, x)), each solved exactly, applied in the table's order with its coefficients times dt (see
    // splitting_table), into new x and v that replace them only when every component is finite.
    template <class Accel>
    ODESTEP_INLINE static status advance(Accel& a, State& x, State& v, T t, T dt, const State* cached, State* last) {
        // Two objects, not one struct: the force sees the position's address, and a velocity in the same
        // object would then have to be stored before, and reloaded after, every evaluation not inlined.
        // No up-front copy of x: a kick before any drift evaluates the force at the caller's x, unchanged.
        // Nor of v when a force evaluation comes first (lazy_velocity): a value read before a call not
        // inlined is held across it, at -Os on the stack (7 instructions a step, x86 Euler-Cromer). Else v
        // is read before any evaluation anyway; the copy costs no more (fewer bytes on Cortex-M0+). Every
        // table has a drift and a kick, so wx and wv are written in full before the test below.
        State wx;
        State wv;
        if constexpr (!lazy_velocity) assign(wv, v);
        run(a, x, v, wx, wv, t, dt, cached, last, std::make_index_sequence<plan::updates>{});
        // The finiteness test's sum (detail::finite_sum) of the new x and v, x's components first: any order
        // serves (only a sum that fails goes on to the exact test), and this one needs the fewest register
        // copies where the force has just taken x apart.
        //
        // A step that ends with a drift, x <- x + h v with h = c dt and v already final, needs x alone: for
        // a v component that is +-Inf or NaN, h v is +-Inf or NaN (h = 0 included: 0 Inf is NaN), and so is
        // x plus it, whatever x. So a finite new x proves the new v finite, and half the test goes.
        T total = -T(0);  // x + (-0) is x, exactly: the compiler drops that first addition
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) total += wx[n];
        if constexpr (ends_with_kick) {
            ODESTEP_UNROLL
            for (std::size_t n = 0; n < N; ++n) total += wv[n];
        }
        if (!detail::finite_sum(total) && !(detail::each_finite(wx) && (!ends_with_kick || detail::each_finite(wv))))
            return status::non_finite;
        assign(x, wx);
        assign(v, wv);
        return status::ok;
    }

    template <class Accel, std::size_t... K>
    ODESTEP_INLINE static void run(Accel& a, const State& x, const State& v, State& wx, State& wv, T t, T dt,
                                   const State* cached, State* last, std::index_sequence<K...>) {
        (update<K>(a, x, v, wx, wv, t, dt, cached, last), ...);
    }

    // Update K of the sequence, emitted only when its coefficient is not zero.
    template <std::size_t K, class Accel>
    ODESTEP_INLINE static void update(Accel& a, const State& x, const State& v, State& wx, State& wv, T t, T dt,
                                      const State* cached, State* last) {
        constexpr T c = plan::coefficient(K);
        if constexpr (c != T(0)) {
            const T h = scaled<K>(dt);
            // What update K starts from: the caller's x until a drift is made; with lazy_velocity, the
            // caller's v until a kick is made (without, wv is v's copy from the start).
            const State& px = plan::drift_before(K) ? wx : x;
            const State& pv = (!lazy_velocity || plan::kick_before(K)) ? wv : v;
            if constexpr (!plan::is_kick(K)) {
                ODESTEP_UNROLL
                for (std::size_t n = 0; n < N; ++n) wx[n] = px[n] + h * pv[n];
            } else if constexpr (fsal && K == plan::first) {
                if (cached != nullptr) {
                    kick(wv, pv, *cached, h);
                } else {
                    kick(wv, pv, detail::acceleration(a, t, px), h);
                }
            } else if constexpr (fsal && K == plan::last) {
                *last = detail::acceleration(a, t + dt, px);  // at x_{n+1}: kept for the next step
                kick(wv, pv, *last, h);
            } else {
                kick(wv, pv, detail::acceleration(a, kick_time<K>(t, dt), px), h);
            }
        }
    }

    // to = from + h acc, component by component (from may be to).
    ODESTEP_INLINE static void kick(State& to, const State& from, const State& acc, T h) noexcept {
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) to[n] = from[n] + h * acc[n];
    }

    // c_K dt for update K, without the multiplication when c_K is 1.
    template <std::size_t K>
    static constexpr T scaled(T dt) noexcept {
        constexpr T c = plan::coefficient(K);
        if constexpr (c == T(1)) {
            return dt;
        } else {
            return c * dt;
        }
    }
    // t + c dt, the time of kick K, with c the drift coefficients before it, summed.
    template <std::size_t K>
    static constexpr T kick_time(T t, T dt) noexcept {
        constexpr T c = plan::time_fraction(K);
        if constexpr (c == T(0)) {
            return t;
        } else if constexpr (c == T(1)) {
            return t + dt;
        } else {
            return t + c * dt;
        }
    }

    // Component by component, as explicit_rk does (a small array assigned whole can become an integer move).
    ODESTEP_INLINE static void assign(State& to, const State& from) noexcept {
        ODESTEP_UNROLL
        for (std::size_t n = 0; n < N; ++n) to[n] = from[n];
    }
};

namespace detail::splitting_coefficients {
// Computed once in long double and rounded once to the table's T. (Not templated: the long double
// literals here never meet a float.)

// 2^(1/3), to 40 digits.
inline constexpr long double cbrt2 = 1.259921049894873164767210607278228350570L;
// Forest & Ruth's gamma = 1 / (2 - 2^(1/3)), also Yoshida's (1990) fourth-order triple-jump weight.
inline constexpr long double fr_gamma = 1.0L / (2.0L - cbrt2);
inline constexpr long double fr_drift_outer = fr_gamma / 2.0L;           // gamma / 2
inline constexpr long double fr_drift_inner = (1.0L - fr_gamma) / 2.0L;  // (1 - gamma) / 2 = -(2^(1/3) - 1) gamma / 2
inline constexpr long double fr_kick_inner = 1.0L - 2.0L * fr_gamma;     // 1 - 2 gamma = -2^(1/3) gamma

// Yoshida's solution A (see yoshida6 below).
inline constexpr long double y6_w1 = -1.17767998417887100694641568096431573L;
inline constexpr long double y6_w2 = 0.235573213359358133684793182978534602L;
inline constexpr long double y6_w3 = 0.784513610477557263819497633866349876L;
inline constexpr long double y6_w0 = 1.0L - 2.0L * (y6_w1 + y6_w2 + y6_w3);
// The drifts of the merged position-Verlet steps: half of each pair of neighbouring weights.
inline constexpr long double y6_d1 = y6_w3 / 2.0L;
inline constexpr long double y6_d2 = (y6_w3 + y6_w2) / 2.0L;
inline constexpr long double y6_d3 = (y6_w2 + y6_w1) / 2.0L;
inline constexpr long double y6_d4 = (y6_w1 + y6_w0) / 2.0L;

// Blanes & Moan's SRKN_6^b (see blanes_moan4 below), as published; a3 and b4 from the sum conditions.
inline constexpr long double bm_a1 = 0.245298957184271L;
inline constexpr long double bm_a2 = 0.604872665711080L;
inline constexpr long double bm_a3 = 0.5L - (bm_a1 + bm_a2);
inline constexpr long double bm_b1 = 0.0829844064174052L;
inline constexpr long double bm_b2 = 0.396309801498368L;
inline constexpr long double bm_b3 = -0.0390563049223486L;
inline constexpr long double bm_b4 = 1.0L - 2.0L * (bm_b1 + bm_b2 + bm_b3);
}  // namespace detail::splitting_coefficients

/// The table library. Each method is a tag type whose `table<T>` is a constexpr splitting table in T.
namespace splittings {

/// Euler-Cromer, symplectic Euler with the kick first (Cromer 1981, "Stable solutions using the Euler
/// approximation", Am. J. Phys. 49, 455-459; Hairer, Lubich & Wanner, Geometric Numerical Integration
/// (HLW), Sect. VI.3):  v_{n+1} = v_n + dt a(t_n, x_n),  x_{n+1} = x_n + dt v_{n+1}.  Order 1; not
/// symmetric (its adjoint is the drift-first form below).
struct euler_cromer {
    static constexpr const char* name = "Euler-Cromer (symplectic Euler, kick then drift)";
    template <class T>
    static constexpr splitting_table<T, 1> table{true, {T(1)}, {T(1)}, 1, false};
};

/// Symplectic Euler with the drift first, the adjoint of Euler-Cromer (HLW, Sect. VI.3, the other
/// variant):  x_{n+1} = x_n + dt v_n,  v_{n+1} = v_n + dt a(t_n + dt, x_{n+1}).  Order 1; not symmetric.
struct euler_cromer_drift_first {
    static constexpr const char* name = "symplectic Euler, drift then kick (adjoint Euler-Cromer)";
    template <class T>
    static constexpr splitting_table<T, 1> table{false, {T(1)}, {T(1)}, 1, false};
};

/// Velocity Verlet = leapfrog in kick-drift-kick form (Verlet 1967, Phys. Rev. 159, 98; Swope, Andersen,
/// Berens & Wilson 1982, J. Chem. Phys. 76, 637; HLW Sect. VI.3):
///     v_{n+1/2} = v_n + dt/2 a(t_n, x_n),  x_{n+1} = x_n + dt v_{n+1/2},  v_{n+1} = v_{n+1/2} + dt/2 a(t_{n+1}, x_{n+1}),
/// that is x_{n+1} = x_n + dt v_n + dt^2/2 a_n and v_{n+1} = v_n + dt/2 (a_n + a_{n+1}). Order 2, symmetric;
/// first same as last: one evaluation of a per step.
struct velocity_verlet {
    static constexpr const char* name = "velocity Verlet (leapfrog, kick-drift-kick)";
    template <class T>
    static constexpr splitting_table<T, 2> table{true, {T(1), T(0)}, {T(1) / T(2), T(1) / T(2)}, 2, true};
};

/// Position Verlet, leapfrog in drift-kick-drift form (HLW Sect. VI.3, the adjoint splitting):
///     x_{n+1/2} = x_n + dt/2 v_n,  v_{n+1} = v_n + dt a(t_n + dt/2, x_{n+1/2}),  x_{n+1} = x_{n+1/2} + dt/2 v_{n+1}.
/// Order 2, symmetric; one evaluation of a per step, no state.
struct position_verlet {
    static constexpr const char* name = "position Verlet (leapfrog, drift-kick-drift)";
    template <class T>
    static constexpr splitting_table<T, 2> table{false, {T(1) / T(2), T(1) / T(2)}, {T(1), T(0)}, 2, true};
};

/// Forest-Ruth, the fourth-order triple jump of position Verlet with gamma = 1 / (2 - 2^(1/3)) (Forest &
/// Ruth 1990, "Fourth-order symplectic integration", Physica D 43, 105-117; found independently by Candy &
/// Rozmus 1991, J. Comput. Phys. 92, 230, and by Yoshida 1990, Phys. Lett. A 150, 262, as the composition
/// S(gamma dt) S((1 - 2 gamma) dt) S(gamma dt) of a second-order S):
///     drift gamma/2, kick gamma, drift (1-gamma)/2, kick 1-2gamma, drift (1-gamma)/2, kick gamma, drift gamma/2.
/// Order 4, symmetric; three evaluations of a per step, no state.
struct forest_ruth {
    static constexpr const char* name = "Forest-Ruth 4th order";
    template <class T>
    static constexpr splitting_table<T, 4> table{
        false,
        {T(detail::splitting_coefficients::fr_drift_outer), T(detail::splitting_coefficients::fr_drift_inner),
         T(detail::splitting_coefficients::fr_drift_inner), T(detail::splitting_coefficients::fr_drift_outer)},
        {T(detail::splitting_coefficients::fr_gamma), T(detail::splitting_coefficients::fr_kick_inner),
         T(detail::splitting_coefficients::fr_gamma), T(0)},
        4,
        true};
};

/// Yoshida's sixth order, solution A (Yoshida 1990, "Construction of higher order symplectic integrators",
/// Phys. Lett. A 150, 262-268, Table 1): the symmetric composition of seven position-Verlet steps of
/// w3, w2, w1, w0, w1, w2, w3 times dt, w0 = 1 - 2 (w1 + w2 + w3); adjacent half drifts merged:
///     drift w3/2, kick w3, drift (w3+w2)/2, kick w2, drift (w2+w1)/2, kick w1, drift (w1+w0)/2, kick w0, ... mirrored.
/// Yoshida prints w1 = -0.117767998417887E1, w2 = 0.235573213359357E0, w3 = 0.784513610477560E0: 15
/// digits, of which the last of w2 and w3 is off by up to 3e-15. The w here are the root of his order
/// equations to 36 digits (w1 = -1.1776799841788710069..., w2 = 0.23557321335935813368..., w3 =
/// 0.78451361047755726382...), as in Principia's integrators/methods.hpp ("derived from equations 5.4
/// through 5.17" of the paper) and in independent lattice codes; they agree with the printed ones to
/// those 15 digits. Checked in __float128 on the Kepler orbit: with these w the error falls as h^6.00 down
/// to 1.6e-22; with the printed ones it leaves h^6 below 1e-18 (invisible in double and x87 long double).
/// Order 6, symmetric; seven evaluations of a per step, no state.
struct yoshida6 {
    static constexpr const char* name = "Yoshida 6th order (solution A)";
    template <class T>
    static constexpr splitting_table<T, 8> table{
        false,
        {T(detail::splitting_coefficients::y6_d1), T(detail::splitting_coefficients::y6_d2),
         T(detail::splitting_coefficients::y6_d3), T(detail::splitting_coefficients::y6_d4),
         T(detail::splitting_coefficients::y6_d4), T(detail::splitting_coefficients::y6_d3),
         T(detail::splitting_coefficients::y6_d2), T(detail::splitting_coefficients::y6_d1)},
        {T(detail::splitting_coefficients::y6_w3), T(detail::splitting_coefficients::y6_w2),
         T(detail::splitting_coefficients::y6_w1), T(detail::splitting_coefficients::y6_w0),
         T(detail::splitting_coefficients::y6_w1), T(detail::splitting_coefficients::y6_w2),
         T(detail::splitting_coefficients::y6_w3), T(0)},
        6,
        true};
};

/// Blanes & Moan's optimized fourth-order Runge-Kutta-Nystrom splitting SRKN_6^b (Blanes & Moan 2002,
/// "Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods", J. Comput. Appl.
/// Math. 142, 313-330, Table 3): kick first, seven kicks and six drifts,
///     kick b1, drift a1, kick b2, drift a2, kick b3, drift a3, kick b4, drift a3, kick b3, drift a2, kick b2, drift a1, kick b1,
/// a1 = 0.245298957184271, a2 = 0.604872665711080, a3 = 1/2 - (a1 + a2), b1 = 0.0829844064174052,
/// b2 = 0.396309801498368, b3 = -0.0390563049223486, b4 = 1 - 2 (b1 + b2 + b3) (all the published
/// digits; the same in Principia's integrators/methods.hpp, BlanesMoan2002SRKN6B, composition BAB).
/// Checked in __float128 on the Kepler orbit: slope 4.00 down to an error of 1.3e-16. Order 4, symmetric,
/// with an error constant far below Forest-Ruth's; first same as last: six evaluations of a per step.
struct blanes_moan4 {
    static constexpr const char* name = "Blanes-Moan SRKN6b 4th order";
    template <class T>
    static constexpr splitting_table<T, 7> table{
        true,
        {T(detail::splitting_coefficients::bm_a1), T(detail::splitting_coefficients::bm_a2),
         T(detail::splitting_coefficients::bm_a3), T(detail::splitting_coefficients::bm_a3),
         T(detail::splitting_coefficients::bm_a2), T(detail::splitting_coefficients::bm_a1), T(0)},
        {T(detail::splitting_coefficients::bm_b1), T(detail::splitting_coefficients::bm_b2),
         T(detail::splitting_coefficients::bm_b3), T(detail::splitting_coefficients::bm_b4),
         T(detail::splitting_coefficients::bm_b3), T(detail::splitting_coefficients::bm_b2),
         T(detail::splitting_coefficients::bm_b1)},
        4,
        true};
};

}  // namespace splittings

// The named steppers.
template <class State> using euler_cromer = splitting<splittings::euler_cromer, State>;
template <class State> using euler_cromer_drift_first = splitting<splittings::euler_cromer_drift_first, State>;
template <class State> using velocity_verlet = splitting<splittings::velocity_verlet, State>;
template <class State> using leapfrog = splitting<splittings::velocity_verlet, State>;
template <class State> using position_verlet = splitting<splittings::position_verlet, State>;
template <class State> using forest_ruth = splitting<splittings::forest_ruth, State>;
template <class State> using yoshida6 = splitting<splittings::yoshida6, State>;
template <class State> using blanes_moan4 = splitting<splittings::blanes_moan4, State>;

}  // namespace odestep
#endif
