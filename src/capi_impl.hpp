// SPDX-License-Identifier: BSL-1.0
// odestep C API: the adapters from the C structs (include/odestep/odestep.h) to the C++ templates, written
// once for float and double; capi_float.cpp and capi_double.cpp instantiate them under the C names.
//
// The state. A C caller's n is known at run time, a C++ state's size at compile time. Three forms:
//   - over n (the single steps of the explicit Runge-Kutta methods, any n): capi_rk.hpp, explicit_rk's step
//     written over a run-time n on the caller's y; each component bit for bit the C++ step's.
//   - exact (the single steps, n <= ODESTEP_C_EXACT_STATES): each method is compiled for every size
//     1 .. ODESTEP_C_EXACT_STATES: the explicit Runge-Kutta methods as the form over n with n a constant,
//     the others the stepper of std::array<T, n> on a copy of the caller's n values, f called directly.
//   - padded (the loops, the event loop, and the single steps of Adams and the Newtonian methods): the
//     stepper of std::array<T, ODESTEP_C_MAX_STATES>; each call copies the caller's n values into a state
//     whose components n .. MAX-1 are zero, and the right-hand side's adapter zeroes dydt and hands the
//     user's f the first n components to write. The padding therefore stays exactly zero through
//     every stage (0 + dt * sum of zeros), so the steppers' finiteness checks, which run over all MAX
//     components, decide on the first n alone.
// Every form writes the caller's values only on success (the form over n puts them back on failure).
//
// The stepper object (explicit_rk, splitting, adams) is constructed in the caller's storage
// (odestep_stepper_*.storage) by placement new: no heap, and a method is a constant table of function
// pointers (method_ops), so that a firmware links the code of the methods it names and no other. The
// storage starts with a binding: the form and size the object there was constructed for, and that form's
// functions. A single step checks its n against the binding (one compare) instead of validating the
// method and n again; a step with another n (or of the other kind of system) validates them and
// constructs the object of its size afresh (an empty history).
#ifndef ODESTEP_SRC_CAPI_IMPL_HPP
#define ODESTEP_SRC_CAPI_IMPL_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>

#include "capi_rk.hpp"
#include "odestep/events/engine.hpp"
#include "odestep/integrate.hpp"
#include "odestep/multistep/adams.hpp"
#include "odestep/newtonian/classic.hpp"
#include "odestep/newtonian/splitting.hpp"
#include "odestep/odestep.h"
#include "odestep/rk/explicit_rk.hpp"
#include "odestep/status.hpp"

namespace odestep::capi {

constexpr std::size_t max_states = ODESTEP_C_MAX_STATES;
/// The sizes whose single steps are compiled exactly (odestep.h, ODESTEP_C_EXACT_STATES; at most max_states).
constexpr std::size_t exact_states = static_cast<std::size_t>(ODESTEP_C_EXACT_STATES) < max_states
                                         ? static_cast<std::size_t>(ODESTEP_C_EXACT_STATES)
                                         : max_states;

/// The padded state of the C API.
template <class T>
using state = std::array<T, max_states>;

/// The C type of precision T: D (the _d name) for double, F (the _f name) for float.
template <class T, class D, class F>
using by_precision = std::conditional_t<std::is_same_v<T, double>, D, F>;

/// The C types of one precision.
template <class T>
struct c_types {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, float>);
    using system = by_precision<T, odestep_system_d, odestep_system_f>;
    using newton = by_precision<T, odestep_newton_d, odestep_newton_f>;
    using stepper = by_precision<T, odestep_stepper_d, odestep_stepper_f>;
    using method = by_precision<T, odestep_method_d, odestep_method_f>;
    using run = by_precision<T, odestep_run_d, odestep_run_f>;
    using observer = by_precision<T, odestep_observer_d, odestep_observer_f>;
    using newton_observer = by_precision<T, odestep_newton_observer_d, odestep_newton_observer_f>;
};

constexpr odestep_status to_c(status s) noexcept { return static_cast<odestep_status>(static_cast<int>(s)); }

/// A user's callback (f or a) on a padded state: `out` zeroed, then the callback writes its first n
/// components, so that the others stay zero. Zeroing all of `out` is a few constant stores; zeroing
/// n .. MAX-1 after the call is a loop whose length is known only at run time (about 15 more
/// instructions per call, RK4 n = 4 of 8, x86-64). The callback and ctx by reference: read after the
/// stores, as a plain call reads them, which keeps two fewer values live across the stores.
template <class T, class Callback>
ODESTEP_INLINE void padded_call(const Callback& callback, T t, const state<T>& in, state<T>& out, void* const& ctx) {
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t i = 0; i < max_states; ++i) out[i] = T(0);
    callback(t, in.data(), out.data(), ctx);
}

/// y' = f(t, y) for the C++ steppers: the user's f on the first n components, zero for the others.
template <class T>
struct c_rhs {
    const typename c_types<T>::system* sys;
    step_count* calls = nullptr;  ///< the loops count every call here (the method is known only at run time)
    void operator()(T t, const state<T>& y, state<T>& dydt) const {
        if (calls != nullptr) ++*calls;
        padded_call(sys->f, t, y, dydt, sys->ctx);
    }
};

