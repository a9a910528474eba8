// SPDX-License-Identifier: BSL-1.0
// The grid clock: how many steps a run over [t0, t1] takes, the length of its last step, and the time of
// step n, in float and double. The expected counts are computed independently, in long double (exact for
// these float and double inputs: their difference and quotient keep 64 bits), from the rule the README
// states: the count is the whole number of steps that reaches t1 to within the grid's rounding, else one
// more with the last step shortened.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace {

// The expected count for t0, t1, dt given in T: r = (t1 - t0) / dt exactly (to long double), and the grid's
// rounding 2 eps_T (|t0| + |t1|) expressed in steps; a whole number within it of r is the count, otherwise
// ceil(r).
template <class T>
std::uint64_t expected_steps(T t0, T t1, T dt) {
    const long double r = (static_cast<long double>(t1) - static_cast<long double>(t0)) / static_cast<long double>(dt);
    const long double slack = 2.0L * static_cast<long double>(std::numeric_limits<T>::epsilon()) *
                              (std::fabs(static_cast<long double>(t0)) + std::fabs(static_cast<long double>(t1))) /
                              std::fabs(static_cast<long double>(dt));
    const long double nearest = std::nearbyint(r);
    if (nearest >= 1.0L && std::fabs(r - nearest) <= slack) return static_cast<std::uint64_t>(nearest);
    return static_cast<std::uint64_t>(std::ceil(r));
}

// A deterministic stream of numbers in [0, 1) (a 64-bit LCG, Knuth's MMIX constants).
struct lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) * 0x1.0p-53;
    }
};

template <class T>
odestep::detail::grid_plan<T> plan_of(T t0, T t1, T dt) {
    odestep::detail::grid_plan<T> p;
    REQUIRE(odestep::detail::plan_run(t0, t1, dt, p) == odestep::status::ok);
    return p;
}

}  // namespace

TEST_CASE("grid clock: whole-second float runs from 1 s to 2000 s at dt = 0.001f take 1000 steps a second") {
    // float(0.001) = 0.0010000000474974513, so t1 / dt falls short of 1000 t1 by 4.75e-5 t1 steps: at most a
    // tenth of a step, far inside the grid's rounding there (0.24 t1 / 1000 s); the old count, rounded with a
    // slack of 16 eps times the quotient, lost a step from 508 s on.
    for (int s = 1; s <= 2000; ++s) {
        const float t1 = static_cast<float>(s);
        const auto p = plan_of(0.0f, t1, 0.001f);
        INFO("t1 = " << s);
        CHECK(p.steps == static_cast<std::uint64_t>(1000 * s));
        CHECK(p.steps == expected_steps(0.0f, t1, 0.001f));
        CHECK(p.h_last == 0.001f);  // the last step is dt: t1 is on the grid to its rounding
    }
}

TEST_CASE("grid clock: t1 half a step past the grid gets a shortened last step, never one of 1.5 dt") {
    // 300.0005f is 300.000488..., half a step of 0.001f past 300: 300 000 steps and a last one of about dt/2.
    const auto p = plan_of(0.0f, 300.0005f, 0.001f);
    CHECK(p.steps == 300001);
    CHECK(p.steps == expected_steps(0.0f, 300.0005f, 0.001f));
    CHECK(p.h_last < 0.6f * 0.001f);
    CHECK(p.h_last > 0.4f * 0.001f);
}

TEST_CASE(
    "grid clock: random runs in float and double take the independently computed count, no step longer "
    "than dt beyond the grid's rounding and no sliver") {
    lcg rng{12345};
    auto check_type = [&](auto zero) {
        using T = decltype(zero);
        for (int k = 0; k < 4000; ++k) {
            // t0 in [-1000, 1000], dt in [1e-4, 1] with either sign, 1 to 2000 steps, t1 sometimes on a grid
            // time (rounded), sometimes anywhere.
            const T t0 = static_cast<T>(2000.0 * rng.next() - 1000.0);
            const T dt_mag = static_cast<T>(std::pow(10.0, -4.0 * rng.next()));
            const T dt = rng.next() < 0.5 ? dt_mag : -dt_mag;
            const auto n = static_cast<std::uint64_t>(1 + 2000.0 * rng.next());
            const bool on_grid = rng.next() < 0.5;
            const T t1 = on_grid ? static_cast<T>(t0 + static_cast<T>(n) * dt)
                                 : static_cast<T>(t0 + (static_cast<T>(n) - static_cast<T>(rng.next())) * dt);
            const long double rounding =
                2.0L * static_cast<long double>(std::numeric_limits<T>::epsilon()) *
                (std::fabs(static_cast<long double>(t0)) + std::fabs(static_cast<long double>(t1)));
            // (where dt is within a few dozen roundings the grid cannot tell a step from a sliver)
            if (t1 == t0 || std::fabs(static_cast<long double>(dt)) < 64.0L * rounding) continue;
            const auto p = plan_of(t0, t1, dt);
            INFO("t0 = " << t0 << ", t1 = " << t1 << ", dt = " << dt);
            CHECK(p.steps == expected_steps(t0, t1, dt));
            CHECK(p.t_end == t1);
            // Every step but the last is t_{i+1} - t_i on the grid; the last one ends on t1. None is longer
            // than dt beyond the rounding of the two times it joins, and the last is not a sliver.
            const long double last = static_cast<long double>(t1) - static_cast<long double>(p.clock.time(p.steps - 1));
            CHECK(std::fabs(last) <= std::fabs(static_cast<long double>(dt)) + 2.0L * rounding);
            CHECK(std::fabs(last) > rounding);
            CHECK((last > 0.0L) == (dt > T(0)));
        }
    };
    check_type(0.0f);
    check_type(0.0);
}

