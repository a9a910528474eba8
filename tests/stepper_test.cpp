// SPDX-License-Identifier: BSL-1.0
// The stepper concept: every stepper of the library publishes the one trait set, and a user's own stepper
// that does runs under every driving loop.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

#include "support/methods.hpp"

namespace {

using s1 = std::array<double, 1>;
using s2 = std::array<double, 2>;
using s3 = std::array<float, 3>;

template <class S>
constexpr bool publishes_the_set() {
    static_assert(odestep::check_stepper<S>());
    static_assert(odestep::is_stepper_v<S>);
    static_assert(std::is_same_v<decltype(S::order), const int>);
    static_assert(std::is_same_v<decltype(S::stages), const std::size_t>);
    static_assert(std::is_same_v<decltype(S::rhs_evals_per_step), const std::size_t>);
    static_assert(std::is_same_v<decltype(S::rhs_evals_per_error_step), const std::size_t>);
    static_assert(std::is_same_v<decltype(S::embedded_order), const int>);
    static_assert(std::is_same_v<decltype(S::system), const odestep::system_form>);
    static_assert(std::is_same_v<decltype(S::checks_finiteness), const bool>);
    static_assert(S::error_estimate == (S::embedded_order > 0));
    static_assert(S::error_estimate == (S::rhs_evals_per_error_step > 0));
    return true;
}

template <class... S>
constexpr bool all_publish(std::tuple<S...>*) {
    return (publishes_the_set<S>() && ...);
}

template <class... M>
constexpr bool all_rk_publish(std::tuple<M...>*) {
    return (publishes_the_set<odestep::explicit_rk<M, s2>>() && ...) &&
           (publishes_the_set<odestep::explicit_rk<M, s3>>() && ...);
}

// Forward Euler written by a user, with the defaults for everything but order and cost.
template <class State>
struct user_euler : odestep::stepper_defaults<State> {
    using T = typename State::value_type;
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    template <class System>
    odestep::status step(System&& f, State& y, T t, T dt) const {
        const State d = f(t, y);
        State next;
        for (std::size_t i = 0; i < y.size(); ++i) next[i] = y[i] + dt * d[i];
        for (const T v : next)
            if (!(v - v == T(0))) return odestep::status::non_finite;
        y = next;
        return odestep::status::ok;
    }
};

}  // namespace

TEST_CASE("stepper: every stepper of the library publishes the one trait set") {
    CHECK(all_rk_publish(static_cast<odestep_test::all_methods*>(nullptr)));
    using others =
        std::tuple<odestep::adams_bashforth2<s2>, odestep::adams_bashforth3<s2>, odestep::adams_bashforth4<s2>,
                   odestep::adams_bashforth5<s2>, odestep::adams_bashforth_moulton4<s2>, odestep::euler_cromer<s2>,
                   odestep::euler_cromer_drift_first<s2>, odestep::velocity_verlet<s2>, odestep::position_verlet<s2>,
                   odestep::forest_ruth<s2>, odestep::yoshida6<s2>, odestep::blanes_moan4<s2>,
                   odestep::newtonian_euler<s2>, odestep::newtonian_midpoint<s2>,
                   odestep::newtonian_euler_richardson<s2>, odestep::half_step<s2>, odestep::leapfrog_position_form<s2>,
                   odestep::beeman<s2>, odestep::predictor_corrector<s2>, odestep::boris<s3>,
                   odestep::boris_relativistic<s3>, user_euler<s1>>;
    CHECK(all_publish(static_cast<others*>(nullptr)));

    // The values that say what a stepper is, from its method (the sources are in the headers and README).
    static_assert(odestep::rk4<s2>::system == odestep::system_form::first_order);
    static_assert(odestep::velocity_verlet<s2>::system == odestep::system_form::newtonian);
    static_assert(odestep::boris<s3>::system == odestep::system_form::charged_particle);
    static_assert(odestep::adams_bashforth4<s2>::uniform_steps && !odestep::rk4<s2>::uniform_steps);
    static_assert(!odestep::boris<s3>::self_starting && odestep::rk4<s2>::self_starting);
    static_assert(odestep::forest_ruth<s2>::symplectic && odestep::forest_ruth<s2>::time_reversible);
    static_assert(!odestep::euler_cromer<s2>::time_reversible && odestep::boris<s3>::time_reversible);
    static_assert(odestep::euler_cromer<s2>::velocity_forces && !odestep::half_step<s2>::velocity_forces);
    static_assert(!odestep::rk4<s2>::velocity_forces && !odestep::rk4<s2>::implicit);
    static_assert(odestep::radau_iia5<s2>::implicit && odestep::rodas3<s2>::implicit);
    static_assert(odestep::gauss4<s2>::symplectic && odestep::gauss4<s2>::time_reversible);
    static_assert(!odestep::backward_euler<s2>::symplectic && !odestep::sdirk3<s2>::time_reversible);
    static_assert(odestep::newtonian_euler_richardson<s2>::error_estimate &&
                  odestep::newtonian_euler_richardson<s2>::embedded_order == 1);
    static_assert(odestep::dormand_prince54<s2>::rhs_evals_per_step == 6 &&
                  odestep::dormand_prince54<s2>::rhs_evals_per_error_step == 7);

    // checks_finiteness: every stepper's default form checks (the policy odestep::checked, or a stepper
    // without a policy, whose step tests its results); the unchecked forms say they do not, and publish
    // the rest of the set unchanged.
    static_assert(odestep::rk4<s2>::checks_finiteness && odestep::dop853<s3>::checks_finiteness);
    static_assert(odestep::adams_bashforth4<s2>::checks_finiteness && odestep::velocity_verlet<s2>::checks_finiteness);
    static_assert(odestep::beeman<s2>::checks_finiteness && odestep::boris<s3>::checks_finiteness);
    static_assert(odestep::radau_iia5<s2>::checks_finiteness && user_euler<s1>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::rk4<s2>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::dop853<s3>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::adams_bashforth4<s2, odestep::rk4<s2>>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::adams_bashforth_moulton4<s2, odestep::rk4<s2>>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::velocity_verlet<s2>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::euler_cromer<s2>>::checks_finiteness);
    static_assert(!odestep::unchecked_t<odestep::position_verlet<s2>>::checks_finiteness);
    static_assert(publishes_the_set<odestep::unchecked_t<odestep::rk4<s2>>>());
    static_assert(publishes_the_set<odestep::unchecked_t<odestep::adams_bashforth4<s2, odestep::rk4<s2>>>>());
    static_assert(publishes_the_set<odestep::unchecked_t<odestep::forest_ruth<s2>>>());
    static_assert(odestep::unchecked_t<odestep::rk4<s2>>::order == 4 &&
                  odestep::unchecked_t<odestep::rk4<s2>>::rhs_evals_per_step == 4);
}

