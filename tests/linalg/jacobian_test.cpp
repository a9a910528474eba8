// SPDX-License-Identifier: BSL-1.0
// Jacobians: the system forms that carry one (detected at compile time), and forward differences against
// closed-form Jacobians in float and double, with their published cost.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace {

template <class T>
using state3 = std::array<T, 3>;

// f(y) = (y0^2 y1, sin(y1) + y2, exp(y0) - y2^3) and its Jacobian, in closed form.
struct nonlinear {
    template <class T>
    void operator()(T, const state3<T>& y, state3<T>& d) const noexcept {
        d[0] = y[0] * y[0] * y[1];
        d[1] = std::sin(y[1]) + y[2];
        d[2] = std::exp(y[0]) - y[2] * y[2] * y[2];
    }
};
template <class T>
odestep::jacobian_t<state3<T>> nonlinear_jacobian(const state3<T>& y) {
    return {{{T(2) * y[0] * y[1], y[0] * y[0], T(0)},
             {T(0), std::cos(y[1]), T(1)},
             {std::exp(y[0]), T(0), T(-3) * y[2] * y[2]}}};
}

struct with_member {  // a system object with its own jacobian member
    void operator()(double, const state3<double>& y, state3<double>& d) const { d = y; }
    void jacobian(double, const state3<double>&, odestep::jacobian_t<state3<double>>& j) const {
        j = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    }
};

// Forward differences at y agree with the closed form to the classic bound: truncation delta |f''| / 2 plus
// rounding 2 eps |f| / delta, with delta = sqrt(eps max(|y_j|, 1e-5)) (the bound written out here from the
// definition; |f''| <= 6 (1 + |y|)^2 e^|y0| for this f).
template <class T>
void differences_match(const state3<T>& y) {
    std::size_t calls = 0;
    auto f = [&calls](T t, const state3<T>& v, state3<T>& d) {
        ++calls;
        nonlinear{}(t, v, d);
    };
    state3<T> fy;
    nonlinear{}(T(0), y, fy);
    odestep::jacobian_t<state3<T>> j{};
    REQUIRE(odestep::finite_difference_jacobian(f, T(0), y, fy, j) == odestep::status::ok);
    CHECK(calls == odestep::finite_difference_jacobian_evals<state3<T>>);
    CHECK(calls == 3);
    const auto exact = nonlinear_jacobian(y);
    const T eps = std::numeric_limits<T>::epsilon();
    const T size = T(1) + std::fmax(std::fabs(y[0]), std::fmax(std::fabs(y[1]), std::fabs(y[2])));
    const T second = T(6) * size * size * std::exp(std::fabs(y[0]));
    for (std::size_t c = 0; c < 3; ++c) {
        const T delta = std::sqrt(eps * std::fmax(std::fabs(y[c]), T(1e-5)));
        for (std::size_t r = 0; r < 3; ++r) {
            const T bound = delta * second / T(2) + T(2) * eps * (T(1) + std::fabs(fy[r])) / delta;
            INFO("entry " << r << ", " << c << ": " << j[r][c] << " against " << exact[r][c] << ", bound " << bound);
            CHECK(std::fabs(j[r][c] - exact[r][c]) <= bound);
        }
    }
}

}  // namespace

TEST_CASE("jacobian: a system carrying its Jacobian is detected at compile time, in every form") {
    using s = state3<double>;
    auto f = [](double, const s& y) { return y; };
    auto j_inplace = [](double, const s&, odestep::jacobian_t<s>& m) { m = {}; };
    auto j_returning = [](double, const s&) { return odestep::jacobian_t<s>{}; };
    static_assert(std::is_same_v<odestep::jacobian_t<s>, std::array<std::array<double, 3>, 3>>);
    static_assert(!odestep::has_jacobian_v<decltype(f), s>);
    static_assert(odestep::has_jacobian_v<decltype(odestep::with_jacobian(f, j_inplace)), s>);
    static_assert(odestep::has_jacobian_v<decltype(odestep::with_jacobian(f, j_returning)), s>);
    static_assert(odestep::has_jacobian_v<with_member, s>);
    // the pair is still a system in the form of its f, for every other stepper and loop
    static_assert(odestep::is_returning_system_v<decltype(odestep::with_jacobian(f, j_inplace)), s>);
    static_assert(odestep::is_inplace_system_v<decltype(odestep::with_jacobian(nonlinear{}, j_inplace)), s>);
    static_assert(odestep::is_system_v<const decltype(odestep::with_jacobian(f, j_inplace)), s>);
    // the cost of a Jacobian to a stepper
    static_assert(odestep::jacobian_rhs_evals_v<decltype(f), s> == 3);
    static_assert(odestep::jacobian_rhs_evals_v<decltype(odestep::with_jacobian(f, j_inplace)), s> == 0);
    static_assert(odestep::jacobian_rhs_evals_v<with_member&, s> == 0);
    CHECK(odestep::finite_difference_jacobian_evals<state3<float>> == 3);
}