/// x'' = a(t, x) for the C++ steppers: a force of position alone, returned.
template <class T>
struct c_accel {
    const typename c_types<T>::newton* sys;
    step_count* calls = nullptr;  ///< as c_rhs's
    state<T> operator()(T t, const state<T>& x) const {
        if (calls != nullptr) ++*calls;
        state<T> a;
        padded_call(sys->a, t, x, a, sys->ctx);
        return a;
    }
};

/// The functions of one form and size of a method (see the file's comment): construct the stepper object
/// of that form and size, and the single steps on the caller's arrays. A step of the other kind of system
/// than the method's is never bound (the binding checks the kind), so its entry refuses. The steps take
/// the stepper (its object at a constant offset, which the step folds into its addressing) and have a
/// form without estimates or a kept acceleration, so that the plain step passes no null arguments and
/// tests none.
template <class T>
struct sized_ops {
    using stepper = typename c_types<T>::stepper;
    void (*construct)(void* object);
    /// y' = f: y[0 .. n-1].
    odestep_status (*step)(stepper* s, const typename c_types<T>::system* sys, T* y, T t, T dt);
    /// y' = f with e1 (not null) and e2 (null: not asked for), both checked against the method before the call.
    odestep_status (*step_error)(stepper* s, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1, T* e2);
    /// x'' = a: a single step (nothing reused from an earlier one).
    odestep_status (*step_newton)(stepper* s, const typename c_types<T>::newton* sys, T* x, T* v, T t, T dt);
    /// x'' = a: the caller-kept step (acc not null).
    odestep_status (*step_newton_kept)(stepper* s, const typename c_types<T>::newton* sys, T* x, T* v, T* acc, T t,
                                       T dt);
};

/// A method: what the C functions need to know of a stepper type, and its steps as function pointers.
template <class T>
struct method_ops {
    const char* name;
    int order;
    int error_estimates;
    bool newtonian;
    bool uniform_steps;
    unsigned rhs_evals_per_step;
    /// The bytes of the stepper object a step changes and an event loop must put back when it rolls a step
    /// back (event_engine's stepper_memory): the object's size for a stepper with memory() (Adams), 0 for
    /// one without (nothing to keep: the one-step methods).
    std::size_t memory_bytes;
    void (*construct)(void* storage);
    void (*reset)(void* storage);
    /// y' = f: a step of the object in storage, with up to two estimates (null: not asked for).
    status (*step)(void* storage, const c_rhs<T>& f, state<T>& y, T t, T dt, state<T>* e1, state<T>* e2);
    /// x'' = a: one step on its own (`kept` false: nothing reused from an earlier step), or a step of a loop
    /// whose x object stays the same (`kept` true: velocity Verlet reuses the last acceleration); with
    /// `acc`, the caller-kept form of a first-same-as-last method (acc = a(t, x) in, a(t + dt, x) out).
    status (*step_newton)(void* storage, const c_accel<T>& a, state<T>& x, state<T>& v, state<T>* acc, T t, T dt,
                          bool kept);
    /// The exact single steps of size n (sizes[n - 1]), n up to ODESTEP_C_EXACT_STATES.
    std::array<sized_ops<T>, exact_states> sizes;
    /// The single steps for n above ODESTEP_C_EXACT_STATES, and after a loop (so that its history goes on):
    /// over n for the explicit Runge-Kutta methods, on the padded object for the others (padded_of).
    sized_ops<T> padded;
};

}  // namespace odestep::capi

/// The method objects the header declares opaque: a method's traits and function pointers.
struct odestep_method_d {
    odestep::capi::method_ops<double> ops;  ///< what the C functions call
};
/// The float method object.
struct odestep_method_f {
    odestep::capi::method_ops<float> ops;  ///< what the C functions call
};

namespace odestep::capi {

template <class S, class = void>
struct estimates_of : std::integral_constant<int, 0> {};
template <class S>
struct estimates_of<S, std::enable_if_t<S::error_estimate>>
    : std::integral_constant<int, static_cast<int>(S::error_estimates)> {};

template <class S, class = void>
struct caller_kept : std::false_type {};
template <class S>
struct caller_kept<S, std::enable_if_t<S::first_same_as_last>> : std::true_type {};

// ---- the storage: the binding, then the stepper object

template <class T>
using stepper_t = typename c_types<T>::stepper;

/// What the object in a stepper's storage was constructed for: n for a first-order system (first_order_n)
/// or for Newton's equations (newton_n), the other 0; both 0 for none (a zeroed or freshly initialised
/// stepper). A step is bound when its kind's n equals its n and n is not 0: every n stored is in range.
template <class T>
struct binding {
    std::size_t first_order_n;
    std::size_t newton_n;
    const sized_ops<T>* form;  // the bound form (its estimating and kept steps)
    // Copies of the form's plain steps, one load from a call (not the whole form: the storage's size)
    decltype(sized_ops<T>::step) step;
    decltype(sized_ops<T>::step_newton) step_newton;
};

template <class T>
constexpr std::size_t object_offset = (sizeof(binding<T>) + alignof(stepper_t<T>) - 1) / alignof(stepper_t<T>) *
                                      alignof(stepper_t<T>);

template <class T>
binding<T>& binding_of(stepper_t<T>* s) noexcept {
    static_assert(alignof(binding<T>) <= alignof(stepper_t<T>));
    return *std::launder(reinterpret_cast<binding<T>*>(s->storage.bytes));
}
template <class T>
void* object_of(stepper_t<T>* s) noexcept {
    return s->storage.bytes + object_offset<T>;
}

/// The function pointers of stepper type S (on state<T>).
template <class S>
struct ops_of {
    using T = typename S::value_type;
    static_assert(std::is_same_v<typename S::state_type, state<T>>);
    static_assert(std::is_trivially_destructible_v<S>, "the C API never destroys a stepper object");
    static_assert(sizeof(S) + object_offset<T> <= sizeof(std::declval<stepper_t<T>&>().storage.bytes),
                  "odestep: ODESTEP_C_STEPPER_SCALARS is too small for this stepper");
    static_assert(alignof(S) <= alignof(stepper_t<T>), "odestep: the stepper storage's alignment");

