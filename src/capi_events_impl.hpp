// SPDX-License-Identifier: BSL-1.0
// odestep C API: the per-tick event loop (odestep_event_loop_*), over odestep::event_stepper. Written once
// for float and double; capi_events_float.cpp and capi_events_double.cpp instantiate it. Kept apart from
// the steppers so that a firmware that does not use events links none of the event code even without
// --gc-sections (a static library is linked by object file).
//
// The events. The C++ event set holds each event as its own type; the C caller gives an array whose length
// is known at run time. The set here has ODESTEP_C_MAX_EVENTS events of one type, each a copy of a C
// descriptor (function pointers and settings, by value: nothing points into the caller's array); the slots
// past the caller's count have no g and evaluate to the constant 1, which never crosses zero, so they never
// fire (they cost a test of a null pointer per evaluation).
//
// The stepper. The method is chosen at run time (the C method table), so the loop's stepper is an adapter
// that holds the method and the stepper object's storage by value (owning_adapter); event_stepper resets it
// (an Adams history) after an action changed the state, and puts it back as it was (kept_object) when it
// rolls a step back.
#ifndef ODESTEP_SRC_CAPI_EVENTS_IMPL_HPP
#define ODESTEP_SRC_CAPI_EVENTS_IMPL_HPP

#include <limits>
#include <tuple>
#include <utility>

#include "capi_impl.hpp"
#include "odestep/events/events.hpp"

namespace odestep::capi {

constexpr std::size_t max_events = ODESTEP_C_MAX_EVENTS;

/// The C event types of one precision.
template <class T>
struct event_types {
    static_assert(std::is_same_v<T, double> || std::is_same_v<T, float>);
    using event = by_precision<T, odestep_event_d, odestep_event_f>;
    using loop = by_precision<T, odestep_event_loop_d, odestep_event_loop_f>;
    using tick = by_precision<T, odestep_tick_d, odestep_tick_f>;
    using g = by_precision<T, odestep_event_fn_d, odestep_event_fn_f>;
    using action = by_precision<T, odestep_event_action_d, odestep_event_action_f>;
    using newton_event = by_precision<T, odestep_newton_event_d, odestep_newton_event_f>;
    using newton_loop = by_precision<T, odestep_newton_event_loop_d, odestep_newton_event_loop_f>;
    using newton_g = by_precision<T, odestep_newton_event_fn_d, odestep_newton_event_fn_f>;
    using newton_action = by_precision<T, odestep_newton_event_action_d, odestep_newton_event_action_f>;
};

/// g(t, y) of one C event; without a function (an unused slot), the constant 1. `calls` counts the calls of
/// g (the loop's copy of the event keeps it: event_counts).
template <class T>
struct c_g {
    typename event_types<T>::g g;
    void* ctx;
    mutable step_count calls = 0;
    T operator()(T t, const state<T>& y) const {
        if (g == nullptr) return T(1);
        ++calls;
        return g(t, y.data(), ctx);
    }
};

/// The action of one C event; without a function, a terminal event.
template <class T>
struct c_action {
    typename event_types<T>::action fn;
    void* ctx;
    event_result operator()(T t, state<T>& y) const {
        if (fn == nullptr) return event_result::stop;
        return fn(t, y.data(), ctx) == ODESTEP_PROCEED ? event_result::proceed : event_result::stop;
    }
};

/// g(t, x, v) of one C event of Newton's equations; without a function, the constant 1.
template <class T>
struct c_newton_g {
    typename event_types<T>::newton_g g;
    void* ctx;
    mutable step_count calls = 0;  ///< (as c_g's)
    T operator()(T t, const state<T>& x, const state<T>& v) const {
        if (g == nullptr) return T(1);
        ++calls;
        return g(t, x.data(), v.data(), ctx);
    }
};

/// The action on x and v of one C event; without a function, a terminal event.
template <class T>
struct c_newton_action {
    typename event_types<T>::newton_action fn;
    void* ctx;
    event_result operator()(T t, state<T>& x, state<T>& v) const {
        if (fn == nullptr) return event_result::stop;
        return fn(t, x.data(), v.data(), ctx) == ODESTEP_PROCEED ? event_result::proceed : event_result::stop;
    }
};

/// What an event loop keeps of its stepper object before a step (the engine's stepper_memory, through the
/// adapters' memory() and restore_memory()): the method's memory_bytes of the object, copied, so that a step
/// the engine rolls back leaves the stepper as it was (an Adams history goes on), as the C++ loops keep it;
/// nothing for a method without memory.
template <class T>
struct kept_object {
    alignas(stepper_t<T>) unsigned char bytes[sizeof(stepper_t<T>::storage)];  // the first memory_bytes kept
};
template <class T>
ODESTEP_INLINE kept_object<T> keep_object(const method_ops<T>* m, const unsigned char* storage) noexcept {
    kept_object<T> k;
    if (m->memory_bytes != 0) std::memcpy(k.bytes, storage, m->memory_bytes);
    return k;
}
template <class T>
ODESTEP_INLINE void put_back_object(const method_ops<T>* m, unsigned char* storage, const kept_object<T>& k) noexcept {
    if (m->memory_bytes != 0) std::memcpy(storage, k.bytes, m->memory_bytes);
}

/// The loop's stepper: a C method and its stepper object, held by value. exact_rhs_evals only keeps the
/// loop from wrapping f: c_rhs counts every evaluation into `evaluations` (see event_counts).
template <class T>
struct owning_adapter : stepper_defaults<state<T>> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    static constexpr bool exact_rhs_evals = true;
    step_count evaluations = 0;
    const method_ops<T>* m = nullptr;
    alignas(stepper_t<T>) unsigned char storage[sizeof(stepper_t<T>::storage)] = {};
    status step(const c_rhs<T>& f, state<T>& y, T t, T dt) { return m->step(storage, f, y, t, dt, nullptr, nullptr); }
    void reset() noexcept { m->reset(storage); }
    kept_object<T> memory() const noexcept { return keep_object(m, storage); }  ///< (see kept_object)
    void restore_memory(const kept_object<T>& k) noexcept { put_back_object(m, storage, k); }
};

