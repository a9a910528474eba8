// SPDX-License-Identifier: BSL-1.0
// The check policy (odestep::checked, odestep::unchecked): the unchecked form of a stepper does the checked
// form's arithmetic, so a finite run gives the same states bit for bit; it does not test for NaN and Inf,
// so a NaN from the right-hand side goes into the state with status::ok, where the checked form returns
// status::non_finite and leaves the state as it was. The other checks (an Adams history's grid) stay.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>

#include "support/methods.hpp"

namespace {

using d3 = std::array<double, 3>;
using f3 = std::array<float, 3>;
using d2 = std::array<double, 2>;

template <class S>
bool same_bits(const S& a, const S& b) {
    return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

// The checked and the unchecked form against each other. Bit for bit where the compiler has no fused
// multiply-add for T (x86-64 without -mfma; double on the Cortex-M4F, in software). Where it has one (float on
// the Cortex-M4F/M33/M55, float and double on the M7: __FP_FAST_FMAF / __FP_FAST_FMA), GCC contracts a * b + c
// into it (-ffp-contract=fast, its default for C++) and the two forms, compiled as different functions,
// may fuse different products: the same arithmetic to rounding (measured on the emulated M4F: the float runs
// differed in the last bits). There the states must agree to 1000 ULPs of their scale over the run; a wrong
// step (a stage or a weight missing) is off by order dt = 1/32.
template <class S>
bool same_arithmetic(const S& a, const S& b) {
    using T = typename S::value_type;
#if defined(__FP_FAST_FMAF)
    constexpr bool fused_float = true;
#else
    constexpr bool fused_float = false;
#endif
#if defined(__FP_FAST_FMA)
    constexpr bool fused_double = true;
#else
    constexpr bool fused_double = false;
#endif
#if defined(__FP_FAST_FMAL)
    constexpr bool fused_long_double = true;
#else
    constexpr bool fused_long_double = false;
#endif
    constexpr bool may_fuse = (std::is_same_v<T, float> && fused_float) ||
                              (std::is_same_v<T, double> && fused_double) ||
                              (std::is_same_v<T, long double> && fused_long_double);
    if constexpr (!may_fuse) {
        return same_bits(a, b);
    } else {
        for (std::size_t i = 0; i < a.size(); ++i) {
            const T scale = std::fabs(b[i]) > T(1) ? std::fabs(b[i]) : T(1);
            if (!(std::fabs(a[i] - b[i]) <= T(1000) * std::numeric_limits<T>::epsilon() * scale)) return false;
        }
        return true;
    }
}

template <class S>
bool all_nan(const S& a) {
    for (const auto c : a)
        if (!std::isnan(c)) return false;
    return true;
}

// A nonlinear, time-dependent system (every stage of every table differs from the others), and the same
// system returning NaN in every component once `poisoned` is set.
template <class S>
struct system3 {
    using T = typename S::value_type;
    bool poisoned = false;
    void operator()(T t, const S& y, S& d) const {
        if (poisoned) {
            d.fill(std::numeric_limits<T>::quiet_NaN());
            return;
        }
        d[0] = y[1];
        d[1] = -y[0] + T(0.25) * t - T(0.1) * y[1] * y[2];
        d[2] = y[0] * y[1] - T(0.5) * y[2];
    }
};

// Runs `steps` steps of the checked and the unchecked form of explicit_rk<M, S> side by side (with the error
// estimates where the table has them) and requires the same bits after every step.
template <class M, class S>
void rk_same_bits(int steps) {
    using T = typename S::value_type;
    const odestep::explicit_rk<M, S> checked{};
    const odestep::explicit_rk<M, S, odestep::unchecked> unchecked{};
    static_assert(checked.checks_finiteness && !unchecked.checks_finiteness);
    const system3<S> f{};
    const T dt = T(0.03125);
    S a{T(1), T(0.5), T(-0.25)};
    S b = a;
    for (int i = 0; i < steps; ++i) {
        const T t = T(i) * dt;
        REQUIRE(checked.step(f, a, t, dt) == odestep::status::ok);
        REQUIRE(unchecked.step(f, b, t, dt) == odestep::status::ok);
        REQUIRE(same_arithmetic(a, b));
    }
    if constexpr (odestep::explicit_rk<M, S>::error_estimates >= 1) {
        S ea{};
        S eb{};
        REQUIRE(checked.step(f, a, T(1), dt, ea) == odestep::status::ok);
        REQUIRE(unchecked.step(f, b, T(1), dt, eb) == odestep::status::ok);
        CHECK(same_arithmetic(a, b));
        CHECK(same_arithmetic(ea, eb));
    }
    if constexpr (odestep::explicit_rk<M, S>::error_estimates >= 2) {
        S ea{};
        S eb{};
        S ea2{};
        S eb2{};
        REQUIRE(checked.step(f, a, T(2), dt, ea, ea2) == odestep::status::ok);
        REQUIRE(unchecked.step(f, b, T(2), dt, eb, eb2) == odestep::status::ok);
        CHECK(same_arithmetic(a, b));
        CHECK(same_arithmetic(ea, eb));
        CHECK(same_arithmetic(ea2, eb2));
    }
}

// A NaN from f: the checked form fails the step and leaves y; the unchecked one returns ok with NaN in y.
template <class M, class S>
void rk_nan() {
    using T = typename S::value_type;
    system3<S> f{};
    f.poisoned = true;
    const S y0{T(1), T(0.5), T(-0.25)};
    S a = y0;
    S b = y0;
    CHECK(odestep::explicit_rk<M, S>{}.step(f, a, T(0), T(0.03125)) == odestep::status::non_finite);
    CHECK(same_bits(a, y0));
    CHECK(odestep::explicit_rk<M, S, odestep::unchecked>{}.step(f, b, T(0), T(0.03125)) == odestep::status::ok);
    CHECK(all_nan(b));
    if constexpr (odestep::explicit_rk<M, S>::error_estimates >= 1) {
        S e{};
        b = y0;
        CHECK(odestep::explicit_rk<M, S, odestep::unchecked>{}.step(f, b, T(0), T(0.03125), e) == odestep::status::ok);
        CHECK(all_nan(b));
    }
}

}  // namespace

TEST_CASE("unchecked: explicit Runge-Kutta, every table, the checked form's bits on a finite run") {
    odestep_test::for_each_method([](auto m) {
        using M = decltype(m);
        rk_same_bits<M, d3>(40);
        rk_same_bits<M, f3>(40);
    });
    // And the arithmetic itself, from the closed form: Euler on y' = -y with dt = 1/8 gives y_1 = 7/8 exactly.
    std::array<double, 1> y{1.0};
    REQUIRE(odestep::unchecked_t<odestep::euler<std::array<double, 1>>>{}.step(
                [](double, const std::array<double, 1>& x) { return std::array<double, 1>{-x[0]}; }, y, 0.0, 0.125) ==
            odestep::status::ok);
    CHECK(y[0] == 0.875);
}

TEST_CASE("unchecked: explicit Runge-Kutta, a NaN from f is the state's, with status ok; checked rolls back") {
    odestep_test::for_each_method([](auto m) {
        using M = decltype(m);
        rk_nan<M, d3>();
        rk_nan<M, f3>();
    });
}

TEST_CASE("unchecked: Adams, every table, the checked form's bits; a NaN from f; the grid check stays") {
    odestep_test::for_each_type<odestep_test::adams_methods>([](auto m) {
        using M = decltype(m);
        odestep::adams<M, d3> checked;
        odestep::adams<M, d3, odestep::unchecked_t<odestep::rk4<d3>>, odestep::unchecked> unchecked;
        odestep::adams<M, d3, odestep::rk4<d3>, odestep::unchecked> unchecked_start;  // checked starter
        static_assert(!decltype(unchecked)::checks_finiteness && !decltype(unchecked_start)::checks_finiteness);
        system3<d3> f{};
        const double dt = 0.03125;
        const d3 y0{1.0, 0.5, -0.25};
        d3 a = y0;
        d3 b = y0;
        d3 c = y0;
        int i = 0;
        for (; i < 30; ++i) {
            const double t = i * dt;
            REQUIRE(checked.step(f, a, t, dt) == odestep::status::ok);
            REQUIRE(unchecked.step(f, b, t, dt) == odestep::status::ok);
            REQUIRE(unchecked_start.step(f, c, t, dt) == odestep::status::ok);
            REQUIRE(same_arithmetic(a, b));
            REQUIRE(same_arithmetic(a, c));
        }
        // Off the grid (half a step late): step_mismatch with y untouched, in both forms.
        const d3 b_before = b;
        CHECK(unchecked.step(f, b, (i + 0.5) * dt, dt) == odestep::status::step_mismatch);
        CHECK(same_bits(b, b_before));
        CHECK(unchecked.step(f, b, i * dt, 2 * dt) == odestep::status::step_mismatch);
        CHECK(unchecked.step(f, b, std::nan(""), dt) == odestep::status::invalid_time);
        CHECK(same_bits(b, b_before));
        // A NaN from f, the history full.
        f.poisoned = true;
        const d3 a_before = a;
        CHECK(checked.step(f, a, i * dt, dt) == odestep::status::non_finite);
        CHECK(same_bits(a, a_before));
        CHECK(unchecked.step(f, b, i * dt, dt) == odestep::status::ok);
        CHECK(all_nan(b));
        // Starting, with both policies unchecked: f's NaN goes into y and into the history.
        unchecked.reset();
        b = y0;
        CHECK(unchecked.step(f, b, 0.0, dt) == odestep::status::ok);
        CHECK(all_nan(b));
        CHECK(unchecked.history_size() == 1);
    });
}

TEST_CASE("unchecked: splitting methods, every table, the checked form's bits; a NaN from the force") {
    odestep_test::for_each_type<odestep_test::splitting_methods>([](auto m) {
        using M = decltype(m);
        odestep::splitting<M, d2> checked;
        odestep::splitting<M, d2, odestep::unchecked> unchecked;
        static_assert(checked.checks_finiteness && !unchecked.checks_finiteness);
        bool poisoned = false;
        // An anharmonic force of position alone (Duffing in the first coordinate).
        auto a = [&poisoned](double, const d2& x) {
            if (poisoned) return d2{std::nan(""), std::nan("")};
            return d2{-x[0] - 0.1 * x[0] * x[0] * x[0], -x[1]};
        };
        const double dt = 0.03125;
        d2 xa{1.0, 0.5};
        d2 va{0.0, -0.25};
        d2 xb = xa;
        d2 vb = va;
        for (int i = 0; i < 40; ++i) {
            REQUIRE(checked.step(a, xa, va, i * dt, dt) == odestep::status::ok);
            REQUIRE(unchecked.step(a, xb, vb, i * dt, dt) == odestep::status::ok);
            REQUIRE(same_arithmetic(xa, xb));
            REQUIRE(same_arithmetic(va, vb));
        }
        poisoned = true;
        checked.reset();
        unchecked.reset();
        const d2 x_before = xa;
        const d2 v_before = va;
        CHECK(checked.step(a, xa, va, 0.0, dt) == odestep::status::non_finite);
        CHECK(same_bits(xa, x_before));
        CHECK(same_bits(va, v_before));
        CHECK(unchecked.step(a, xb, vb, 0.0, dt) == odestep::status::ok);
        CHECK(all_nan(vb));  // every table ends its velocity with a kick by the NaN force
    });
}

TEST_CASE("unchecked: velocity Verlet with the acceleration kept by the caller") {
    const odestep::velocity_verlet<d2> checked{};
    const odestep::unchecked_t<odestep::velocity_verlet<d2>> unchecked{};
    auto a = [](double, const d2& x) { return d2{-x[0] - 0.1 * x[0] * x[0] * x[0], -x[1]}; };
    const double dt = 0.03125;
    d2 xa{1.0, 0.5};
    d2 va{0.0, -0.25};
    d2 acc_a = a(0.0, xa);
    d2 xb = xa;
    d2 vb = va;
    d2 acc_b = acc_a;
    for (int i = 0; i < 40; ++i) {
        REQUIRE(checked.step(a, xa, va, acc_a, i * dt, dt) == odestep::status::ok);
        REQUIRE(unchecked.step(a, xb, vb, acc_b, i * dt, dt) == odestep::status::ok);
        REQUIRE(same_arithmetic(xa, xb));
        REQUIRE(same_arithmetic(va, vb));
        REQUIRE(same_arithmetic(acc_a, acc_b));
    }
    // A NaN in the kept acceleration (the caller's): the checked step fails and keeps x, v and acc.
    acc_a[0] = std::nan("");
    acc_b[0] = std::nan("");
    const d2 x_before = xa;
    const d2 v_before = va;
    CHECK(checked.step(a, xa, va, acc_a, 0.0, dt) == odestep::status::non_finite);
    CHECK(same_bits(xa, x_before));
    CHECK(same_bits(va, v_before));
    CHECK(unchecked.step(a, xb, vb, acc_b, 0.0, dt) == odestep::status::ok);
    CHECK(std::isnan(vb[0]));
}