    static S& object(void* storage) noexcept { return *std::launder(static_cast<S*>(storage)); }

    static void construct(void* storage) noexcept { ::new (storage) S(); }
    static void reset(void* storage) noexcept {
        if constexpr (detail::has_reset<S>::value) object(storage).reset();
    }
    static status step(void* storage, const c_rhs<T>& f, state<T>& y, T t, T dt, state<T>* e1, state<T>* e2) {
        if constexpr (S::system != system_form::first_order) {
            return status::invalid_setting;
        } else {
            S& s = object(storage);
            if constexpr (estimates_of<S>::value >= 2) {
                if (e2 != nullptr) return s.step(f, y, t, dt, *e1, *e2);
            }
            if constexpr (estimates_of<S>::value >= 1) {
                if (e1 != nullptr) return s.step(f, y, t, dt, *e1);
            }
            return s.step(f, y, t, dt);
        }
    }
    static status step_newton(void* storage, const c_accel<T>& a, state<T>& x, state<T>& v, state<T>* acc, T t, T dt,
                              bool kept) {
        if constexpr (S::system != system_form::newtonian) {
            return status::invalid_setting;
        } else {
            S& s = object(storage);
            if (acc != nullptr) {
                if constexpr (caller_kept<S>::value) {
                    return s.step(a, x, v, *acc, t, dt);
                } else {
                    return status::invalid_setting;  // no acceleration to keep: not first same as last
                }
            }
            // A single step's x is a copy that lives as long as the call: a kept acceleration would be
            // matched by that copy's address alone, so it is forgotten first (the step evaluates afresh).
            if (!kept) reset(storage);
            return s.step(a, x, v, t, dt);
        }
    }
};

/// The caller's n values into a padded state: the first n copied, the others zero.
template <class T>
ODESTEP_INLINE void load_into(state<T>& s, const T* from, std::size_t n) noexcept {
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t i = 0; i < max_states; ++i) s[i] = i < n ? from[i] : T(0);
}
template <class T>
ODESTEP_INLINE state<T> load(const T* from, std::size_t n) noexcept {
    state<T> s;  // every component written by load_into
    load_into(s, from, n);
    return s;
}
template <class T>
ODESTEP_INLINE void store(T* to, const state<T>& s, std::size_t n) noexcept {
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t i = 0; i < max_states; ++i) {
        if (i < n) to[i] = s[i];
    }
}

/// A stepper that refuses (a step of the other kind of system than its method's): never bound, present so
/// that every entry of a method's table is a function.
template <class T>
struct refuse {
    static odestep_status step(stepper_t<T>*, const typename c_types<T>::system*, T*, T, T) noexcept {
        return ODESTEP_INVALID_SETTING;
    }
    static odestep_status step_error(stepper_t<T>*, const typename c_types<T>::system*, T*, T, T, T*, T*) noexcept {
        return ODESTEP_INVALID_SETTING;
    }
    static odestep_status step_newton(stepper_t<T>*, const typename c_types<T>::newton*, T*, T*, T, T) noexcept {
        return ODESTEP_INVALID_SETTING;
    }
    static odestep_status step_newton_kept(stepper_t<T>*, const typename c_types<T>::newton*, T*, T*, T*, T,
                                           T) noexcept {
        return ODESTEP_INVALID_SETTING;
    }
};

