// SPDX-License-Identifier: BSL-1.0
// The explicit Runge-Kutta stepper: traits, evaluation counts, error estimates, rollback.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "support/compare.hpp"
#include "support/counting.hpp"
#include "support/methods.hpp"
#include "support/problems.hpp"

namespace {

using state2 = std::array<double, 2>;

using odestep_test::same_bits;

// Counts its calls; y' = (y1, -y0), the harmonic oscillator.
using counting_sho = odestep_test::counting<odestep_test::harmonic>;

struct expected_traits {
    int order;
    std::size_t stages, evals, evals_with_error;
    int embedded_order;
};

// From the published tables (see tableaux.hpp for the sources): a stage the solution does not read is
// not evaluated (and a table without embedded weights has no estimating step: 0), so Bogacki-Shampine's and Dormand-Prince's last (FSAL) stage and Fehlberg 7(8)'s
// eleventh stage (read only by the seventh-order weights) cost an evaluation only with the error estimate.
template <class M>
constexpr expected_traits published() {
    using namespace odestep::tableaux;
    if constexpr (std::is_same_v<M, euler>)
        return {1, 1, 1, 0, 0};
    else if constexpr (std::is_same_v<M, midpoint>)
        return {2, 2, 2, 2, 1};
    else if constexpr (std::is_same_v<M, heun>)
        return {2, 2, 2, 0, 0};
    else if constexpr (std::is_same_v<M, ralston2>)
        return {2, 2, 2, 0, 0};
    else if constexpr (std::is_same_v<M, kutta3>)
        return {3, 3, 3, 0, 0};
    else if constexpr (std::is_same_v<M, ssprk3>)
        return {3, 3, 3, 0, 0};
    else if constexpr (std::is_same_v<M, rk4>)
        return {4, 4, 4, 0, 0};
    else if constexpr (std::is_same_v<M, rk38>)
        return {4, 4, 4, 0, 0};
    else if constexpr (std::is_same_v<M, bogacki_shampine32>)
        return {3, 4, 3, 4, 2};
    else if constexpr (std::is_same_v<M, fehlberg45>)
        return {5, 6, 6, 6, 4};
    else if constexpr (std::is_same_v<M, cash_karp54>)
        return {5, 6, 6, 6, 4};
    else if constexpr (std::is_same_v<M, dormand_prince54>)
        return {5, 7, 6, 7, 4};
    else if constexpr (std::is_same_v<M, fehlberg78>)
        return {8, 13, 12, 13, 7};
    else if constexpr (std::is_same_v<M, dop853>)
        return {8, 12, 12, 12, 5};
    else
        return {0, 0, 0, 0, 0};
}

}  // namespace

TEST_CASE("explicit_rk: traits match the published tables, and a step makes exactly the evaluations it says") {
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        using stepper = odestep::explicit_rk<M, state2>;
        constexpr expected_traits e = published<M>();
        INFO(doctest::String(M::name));
        CHECK(stepper::order == e.order);
        CHECK(stepper::stages == e.stages);
        CHECK(stepper::rhs_evals_per_step == e.evals);
        CHECK(stepper::rhs_evals_per_error_step == e.evals_with_error);
        CHECK(stepper::error_estimate == (e.embedded_order > 0));
        CHECK(stepper::embedded_order == e.embedded_order);
        CHECK_FALSE(stepper::symplectic);
        CHECK(stepper::self_starting);

        std::size_t calls = 0;
        state2 y{1.0, 0.0};
        REQUIRE(stepper{}.step(counting_sho{{}, &calls}, y, 0.0, 0.1) == odestep::status::ok);
        CHECK(calls == e.evals);
        if constexpr (stepper::error_estimate) {
            calls = 0;
            state2 err{};
            REQUIRE(stepper{}.step(counting_sho{{}, &calls}, y, 0.0, 0.1, err) == odestep::status::ok);
            CHECK(calls == e.evals_with_error);
        }
    });
}

TEST_CASE("explicit_rk: the error-estimating step advances y exactly as the plain step does") {
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        using stepper = odestep::explicit_rk<M, state2>;
        if constexpr (stepper::error_estimate) {
            std::size_t calls = 0;
            state2 a{0.3, -0.7};
            state2 b = a;
            state2 err{};
            REQUIRE(stepper{}.step(counting_sho{{}, &calls}, a, 0.0, 0.2) == odestep::status::ok);
            REQUIRE(stepper{}.step(counting_sho{{}, &calls}, b, 0.0, 0.2, err) == odestep::status::ok);
            INFO(doctest::String(M::name));
            CHECK(same_bits(a, b));
        }
    });
}