TEST_CASE("jacobian: with_jacobian holds an lvalue by reference and an rvalue by value") {
    using s = state3<double>;
    auto f = [](double, const s& y) { return y; };
    auto j = [](double, const s&, odestep::jacobian_t<s>& m) { m = {}; };
    using held_refs = decltype(odestep::with_jacobian(f, j));
    static_assert(std::is_same_v<held_refs, odestep::system_with_jacobian<decltype(f)&, decltype(j)&>>);
    using held_values = decltype(odestep::with_jacobian(nonlinear{}, decltype(j){j}));
    static_assert(std::is_same_v<held_values, odestep::system_with_jacobian<nonlinear, decltype(j)>>);
    // and calls them: the system's own Jacobian goes through the stepper's dispatch unchanged
    std::size_t calls = 0;
    auto jc = [&calls](double, const s&, odestep::jacobian_t<s>& m) {
        ++calls;
        m = {{{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}};
    };
    const auto sys = odestep::with_jacobian(f, jc);
    odestep::jacobian_t<s> m{};
    const s y{1, 2, 3};
    REQUIRE(odestep::detail::jacobian_of(sys, 0.0, y, y, m) == odestep::status::ok);
    CHECK(calls == 1);
    CHECK(m[1][1] == 2.0);
    with_member member;
    REQUIRE(odestep::detail::jacobian_of(member, 0.0, y, y, m) == odestep::status::ok);
    CHECK(m[1][1] == 1.0);
}

TEST_CASE("jacobian: forward differences match the closed form to sqrt(eps), in float and double, small |y| too") {
    differences_match<double>({0.7, -1.3, 0.4});
    differences_match<float>({0.7f, -1.3f, 0.4f});
    differences_match<double>({3e-4, 2e-3, -1e-3});  // below the 1e-5 floor's reach: sqrt(eps 1e-5) increments
    differences_match<float>({3e-4f, 2e-3f, -1e-3f});
    differences_match<double>({12.0, -40.0, 3.0});
}

TEST_CASE("jacobian: the increment is sqrt(eps max(|x|, 1e-5)), exact in T") {
    CHECK(odestep::difference_increment(1.0) == doctest::Approx(std::sqrt(std::numeric_limits<double>::epsilon())));
    CHECK(double(odestep::difference_increment(0.0f)) ==
          doctest::Approx(double(std::sqrt(std::numeric_limits<float>::epsilon() * 1e-5f))).epsilon(1e-6));
    CHECK(odestep::difference_increment(-400.0) ==
          doctest::Approx(20 * std::sqrt(std::numeric_limits<double>::epsilon())));
}

TEST_CASE("jacobian: a linear system's difference Jacobian is its matrix to about sqrt(eps)") {
    // f(y) = A y with A = [[-1, 2, 0], [0, -1000, 1], [3, 0, -0.5]]
    auto f = [](double, const state3<double>& y) {
        return state3<double>{-y[0] + 2 * y[1], -1000 * y[1] + y[2], 3 * y[0] - 0.5 * y[2]};
    };
    const state3<double> y{1, 0.001, -2};
    odestep::jacobian_t<state3<double>> j{};
    REQUIRE(odestep::finite_difference_jacobian(f, 0.0, y, f(0.0, y), j) == odestep::status::ok);
    const double a[3][3] = {{-1, 2, 0}, {0, -1000, 1}, {3, 0, -0.5}};
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) CHECK(std::fabs(j[r][c] - a[r][c]) <= 1e-6 * (1 + std::fabs(a[r][c])));
}

TEST_CASE("jacobian: a NaN from f in any column is non_finite; df/dt costs one evaluation") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const state3<double> y{1, 2, 3};
    auto poisoned = [nan, y](double, const state3<double>& v) {
        return v[2] == y[2] ? v : state3<double>{0, nan, 0};  // NaN only when the third component moves
    };
    odestep::jacobian_t<state3<double>> j{};
    CHECK(odestep::finite_difference_jacobian(poisoned, 0.0, y, y, j) == odestep::status::non_finite);
    // df/dt of f = (t^2, sin t, 1) at t = 2: (4, cos 2, 0), by one evaluation
    std::size_t calls = 0;
    auto ft = [&calls](double t, const state3<double>&) {
        ++calls;
        return state3<double>{t * t, std::sin(t), 1};
    };
    state3<double> dfdt{};
    REQUIRE(odestep::finite_difference_time_derivative(ft, 2.0, y, state3<double>{4, std::sin(2.0), 1}, dfdt) ==
            odestep::status::ok);
    CHECK(calls == 1);
    CHECK(dfdt[0] == doctest::Approx(4).epsilon(1e-7));
    CHECK(dfdt[1] == doctest::Approx(std::cos(2.0)).epsilon(1e-7));
    CHECK(dfdt[2] == 0);
    auto nan_t = [nan](double, const state3<double>&) { return state3<double>{nan, 0, 0}; };
    CHECK(odestep::finite_difference_time_derivative(nan_t, 2.0, y, y, dfdt) == odestep::status::non_finite);
}
