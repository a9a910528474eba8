// SPDX-License-Identifier: BSL-1.0
// The splitting methods on large states (issue 27): the unchecked step updates the caller's x, v and kept
// acceleration in place and an in-place force writes straight into the kept acceleration; the checked
// step's finiteness test sums a large state in lanes (detail::add_in_lanes). Expected values: a
// kick-drift-kick loop written here (the textbook velocity Verlet, an independent computation with the
// same operations, so bit for bit under -ffp-contract=off), the checked step for the unchecked one (the
// same arithmetic, a separate code path), and the caller's own objects for the roll-back.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <tuple>

#include "support/compare.hpp"
#include "support/type_list.hpp"

namespace {

// x'' = -w^2 x - x^3 / 4 componentwise, with w^2 = 1 + n / N: every component its own non-linear spring.
template <class T, std::size_t N>
struct springs {
    using state = std::array<T, N>;
    state operator()(T, const state& x) const {
        state a;
        (*this)(T(0), x, a);
        return a;
    }
    void operator()(T, const state& x, state& a) const {
        for (std::size_t n = 0; n < N; ++n)
            a[n] = -(T(1) + T(static_cast<float>(n)) / T(static_cast<float>(N))) * x[n] - x[n] * x[n] * x[n] / T(4);
    }
};
// Only the in-place form (no State returned).
template <class T, std::size_t N>
struct springs_in_place {
    void operator()(T t, const std::array<T, N>& x, std::array<T, N>& a) const { springs<T, N>{}(t, x, a); }
};

template <class T, std::size_t N>
void start(std::array<T, N>& x, std::array<T, N>& v) {
    for (std::size_t n = 0; n < N; ++n) {
        x[n] = T(1) + T(static_cast<float>(n % 7)) / T(8);
        v[n] = T(static_cast<float>(n % 5)) / T(4) - T(0.5f);
    }
}

// Velocity Verlet, kick-drift-kick, as written in every textbook: v += h/2 a; x += h v; a = a(x); v += h/2 a.
template <class T, std::size_t N>
void textbook_verlet(std::array<T, N>& x, std::array<T, N>& v, std::array<T, N>& acc, T t, T h) {
    const T h2 = T(0.5f) * h;
    for (std::size_t n = 0; n < N; ++n) {
        v[n] = v[n] + h2 * acc[n];
        x[n] = x[n] + h * v[n];
    }
    springs<T, N>{}(t + h, x, acc);
    for (std::size_t n = 0; n < N; ++n) v[n] = v[n] + h2 * acc[n];
}

template <class T, std::size_t N, class Stepper, class Force>
void check_caller_kept_against_textbook(Force force) {
    std::array<T, N> x, v, acc, xr, vr, ar;
    start(x, v);
    start(xr, vr);
    springs<T, N>{}(T(0), x, acc);
    ar = acc;
    Stepper stepper;
    const T h = T(0.01f);
    for (int i = 0; i < 50; ++i) {
        const T t = T(static_cast<float>(i)) * h;
        REQUIRE(stepper.step(force, x, v, acc, t, h) == odestep::status::ok);
        textbook_verlet(xr, vr, ar, t, h);
    }
    CHECK(odestep_test::same_bits(x, xr));
    CHECK(odestep_test::same_bits(v, vr));
    CHECK(odestep_test::same_bits(acc, ar));
}

template <class T, std::size_t N, class Stepper, class Force>
void check_stepper_kept_against_textbook(Force force) {
    std::array<T, N> x, v, xr, vr, ar;
    start(x, v);
    start(xr, vr);
    springs<T, N>{}(T(0), xr, ar);
    Stepper stepper;
    const T h = T(0.01f);
    for (int i = 0; i < 50; ++i) {
        const T t = T(static_cast<float>(i)) * h;
        REQUIRE(stepper.step(force, x, v, t, h) == odestep::status::ok);
        textbook_verlet(xr, vr, ar, t, h);
    }
    CHECK(odestep_test::same_bits(x, xr));
    CHECK(odestep_test::same_bits(v, vr));
}

template <class T, std::size_t N>
void check_verlet_against_textbook() {
    using S = std::array<T, N>;
    using checked = odestep::velocity_verlet<S>;
    using unchecked = odestep::unchecked_t<checked>;
    check_caller_kept_against_textbook<T, N, checked>(springs<T, N>{});
    check_caller_kept_against_textbook<T, N, unchecked>(springs<T, N>{});
    check_caller_kept_against_textbook<T, N, checked>(springs_in_place<T, N>{});
    check_caller_kept_against_textbook<T, N, unchecked>(springs_in_place<T, N>{});
    check_stepper_kept_against_textbook<T, N, checked>(springs_in_place<T, N>{});
    check_stepper_kept_against_textbook<T, N, unchecked>(springs_in_place<T, N>{});
}

// 30 steps of a table under both policies, with the in-place force: the same results, bit for bit.
template <class T, std::size_t N, class Method>
void check_policies_agree() {
    using S = std::array<T, N>;
    odestep::splitting<Method, S> checked;
    odestep::splitting<Method, S, odestep::unchecked> unchecked;
    S xc, vc, xu, vu;
    start(xc, vc);
    start(xu, vu);
    const T h = T(0.02f);
    for (int i = 0; i < 30; ++i) {
        const T t = T(static_cast<float>(i)) * h;
        REQUIRE(checked.step(springs_in_place<T, N>{}, xc, vc, t, h) == odestep::status::ok);
        REQUIRE(unchecked.step(springs_in_place<T, N>{}, xu, vu, t, h) == odestep::status::ok);
    }
    CHECK(odestep_test::same_bits(xc, xu));
    CHECK(odestep_test::same_bits(vc, vu));
}

using tables = std::tuple<odestep::tables::euler_cromer, odestep::tables::euler_cromer_drift_first,
                          odestep::tables::velocity_verlet, odestep::tables::position_verlet,
                          odestep::tables::forest_ruth, odestep::tables::yoshida6, odestep::tables::blanes_moan4>;

// A force that is not finite at component `bad` when x[0] has left its start (the step's last kick), so
// that the new v is not finite there.
template <class T, std::size_t N>
struct breaks_at {
    std::size_t bad;
    void operator()(T t, const std::array<T, N>& x, std::array<T, N>& a) const {
        springs<T, N>{}(t, x, a);
        if (!(x[0] == T(1))) a[bad] = std::numeric_limits<T>::infinity();
    }
};

// The checked step refuses a non-finite result at any component (inside the lanes or in the tail past
// them) and leaves x, v and the acceleration as they were.
template <class T, std::size_t N>
void check_rollback() {
    using S = std::array<T, N>;
    for (std::size_t bad : {std::size_t(0), N / 2, N - 1}) {
        CAPTURE(bad);
        S x, v, acc;
        start(x, v);
        springs<T, N>{}(T(0), x, acc);
        const S x0 = x, v0 = v, a0 = acc;
        odestep::velocity_verlet<S> stepper;
        CHECK(stepper.step(breaks_at<T, N>{bad}, x, v, acc, T(0), T(0.01f)) == odestep::status::non_finite);
        CHECK(odestep_test::same_bits(x, x0));
        CHECK(odestep_test::same_bits(v, v0));
        CHECK(odestep_test::same_bits(acc, a0));
        // The stepper-kept form too.
        CHECK(stepper.step(breaks_at<T, N>{bad}, x, v, T(0), T(0.01f)) == odestep::status::non_finite);
        CHECK(odestep_test::same_bits(x, x0));
        CHECK(odestep_test::same_bits(v, v0));
    }
}

// Every component finite and near the largest T: the lane sums overflow to Inf, the exact test then finds
// every component finite, and the step goes ahead (x'' = 0, so x + h v with v = 0: x unchanged).
template <class T, std::size_t N>
void check_overflowing_sum_is_not_a_failure() {
    using S = std::array<T, N>;
    S x, v{}, acc{};
    x.fill(std::numeric_limits<T>::max() / T(2));
    const S x0 = x;
    odestep::velocity_verlet<S> stepper;
    const auto zero_force = [](T, const S&, S& a) { a.fill(T(0)); };
    CHECK(stepper.step(zero_force, x, v, acc, T(0), T(0.01f)) == odestep::status::ok);
    CHECK(odestep_test::same_bits(x, x0));
}

}  // namespace

TEST_CASE(
    "newtonian large state: velocity Verlet equals the textbook kick-drift-kick loop bit for bit, both "
    "policies, returning and in-place forces") {
    check_verlet_against_textbook<float, 64>();
    check_verlet_against_textbook<float, 67>();  // a tail past the lanes
    check_verlet_against_textbook<double, 35>();
    check_verlet_against_textbook<float, 3>();
}

TEST_CASE("newtonian large state: every splitting table gives the same run checked and unchecked, bit for bit") {
    odestep_test::for_each_type<tables>([](auto method) {
        using M = decltype(method);
        check_policies_agree<float, 67, M>();
        check_policies_agree<double, 40, M>();
        check_policies_agree<float, 2, M>();
    });
}

TEST_CASE("newtonian large state: a non-finite component anywhere is refused and x, v, acc are kept") {
    check_rollback<float, 67>();
    check_rollback<double, 40>();
    check_rollback<float, 5>();
}

TEST_CASE("newtonian large state: a finiteness sum that overflows does not fail a finite step") {
    check_overflowing_sum_is_not_a_failure<float, 64>();
    check_overflowing_sum_is_not_a_failure<double, 64>();
}