TEST_CASE("midpoint: the error estimate is the Euler-Richardson difference h (k2 - k1)") {
    // Written out by hand for y' = (y1, -y0): k1 = f(y), k2 = f(y + h/2 k1); Euler gives y + h k1, the
    // midpoint y + h k2, so the estimate is their difference.
    const double h = 0.1;
    const state2 y0{1.0, 0.5};
    const state2 k1{y0[1], -y0[0]};
    const state2 mid{y0[0] + h / 2 * k1[0], y0[1] + h / 2 * k1[1]};
    const state2 k2{mid[1], -mid[0]};
    std::size_t calls = 0;
    state2 y = y0;
    state2 err{};
    REQUIRE(odestep::midpoint<state2>{}.step(counting_sho{{}, &calls}, y, 0.0, h, err) == odestep::status::ok);
    CHECK(y[0] == doctest::Approx(y0[0] + h * k2[0]).epsilon(1e-15));
    CHECK(y[1] == doctest::Approx(y0[1] + h * k2[1]).epsilon(1e-15));
    CHECK(err[0] == doctest::Approx(h * (k2[0] - k1[0])).epsilon(1e-13));
    CHECK(err[1] == doctest::Approx(h * (k2[1] - k1[1])).epsilon(1e-13));
}

TEST_CASE("embedded pairs: the error estimate shrinks like h^(p+1) of the embedded order p") {
    // The estimate is y_high - y_low; its leading term is the embedded method's local error, C h^(p+1).
    // Halving h divides it by 2^(p+1); measured on the oscillator at h = 0.1 and 0.05 (ratio within 15%).
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        using stepper = odestep::explicit_rk<M, state2>;
        if constexpr (stepper::error_estimate) {
            auto estimate = [](double h) {
                std::size_t calls = 0;
                state2 y{1.0, 0.0};
                state2 err{};
                REQUIRE(stepper{}.step(counting_sho{{}, &calls}, y, 0.0, h, err) == odestep::status::ok);
                return std::hypot(err[0], err[1]);
            };
            const double ratio = estimate(0.1) / estimate(0.05);
            const double expected = std::pow(2.0, stepper::embedded_order + 1);
            INFO(doctest::String(M::name), ": ratio ", ratio, ", expected ", expected);
            CHECK(ratio == doctest::Approx(expected).epsilon(0.15));
        }
    });
}

TEST_CASE("dop853: the second (3rd-order) estimate shrinks like h^4") {
    using stepper = odestep::dop853<state2>;
    auto estimates = [](double h) {
        std::size_t calls = 0;
        state2 y{1.0, 0.0};
        state2 e5{};
        state2 e3{};
        REQUIRE(stepper{}.step(counting_sho{{}, &calls}, y, 0.0, h, e5, e3) == odestep::status::ok);
        return std::array<double, 2>{std::hypot(e5[0], e5[1]), std::hypot(e3[0], e3[1])};
    };
    const auto coarse = estimates(0.1);
    const auto fine = estimates(0.05);
    CHECK(coarse[0] / fine[0] == doctest::Approx(64.0).epsilon(0.15));
    CHECK(coarse[1] / fine[1] == doctest::Approx(16.0).epsilon(0.15));
}

TEST_CASE("explicit_rk: a NaN or Inf from any stage leaves y (and the estimate) exactly as they were") {
    constexpr double qnan = std::numeric_limits<double>::quiet_NaN();
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        using stepper = odestep::explicit_rk<M, state2>;
        // Poison the last evaluation of the step (the one most likely to be left unchecked).
        for (std::size_t poisoned = 1; poisoned <= stepper::rhs_evals_per_step; ++poisoned) {
            std::size_t calls = 0;
            auto f = [&calls, poisoned](double, const state2& y) {
                ++calls;
                return calls == poisoned ? state2{qnan, y[0]} : state2{y[1], -y[0]};
            };
            state2 y{0.25, 0.5};
            const state2 before = y;
            INFO(doctest::String(M::name), ", evaluation ", poisoned);
            CHECK(stepper{}.step(f, y, 0.0, 0.1) == odestep::status::non_finite);
            CHECK(same_bits(y, before));
        }
        if constexpr (stepper::error_estimate) {
            std::size_t calls = 0;
            auto f = [&calls](double, const state2& y) {
                ++calls;
                return calls == stepper::rhs_evals_per_error_step ? state2{y[1], qnan} : state2{y[1], -y[0]};
            };
            state2 y{0.25, 0.5};
            state2 err{7.0, 8.0};
            const state2 before = y;
            CHECK(stepper{}.step(f, y, 0.0, 0.1, err) == odestep::status::non_finite);
            CHECK(same_bits(y, before));
            CHECK(err[0] == 7.0);
            CHECK(err[1] == 8.0);
        }
    });
}

