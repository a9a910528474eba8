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

namespace {

// One stepper's published Newtonian traits, as docs/reference.md's table states them (order, a evaluations
// per step at most, symplectic, reversible) with stages, velocity_forces and self_starting.
template <class S>
constexpr bool newtonian_traits_are(int order, std::size_t stages, std::size_t evals, bool symplectic, bool reversible,
                                    bool velocity_forces) {
    return S::order == order && S::stages == stages && S::rhs_evals_per_step == evals && S::symplectic == symplectic &&
           S::time_reversible == reversible && S::velocity_forces == velocity_forces && S::self_starting &&
           !S::uniform_steps && !S::implicit && S::system == odestep::system_form::newtonian &&
           odestep::is_stepper_v<S>;
}

// Steppers that miss a requirement (detail::first_missing_trait's codes), and one that misses none.
struct no_types {};
struct only_order {
    using state_type = s1;
    using value_type = double;
    static constexpr int order = 1;
};
struct no_implicit {  // every trait of the list but the last
    using state_type = s1;
    using value_type = double;
    static constexpr int order = 1;
    static constexpr std::size_t stages = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
    static constexpr bool error_estimate = false;
    static constexpr int embedded_order = 0;
    static constexpr std::size_t rhs_evals_per_error_step = 0;
    static constexpr bool symplectic = false;
    static constexpr bool time_reversible = false;
    static constexpr bool self_starting = true;
    static constexpr bool uniform_steps = false;
    static constexpr odestep::system_form system = odestep::system_form::first_order;
    static constexpr bool velocity_forces = false;
};
struct zero_order : odestep::stepper_defaults<s1> {
    static constexpr std::size_t rhs_evals_per_step = 1;
};
struct complete : odestep::stepper_defaults<s1> {
    static constexpr int order = 1;
    static constexpr std::size_t rhs_evals_per_step = 1;
};

}  // namespace

TEST_CASE("stepper: named traits set exactly the traits they name, and the Newtonian steppers publish theirs") {
    using named = odestep::stepper_traits<s1, odestep::trait::order<3>, odestep::trait::rhs_evals_per_step<5>,
                                          odestep::trait::time_reversible<true>,
                                          odestep::trait::system<odestep::system_form::newtonian>>;
    static_assert(named::order == 3 && named::rhs_evals_per_step == 5 && named::time_reversible);
    static_assert(named::system == odestep::system_form::newtonian);
    using defaults = odestep::stepper_defaults<s1>;  // every trait not named keeps its default
    static_assert(named::stages == defaults::stages && named::symplectic == defaults::symplectic);
    static_assert(named::self_starting == defaults::self_starting && named::implicit == defaults::implicit);
    static_assert(named::error_estimate == defaults::error_estimate && named::uniform_steps == defaults::uniform_steps);
    static_assert(odestep::check_stepper<named>());

    static_assert(newtonian_traits_are<odestep::newtonian_euler<s2>>(1, 1, 1, false, false, true));
    static_assert(newtonian_traits_are<odestep::newtonian_midpoint<s2>>(1, 1, 1, false, false, true));
    static_assert(newtonian_traits_are<odestep::newtonian_euler_richardson<s2>>(2, 2, 2, false, false, true));
    static_assert(newtonian_traits_are<odestep::half_step<s2>>(2, 1, 2, true, true, false));
    static_assert(newtonian_traits_are<odestep::leapfrog_position_form<s2>>(2, 1, 2, true, true, false));
    static_assert(newtonian_traits_are<odestep::beeman<s2>>(2, 1, 2, false, false, true));
    static_assert(newtonian_traits_are<odestep::predictor_corrector<s2>>(2, 2, 17, false, false, true));
    // Boris, both forms, from the one block: second order, one field evaluation, reversible and volume
    // preserving, not symplectic, not self starting (docs/reference.md, the charged particle).
    using boris = odestep::boris<s3>;
    using relativistic = odestep::boris_relativistic<s3>;
    static_assert(boris::order == 2 && boris::rhs_evals_per_step == 1 && boris::time_reversible && !boris::symplectic);
    static_assert(boris::volume_preserving && !boris::self_starting);
    static_assert(boris::system == odestep::system_form::charged_particle);
    static_assert(relativistic::order == 2 && relativistic::rhs_evals_per_step == 1 && relativistic::time_reversible);
    static_assert(!relativistic::symplectic && relativistic::volume_preserving && !relativistic::self_starting);
    static_assert(relativistic::system == odestep::system_form::charged_particle);
    CHECK(odestep::is_stepper_v<boris>);
}

TEST_CASE("stepper: a missing trait is named by the code the trait list gives it, in the list's order") {
    namespace d = odestep::detail;
    static_assert(d::first_missing_trait<no_types>() == d::trait_types);
    static_assert(d::first_missing_trait<only_order>() == d::trait_missing_stages);
    static_assert(d::first_missing_trait<no_implicit>() == d::trait_missing_implicit);
    static_assert(d::first_missing_trait<zero_order>() == d::trait_order_below_one);
    static_assert(d::first_missing_trait<complete>() == d::trait_ok);
    CHECK(!odestep::is_stepper_v<no_implicit>);
}
