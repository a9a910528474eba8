// SPDX-License-Identifier: BSL-1.0
// No library call allocates: every stepper, float/double/long double, the loops, the bad-input and
// non-finite paths, all under the replaced global allocator.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cstdlib>
#include <limits>
#include <new>

#include "support/alloc_counter.hpp"
#include "support/methods.hpp"

namespace {

template <class T>
using state3 = std::array<T, 3>;

struct lorenz {
    template <class T>
    void operator()(T, const state3<T>& x, state3<T>& d) const noexcept {
        d[0] = T(10) * (x[1] - x[0]);
        d[1] = x[0] * (T(28) - x[2]) - x[1];
        d[2] = x[0] * x[1] - T(8) / T(3) * x[2];
    }
};

template <class T>
std::size_t allocations_of_every_call() {
    const std::size_t before = odestep_test::allocations();
    std::size_t observed = 0;
    odestep_test::for_each_method([&](auto method) {
        using M = decltype(method);
        using stepper_t = odestep::explicit_rk<M, state3<T>>;
        stepper_t stepper;
        state3<T> y{T(1), T(1), T(1)};
        (void)odestep::integrate(stepper, lorenz{}, y, T(0), T(1), T(0.01), [&](T, const state3<T>&) { ++observed; });
        (void)odestep::integrate_n_steps(stepper, lorenz{}, y, T(0), T(0.01), 10);
        (void)odestep::integrate(stepper, lorenz{}, y, T(0), T(1), T(0));     // invalid_step
        (void)odestep::integrate(stepper, lorenz{}, y, T(0), T(1), T(-0.1));  // wrong_direction
        auto poison = [](T, const state3<T>&) { return state3<T>{std::numeric_limits<T>::quiet_NaN(), T(0), T(0)}; };
        (void)odestep::integrate(stepper, poison, y, T(0), T(1), T(0.1));  // non_finite
        if constexpr (stepper_t::error_estimate) {
            state3<T> err{};
            (void)stepper.step(lorenz{}, y, T(0), T(0.01), err);
        }
    });
    CHECK(observed > 0);
    return odestep_test::allocations() - before;
}

template <class T>
std::size_t allocations_of_newtonian_calls() {
    using vec = std::array<T, 2>;
    auto spring = [](T, const vec& x) { return vec{-x[0], -x[1]}; };
    const std::size_t before = odestep_test::allocations();
    auto run = [&](auto stepper) {
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        (void)odestep::integrate(stepper, spring, x, v, T(0), T(1), T(0.01), [](T, const vec&, const vec&) {});
        (void)odestep::integrate_n_steps(stepper, spring, x, v, T(0), T(0.01), 10);
        (void)odestep::integrate(stepper, spring, x, v, T(0), T(1), T(-0.1));  // wrong_direction
    };
    odestep_test::for_each_type<odestep_test::newtonian_steppers<vec>>(run);
    // the first-same-as-last steppers' form with the acceleration kept by the caller, a good step and a
    // failing one (NaN from the force)
    auto run_caller_kept = [&](const auto& stepper) {
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        vec acc = spring(T(0), x);
        (void)stepper.step(spring, x, v, acc, T(0), T(0.01));
        auto poison = [](T, const vec&) { return vec{std::numeric_limits<T>::quiet_NaN(), T(0)}; };
        (void)stepper.step(poison, x, v, acc, T(0.01), T(0.01));
    };
    run_caller_kept(odestep::velocity_verlet<vec>{});
    run_caller_kept(odestep::blanes_moan4<vec>{});
    // Beeman's form with the history kept by the caller: a self-starting step, a continuing one, a failing one
    {
        const odestep::beeman<vec> stepper;
        vec x{T(1), T(0)};
        vec v{T(0), T(1)};
        typename odestep::beeman<vec>::history hist{};
        (void)stepper.step(spring, x, v, hist, T(0), T(0.01));
        (void)stepper.step(spring, x, v, hist, T(0.01), T(0.01));
        auto poison = [](T, const vec&) { return vec{std::numeric_limits<T>::quiet_NaN(), T(0)}; };
        (void)stepper.step(poison, x, v, hist, T(0.02), T(0.01));
    }
    return odestep_test::allocations() - before;
}

template <class T>
std::size_t allocations_of_boris_calls() {
    using vec = std::array<T, 3>;
    auto fields = [](T, const vec&, vec& E, vec& B) {
        E = {T(0), T(0.5), T(0)};
        B = {T(0), T(0), T(1)};
    };
    auto poison = [](T, const vec&, vec& E, vec&) { E[0] = std::numeric_limits<T>::quiet_NaN(); };
    const std::size_t before = odestep_test::allocations();
    auto run = [&](const auto& pusher) {
        vec x{T(0), T(0), T(0)};
        vec v{T(1), T(0), T(0)};
        (void)pusher.stagger(fields, x, v, T(0), T(0.01));
        (void)odestep::integrate(pusher, fields, x, v, T(0), T(1), T(0.01), [](T, const vec&, const vec&) {});
        (void)odestep::integrate_n_steps(pusher, fields, x, v, T(0), T(0.01), 10);
        (void)pusher.synchronize(fields, x, v, T(1), T(0.01));
        (void)odestep::integrate(pusher, fields, x, v, T(0), T(1), T(-0.1));  // wrong_direction
        (void)odestep::integrate(pusher, poison, x, v, T(0), T(1), T(0.1));   // non_finite
    };
    run(odestep::boris<vec>{T(-2)});
    run(odestep::boris_relativistic<vec>{T(-2), T(3)});
    return odestep_test::allocations() - before;
}

template <class T>
std::size_t allocations_of_multistep_calls() {
    const std::size_t before = odestep_test::allocations();
    auto run = [](auto stepper) {
        state3<T> y{T(1), T(1), T(1)};
        (void)odestep::integrate(stepper, lorenz{}, y, T(0), T(1), T(0.125), [](T, const state3<T>&) {});
        (void)odestep::integrate(stepper, lorenz{}, y, T(1), T(2), T(0.3));  // step_mismatch at the end
        (void)stepper.step(lorenz{}, y, T(7), T(0.5));                       // step_mismatch (t, dt)
        stepper.reset();
        (void)odestep::integrate_n_steps(stepper, lorenz{}, y, T(0), T(0.01), 10);
        auto poison = [](T, const state3<T>&) { return state3<T>{std::numeric_limits<T>::quiet_NaN(), T(0), T(0)}; };
        (void)stepper.step(poison, y, T(0.1), T(0.01));  // non_finite
    };
    odestep_test::for_each_type<odestep_test::adams_steppers<state3<T>>>(run);
    return odestep_test::allocations() - before;
}

template <class T>
std::size_t allocations_of_event_calls() {
    using state2 = std::array<T, 2>;
    using vec = std::array<T, 1>;
    const std::size_t before = odestep_test::allocations();
    auto fall = [](T, const state2& s) { return state2{s[1], T(-9.8)}; };
    auto height = [](T, const state2& s) { return s[0]; };
    auto bounce = [](T, state2& s) { s[1] = T(-0.7) * s[1]; };
    for (std::size_t probes = 0; probes < 2; ++probes) {
        const odestep::event_limits limits{0, 8, probes};
        state2 s{T(1), T(0)};
        // bounces until the event limit (a Zeno storm), then a terminal event, then bad settings, a NaN g
        (void)odestep::integrate(
            odestep::rk4<state2>{}, fall, s, T(0), T(5), T(0.01),
            odestep::watch(odestep::make_event<state2>(height, odestep::direction::falling, bounce))
                .with_limits(limits),
            [](T, const state2&) {});
        s = {T(1), T(0)};
        (void)odestep::integrate(odestep::rk4<state2>{}, fall, s, T(0), T(5), T(0.01),
                                 odestep::watch(odestep::make_event<state2>(height, odestep::direction::falling)));
        (void)odestep::integrate(
            odestep::rk4<state2>{}, fall, s, T(0), T(5), T(0.01),
            odestep::watch(odestep::make_event<state2>(height, odestep::direction::falling).with_tolerance(T(-1))));
        auto nan_g = [](T, const state2&) { return std::numeric_limits<T>::quiet_NaN(); };
        (void)odestep::integrate(odestep::rk4<state2>{}, fall, s, T(0), T(5), T(0.01),
                                 odestep::watch(odestep::make_event<state2>(nan_g, odestep::direction::falling)));
        // the per-tick stepper, Newtonian, with a multistep-free symplectic stepper
        auto a = [](T, const vec&) { return vec{T(-9.8)}; };
        auto ground = [](T, const vec& x, const vec&) { return x[0]; };
        auto flip = [](T, vec&, vec& v) { v[0] = -v[0]; };
        auto loop = odestep::make_event_stepper(
            odestep::velocity_verlet<vec>{},
            odestep::watch(odestep::make_event<vec>(ground, odestep::direction::falling, flip)).with_limits(limits));
        vec x{T(1)};
        vec v{T(0)};
        if (loop.start(T(0), T(0.01), x, v) == odestep::status::ok)
            for (int n = 0; n < 200; ++n) (void)loop.tick(a, x, v);
        // rearm after the caller moved the state, and one refused (a NaN position: g is NaN)
        x = {T(2)};
        (void)loop.rearm(x, v);
        (void)loop.rearm(vec{std::numeric_limits<T>::quiet_NaN()}, v);
    }
    // the multistep restart after a state change
    state2 s{T(1), T(0)};
    (void)odestep::integrate(odestep::adams_bashforth_moulton4<state2>{}, fall, s, T(0), T(2), T(0.01),
                             odestep::watch(odestep::make_event<state2>(height, odestep::direction::falling, bounce)));
    return odestep_test::allocations() - before;
}

template <class T>
std::size_t allocations_of_implicit_calls() {
    using s = state3<T>;
    const std::size_t before = odestep_test::allocations();
    auto lorenz_jacobian = [](T, const s& x, odestep::jacobian_t<s>& j) {
        j[0] = {T(-10), T(10), T(0)};
        j[1] = {T(28) - x[2], T(-1), -x[0]};
        j[2] = {x[1], x[0], T(-8) / T(3)};
    };
    auto run = [&](auto stepper) {
        s y{T(1), T(1), T(1)};
        // good steps: by differences and with the system's Jacobian, both loops
        (void)odestep::integrate(stepper, lorenz{}, y, T(0), T(0.1), T(0.01), [](T, const s&) {});
        (void)odestep::integrate_n_steps(stepper, odestep::with_jacobian(lorenz{}, lorenz_jacobian), y, T(0), T(0.01),
                                         10);
        // failing steps: NaN from f, NaN in J, a singular matrix, an iteration that does not converge
        auto poison = [](T, const s&) { return s{std::numeric_limits<T>::quiet_NaN(), T(0), T(0)}; };
        (void)stepper.step(poison, y, T(0), T(0.01));
        auto nan_j = [](T, const s&, odestep::jacobian_t<s>& j) {
            j = {};
            j[0][0] = std::numeric_limits<T>::quiet_NaN();
        };
        (void)stepper.step(odestep::with_jacobian(lorenz{}, nan_j), y, T(0), T(0.01));
        auto identity = [](T, const s& v) { return v; };
        auto unit = [](T, const s&, odestep::jacobian_t<s>& j) {
            j = {{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
        };
        (void)stepper.step(odestep::with_jacobian(identity, unit), y, T(0), T(1));
        (void)stepper.step(odestep::with_jacobian(identity, unit), y, T(0), T(2));
        auto cubic = [](T, const s& v) { return s{-v[0] * v[0] * v[0], T(0), T(0)}; };
        (void)stepper.step(cubic, y, T(0), T(100));
    };
    run(odestep::backward_euler<s>{});
    run(odestep::trapezoid<s>{});
    run(odestep::implicit_midpoint<s>{});
    run(odestep::gauss4<s>{});
    run(odestep::sdirk3<s>{});
    run(odestep::radau_iia5<s>{});
    run(odestep::radau_iia5<s, odestep::fixed_newton<2>>{});
    run(odestep::rodas3<s>{});
    run(odestep::radau5_substeps<s, 64>{});
    run(odestep::rodas4_substeps<s, 64>{});
    // and an event loop driving an implicit stepper
    s y{T(1), T(1), T(1)};
    auto g = [](T, const s& v) { return v[0] - T(5); };
    (void)odestep::integrate(odestep::sdirk3<s>{}, lorenz{}, y, T(0), T(1), T(0.01),
                             odestep::watch(odestep::make_event<s>(g, odestep::direction::rising)));
    return odestep_test::allocations() - before;
}

}  // namespace

TEST_CASE("allocation: the counter sees an allocation when there is one") {
    const std::size_t before = odestep_test::allocations();
    void* volatile p = ::operator new(16);  // volatile: a new/delete pair may otherwise be elided
    ::operator delete(p);
    CHECK(odestep_test::allocations() == before + 1);
    void* volatile m = std::malloc(16);
    std::free(m);
    CHECK(odestep_test::allocations() == before + 2);
}

TEST_CASE("allocation: no library call allocates, in float, double or long double") {
    CHECK(allocations_of_every_call<float>() == 0);
    CHECK(allocations_of_every_call<double>() == 0);
    CHECK(allocations_of_every_call<long double>() == 0);
}

TEST_CASE("allocation: no Newtonian stepper allocates, in float, double or long double") {
    CHECK(allocations_of_newtonian_calls<float>() == 0);
    CHECK(allocations_of_newtonian_calls<double>() == 0);
    CHECK(allocations_of_newtonian_calls<long double>() == 0);
}

TEST_CASE("allocation: the Boris pushers do not allocate, in float, double or long double") {
    CHECK(allocations_of_boris_calls<float>() == 0);
    CHECK(allocations_of_boris_calls<double>() == 0);
    CHECK(allocations_of_boris_calls<long double>() == 0);
}

TEST_CASE("allocation: no multistep stepper allocates, in float, double or long double") {
    CHECK(allocations_of_multistep_calls<float>() == 0);
    CHECK(allocations_of_multistep_calls<double>() == 0);
    CHECK(allocations_of_multistep_calls<long double>() == 0);
}

TEST_CASE("allocation: the event loops do not allocate, in float, double or long double") {
    CHECK(allocations_of_event_calls<float>() == 0);
    CHECK(allocations_of_event_calls<double>() == 0);
    CHECK(allocations_of_event_calls<long double>() == 0);
}

TEST_CASE("allocation: the implicit and Rosenbrock steppers do not allocate, good steps or failing ones") {
    CHECK(allocations_of_implicit_calls<float>() == 0);
    CHECK(allocations_of_implicit_calls<double>() == 0);
    CHECK(allocations_of_implicit_calls<long double>() == 0);
}
