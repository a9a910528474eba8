// SPDX-License-Identifier: BSL-1.0
// Compiled with -fno-exceptions -fno-rtti and inspected for mutable static storage (.data/.bss) by
// check_static_state.cmake: every stepper instantiated in float, double and long double.
#include <odestep/odestep.hpp>

#include <array>

#include "support/methods.hpp"

namespace {
template <class T>
using state4 = std::array<T, 4>;

struct oscillators {
    template <class T>
    state4<T> operator()(T, const state4<T>& y) const noexcept {
        return {y[1], -y[0], y[3], T(-4) * y[2]};
    }
};

template <class T>
T run_everything() {
    T sum = T(0);
    odestep_test::for_each_method([&](auto method) {
        using stepper_t = odestep::explicit_rk<decltype(method), state4<T>>;
        state4<T> y{T(1), T(0), T(1), T(0)};
        if (odestep::integrate(stepper_t{}, oscillators{}, y, T(0), T(1), T(0.125)).status == odestep::status::ok)
            sum += y[0];
        if constexpr (stepper_t::error_estimate) {
            state4<T> err{};
            if (stepper_t{}.step(oscillators{}, y, T(0), T(0.125), err) == odestep::status::ok) sum += err[0];
        }
    });
    // and the Newtonian family, whose history lives in the stepper objects, never in statics
    using vec = std::array<T, 2>;
    auto spring = [](T, const vec& x) { return vec{-x[0], -x[1]}; };
    auto add = [&](auto stepper) {
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        if (odestep::integrate(stepper, spring, x, v, T(0), T(1), T(0.125)).status == odestep::status::ok) sum += x[0];
    };
    odestep_test::for_each_type<odestep_test::newtonian_steppers<vec>>(add);
    // the first-same-as-last steppers' form with the acceleration kept by the caller
    auto add_caller_kept = [&](const auto& stepper) {
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        vec acc = spring(T(0), x);
        for (int i = 0; i < 8; ++i)
            if (stepper.step(spring, x, v, acc, T(i) * T(0.125), T(0.125)) != odestep::status::ok) return;
        sum += x[0] + acc[1];
    };
    add_caller_kept(odestep::velocity_verlet<vec>{});
    add_caller_kept(odestep::blanes_moan4<vec>{});
    // Beeman's form with a_n and a_{n-1} kept by the caller
    {
        const odestep::beeman<vec> stepper;
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        typename odestep::beeman<vec>::history hist{};
        for (int i = 0; i < 8; ++i)
            if (stepper.step(spring, x, v, hist, T(i) * T(0.125), T(0.125)) != odestep::status::ok) break;
        sum += x[0] + hist.acc_prev[1];
    }
    // and the Boris pushers
    using vec3 = std::array<T, 3>;
    auto fields = [](T, const vec3& x, vec3& E, vec3& B) {
        E = {T(0), T(0.5), x[2]};
        B = {T(0), T(0), T(1)};
    };
    auto push = [&](const auto& pusher) {
        vec3 x{T(0), T(0), T(0)};
        vec3 v{T(1), T(0), T(0)};
        if (pusher.stagger(fields, x, v, T(0), T(0.125)) == odestep::status::ok &&
            odestep::integrate(pusher, fields, x, v, T(0), T(1), T(0.125)).status == odestep::status::ok &&
            pusher.synchronize(fields, x, v, T(1), T(0.125)) == odestep::status::ok)
            sum += x[0] + v[0];
    };
    push(odestep::boris<vec3>{T(2)});
    push(odestep::boris_relativistic<vec3>{T(2), T(3)});
    // and the Adams family, whose derivative history lives in the stepper objects too
    auto add_adams = [&](auto stepper) {
        state4<T> y{T(1), T(0), T(1), T(0)};
        if (odestep::integrate_n_steps(stepper, oscillators{}, y, T(0), T(0.125), 8).status == odestep::status::ok)
            sum += y[0];
    };
    odestep_test::for_each_type<odestep_test::adams_steppers<state4<T>>>(add_adams);
    // and the event loops, with every root finder: their memory lives in the loop objects
    auto events_with = [&](auto finder) {
        using F = decltype(finder);
        auto g = [](T, const state4<T>& y) { return y[0]; };
        auto flip = [](T, state4<T>& y) { y[1] = -y[1]; };
        state4<T> y{T(1), T(0), T(1), T(0)};
        const auto r =
            odestep::integrate(odestep::rk4<state4<T>>{}, oscillators{}, y, T(0), T(4), T(0.125),
                               odestep::watch<F>(odestep::make_event<state4<T>>(g, odestep::direction::falling, flip)));
        if (r.status == odestep::status::ok) sum += y[0];
        auto loop = odestep::make_event_stepper(
            odestep::rk4<state4<T>>{},
            odestep::watch<F>(odestep::make_event<state4<T>>(g, odestep::direction::either)));
        if (loop.start(T(0), T(0.125), y) == odestep::status::ok &&
            loop.tick(oscillators{}, y).status == odestep::status::ok)
            sum += y[0];
    };
    // and the implicit and Rosenbrock steppers: their settings live in the objects, their work on the stack
    auto add_implicit = [&](auto stepper) {
        state4<T> y{T(1), T(0), T(1), T(0)};
        if (odestep::integrate(stepper, oscillators{}, y, T(0), T(1), T(0.125)).status == odestep::status::ok)
            sum += y[0];
    };
    add_implicit(odestep::backward_euler<state4<T>>{});
    add_implicit(odestep::trapezoid<state4<T>>{});
    add_implicit(odestep::implicit_midpoint<state4<T>>{});
    add_implicit(odestep::gauss4<state4<T>>{});
    add_implicit(odestep::sdirk3<state4<T>>{});
    add_implicit(odestep::radau_iia5<state4<T>>{});
    add_implicit(odestep::radau_iia5<state4<T>, odestep::fixed_newton<3>>{});
    add_implicit(odestep::rodas3<state4<T>>{});
    add_implicit(odestep::radau5_substeps<state4<T>, 64>{});
    add_implicit(odestep::rodas4_substeps<state4<T>, 64>{});
    // and the error-controlled steppers: the step size and the kept stage live in the objects
    auto add_adaptive = [&](auto method) {
        using M = decltype(method);
        state4<T> y{T(1), T(0), T(1), T(0)};
        if (odestep::integrate(odestep::adaptive_substeps<M, state4<T>, 64>{}, oscillators{}, y, T(0), T(1), T(0.125))
                .status == odestep::status::ok)
            sum += y[0];
        odestep::adaptive_rk<M, state4<T>> engine;
        const std::array<T, 2> times{T(0.5), T(1)};
        if (odestep::integrate_times(engine, oscillators{}, y, T(0), times, [&](T, const state4<T>& u) {
                sum += u[0];
            }).status == odestep::status::ok)
            sum += y[0];
    };
    add_adaptive(odestep::tables::bogacki_shampine32{});
    add_adaptive(odestep::tables::cash_karp54{});
    add_adaptive(odestep::tables::dormand_prince54{});
    add_adaptive(odestep::tables::dop853{});
    events_with(odestep::bisection{});
    events_with(odestep::illinois{});
    events_with(odestep::anderson_bjorck{});
    events_with(odestep::brent{});
    events_with(odestep::itp{});
    return sum;
}
}  // namespace

// External linkage so nothing is optimised away.
float discipline_float() { return run_everything<float>(); }
double discipline_double() { return run_everything<double>(); }
long double discipline_long_double() { return run_everything<long double>(); }
