// SPDX-License-Identifier: BSL-1.0
// odestep: symplectic splitting (composition) methods for Newton's equations x'' = a(t, x), driven by
// constexpr coefficient tables, and the table library.
#ifndef ODESTEP_NEWTONIAN_SPLITTING_HPP
#define ODESTEP_NEWTONIAN_SPLITTING_HPP

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "../detail/continuation.hpp"
#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../stepper.hpp"
#include "../system.hpp"
#include "../tables/splitting.hpp"

namespace odestep {

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
/// The sequence of drifts and kicks is unrolled at compile time: a zero coefficient emits nothing. With a
/// force of position alone, `State a(T t, const State& x)`, each kick is an exact flow and the method
/// symplectic; a velocity-dependent force `a(t, x, v)` is accepted too (velocity_forces), each kick then
/// using the velocity at hand: no longer symplectic and, but for Euler-Cromer, first order.
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
///
/// Check (odestep::checked, the default, or odestep::unchecked): whether the step tests the new x and v for
/// NaN and Inf (and returns `status::non_finite` with x, v and a kept acceleration untouched) or writes
/// them as they come: unchecked, a state larger than 32 bytes is updated in x, v and the kept
/// acceleration themselves, with no local copy (x and v are distinct objects). The arithmetic is the same
/// in both, bit for bit.
template <class Method, class State, class Check = checked>
class splitting : public stepper_defaults<State> {
public:
    /// The state, std::array<T, N>.
    using state_type = State;
    /// The scalar type T.
    using value_type = value_type_t<State>;
    /// The method (table tag) type.
    using method_type = Method;
    /// The check policy: odestep::checked or odestep::unchecked.
    using check_type = Check;
    /// The same stepper under check policy C (odestep::with_check_t).
    template <class C>
    using with_check = splitting<Method, State, C>;
    /// The step tests its results for NaN and Inf (trait; see odestep::stepper_defaults).
    static constexpr bool checks_finiteness = Check::checks_finiteness;

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
    // A state that fits in registers (32 bytes: one AVX register, eight of Cortex-M4F's single-precision
    // registers; and up to 8 components where the build optimizes for size). Its step is worked in locals,
    // v copied into its local first, and the updates one loop each: the compiler keeps them in registers
    // and stores each result once. A larger state's step copies nothing it need not (see in_place,
    // copy_velocity, fused_drift_after): there the copies are passes over memory. (Small, the large form
    // cost more: in place, each store to x or v, which may be the same memory for all the compiler knows,
    // made it reload the other, x86-64 GCC 12 -O2 velocity Verlet N = 2 29 instructions against 20,
    // Cortex-M4F -Os 28 bytes more; v read from the caller, Kepler's stepper-kept step 3 more.)
    static constexpr bool small_state = sizeof(State) <= 32 || (detail::optimizing_for_size && N <= 8);
    // Unchecked, a large state is updated in place: x, v and the kept acceleration themselves, no locals
    // and no copies at the end.
    static constexpr bool in_place = !checks_finiteness && !small_state;
    // The drifts and kicks as loops written in the step (checked: into locals, which alias nothing; and
    // optimizing for size, where GCC vectorizes nothing and would keep add_scaled a call), or through
    // add_scaled, which says that x, v and the acceleration are distinct.
    static constexpr bool plain_loops = !in_place || detail::optimizing_for_size;
    // v is copied into its local before the first update (see advance): a small state's, and a large one's
    // where the build optimizes for size; not with lazy_velocity.
    static constexpr bool copy_velocity = !in_place && !lazy_velocity && (small_state || detail::optimizing_for_size);

public:
    /// The order of the global error (trait; see odestep::stepper_defaults).
    static constexpr int order = plan::tab.order;
    /// Kicks per step.
    static constexpr std::size_t stages = plan::kicks;
    /// Evaluations of a in one step, the most it makes (first same as last: the first step, or the first
    /// after reset(); the others make one fewer).
    [[deprecated("odestep: use rhs_evals_per_step")]] static constexpr std::size_t accelerations_per_step = plan::kicks;
    /// The most evaluations of the right-hand side one step makes (trait; see odestep::stepper_defaults).
    static constexpr std::size_t rhs_evals_per_step = plan::kicks;
    /// The last kick's acceleration is the next step's first (kept between steps).
    static constexpr bool first_same_as_last = fsal;
    /// Symplectic with a force of position alone (trait; see odestep::stepper_defaults).
    static constexpr bool symplectic = true;
    /// The step with -dt undoes the step with dt (trait; see odestep::stepper_defaults).
    static constexpr bool time_reversible = plan::tab.time_reversible;
    /// The form of system the stepper takes (trait; see odestep::stepper_defaults).
    static constexpr system_form system = system_form::newtonian;
    /// A force of position and velocity, a(t, x, v), is accepted: each kick evaluates it with the velocity
    /// at hand (the one before the kick). The method is then not symplectic (is_symplectic_with_v says so)
    /// and, but for Euler-Cromer, of first order only; nothing is kept between steps.
    static constexpr bool velocity_forces = true;