/// The Newtonian loop's stepper. Each step evaluates the acceleration afresh (`kept` false): the loop's x
/// is a copy made for each tick, so a kept acceleration could be matched by that copy's address alone.
template <class T>
struct owning_newton_adapter : stepper_defaults<state<T>> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    static constexpr bool exact_rhs_evals = true;  ///< (see owning_adapter)
    static constexpr system_form system = system_form::newtonian;
    step_count evaluations = 0;
    const method_ops<T>* m = nullptr;
    alignas(stepper_t<T>) unsigned char storage[sizeof(stepper_t<T>::storage)] = {};
    status step(const c_accel<T>& a, state<T>& x, state<T>& v, T t, T dt) {
        return m->step_newton(storage, a, x, v, nullptr, t, dt, false);
    }
    void reset() noexcept { m->reset(storage); }
    kept_object<T> memory() const noexcept { return keep_object(m, storage); }  ///< (see kept_object)
    void restore_memory(const kept_object<T>& k) noexcept { put_back_object(m, storage, k); }
};

/// What differs between the first-order loop and the Newtonian one.
template <class T, bool Newton>
struct kind;
template <class T>
struct kind<T, false> {
    using c_event = typename event_types<T>::event;
    using c_loop = typename event_types<T>::loop;
    using c_system = typename c_types<T>::system;
    using g_type = c_g<T>;
    using action_type = c_action<T>;
    using stepper = owning_adapter<T>;
    using system_adapter = c_rhs<T>;
    static bool system_ok(const c_system* s) noexcept { return s != nullptr && s->f != nullptr; }
};
template <class T>
struct kind<T, true> {
    using c_event = typename event_types<T>::newton_event;
    using c_loop = typename event_types<T>::newton_loop;
    using c_system = typename c_types<T>::newton;
    using g_type = c_newton_g<T>;
    using action_type = c_newton_action<T>;
    using stepper = owning_newton_adapter<T>;
    using system_adapter = c_accel<T>;
    static bool system_ok(const c_system* s) noexcept { return s != nullptr && s->a != nullptr; }
};

template <class T, bool Newton>
using c_event = event<state<T>, typename kind<T, Newton>::g_type, typename kind<T, Newton>::action_type>;

template <class T, bool Newton, std::size_t>
using event_at = c_event<T, Newton>;