/// The padded single steps of stepper type S (on state<T>): the caller's n values copied in with zero
/// padding, the step, the n values copied back on success.
template <class S>
struct padded_ops {
    using T = typename S::value_type;
    // Each entry point with its own copy of the padded step: a plain step that called the estimating one
    // took 14 instructions more (x86-64, RK4 n = 4 of 8) for 88 bytes less flash (M4F -Os).
    static odestep_status step(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt) {
        return to_c(run(object_of<T>(s), sys, y, t, dt, nullptr, nullptr));
    }
    static odestep_status step_error(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1,
                                     T* e2) {
        return to_c(run(object_of<T>(s), sys, y, t, dt, e1, e2));
    }
    static odestep_status step_newton(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T t, T dt) {
        return to_c(run_newton(object_of<T>(s), sys, x, v, nullptr, t, dt));
    }
    static odestep_status step_newton_kept(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T* acc,
                                           T t, T dt) {
        return to_c(run_newton(object_of<T>(s), sys, x, v, acc, t, dt));
    }
    ODESTEP_INLINE static status run(void* object, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1,
                                     T* e2) {
        const std::size_t n = sys->n;
        state<T> ys = load(y, n);
        if (e1 == nullptr) {  // the plain step: no estimate arrays at all
            const status r = ops_of<S>::step(object, c_rhs<T>{sys}, ys, t, dt, nullptr, nullptr);
            if (r == status::ok) store(y, ys, n);
            return r;
        }
        state<T> err1{};
        state<T> err2{};
        const status r = ops_of<S>::step(object, c_rhs<T>{sys}, ys, t, dt, &err1, e2 != nullptr ? &err2 : nullptr);
        if (r == status::ok) {
            store(y, ys, n);
            store(e1, err1, n);
            if (e2 != nullptr) store(e2, err2, n);
        }
        return r;
    }
    ODESTEP_INLINE static status run_newton(void* object, const typename c_types<T>::newton* sys, T* x, T* v, T* acc,
                                            T t, T dt) {
        const std::size_t n = sys->n;
        state<T> xs = load(x, n);
        state<T> vs = load(v, n);
        state<T> as{};
        if (acc != nullptr) load_into(as, acc, n);
        const status r =
            ops_of<S>::step_newton(object, c_accel<T>{sys}, xs, vs, acc != nullptr ? &as : nullptr, t, dt, false);
        if (r == status::ok) {
            store(x, xs, n);
            store(v, vs, n);
            if (acc != nullptr) store(acc, as, n);
        }
        return r;
    }
};

/// The exact single steps of stepper type S on std::array<T, N>, N the caller's n: the user's f called
/// with the step's own arrays, no padding, nothing zeroed.
template <class S>
struct exact_ops {
    using T = typename S::value_type;
    using A = typename S::state_type;
    static constexpr std::size_t N = std::tuple_size<A>::value;
    static_assert(sizeof(S) + object_offset<T> <= sizeof(std::declval<stepper_t<T>&>().storage.bytes),
                  "odestep: ODESTEP_C_STEPPER_SCALARS is too small for this stepper");
    static_assert(alignof(S) <= alignof(stepper_t<T>), "odestep: the stepper storage's alignment");
    static_assert(std::is_trivially_destructible_v<S>, "the C API never destroys a stepper object");

    static S& object(void* storage) noexcept { return *std::launder(static_cast<S*>(storage)); }
    static void construct(void* storage) noexcept { ::new (storage) S(); }

    // One copy of N scalars each way, unrolled as the step's own loops over N are (a loop at -Os: Cortex-M4F,
    // RK4 on 4 floats, about 20 instructions more a step).
    ODESTEP_INLINE static A load(const T* from) noexcept {
        A s;
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t i = 0; i < N; ++i) s[i] = from[i];
        return s;
    }
    ODESTEP_INLINE static void store(T* to, const A& s) noexcept {
        ODESTEP_STEP_UNROLL_ALWAYS
        for (std::size_t i = 0; i < N; ++i) to[i] = s[i];
    }

    static odestep_status step(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt) {
        return to_c(run<false>(object_of<T>(s), sys, y, t, dt, nullptr, nullptr));
    }
    static odestep_status step_error(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1,
                                     T* e2) {
        return to_c(run<true>(object_of<T>(s), sys, y, t, dt, e1, e2));
    }
    static odestep_status step_newton(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T t, T dt) {
        return to_c(run_newton<false>(object_of<T>(s), sys, x, v, nullptr, t, dt));
    }
    static odestep_status step_newton_kept(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T* acc,
                                           T t, T dt) {
        return to_c(run_newton<true>(object_of<T>(s), sys, x, v, acc, t, dt));
    }
    // Estimating (e1 not null) and Kept (acc not null) at compile time: each entry point has its own
    // instantiation of the step, which then has one caller and is inlined into it.
    template <bool Estimating>
    ODESTEP_INLINE static status run(void* storage, const typename c_types<T>::system* sys, T* y, T t, T dt,
                                     [[maybe_unused]] T* e1, [[maybe_unused]] T* e2) {
        const auto fn = sys->f;
        void* const ctx = sys->ctx;
        const auto f = [fn, ctx](T tt, const A& yy, A& dydt) { fn(tt, yy.data(), dydt.data(), ctx); };
        S& s = object(storage);
        A ys = load(y);
        if constexpr (Estimating) {
            if constexpr (estimates_of<S>::value < 1) {
                return status::invalid_setting;  // (not reached: the entry checks the estimates asked for)
            } else {
                A err1;  // written by the step on success, read only then
                status r = status::ok;
                if constexpr (estimates_of<S>::value >= 2) {
                    A err2;
                    if (e2 != nullptr) {
                        r = s.step(f, ys, t, dt, err1, err2);
                        if (r == status::ok) store(e2, err2);
                    } else {
                        r = s.step(f, ys, t, dt, err1);
                    }
                } else {
                    r = s.step(f, ys, t, dt, err1);
                }
                if (r == status::ok) {
                    store(y, ys);
                    store(e1, err1);
                }
                return r;
            }
        } else {
            const status r = s.step(f, ys, t, dt);
            if (r == status::ok) store(y, ys);
            return r;
        }
    }

    template <bool Kept>
    ODESTEP_INLINE static status run_newton(void* storage, const typename c_types<T>::newton* sys, T* x, T* v,
                                            [[maybe_unused]] T* acc, T t, T dt) {
        const auto fn = sys->a;
        void* const ctx = sys->ctx;
        const auto a = [fn, ctx](T tt, const A& xx) {
            A out;  // every component written by the user's a
            fn(tt, xx.data(), out.data(), ctx);
            return out;
        };
        S& s = object(storage);
        A xs = load(x);
        A vs = load(v);
        status r = status::ok;
        if constexpr (Kept) {
            if constexpr (caller_kept<S>::value) {
                A as = load(acc);
                r = s.step(a, xs, vs, as, t, dt);
                if (r == status::ok) store(acc, as);
            } else {
                return status::invalid_setting;  // no acceleration to keep: not first same as last
            }
        } else {
            // A single step's x is a copy that lives as long as the call: a kept acceleration would be
            // matched by that copy's address alone, so it is forgotten first (the step evaluates afresh).
            if constexpr (detail::has_reset<S>::value) s.reset();
            r = s.step(a, xs, vs, t, dt);
        }
        if (r == status::ok) {
            store(x, xs);
            store(v, vs);
        }
        return r;
    }
};