    /// (x, v) <- (x, v)(t + dt). On `status::non_finite` x and v are left exactly as they were.
    template <class Accel, bool F = fsal, std::enable_if_t<!F, int> = 0>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, T t, T dt) const {
        return advance<false>(a, x, v, t, dt, nullptr, nullptr);
    }

    /// As above; the acceleration of the last kick is kept for the next step (not when the step fails). With
    /// a force a(t, x, v) nothing is kept: the last kick's velocity is not the next step's.
    template <class Accel, bool F = fsal, std::enable_if_t<F, int> = 0>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, T t, T dt) {
        if constexpr (is_velocity_force_v<Accel, State, T>) {
            return advance<false>(a, x, v, t, dt, nullptr, nullptr);
        } else {
            return kept_step(a, x, v, t, dt);
        }
    }

    /// The first-same-as-last step for a caller who keeps the acceleration, as a hand-written loop does:
    /// on entry `acc` is a(t, x) (evaluate it once, `acc = a(t0, x0)`, before the first step; again after
    /// changing x outside the stepper); on status::ok it is a(t + dt, x) of the new x, the next step's
    /// entry value. The stepper keeps and checks nothing, so this form has no continuation test: one
    /// evaluation of a per step, always, and the step is const (one stepper serves any number of states).
    /// On status::non_finite x, v and acc are left exactly as they were. acc is an object of its own (not
    /// x or v), which nothing but the step reaches while it runs (the force writes it only through its
    /// a_out): the step says so to the compiler (ODESTEP_RESTRICT), so that a force written in place
    /// vectorizes. A force of position alone only.
    template <class Accel, bool F = fsal, std::enable_if_t<F, int> = 0>
    ODESTEP_STEP_FLATTEN [[nodiscard]] status step(Accel&& a, State& x, State& v, State& ODESTEP_RESTRICT acc, T t,
                                                   T dt) const {
        static_assert(is_position_force_v<Accel, State, T>,
                      "odestep: a caller-kept acceleration needs a force of position alone, a(t, x): with "
                      "a(t, x, v) the last kick's acceleration is not the next step's first");
        if constexpr (in_place) {
            return advance<true>(a, x, v, t, dt, &acc, &acc);  // nothing to roll back: a(t + dt) into acc itself
        } else {
            State last;
            const status s = advance<true>(a, x, v, t, dt, &acc, &last);
            if (s == status::ok) detail::assign(acc, last);
            return s;
        }
    }

    /// Forgets the kept acceleration, so the next step evaluates a afresh. Call it after changing x or v
    /// outside the stepper, or the force. A no-op for the tables that keep nothing.
    constexpr void reset() noexcept {
        if constexpr (fsal) cache_.next.clear();
    }
    /// What a step changes (the kept acceleration and where it belongs; nothing for a table that keeps
    /// nothing), to hand back to restore_memory() and undo a step (the event engine does, when it rolls a step
    /// back to its start).
    constexpr splitting memory() const noexcept { return *this; }
    /// Puts back the memory() kept before the last step (the caller puts x and v back too).
    constexpr void restore_memory(const splitting& m) noexcept { *this = m; }