template <class T, bool Newton, class Sequence>
struct set_for;
template <class T, bool Newton, std::size_t... I>
struct set_for<T, Newton, std::index_sequence<I...>> {
    using type = event_set<default_root_finder, event_at<T, Newton, I>...>;
    static type make(const std::array<c_event<T, Newton>, max_events>& e, event_limits limits) {
        return type{std::tuple<event_at<T, Newton, I>...>(e[I]...), limits};
    }
};
template <class T, bool Newton>
using set_maker = set_for<T, Newton, std::make_index_sequence<max_events>>;
template <class T, bool Newton>
using loop_t =
    event_stepper<typename kind<T, Newton>::stepper, typename set_maker<T, Newton>::type, ODESTEP_C_TICK_FIRINGS>;

template <class T, bool Newton>
loop_t<T, Newton>& loop_object(typename kind<T, Newton>::c_loop* loop) noexcept {
    static_assert(sizeof(loop_t<T, Newton>) <= sizeof(loop->storage.bytes),
                  "odestep: the event loop's storage in odestep.h is too small");
    static_assert(alignof(loop_t<T, Newton>) <= alignof(typename kind<T, Newton>::c_loop),
                  "odestep: the event loop's storage alignment");
    static_assert(std::is_trivially_destructible_v<loop_t<T, Newton>>, "the C API never destroys a loop object");
    return *std::launder(reinterpret_cast<loop_t<T, Newton>*>(loop->storage.bytes));
}
template <class T, bool Newton>
const loop_t<T, Newton>& loop_object(const typename kind<T, Newton>::c_loop* loop) noexcept {
    return *std::launder(reinterpret_cast<const loop_t<T, Newton>*>(loop->storage.bytes));
}

/// Starts a loop: y is {y} (first order) or {x, v} (Newton's equations).
template <class T, bool Newton>
odestep_status event_start(typename kind<T, Newton>::c_loop* loop, const typename c_types<T>::method* method,
                           const typename kind<T, Newton>::c_event* events, std::size_t count,
                           const odestep_event_limits* limits, const typename kind<T, Newton>::c_system* sys,
                           const T* y, const T* v, T t0, T dt) {
    using K = kind<T, Newton>;
    if (loop == nullptr) return ODESTEP_INVALID_SETTING;
    loop->n = 0;  // not started until start succeeds
    if (method == nullptr || events == nullptr || !K::system_ok(sys) || y == nullptr || (Newton && v == nullptr) ||
        !size_ok<T>(sys->n) || count == 0 || count > max_events || method->ops.newtonian != Newton)
        return ODESTEP_INVALID_SETTING;
    std::array<c_event<T, Newton>, max_events> set{};
    for (std::size_t i = 0; i < max_events; ++i) {
        if (i >= count) {
            set[i] = c_event<T, Newton>{typename K::g_type{nullptr, nullptr},
                                        direction::either,
                                        typename K::action_type{nullptr, nullptr},
                                        T(0),
                                        T(0),
                                        T(0),
                                        0};
            continue;
        }
        const auto& e = events[i];
        if (e.g == nullptr) return ODESTEP_INVALID_SETTING;
        direction d = direction::either;
        switch (e.direction) {
            case ODESTEP_RISING: d = direction::rising; break;
            case ODESTEP_FALLING: d = direction::falling; break;
            case ODESTEP_EITHER: d = direction::either; break;
            default: return ODESTEP_INVALID_SETTING;
        }
        set[i] = c_event<T, Newton>{typename K::g_type{e.g, e.ctx},
                                    d,
                                    typename K::action_type{e.action, e.ctx},
                                    e.tolerance,
                                    e.band,
                                    e.dead_time,
                                    e.max_firings};
    }
    event_limits l{};
    if (limits != nullptr) {
        l.max_iterations = limits->max_iterations;
        if (limits->max_firings_per_step != 0) l.max_firings_per_step = limits->max_firings_per_step;
        l.probes = limits->probes;
    }
    loop_t<T, Newton>* lp = ::new (static_cast<void*>(loop->storage.bytes))
        loop_t<T, Newton>(typename K::stepper{}, set_maker<T, Newton>::make(set, l));
    lp->stepper().m = &method->ops;
    method->ops.construct(lp->stepper().storage);
    const state<T> ys = load(y, sys->n);
    status s = status::ok;
    if constexpr (Newton) {
        const state<T> vs = load(v, sys->n);
        s = lp->start(t0, dt, ys, vs);
    } else {
        s = lp->start(t0, dt, ys);
    }
    if (s == status::ok) loop->n = sys->n;
    return to_c(s);
}