/// The single steps of an explicit Runge-Kutta method S (on state<T>) over the caller's n (capi_rk.hpp): no
/// padding, no copy of y in; the object in the storage is S's (constructed for the loops, which step it; the
/// single step needs none: explicit_rk holds no state). Size: std::size_t (n read from the system), or
/// std::integral_constant<std::size_t, N> for the step compiled for n = N (ODESTEP_C_EXACT_STATES).
template <class S, class Size = std::size_t>
struct any_n_ops {
    using T = typename S::value_type;
    using body = any_n_rk<typename rk_table_of<S>::type, T, max_states>;
    static Size size(const typename c_types<T>::system* sys) noexcept {
        if constexpr (std::is_same_v<Size, std::size_t>) {
            return sys->n;
        } else {
            return Size{};  // (the binding checked that sys->n is N)
        }
    }
    // Flattened, as explicit_rk's step is: at -Os GCC otherwise keeps the sums' helpers out of line.
    ODESTEP_STEP_FLATTEN static odestep_status step(stepper_t<T>*, const typename c_types<T>::system* sys, T* y, T t,
                                                    T dt) {
        return to_c(body::template step<0>(sys->f, sys->ctx, size(sys), y, t, dt, nullptr, nullptr));
    }
    ODESTEP_STEP_FLATTEN static odestep_status step_error(stepper_t<T>*, const typename c_types<T>::system* sys, T* y,
                                                          T t, T dt, T* e1, [[maybe_unused]] T* e2) {
        if constexpr (estimates_of<S>::value >= 2) {
            if (e2 != nullptr) return to_c(body::template step<2>(sys->f, sys->ctx, size(sys), y, t, dt, e1, e2));
        }
        if constexpr (estimates_of<S>::value >= 1) {
            return to_c(body::template step<1>(sys->f, sys->ctx, size(sys), y, t, dt, e1, nullptr));
        } else {
            return ODESTEP_INVALID_SETTING;  // (not reached: the entry checks the estimates asked for)
        }
    }
};

/// The single steps of a method for any n above ODESTEP_C_EXACT_STATES, and the form the loops bind: the
/// explicit Runge-Kutta methods over n (any_n_ops), the others padded (padded_ops).
template <class T, class Family>
constexpr sized_ops<T> padded_of() noexcept {
    using S = typename Family::template type<state<T>>;
    if constexpr (!std::is_void_v<typename rk_table_of<S>::type>) {
        return {&ops_of<S>::construct, &any_n_ops<S>::step, &any_n_ops<S>::step_error, &refuse<T>::step_newton,
                &refuse<T>::step_newton_kept};
    } else if constexpr (S::system == system_form::newtonian) {
        return {&ops_of<S>::construct, &refuse<T>::step, &refuse<T>::step_error, &padded_ops<S>::step_newton,
                &padded_ops<S>::step_newton_kept};
    } else {
        return {&ops_of<S>::construct, &padded_ops<S>::step, &padded_ops<S>::step_error, &refuse<T>::step_newton,
                &refuse<T>::step_newton_kept};
    }
}

/// The exact single steps of a method (Family::type<State> its stepper on State) for size N.
template <class T, class Family, std::size_t N>
constexpr sized_ops<T> sized() noexcept {
    using S = typename Family::template type<std::array<T, N>>;
    using E = exact_ops<S>;
    using P = typename Family::template type<state<T>>;
    if constexpr (!std::is_void_v<typename rk_table_of<P>::type>) {
        using A = any_n_ops<P, std::integral_constant<std::size_t, N>>;
        return {&ops_of<P>::construct, &A::step, &A::step_error, &refuse<T>::step_newton, &refuse<T>::step_newton_kept};
    } else if constexpr (S::system == system_form::newtonian) {
        return {&E::construct, &refuse<T>::step, &refuse<T>::step_error, &E::step_newton, &E::step_newton_kept};
    } else {
        return {&E::construct, &E::step, &E::step_error, &refuse<T>::step_newton, &refuse<T>::step_newton_kept};
    }
}

template <class T, class Family, std::size_t... I>
constexpr std::array<sized_ops<T>, exact_states> sizes_of(std::index_sequence<I...>) noexcept {
    return {{sized<T, Family, I + 1>()...}};
}