TEST_CASE("grid clock: a quotient that underflows to zero against the direction of dt is wrong_direction") {
    // (t1 - t0) / dt = -1e-300 / 1e300 underflows to -0, which is not < 0: the old check let the run go
    // backwards with status ok.
    odestep::detail::grid_plan<double> p;
    CHECK(odestep::detail::plan_run(0.0, -1e-300, 1e300, p) == odestep::status::wrong_direction);
    CHECK(odestep::detail::plan_run(0.0, 1e-300, -1e300, p) == odestep::status::wrong_direction);
    // ... and along dt it is one (short) step.
    REQUIRE(odestep::detail::plan_run(0.0, 1e-300, 1e300, p) == odestep::status::ok);
    CHECK(p.steps == 1);
    CHECK(p.h_last == 1e-300);
}

TEST_CASE("grid clock: n steps whose last time overflows are invalid_time") {
    odestep::detail::grid_plan<double> p;
    const double big = std::numeric_limits<double>::max();
    CHECK(odestep::detail::plan_steps(big, -big, 2, p) == odestep::status::invalid_time);  // max - 2 max = -Inf
    CHECK(odestep::detail::plan_steps(0.0, big, 2, p) == odestep::status::invalid_time);
    REQUIRE(odestep::detail::plan_steps(big, -big, 1, p) == odestep::status::ok);  // max - max = 0
    CHECK(p.t_end == 0.0);
}

TEST_CASE("grid clock: the split 64-bit count conversion (a 32-bit target's) is exact to one rounding") {
    // Integers exact in double: below 2^32 the low half's conversion, above it hi 2^32 + lo.
    CHECK(odestep::detail::count_halves<double>(4294967295u) == 4294967295.0);
    CHECK(odestep::detail::count_halves<double>((std::uint64_t{1} << 32) + 5) == 4294967301.0);
    CHECK(odestep::detail::count_halves<double>((std::uint64_t{3} << 40) + 7) == 3298534883335.0);
    CHECK(odestep::detail::count_value<double>((std::uint64_t{3} << 40) + 7) == 3298534883335.0);
    // float: 2^33 + 1 is not a float; its nearest is 2^33.
    CHECK(odestep::detail::count_halves<float>((std::uint64_t{1} << 33) + 1) == 8589934592.0f);
    CHECK(odestep::detail::count_halves<float>(16777217u) == static_cast<float>(16777217u));
    static_assert(std::is_same_v<decltype(odestep::integrate_result<double>{}.steps), std::uint64_t>);
}

TEST_CASE("grid clock: the split T-to-count conversion (a 32-bit target's, no double in float) truncates exactly") {
    // Expected: the whole part of x, written out by hand (x are exactly representable in T).
    using odestep::detail::count_of_halves;
    CHECK(count_of_halves(0.0f) == 0u);
    CHECK(count_of_halves(999999.75f) == 999999u);
    CHECK(count_of_halves(4294967040.0f) == 4294967040u);  // the largest float below 2^32
    CHECK(count_of_halves(4294967296.0f) == std::uint64_t{1} << 32);
    CHECK(count_of_halves(12884901888.0f) == std::uint64_t{3} << 32);                 // 3 * 2^32
    CHECK(count_of_halves(4611686018427387904.0f / 2.0f) == std::uint64_t{1} << 61);  // 2^61
    CHECK(count_of_halves(4294967297.5) == (std::uint64_t{1} << 32) + 1);             // double: 2^32 + 1.5
    CHECK(count_of_halves(1099511627776.25) == std::uint64_t{1} << 40);               // 2^40 + 0.25
    CHECK(count_of_halves(3298534883335.0) == (std::uint64_t{3} << 40) + 7);
    // Against the one conversion, over a sweep of doubles below 2^62 (the host's conversion is exact).
    for (double x = 0.5; x < 4.0e18; x = x * 1.37 + 0.25) CHECK(count_of_halves(x) == static_cast<std::uint64_t>(x));
}