TEST_CASE(
    "explicit_rk: a NaN or Inf from a stage that does not reach the new state (a zero weight, an f that ignores y) "
    "is non_finite, not an ok step") {
    // f(t, y) = (1, 1) ignores y (a forcing f(t), a switch, a saturation), so a non-finite stage value does not
    // propagate through the later stage inputs; in a stage whose weight b_i is zero (the midpoint rule's b_1,
    // Dormand-Prince's b_2, ...) it reaches neither the new state nor the estimate. Every stage value must be
    // finite for an ok step: each evaluation of each step form is poisoned in turn.
    constexpr double poisons[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
    odestep_test::for_each_method([&](auto method) {
        using M = decltype(method);
        using stepper = odestep::explicit_rk<M, state2>;
        for (const double poison : poisons) {
            for (std::size_t poisoned = 1; poisoned <= stepper::rhs_evals_per_step; ++poisoned) {
                std::size_t calls = 0;
                auto f = [&calls, poisoned, poison](double, const state2&) {
                    ++calls;
                    return calls == poisoned ? state2{poison, poison} : state2{1.0, 1.0};
                };
                state2 y{0.25, 0.5};
                const state2 before = y;
                INFO(doctest::String(M::name), ", evaluation ", poisoned, ", poison ", poison);
                CHECK(stepper{}.step(f, y, 0.0, 0.1) == odestep::status::non_finite);
                CHECK(same_bits(y, before));
            }
            if constexpr (stepper::error_estimate) {
                for (std::size_t poisoned = 1; poisoned <= stepper::rhs_evals_per_error_step; ++poisoned) {
                    std::size_t calls = 0;
                    auto f = [&calls, poisoned, poison](double, const state2&) {
                        ++calls;
                        return calls == poisoned ? state2{poison, poison} : state2{1.0, 1.0};
                    };
                    state2 y{0.25, 0.5};
                    state2 err{7.0, 8.0};
                    const state2 before = y;
                    INFO(doctest::String(M::name), ", estimating step, evaluation ", poisoned, ", poison ", poison);
                    CHECK(stepper{}.step(f, y, 0.0, 0.1, err) == odestep::status::non_finite);
                    CHECK(same_bits(y, before));
                    CHECK(err[0] == 7.0);
                    CHECK(err[1] == 8.0);
                    if constexpr (stepper::error_estimates >= 2) {
                        calls = 0;
                        state2 err2{9.0, 10.0};
                        CHECK(stepper{}.step(f, y, 0.0, 0.1, err, err2) == odestep::status::non_finite);
                        CHECK(same_bits(y, before));
                        CHECK(err[0] == 7.0);
                        CHECK(err2[1] == 10.0);
                    }
                }
            }
        }
    });
}

TEST_CASE("explicit_rk: a step of the oscillator agrees with its closed-form amplification") {
    // For y' = A y with A the rotation generator, one RK4 step is the Taylor polynomial of exp(hA) to
    // degree 4: x1 = (1 - h^2/2 + h^4/24) x0 + (h - h^3/6) v0.
    const double h = 0.3;
    state2 y{1.0, 0.0};
    std::size_t calls = 0;
    REQUIRE(odestep::rk4<state2>{}.step(counting_sho{{}, &calls}, y, 0.0, h) == odestep::status::ok);
    CHECK(y[0] == doctest::Approx(1 - h * h / 2 + h * h * h * h / 24).epsilon(1e-15));
    CHECK(y[1] == doctest::Approx(-(h - h * h * h / 6)).epsilon(1e-15));
}

TEST_CASE("explicit_rk: float, double and long double steppers come from the same template") {
    auto decay = [](auto, const auto& y) {
        auto d = y;
        d[0] = -y[0];
        return d;
    };
    std::array<float, 1> yf{1.0f};
    std::array<double, 1> yd{1.0};
    std::array<long double, 1> yl{1.0L};
    REQUIRE(odestep::integrate(odestep::rk4<std::array<float, 1>>{}, decay, yf, 0.0f, 1.0f, 0.125f).status ==
            odestep::status::ok);
    REQUIRE(odestep::integrate(odestep::rk4<std::array<double, 1>>{}, decay, yd, 0.0, 1.0, 0.125).status ==
            odestep::status::ok);
    REQUIRE(odestep::integrate(odestep::rk4<std::array<long double, 1>>{}, decay, yl, 0.0L, 1.0L, 0.125L).status ==
            odestep::status::ok);
    // RK4's amplification per step R(-h) = 1 - h + h^2/2 - h^3/6 + h^4/24, to the 8th power
    const long double h = 0.125L;
    const long double r = 1 - h + h * h / 2 - h * h * h / 6 + h * h * h * h / 24;
    long double exact = 1;
    for (int i = 0; i < 8; ++i) exact *= r;
    CHECK(static_cast<long double>(yf[0]) == doctest::Approx(static_cast<double>(exact)).epsilon(1e-6));
    CHECK(yd[0] == doctest::Approx(static_cast<double>(exact)).epsilon(1e-15));
    CHECK(std::fabs(yl[0] - exact) <= 16 * std::numeric_limits<long double>::epsilon());
}

// Compile-time: the traits are constants of the right type.
static_assert(std::is_same_v<odestep::rk4<std::array<float, 3>>::value_type, float>);
static_assert(odestep::rk4<std::array<float, 3>>::rhs_evals_per_step == 4);

// The one first-same-as-last detector (tables/butcher.hpp), which explicit_rk and the adaptive engine share:
// the stage whose row of a is b. Dormand & Prince (1980): the seventh row of a is b (c_7 = 1); Bogacki &
// Shampine (1989): the fourth; RK4 and Cash-Karp have none (b_4 = 1/6 and b_6 = 512/1771 are not zero).
static_assert(odestep::detail::b_row(odestep::tables::dormand_prince54::table<double>) == 6);
static_assert(odestep::detail::b_row(odestep::tables::bogacki_shampine32::table<float>) == 3);
static_assert(odestep::detail::b_row(odestep::tables::rk4::table<double>) == 4);
static_assert(odestep::detail::b_row(odestep::tables::cash_karp54::table<double>) == 6);
static_assert(odestep::detail::first_same_as_last(odestep::tables::dormand_prince54::table<long double>));
static_assert(!odestep::detail::first_same_as_last(odestep::tables::cash_karp54::table<double>));

TEST_CASE("explicit_rk: a large state (its finiteness sum taken in lanes) refuses a NaN or Inf in any one component") {
    // 67 components: eight passes of explicit_rk's 8 float lanes (add_all sums a float state of at least 32
    // in lanes) and 3 left over, so that every lane and the remainder are poisoned in turn. f ignores y, so a
    // poisoned stage reaches the test only through its own sum: through the new state for RK4's stages
    // (all weights non-zero), and through the zero-weight stages' sum for Dormand-Prince's second stage.
    // Expected: non_finite and y untouched for each poison; ok for f = 0 on components at half the largest
    // float, whose sum overflows (the slow path then finds every component finite; y' = 0 keeps y exactly).
    constexpr std::size_t n = 67;
    using big = std::array<float, n>;
    const float poisons[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity()};
    const auto poisoned_run = [&](auto stepper, std::size_t evaluation) {
        for (const float poison : poisons) {
            for (std::size_t c = 0; c < n; ++c) {
                std::size_t calls = 0;
                auto f = [&](float, const big&, big& d) {
                    ++calls;
                    d.fill(1.0f);
                    if (calls == evaluation) d[c] = poison;
                };
                big y;
                y.fill(0.5f);
                const big before = y;
                INFO("evaluation ", evaluation, ", component ", c, ", poison ", poison);
                CHECK(stepper.step(f, y, 0.0f, 0.125f) == odestep::status::non_finite);
                CHECK(same_bits(y, before));
            }
        }
    };
    for (std::size_t evaluation = 1; evaluation <= 4; ++evaluation) poisoned_run(odestep::rk4<big>{}, evaluation);
    poisoned_run(odestep::dormand_prince54<big>{}, 2);

    big y;
    y.fill(std::numeric_limits<float>::max() / 2.0f);
    const big before = y;
    CHECK(odestep::rk4<big>{}.step([](float, const big&, big& d) { d.fill(0.0f); }, y, 0.0f, 0.125f) ==
          odestep::status::ok);
    CHECK(same_bits(y, before));
}