/// The method object of Family (a struct whose member template type<State> is the method's stepper).
template <class T, class Family>
constexpr method_ops<T> make_ops(const char* name) noexcept {
    using S = typename Family::template type<state<T>>;
    return {name, S::order, estimates_of<S>::value, S::system == system_form::newtonian, S::uniform_steps,
            // The most of either step: Dormand-Prince's estimating step makes one more than its plain step.
            static_cast<unsigned>(S::rhs_evals_per_step > S::rhs_evals_per_error_step ? S::rhs_evals_per_step
                                                                                      : S::rhs_evals_per_error_step),
            detail::has_step_memory<S>::value ? sizeof(S) : 0, &ops_of<S>::construct, &ops_of<S>::reset,
            &ops_of<S>::step, &ops_of<S>::step_newton, sizes_of<T, Family>(std::make_index_sequence<exact_states>{}),
            padded_of<T, Family>()};
}

// ---- the C functions, for one precision

template <class T>
const method_ops<T>* ops(const stepper_t<T>* s) noexcept {
    return s->method != nullptr ? &s->method->ops : nullptr;
}

template <class T>
bool size_ok(std::size_t n) noexcept {
    return n >= 1 && n <= max_states;
}

/// The single-step functions of size n (in range): exact up to exact_states, else padded.
template <class T>
const sized_ops<T>* form_for(const method_ops<T>* m, std::size_t n) noexcept {
    if constexpr (exact_states > 0) {
        if (n <= exact_states) return &m->sizes[n - 1];
    }
    return &m->padded;
}

/// Binds the stepper's storage to `form` for n (of Newton's equations if `newton`): the object constructed
/// afresh.
template <class T>
void bind(stepper_t<T>* s, std::size_t n, bool newton, const sized_ops<T>* form) noexcept {
    binding<T>& b = binding_of<T>(s);
    form->construct(object_of<T>(s));
    b.first_order_n = newton ? 0 : n;
    b.newton_n = newton ? n : 0;
    b.form = form;
    b.step = form->step;
    b.step_newton = form->step_newton;
}

/// Forgets the binding: the next single step constructs its object afresh.
template <class T>
void unbind(stepper_t<T>* s) noexcept {
    binding<T>& b = binding_of<T>(s);
    b.first_order_n = 0;
    b.newton_n = 0;
    b.form = nullptr;
    b.step = nullptr;
    b.step_newton = nullptr;
}

/// A single step of y' = f whose stepper is not bound to its n (the first step, or one with another n or
/// after a reset): the checks a bound step skips, then the binding (the object constructed afresh).
template <class T>
[[gnu::noinline, gnu::cold]] odestep_status step_unbound(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y,
                                                         T t, T dt, T* e1, T* e2) {
    const method_ops<T>* m = ops<T>(s);
    const std::size_t n = sys->n;
    if (m == nullptr || !size_ok<T>(n) || m->newtonian) return ODESTEP_INVALID_SETTING;
    const status checked = detail::check_step(t, dt);
    if (checked != status::ok) return to_c(checked);
    if (e1 != nullptr && (m->error_estimates < 1 || (e2 != nullptr && m->error_estimates < 2)))
        return ODESTEP_INVALID_SETTING;
    bind<T>(s, n, false, form_for(m, n));
    const binding<T>& b = binding_of<T>(s);
    return e1 == nullptr ? b.step(s, sys, y, t, dt) : b.form->step_error(s, sys, y, t, dt, e1, e2);
}

/// A single step of y' = f with every test of the header in order, each failure its status: the pointers, the
/// binding (else step_unbound checks the method and n and binds), t and dt, the estimates asked for. Out of
/// line where the plain step's fast path (step) fails a test (step_checked_plain); inline in the estimating
/// step's entry.
template <class T>
ODESTEP_INLINE odestep_status step_checked(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt,
                                           T* e1, T* e2) {
    if (ODESTEP_UNLIKELY(s == nullptr || sys == nullptr || sys->f == nullptr || y == nullptr))
        return ODESTEP_INVALID_SETTING;
    const binding<T>& b = binding_of<T>(s);
    const std::size_t n = sys->n;
    if (ODESTEP_UNLIKELY(b.first_order_n != n || n == 0)) {
        return step_unbound<T>(s, sys, y, t, dt, e1, e2);
    }
    const status checked = detail::check_step(t, dt);
    if (ODESTEP_UNLIKELY(checked != status::ok)) return to_c(checked);
    if (e1 == nullptr) return b.step(s, sys, y, t, dt);
    const method_ops<T>* m = ops<T>(s);
    if (m->error_estimates < 1 || (e2 != nullptr && m->error_estimates < 2)) return ODESTEP_INVALID_SETTING;
    return b.form->step_error(s, sys, y, t, dt, e1, e2);
}

/// step_checked of the plain step: its arguments all in registers (AAPCS: four integer ones, which
/// step_checked's seven do not fit), so that step reaches it with them untouched, by a tail call. Static:
/// GCC for ARM does not tail-call a function that may be replaced at link time (a template's weak instance).
template <class T>
[[gnu::noinline]] static odestep_status step_checked_plain(stepper_t<T>* s, const typename c_types<T>::system* sys,
                                                           T* y, T t, T dt) {
    return step_checked<T>(s, sys, y, t, dt, nullptr, nullptr);
}

