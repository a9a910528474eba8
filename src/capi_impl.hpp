// SPDX-License-Identifier: BSL-1.0
// odestep C API: the adapters from the C structs (include/odestep/odestep.h) to the C++ templates, written
// once for float and double; capi_float.cpp and capi_double.cpp instantiate them under the C names.
//
// The state. A C caller's n is known at run time, a C++ state's size at compile time: each call copies the
// caller's n values into a std::array<T, ODESTEP_C_MAX_STATES> whose components n .. MAX-1 are zero, and
// the right-hand side's adapter hands the user's f only the first n components and writes zero to the
// others of dydt. The padding therefore stays exactly zero through every stage (0 + dt * sum of zeros), so
// the steppers' finiteness checks, which run over all MAX components, decide on the first n alone. On
// success the first n components are copied back; on failure nothing is.
//
// The stepper object (explicit_rk, splitting, adams) is constructed in the caller's storage
// (odestep_stepper_*.storage) by placement new: no heap, and a method is a constant table of function
// pointers (method_ops), so that a firmware links the code of the methods it names and no other.
#ifndef ODESTEP_SRC_CAPI_IMPL_HPP
#define ODESTEP_SRC_CAPI_IMPL_HPP

#include <array>
#include <cstddef>
#include <new>
#include <type_traits>

#include "odestep/explicit_rk.hpp"
#include "odestep/integrate.hpp"
#include "odestep/multistep.hpp"
#include "odestep/newtonian.hpp"
#include "odestep/odestep.h"
#include "odestep/status.hpp"
#include "odestep/symplectic.hpp"

namespace odestep::capi {

constexpr std::size_t max_states = ODESTEP_C_MAX_STATES;

/// The padded state of the C API.
template <class T>
using state = std::array<T, max_states>;

/// The C types of one precision.
template <class T>
struct c_types;
template <>
struct c_types<double> {
    using system = odestep_system_d;
    using newton = odestep_newton_d;
    using stepper = odestep_stepper_d;
    using method = odestep_method_d;
    using run = odestep_run_d;
    using observer = odestep_observer_d;
    using newton_observer = odestep_newton_observer_d;
};
template <>
struct c_types<float> {
    using system = odestep_system_f;
    using newton = odestep_newton_f;
    using stepper = odestep_stepper_f;
    using method = odestep_method_f;
    using run = odestep_run_f;
    using observer = odestep_observer_f;
    using newton_observer = odestep_newton_observer_f;
};

constexpr odestep_status to_c(status s) noexcept { return static_cast<odestep_status>(static_cast<int>(s)); }

/// y' = f(t, y) for the C++ steppers: the user's f on the first n components, zero for the others.
template <class T>
struct c_rhs {
    const typename c_types<T>::system* sys;
    void operator()(T t, const state<T>& y, state<T>& dydt) const {
        sys->f(t, y.data(), dydt.data(), sys->ctx);
        for (std::size_t i = sys->n; i < max_states; ++i) dydt[i] = T(0);
    }
};

/// x'' = a(t, x) for the C++ steppers: a force of position alone, returned.
template <class T>
struct c_accel {
    const typename c_types<T>::newton* sys;
    state<T> operator()(T t, const state<T>& x) const {
        state<T> a;
        sys->a(t, x.data(), a.data(), sys->ctx);
        for (std::size_t i = sys->n; i < max_states; ++i) a[i] = T(0);
        return a;
    }
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
    void (*construct)(void* storage);
    void (*reset)(void* storage);
    /// y' = f: a step of the object in storage, with up to two estimates (null: not asked for).
    status (*step)(void* storage, const c_rhs<T>& f, state<T>& y, T t, T dt, state<T>* e1, state<T>* e2);
    /// x'' = a: one step on its own (`kept` false: nothing reused from an earlier step), or a step of a loop
    /// whose x object stays the same (`kept` true: velocity Verlet reuses the last acceleration); with
    /// `acc`, the caller-kept form of a first-same-as-last method (acc = a(t, x) in, a(t + dt, x) out).
    status (*step_newton)(void* storage, const c_accel<T>& a, state<T>& x, state<T>& v, state<T>* acc, T t, T dt,
                          bool kept);
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

template <class S, class = void>
struct resettable : std::false_type {};
template <class S>
struct resettable<S, std::void_t<decltype(std::declval<S&>().reset())>> : std::true_type {};

/// The function pointers of stepper type S (on state<T>).
template <class S>
struct ops_of {
    using T = typename S::value_type;
    static_assert(std::is_same_v<typename S::state_type, state<T>>);
    static_assert(std::is_trivially_destructible_v<S>, "the C API never destroys a stepper object");
    static_assert(sizeof(S) <= sizeof(std::declval<typename c_types<T>::stepper&>().storage.bytes),
                  "odestep: ODESTEP_C_STEPPER_SCALARS is too small for this stepper");
    static_assert(alignof(S) <= alignof(typename c_types<T>::stepper), "odestep: the stepper storage's alignment");

