// SPDX-License-Identifier: BSL-1.0
// Smoke test of the bare-metal harness itself (startup code, linker script, semihosting, emulator), kept
// independent of odestep so that a harness failure is told apart from a library failure.

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstddef>

namespace {

// .data (initialised), .bss (zeroed) and a static constructor, all set up by Reset_Handler.
int initialised_global = 42;
int zeroed_global;
struct constructed {
    int value;
    constructed() : value(7) {}
};
const constructed constructed_global;

// volatile keeps the compiler from folding the arithmetic at compile time: it must run on the core.
volatile float float_input = 2.0f;
volatile double double_input = 2.0;

}  // namespace

TEST_CASE("startup initialises .data and .bss and runs static constructors") {
    CHECK(initialised_global == 42);
    CHECK(zeroed_global == 0);
    CHECK(constructed_global.value == 7);
}

TEST_CASE("float arithmetic runs on the target") {
    const float x = float_input;
    const float root = std::sqrt(x);
    CHECK(root * root == doctest::Approx(2.0f).epsilon(1e-6f));
    CHECK(x / 3.0f == doctest::Approx(0.6666667f).epsilon(1e-6f));
    CHECK(std::exp(x) == doctest::Approx(7.389056f).epsilon(1e-6f));
}

TEST_CASE("double arithmetic runs on the target") {
    const double x = double_input;
    const double root = std::sqrt(x);
    CHECK(root * root == doctest::Approx(2.0).epsilon(1e-15));
    CHECK(std::sin(x) == doctest::Approx(0.90929742682568170).epsilon(1e-15));
}

TEST_CASE("std::array computation") {
    std::array<double, 8> values{};
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = double_input * static_cast<double>(i);
    }
    double sum = 0.0;
    for (const double v : values) {
        sum += v;
    }
    CHECK(sum == 56.0);
}