/// A single step of y' = f. The plain step's fast path is one test of everything: the pointers not null, n
/// the bound one (whose method and n were checked when it was bound) and t and dt good; then a tail call of
/// the bound step. Any test failing, step_checked_plain, with the same arguments, finds the status. The two
/// are one indirect tail call of the function chosen, with the arguments as they came: as two calls, GCC
/// copied the arguments aside for the slow one and back (about 10 instructions on every step, Cortex-M4F).
template <class T>
ODESTEP_INLINE odestep_status step(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1,
                                   T* e2) {
    if (e1 != nullptr) return step_checked<T>(s, sys, y, t, dt, e1, e2);
    decltype(binding<T>::step) next = &step_checked_plain<T>;
    if (s != nullptr && sys != nullptr && sys->f != nullptr && y != nullptr) {
        const binding<T>& b = binding_of<T>(s);
        const std::size_t n = sys->n;
        if (b.first_order_n == n && n != 0 && detail::check_step(t, dt) == status::ok) next = b.step;
    }
    return next(s, sys, y, t, dt);
}

/// step_unbound for x'' = a.
template <class T>
[[gnu::noinline, gnu::cold]] odestep_status step_newton_unbound(stepper_t<T>* s, const typename c_types<T>::newton* sys,
                                                                T* x, T* v, T* acc, T t, T dt) {
    const method_ops<T>* m = ops<T>(s);
    const std::size_t n = sys->n;
    if (m == nullptr || !size_ok<T>(n) || !m->newtonian) return ODESTEP_INVALID_SETTING;
    const status checked = detail::check_step(t, dt);
    if (checked != status::ok) return to_c(checked);
    bind<T>(s, n, true, form_for(m, n));
    const binding<T>& b = binding_of<T>(s);
    return acc == nullptr ? b.step_newton(s, sys, x, v, t, dt) : b.form->step_newton_kept(s, sys, x, v, acc, t, dt);
}

/// step_checked for x'' = a (acc not null: the caller-kept step).
template <class T>
ODESTEP_INLINE odestep_status step_newton_checked(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v,
                                                  T* acc, T t, T dt) {
    if (ODESTEP_UNLIKELY(s == nullptr || sys == nullptr || sys->a == nullptr || x == nullptr || v == nullptr))
        return ODESTEP_INVALID_SETTING;
    const binding<T>& b = binding_of<T>(s);
    const std::size_t n = sys->n;
    if (ODESTEP_UNLIKELY(b.newton_n != n || n == 0)) {
        return step_newton_unbound<T>(s, sys, x, v, acc, t, dt);
    }
    const status checked = detail::check_step(t, dt);
    if (ODESTEP_UNLIKELY(checked != status::ok)) return to_c(checked);
    if (acc == nullptr) return b.step_newton(s, sys, x, v, t, dt);
    return b.form->step_newton_kept(s, sys, x, v, acc, t, dt);
}

/// step_checked_plain for x'' = a.
template <class T>
[[gnu::noinline]] static odestep_status step_newton_checked_plain(stepper_t<T>* s,
                                                                  const typename c_types<T>::newton* sys, T* x, T* v,
                                                                  T t, T dt) {
    return step_newton_checked<T>(s, sys, x, v, nullptr, t, dt);
}

/// A single step of x'' = a, as step.
template <class T>
ODESTEP_INLINE odestep_status step_newton(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T* acc,
                                          T t, T dt) {
    if (acc != nullptr) return step_newton_checked<T>(s, sys, x, v, acc, t, dt);
    decltype(binding<T>::step_newton) next = &step_newton_checked_plain<T>;
    if (s != nullptr && sys != nullptr && sys->a != nullptr && x != nullptr && v != nullptr) {
        const binding<T>& b = binding_of<T>(s);
        const std::size_t n = sys->n;
        if (b.newton_n == n && n != 0 && detail::check_step(t, dt) == status::ok) next = b.step_newton;
    }
    return next(s, sys, x, v, t, dt);
}

/// The stepper of the loops: the C method behind the stepper interface the C++ loops take. Its traits are
/// the loop's concern only (uniform_steps is checked by the C function before the loop, as the method's
/// trait is known only at run time). exact_rhs_evals only keeps the loop from wrapping f: c_rhs counts the
/// evaluations itself, and the C function reports that count instead of the loop's.
template <class T>
struct first_order_adapter : stepper_defaults<state<T>> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    static constexpr bool exact_rhs_evals = true;
    const method_ops<T>* m;
    void* storage;
    status step(const c_rhs<T>& f, state<T>& y, T t, T dt) const {
        return m->step(storage, f, y, t, dt, nullptr, nullptr);
    }
    void reset() const noexcept { m->reset(storage); }
};
template <class T>
struct newton_adapter : stepper_defaults<state<T>> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    static constexpr bool exact_rhs_evals = true;  ///< (see first_order_adapter)
    static constexpr system_form system = system_form::newtonian;
    const method_ops<T>* m;
    void* storage;
    status step(const c_accel<T>& a, state<T>& x, state<T>& v, T t, T dt) const {
        return m->step_newton(storage, a, x, v, nullptr, t, dt, true);
    }
    void reset() const noexcept { m->reset(storage); }
};