private:
    detail::splitting_cache<State, fsal> cache_{};

    // The stepper-kept first-same-as-last step (a force of position alone).
    template <class Accel>
    status kept_step(Accel& a, State& x, State& v, T t, T dt) {
        const bool hit = cache_.next.at(t, x);
        if (!hit) {
            cache_.next.clear();  // until a step succeeds, the kept value belongs to no step
            cache_.acceleration = detail::acceleration(a, t, x);  // (a force of position alone here)
        }
        if constexpr (in_place) {
            const status s = advance<true>(a, x, v, t, dt, &cache_.acceleration, &cache_.acceleration);
            cache_.next.expect(t, dt, x, hit);
            return s;
        } else {
            State last;
            const status s = advance<true>(a, x, v, t, dt, &cache_.acceleration, &last);
            if (s == status::ok) {
                detail::assign(cache_.acceleration, last);  // evaluated at t + dt, where the next step starts
                cache_.next.expect(t, dt, x, hit);
            }
            return s;
        }
    }

    // The step: the splitting of x' = v, v' = a(t, x) into the drift (x' = v, v' = 0) and the kick (x' = 0,
    // v' = a(t, x)), each solved exactly, applied in the table's order with its coefficients times dt (see
    // splitting_table), into new x and v that replace them only when every component is finite.
    // Kept: a first-same-as-last table's first kick uses *cached and its last kick's acceleration goes to
    // *last (the same object in_place: the first kick has read it before the last writes it); otherwise
    // both are evaluated (and the pointers are not read). in_place, nothing is rolled back: the updates go
    // to x and v themselves, component n of each read before it is written.
    template <bool Kept, class Accel>
    ODESTEP_INLINE static status advance(Accel& a, State& x, State& v, T t, T dt, const State* cached, State* last) {
        // Two objects, not one struct: the force sees the position's address, and a velocity in the same
        // object would then have to be stored before, and reloaded after, every evaluation not inlined.
        // No up-front copy of x: a drift before any drift reads the caller's x, and so does a kick before
        // any drift. Nor of v: an update before any kick reads the caller's v (a value read before a call not
        // inlined is held across it, at -Os on the stack, 7 instructions a step, x86 Euler-Cromer; and a
        // copy of a large state is a pass over it); optimizing for size without lazy_velocity, v is copied
        // into wv first (copy_velocity: fewer bytes on Cortex-M0+). Every table has a drift and a kick, so
        // wx and wv are written in full before the test below.
        State local_x;
        State local_v;
        State& wx = detail::result_target<in_place>(local_x, x);
        State& wv = detail::result_target<in_place>(local_v, v);
        if constexpr (copy_velocity) detail::assign(wv, v);
        run<Kept>(a, x, v, wx, wv, t, dt, cached, last, std::make_index_sequence<plan::updates>{});
        // The finiteness test's sum (detail::finite_sum) of the new x and v, x's components first: any order
        // serves (only a sum that fails goes on to the exact test), and this one needs the fewest register
        // copies where the force has just taken x apart. A large state is summed in lanes, which vectorize
        // (detail::add_in_lanes).
        //
        // A step that ends with a drift, x <- x + h v with h = c dt and v already final, needs x alone: for
        // a v component that is +-Inf or NaN, h v is +-Inf or NaN (h = 0 included: 0 Inf is NaN), and so is
        // x plus it, whatever x. So a finite new x proves the new v finite, and half the test goes.
        T total = -T(0);  // x + (-0) is x, exactly: the compiler drops that first addition
        if constexpr (checks_finiteness) {
            detail::add_in_lanes(total, wx);
            if constexpr (ends_with_kick) detail::add_in_lanes(total, wv);
        }
        if (!detail::finite_sum_under<Check>(total) &&
            !(detail::each_finite(wx) && (!ends_with_kick || detail::each_finite(wv))))
            return status::non_finite;
        if constexpr (!in_place) {
            detail::assign(x, wx);
            detail::assign(v, wv);
        }
        return status::ok;
    }

    template <bool Kept, class Accel, std::size_t... K>
    ODESTEP_INLINE static void run(Accel& a, const State& x, const State& v, State& wx, State& wv, T t, T dt,
                                   const State* cached, State* last, std::index_sequence<K...>) {
        (update<K, Kept>(a, x, v, wx, wv, t, dt, cached, last), ...);
    }

    // Update K of the sequence, emitted only when its coefficient is not zero.
    template <std::size_t K, bool Kept, class Accel>
    ODESTEP_INLINE static void update(Accel& a, const State& x, const State& v, State& wx, State& wv, T t, T dt,
                                      const State* cached, State* last) {
        (void)cached, (void)last;
        constexpr T c = plan::coefficient(K);
        if constexpr (c != T(0) && !(Kept && K > 0 && fused_drift_after(K - 1))) {
            const T h = scaled<K>(dt);
            // What update K starts from: the caller's x until a drift is made, the caller's v until a kick is
            // made (with copy_velocity, wv is v's copy from the start).
            const State& px = plan::drift_before(K) ? wx : x;
            const State& pv = (copy_velocity || plan::kick_before(K)) ? wv : v;
            if constexpr (!plan::is_kick(K)) {
                if constexpr (plain_loops) {
                    ODESTEP_STEP_UNROLL_ALWAYS
                    for (std::size_t n = 0; n < N; ++n) wx[n] = px[n] + h * pv[n];
                } else {
                    add_scaled(wx, wv, h);  // px is wx (x itself) and pv is wv (v itself)
                }
            } else if constexpr (fsal && Kept && K == plan::first) {
                // a(t, x), kept from the last step's last kick
                if constexpr (fused_drift_after(K)) {
                    kick_drift<K>(wx, wv, x, pv, *cached, h, dt);
                } else {
                    kick(wv, pv, *cached, h);
                }
            } else if constexpr (fsal && Kept && K == plan::last) {
                detail::accelerate(a, t + dt, px, pv, *last);  // at x_{n+1}: kept for the next step
                kick(wv, pv, *last, h);
            } else {
                kick(wv, pv, detail::acceleration(a, kick_time<K>(t, dt), px, pv), h);
            }
        }
    }

    // The kept first kick (a first-same-as-last step with the acceleration kept) and the drift right after
    // it, made in one pass over the components as a hand-written kick-drift loop is (no evaluation of the
    // force comes between them): update K + 1 is then made here and emits nothing itself. A large state's,
    // not optimizing for size.
    static constexpr bool fused_drift_after(std::size_t k) noexcept {
        return !small_state && !detail::optimizing_for_size && fsal && k == plan::first && k + 1 < plan::updates &&
               !plan::is_kick(k + 1) && plan::coefficient(k + 1) != T(0);
    }
    // wv = pv + h acc, then wx = x + h' wv (h' the drift's c dt), component by component; x is the caller's
    // (no drift comes before the first kick). in_place, wv is v and wx is x, both updated in place.
    template <std::size_t K>
    ODESTEP_INLINE static void kick_drift(State& wx, State& wv, const State& x, const State& pv, const State& acc, T h,
                                          T dt) noexcept {
        const T hd = scaled<K + 1>(dt);
        if constexpr (!in_place) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < N; ++n) {
                wv[n] = pv[n] + h * acc[n];
                wx[n] = x[n] + hd * wv[n];
            }
        } else {
            (void)x, (void)pv;
            kick_drift_in_place(wx, wv, acc, h, hd);
        }
    }
    // v += h acc, then x += h' v (restrict and not always_inline: see add_scaled).
    static void kick_drift_in_place(State& ODESTEP_RESTRICT x, State& ODESTEP_RESTRICT v,
                                    const State& ODESTEP_RESTRICT acc, T h, T hd) noexcept {
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) {
            v[n] += h * acc[n];
            x[n] += hd * v[n];
        }
    }

    // to = from + h acc, component by component (from may be to). in_place, from is to (v itself).
    ODESTEP_INLINE static void kick(State& to, const State& from, const State& acc, T h) noexcept {
        if constexpr (plain_loops) {
            ODESTEP_STEP_UNROLL_ALWAYS
            for (std::size_t n = 0; n < N; ++n) to[n] = from[n] + h * acc[n];
        } else {
            (void)from;
            add_scaled(to, acc, h);
        }
    }
    // to += h by, component by component: the in_place step's updates of the caller's x and v, which are
    // distinct objects, and distinct from the acceleration (the step's contract): said to the compiler,
    // which can then vectorize the loop without a run-time overlap test (GCC at -O2 makes none). Not
    // always_inline: GCC 12 inlines an always_inline function before it reads the function's restrict, and
    // the promise is lost; inlined as an ordinary inline function (flattened at -Os), it is kept.
    static void add_scaled(State& ODESTEP_RESTRICT to, const State& ODESTEP_RESTRICT by, T h) noexcept {
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t n = 0; n < N; ++n) to[n] += h * by[n];
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
};

// The named steppers.
template <class State>
using euler_cromer = splitting<tables::euler_cromer, State>;
template <class State>
using euler_cromer_drift_first = splitting<tables::euler_cromer_drift_first, State>;
template <class State>
using velocity_verlet = splitting<tables::velocity_verlet, State>;
template <class State>
using leapfrog = splitting<tables::velocity_verlet, State>;
template <class State>
using position_verlet = splitting<tables::position_verlet, State>;
template <class State>
using forest_ruth = splitting<tables::forest_ruth, State>;
template <class State>
using yoshida6 = splitting<tables::yoshida6, State>;
template <class State>
using blanes_moan4 = splitting<tables::blanes_moan4, State>;

}  // namespace odestep
#endif