TEST_CASE("stepper: a user's own stepper runs under integrate, integrate_n_steps and both event loops") {
    // y' = -y with forward Euler: y_n = (1 - h)^n exactly in the algebra; computed, within a few roundings.
    auto decay = [](double, const s1& y) { return s1{-y[0]}; };
    const double h = 0.125;  // (1 - h)^n: every product of 7/8 powers is exact in double up to n = 17
    {
        s1 y{1.0};
        const auto r = odestep::integrate(user_euler<s1>{}, decay, y, 0.0, 2.0, h);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(r.steps == 16);
        CHECK(y[0] == std::pow(0.875, 16));
    }
    {
        s1 y{1.0};
        const auto r = odestep::integrate_n_steps(user_euler<s1>{}, decay, y, 0.0, h, 16);
        REQUIRE(r.status == odestep::status::ok);
        CHECK(y[0] == std::pow(0.875, 16));
    }
    // The event y = 1/2 is located by re-stepping the user's stepper from the start of the step that
    // crossed: Euler's own state there, y(s) = y_n (1 - s), so the root of y_n (1 - s) = 1/2 in the fifth
    // step (y_5 = 0.875^5 = 0.5129, y_6 = 0.4488) is at s = 1 - 0.5 / 0.875^5.
    auto half = odestep::make_event<s1>([](double, const s1& y) { return y[0] - 0.5; }, odestep::direction::falling);
    const double expected = 5 * h + (1.0 - 0.5 / std::pow(0.875, 5));
    {
        s1 y{1.0};
        const auto r = odestep::integrate(user_euler<s1>{}, decay, y, 0.0, 2.0, h, odestep::watch(half));
        REQUIRE(r.status == odestep::status::stopped_by_event);
        CHECK(r.t == doctest::Approx(expected).epsilon(1e-14));
        CHECK(y[0] == doctest::Approx(0.5).epsilon(1e-13));
    }
    {
        s1 y{1.0};
        auto loop = odestep::make_event_stepper(user_euler<s1>{}, odestep::watch(half));
        REQUIRE(loop.start(0.0, h, y) == odestep::status::ok);
        odestep::status last = odestep::status::ok;
        double when = 0.0;
        for (int k = 0; k < 16 && last == odestep::status::ok; ++k) {
            const auto t = loop.tick(decay, y);
            last = t.status;
            when = t.t;
        }
        CHECK(last == odestep::status::stopped_by_event);
        CHECK(when == doctest::Approx(expected).epsilon(1e-14));
    }
}