    static S& object(void* storage) noexcept { return *std::launder(static_cast<S*>(storage)); }

    static void construct(void* storage) noexcept { ::new (storage) S(); }
    static void reset(void* storage) noexcept {
        if constexpr (resettable<S>::value) object(storage).reset();
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

template <class S>
constexpr method_ops<typename S::value_type> make_ops(const char* name) noexcept {
    return {name, S::order, estimates_of<S>::value, S::system == system_form::newtonian, S::uniform_steps,
            // The most of either step: Dormand-Prince's estimating step makes one more than its plain step.
            static_cast<unsigned>(S::rhs_evals_per_step > S::rhs_evals_per_error_step ? S::rhs_evals_per_step
                                                                                      : S::rhs_evals_per_error_step),
            &ops_of<S>::construct, &ops_of<S>::reset, &ops_of<S>::step, &ops_of<S>::step_newton};
}

// ---- the C functions, for one precision

template <class T>
using stepper_t = typename c_types<T>::stepper;

template <class T>
const method_ops<T>* ops(const stepper_t<T>* s) noexcept {
    return s->method != nullptr ? &s->method->ops : nullptr;
}

template <class T>
bool size_ok(std::size_t n) noexcept {
    return n >= 1 && n <= max_states;
}

/// The caller's n values into a padded state: the first n copied, the others zero.
template <class T>
ODESTEP_INLINE void load_into(state<T>& s, const T* from, std::size_t n) noexcept {
    ODESTEP_UNROLL
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
    ODESTEP_UNROLL
    for (std::size_t i = 0; i < max_states; ++i) {
        if (i < n) to[i] = s[i];
    }
}

/// The checks of a single step: t finite, dt finite and non-zero.
template <class T>
status check_step(T t, T dt) noexcept {
    if (!detail::is_finite(t)) return status::invalid_time;
    if (!detail::is_finite(dt) || dt == T(0)) return status::invalid_step;
    return status::ok;
}

template <class T>
odestep_status step(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t, T dt, T* e1, T* e2) {
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (ODESTEP_UNLIKELY(m == nullptr || sys == nullptr || sys->f == nullptr || y == nullptr || !size_ok<T>(sys->n) ||
                         m->newtonian))
        return ODESTEP_INVALID_SETTING;
    const status checked = check_step(t, dt);
    if (ODESTEP_UNLIKELY(checked != status::ok)) return to_c(checked);
    const std::size_t n = sys->n;
    state<T> ys = load(y, n);
    if (e1 == nullptr) {  // the plain step: no estimate arrays at all
        const status r = m->step(s->storage.bytes, c_rhs<T>{sys}, ys, t, dt, nullptr, nullptr);
        if (r == status::ok) store(y, ys, n);
        return to_c(r);
    }
    if (m->error_estimates < 1 || (e2 != nullptr && m->error_estimates < 2)) return ODESTEP_INVALID_SETTING;
    state<T> err1{};
    state<T> err2{};
    const status r = m->step(s->storage.bytes, c_rhs<T>{sys}, ys, t, dt, &err1, e2 != nullptr ? &err2 : nullptr);
    if (r == status::ok) {
        store(y, ys, n);
        store(e1, err1, n);
        if (e2 != nullptr) store(e2, err2, n);
    }
    return to_c(r);
}

template <class T>
odestep_status step_newton(stepper_t<T>* s, const typename c_types<T>::newton* sys, T* x, T* v, T* acc, T t, T dt) {
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (m == nullptr || sys == nullptr || sys->a == nullptr || x == nullptr || v == nullptr || !size_ok<T>(sys->n) ||
        !m->newtonian)
        return ODESTEP_INVALID_SETTING;
    const status checked = check_step(t, dt);
    if (checked != status::ok) return to_c(checked);
    state<T> xs = load(x, sys->n);
    state<T> vs = load(v, sys->n);
    state<T> as{};
    if (acc != nullptr) load_into(as, acc, sys->n);
    const status r =
        m->step_newton(s->storage.bytes, c_accel<T>{sys}, xs, vs, acc != nullptr ? &as : nullptr, t, dt, false);
    if (r == status::ok) {
        store(x, xs, sys->n);
        store(v, vs, sys->n);
        if (acc != nullptr) store(acc, as, sys->n);
    }
    return to_c(r);
}

/// The stepper of the loops: the C method behind the stepper interface the C++ loops take. Its traits are
/// the loop's concern only (uniform_steps is checked by the C function before the loop, as the method's
/// trait is known only at run time).
template <class T>
struct first_order_adapter : stepper_defaults<state<T>> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
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
    static constexpr system_form system = system_form::newtonian;
    const method_ops<T>* m;
    void* storage;
    status step(const c_accel<T>& a, state<T>& x, state<T>& v, T t, T dt) const {
        return m->step_newton(storage, a, x, v, nullptr, t, dt, true);
    }
    void reset() const noexcept { m->reset(storage); }
};

/// A uniform-step method refuses a plan whose last step is shortened, before anything is touched (as
/// odestep::integrate does with the trait known at compile time).
template <class T>
status check_uniform(const method_ops<T>* m, T t0, T t1, T dt) noexcept {
    if (!m->uniform_steps) return status::ok;
    detail::grid_plan<T> plan;
    const status planned = detail::plan_run(t0, t1, dt, plan);
    if (planned == status::ok && plan.uneven_last()) return status::step_mismatch;
    return status::ok;  // a bad plan is reported by the loop itself
}

template <class T>
void report(typename c_types<T>::run* run, T t, step_count steps) noexcept {
    if (run != nullptr) {
        run->t = t;
        run->steps = steps;
    }
}

template <class T>
odestep_status integrate(stepper_t<T>* s, const typename c_types<T>::system* sys, T* y, T t0, T t1, T dt,
                         typename c_types<T>::observer observe, void* octx, typename c_types<T>::run* run) {
    report<T>(run, t0, 0);
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (m == nullptr || sys == nullptr || sys->f == nullptr || y == nullptr || !size_ok<T>(sys->n) || m->newtonian)
        return ODESTEP_INVALID_SETTING;
    const status uniform = check_uniform(m, t0, t1, dt);
    if (uniform != status::ok) return to_c(uniform);
    m->reset(s->storage.bytes);
    state<T> ys = load(y, sys->n);
    const first_order_adapter<T> stepper{{}, m, s->storage.bytes};
    const c_rhs<T> f{sys};
    const auto watch = [observe, octx](T t, const state<T>& at) {
        if (observe != nullptr) observe(t, at.data(), octx);
    };
    const integrate_result<T> r = odestep::integrate(stepper, f, ys, t0, t1, dt, watch);
    store(y, ys, sys->n);  // the state at r.t, the last good one
    report<T>(run, r.t, r.steps);
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
    const status uniform = check_uniform(m, t0, t1, dt);
    if (uniform != status::ok) return to_c(uniform);
    m->reset(s->storage.bytes);
    state<T> xs = load(x, sys->n);
    state<T> vs = load(v, sys->n);
    const newton_adapter<T> stepper{{}, m, s->storage.bytes};
    const c_accel<T> a{sys};
    const auto watch = [observe, octx](T t, const state<T>& px, const state<T>& pv) {
        if (observe != nullptr) observe(t, px.data(), pv.data(), octx);
    };
    const integrate_result<T> r = odestep::integrate(stepper, a, xs, vs, t0, t1, dt, watch);
    store(x, xs, sys->n);
    store(v, vs, sys->n);
    report<T>(run, r.t, r.steps);
    return to_c(r.status);
}

template <class T>
odestep_status init(stepper_t<T>* s, const typename c_types<T>::method* method) {
    if (s == nullptr || method == nullptr) return ODESTEP_INVALID_SETTING;
    s->method = method;
    ops<T>(s)->construct(s->storage.bytes);
    return ODESTEP_OK;
}

template <class T>
void reset(stepper_t<T>* s) {
    const method_ops<T>* m = s != nullptr ? ops<T>(s) : nullptr;
    if (m != nullptr) m->reset(s->storage.bytes);
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
