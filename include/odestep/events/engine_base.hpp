// SPDX-License-Identifier: BSL-1.0
// odestep: the event engine's base: its types, the events' memory, the work counted off the quiet path, and the
// evaluation of the set (every g at a state, one g by a run-time index, the crossing tests), which the location
// (location.hpp) and the engine's phases (engine.hpp) share.
#ifndef ODESTEP_EVENTS_ENGINE_BASE_HPP
#define ODESTEP_EVENTS_ENGINE_BASE_HPP

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "../detail/grid_clock.hpp"
#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "arming.hpp"
#include "event.hpp"

namespace odestep {

namespace detail {

template <class State, class G, class T, class Ptrs, std::size_t... I>
constexpr T call_g(G& g, T t, const Ptrs& y, std::index_sequence<I...>) {
    return static_cast<T>(g(t, static_cast<const State&>(*y[I])...));
}

template <class S, class System, class State, class T, std::size_t... I>
constexpr status call_step(S& stepper, System& f, const std::array<State*, sizeof...(I)>& y, T t, T h,
                           std::index_sequence<I...>) {
    return stepper.step(f, *y[I]..., t, h);
}

// The engine's types, the events' memory and the evaluation of the set. K is the number of state objects
// (1: y; 2: x and v).
template <class State, std::size_t K, class Set>
class event_engine_base;

template <class State, std::size_t K, class Finder, class... Events>
class event_engine_base<State, K, event_set<Finder, Events...>> {
public:
    using T = value_type_t<State>;
    using set_type = event_set<Finder, Events...>;
    static constexpr std::size_t E = sizeof...(Events);
    using pack = std::array<State, K>;
    using refs = std::array<State*, K>;
    using values = std::array<T, E>;

    std::array<event_memory<T>, E> memory{};
    // Every event is armed and the set has no probes: the quiet step's test is then one product per event.
    // Kept by rearm (which reads the probes: a change of set.limits.probes takes effect at the next rearm)
    // and fire_all; read by the quiet step's test.
    bool all_armed = false;
    // The work done off the quiet path, counted where it is done (the loops derive the quiet step's: one step
    // call and E evaluations of g): step calls that failed in advance, re-step calls (location, probes, the
    // rest of a step after an action), evaluations of f made directly (Hermite slopes, headings), and
    // evaluations of g (the start's, and every one off the quiet path).
    struct rest_work {
        step_count failed_steps = 0;
        step_count steps = 0;
        step_count rhs = 0;
        step_count g = 0;
    };
    rest_work work{};

protected:
    using seq = std::make_index_sequence<K>;
    using events_seq = std::index_sequence_for<Events...>;

    ODESTEP_INLINE static void load(const refs& y, pack& p) {
        for (std::size_t k = 0; k < K; ++k) p[k] = *y[k];
    }
    static void store(const refs& y, const pack& p) {
        for (std::size_t k = 0; k < K; ++k) *y[k] = p[k];
    }
    static refs pointers(pack& p) {
        refs r;
        for (std::size_t k = 0; k < K; ++k) r[k] = &p[k];
        return r;
    }
    static bool all_finite_pack(const pack& p) {
        for (std::size_t k = 0; k < K; ++k)
            if (!finite_values(p[k])) return false;
        return true;
    }
    // detail::all_finite, which is always inlined (the steppers' hot paths), behind a call the compiler may
    // keep out of line: these are the event loop's rare paths, and at -Os one shared copy is the smaller
    // (inlined everywhere, the M4F float -Os event tick is larger).
    template <class A>
    static bool finite_values(const A& a) noexcept {
        return all_finite(a);
    }

    template <class Set, class Fn, std::size_t... I>
    ODESTEP_INLINE static void for_each_impl(Set& set, Fn&& fn, std::index_sequence<I...>) {
        (fn(std::integral_constant<std::size_t, I>{}, std::get<I>(set.events)), ...);
    }
    template <class Set, class Fn>
    ODESTEP_INLINE static void for_each(Set& set, Fn&& fn) {
        for_each_impl(set, fn, events_seq{});
    }

    template <class Ev>
    static void check_event_type() {
        static_assert(std::is_same_v<typename Ev::state_type, State>,
                      "odestep: an event's State (make_event<State>) must be the integrated state type");
    }

    // g_i(t, y) for every event, unchecked.
    template <class Ptrs>
    ODESTEP_INLINE static void evaluate(set_type& set, T t, const Ptrs& y, values& g) {
        for_each(set, [&](auto index, auto& e) {
            using Ev = std::remove_reference_t<decltype(e)>;
            check_event_type<Ev>();
            constexpr std::size_t i = decltype(index)::value;
            g[i] = call_g<State>(e.g, t, y, seq{});
        });
    }

    // g_i(t, y) for every event; false if one is NaN or Inf.
    template <class Ptrs>
    bool evaluate_all(set_type& set, T t, const Ptrs& y, values& g) {
        evaluate(set, t, y, g);
        work.g += E;
        return finite_values(g);
    }

    // fn(event) for event i, a run-time index: the one place that turns an index into an event's type.
    template <class Set, class Fn>
    static void visit(Set& set, std::size_t i, Fn&& fn) {
        for_each(set, [&](auto index, auto& e) {
            if (decltype(index)::value == i) fn(e);
        });
    }

    // g of event i at (t, y).
    T evaluate_one(set_type& set, std::size_t i, T t, const refs& y) {
        T value = T(0);
        work.g += 1;
        visit(set, i, [&](auto& e) { value = call_g<State>(e.g, t, y, seq{}); });
        return value;
    }

    static direction direction_of(const set_type& set, std::size_t i) {
        direction d = direction::either;
        visit(set, i, [&](const auto& e) { d = e.direction; });
        return d;
    }

    // Event i (a run-time index) has crossed zero in its direction between its memory and g_now.
    bool crossed(const set_type& set, std::size_t i, T g_now) const {
        return memory[i].armed && crosses(direction_of(set, i), memory[i].g, g_now);
    }

    // Any event crossed (compile-time indices, each event's own direction).
    bool any_crossing(const set_type& set, const values& g) const {
        bool any = false;
        for_each(set, [&](auto index, const auto& e) {
            constexpr std::size_t i = decltype(index)::value;
            any = any || (memory[i].armed && crosses(e.direction, memory[i].g, g[i]));
        });
        return any;
    }
};

}  // namespace detail

}  // namespace odestep

#endif