/// The C loops' pre-run check: odestep::integrate's (detail::preflight), with the method's uniform_steps, which
/// only its table knows (the adapters publish false): a bad plan, or a uniform-step method's shortened last
/// step, is refused before anything is touched.
template <class T, class Adapter>
status loop_preflight(const Adapter& stepper, T t0, T t1, T dt) noexcept {
    detail::grid_plan<T> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    return detail::preflight(stepper, planned, plan, stepper.m->uniform_steps);
}

template <class T>
void report(typename c_types<T>::run* run, T t, step_count steps, const counts& c = {}) noexcept {
    if (run != nullptr) {
        run->t = t;
        run->steps = steps;
        run->counts.rhs_evals = c.rhs_evals;
        run->counts.jacobian_evals = c.jacobian_evals;
        run->counts.event_evals = c.event_evals;
        run->counts.factorizations = c.factorizations;
        run->counts.newton_iterations = c.newton_iterations;
        run->counts.accepted_steps = c.accepted_steps;
        run->counts.rejected_steps = c.rejected_steps;
        run->counts.firings = c.firings;
    }
}

template <class T>
odestep_status integrate(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t0, T t1, T dt,
                         typename c_types<T>::observer observe, void* octx, typename c_types<T>::run* run) {
    report<T>(run, t0, 0);
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (m == nullptr || sys == nullptr || sys->f == nullptr || y == nullptr || !size_ok<T>(sys->n) || m->newtonian)
        return ODESTEP_INVALID_SETTING;
    const first_order_adapter<T> stepper{{}, m, object_of<T>(s)};
    const status checked = loop_preflight(stepper, t0, t1, dt);
    if (checked != status::ok) return to_c(checked);
    // The loop's object: padded, constructed afresh (an empty history), and bound, so that single steps of
    // the same n continue its history.
    bind<T>(s, sys->n, false, &m->padded);
    state<T> ys = load(y, sys->n);
    step_count calls = 0;
    const c_rhs<T> f{sys, &calls};
    const auto watch = [observe, octx](T t, const state<T>& at) {
        if (observe != nullptr) observe(t, at.data(), octx);
    };
    integrate_result<T> r = odestep::integrate(stepper, f, ys, t0, t1, dt, watch);
    store(y, ys, sys->n);  // the state at r.t, the last good one
    r.counts.rhs_evals = calls;
    report<T>(run, r.t, r.steps, r.counts);
    return to_c(r.status);
}

template <class T>
odestep_status integrate_newton(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T t0, T t1, T dt,
                                typename c_types<T>::newton_observer observe, void* octx,
                                typename c_types<T>::run* run) {
    report<T>(run, t0, 0);
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (m == nullptr || sys == nullptr || sys->a == nullptr || x == nullptr || v == nullptr || !size_ok<T>(sys->n) ||
        !m->newtonian)
        return ODESTEP_INVALID_SETTING;
    const newton_adapter<T> stepper{{}, m, object_of<T>(s)};
    const status checked = loop_preflight(stepper, t0, t1, dt);
    if (checked != status::ok) return to_c(checked);
    bind<T>(s, sys->n, true, &m->padded);  // as integrate's
    state<T> xs = load(x, sys->n);
    state<T> vs = load(v, sys->n);
    step_count calls = 0;
    const c_accel<T> a{sys, &calls};
    const auto watch = [observe, octx](T t, const state<T>& px, const state<T>& pv) {
        if (observe != nullptr) observe(t, px.data(), pv.data(), octx);
    };
    integrate_result<T> r = odestep::integrate(stepper, a, xs, vs, t0, t1, dt, watch);
    store(x, xs, sys->n);
    store(v, vs, sys->n);
    r.counts.rhs_evals = calls;
    report<T>(run, r.t, r.steps, r.counts);
    return to_c(r.status);
}

template <class T>
odestep_status init(stepper_t<T>* s, const typename c_types<T>::method* method) {
    if (s == nullptr || method == nullptr) return ODESTEP_INVALID_SETTING;
    s->method = method;
    unbind<T>(s);  // the object is constructed by the first step, for its n
    return ODESTEP_OK;
}

template <class T>
void reset(stepper_t<T>* s) {
    // An empty history: the next step constructs its object afresh.
    if (s != nullptr && s->method != nullptr) unbind<T>(s);
}

inline odestep_status info(const void* ops_or_null, const char* name, int order, int estimates, bool newtonian,
                           bool uniform, unsigned evals, odestep_method_info* out) {
    if (ops_or_null == nullptr || out == nullptr) return ODESTEP_INVALID_SETTING;
    out->name = name;
    out->order = order;
    out->error_estimates = estimates;
    out->newtonian = newtonian ? 1 : 0;
    out->uniform_steps = uniform ? 1 : 0;
    out->rhs_evals_per_step = evals;
    return ODESTEP_OK;
}

template <class T>
odestep_status method_info(const method_ops<T>* m, odestep_method_info* out) {
    if (m == nullptr) return ODESTEP_INVALID_SETTING;
    return info(m, m->name, m->order, m->error_estimates, m->newtonian, m->uniform_steps, m->rhs_evals_per_step, out);
}

}  // namespace odestep::capi

#endif