/// One tick: y is y (first order) or x, with v (Newton's equations).
template <class T, bool Newton>
odestep_status event_tick(typename kind<T, Newton>::c_loop* loop, const typename kind<T, Newton>::c_system* sys, T* y,
                          T* v, typename event_types<T>::tick* tick) {
    using K = kind<T, Newton>;
    if (loop == nullptr || loop->n == 0) return ODESTEP_INVALID_TIME;  // as event_stepper::tick before start
    if (!K::system_ok(sys) || y == nullptr || (Newton && v == nullptr) || sys->n != loop->n)
        return ODESTEP_INVALID_SETTING;
    loop_t<T, Newton>& lp = loop_object<T, Newton>(loop);
    state<T> ys = load(y, sys->n);
    tick_result<T, ODESTEP_C_TICK_FIRINGS> r;
    if constexpr (Newton) {
        state<T> vs = load(v, sys->n);
        r = lp.tick(typename K::system_adapter{sys, &lp.stepper().evaluations}, ys, vs);
        store(v, vs, sys->n);
    } else {
        r = lp.tick(typename K::system_adapter{sys, &lp.stepper().evaluations}, ys);
    }
    store(y, ys, sys->n);  // the state at r.t, whatever the status
    if (tick != nullptr) {
        tick->t = r.t;
        tick->fired = r.fired;
        tick->event = r.event;
        for (std::size_t k = 0; k < r.fired && k < ODESTEP_C_TICK_FIRINGS; ++k) {
            tick->firings[k].event = r.firings[k].event;
            tick->firings[k].t = r.firings[k].t;
        }
    }
    return to_c(r.status);
}

template <class T, bool Newton>
odestep_status event_rearm(typename kind<T, Newton>::c_loop* loop, const T* y, const T* v) {
    if (loop == nullptr || loop->n == 0) return ODESTEP_INVALID_TIME;
    if (y == nullptr || (Newton && v == nullptr)) return ODESTEP_INVALID_SETTING;
    const state<T> ys = load(y, loop->n);
    if constexpr (Newton) {
        const state<T> vs = load(v, loop->n);
        return to_c(loop_object<T, Newton>(loop).rearm(ys, vs));
    } else {
        return to_c(loop_object<T, Newton>(loop).rearm(ys));
    }
}

template <class T, bool Newton>
T event_time(const typename kind<T, Newton>::c_loop* loop) {
    if (loop == nullptr || loop->n == 0) return std::numeric_limits<T>::quiet_NaN();
    return loop_object<T, Newton>(loop).time();
}

/// What the loop did since start (event_stepper::counts), with f's and g's evaluations as c_rhs and c_g
/// counted them (the unused slots' constant g is no evaluation).
template <class T, bool Newton>
odestep_status event_counts(const typename kind<T, Newton>::c_loop* loop, odestep_counts* out) {
    if (out == nullptr) return ODESTEP_INVALID_SETTING;
    *out = odestep_counts{};
    if (loop == nullptr || loop->n == 0) return ODESTEP_INVALID_TIME;
    const loop_t<T, Newton>& lp = loop_object<T, Newton>(loop);
    const counts c = lp.counts();
    out->rhs_evals = lp.stepper().evaluations;
    step_count g_calls = 0;
    std::apply([&](const auto&... e) { ((g_calls += e.g.calls), ...); }, lp.events().events);
    out->event_evals = g_calls;
    out->accepted_steps = c.accepted_steps;
    out->firings = c.firings;
    return ODESTEP_OK;
}

template <class T, bool Newton>
std::size_t event_firings(const typename kind<T, Newton>::c_loop* loop, std::size_t i) {
    if (loop == nullptr || loop->n == 0 || i >= max_events) return 0;
    return loop_object<T, Newton>(loop).firings(i);
}

}  // namespace odestep::capi

#endif
