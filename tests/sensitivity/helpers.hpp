// SPDX-License-Identifier: BSL-1.0
// What the sensitivity tests share: small dense matrices, the nonlinear test problems with their hand-written
// Jacobians, and the check of a transition's Phi against central differences of the plain step.
#ifndef ODESTEP_TESTS_SENSITIVITY_HELPERS_HPP
#define ODESTEP_TESTS_SENSITIVITY_HELPERS_HPP

#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "support/compare.hpp"

namespace sensitivity_test {

using odestep_test::same_bits;

template <class T, std::size_t N>
using mat = std::array<std::array<T, N>, N>;

template <class T, std::size_t N>
mat<T, N> identity() {
    mat<T, N> m{};
    for (std::size_t i = 0; i < N; ++i) m[i][i] = T(1);
    return m;
}
template <class T, std::size_t N>
mat<T, N> product(const mat<T, N>& a, const mat<T, N>& b) {
    mat<T, N> c{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j)
            for (std::size_t l = 0; l < N; ++l) c[i][j] += a[i][l] * b[l][j];
    return c;
}
template <class T, std::size_t N>
mat<T, N> transpose(const mat<T, N>& a) {
    mat<T, N> t{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) t[i][j] = a[j][i];
    return t;
}
// The largest |a_ij - b_ij|; NaN if any difference is NaN.
template <class T, std::size_t N>
T max_difference(const mat<T, N>& a, const mat<T, N>& b) {
    T largest = T(0);
    for (std::size_t i = 0; i < N; ++i) {
        const T d = odestep_test::max_abs_difference(a[i], b[i]);
        if (d != d) return d;
        if (d > largest) largest = d;
    }
    return largest;
}
template <class T, std::size_t N>
T max_entry(const mat<T, N>& a) {
    T largest = T(0);
    for (const auto& row : a)
        for (T x : row) largest = std::fabs(x) > largest ? std::fabs(x) : largest;
    return largest;
}

struct lorenz {
    template <class T>
    std::array<T, 3> operator()(T, const std::array<T, 3>& y) const {
        return {T(10) * (y[1] - y[0]), y[0] * (T(28) - y[2]) - y[1], y[0] * y[1] - T(8) / T(3) * y[2]};
    }
};
// d f / d y of Lorenz, by hand.
struct lorenz_jacobian {
    template <class T>
    void operator()(T, const std::array<T, 3>& y, mat<T, 3>& J) const {
        J = {{{T(-10), T(10), T(0)}, {T(28) - y[2], T(-1), -y[0]}, {y[1], y[0], T(-8) / T(3)}}};
    }
};
// The pendulum y = (theta, omega): theta' = omega, omega' = -sin theta.
struct pendulum {
    template <class T>
    std::array<T, 2> operator()(T, const std::array<T, 2>& y) const {
        return {y[1], -std::sin(y[0])};
    }
};
struct pendulum_jacobian {
    template <class T>
    void operator()(T, const std::array<T, 2>& y, mat<T, 2>& J) const {
        J = {{{T(0), T(1)}, {-std::cos(y[0]), T(0)}}};
    }
};
// Kepler (GM = 1) as a first-order system y = (x1, x2, v1, v2).
struct kepler4 {
    template <class T>
    std::array<T, 4> operator()(T, const std::array<T, 4>& y) const {
        const T r2 = y[0] * y[0] + y[1] * y[1];
        const T k = T(1) / (r2 * std::sqrt(r2));
        return {y[2], y[3], -k * y[0], -k * y[1]};
    }
};
// d a / d x of a = -x / r^3: -(I - 3 x x^T / r^2) / r^3.
template <class T>
mat<T, 2> kepler_hessian(const std::array<T, 2>& x) {
    const T r2 = x[0] * x[0] + x[1] * x[1];
    const T r = std::sqrt(r2);
    const T k = T(1) / (r2 * r);
    const T q = T(3) * k / r2;
    return {{{-k + q * x[0] * x[0], q * x[0] * x[1]}, {q * x[1] * x[0], -k + q * x[1] * x[1]}}};
}
struct kepler4_jacobian {
    template <class T>
    void operator()(T, const std::array<T, 4>& y, mat<T, 4>& J) const {
        const mat<T, 2> h = kepler_hessian(std::array<T, 2>{y[0], y[1]});
        J = {{{T(0), T(0), T(1), T(0)},
              {T(0), T(0), T(0), T(1)},
              {h[0][0], h[0][1], T(0), T(0)},
              {h[1][0], h[1][1], T(0), T(0)}}};
    }
};

// Central differences of the plain stepper's step: column j = (step(y + e e_j) - step(y - e e_j)) / (2 e).
template <class Plain, class F, class T, std::size_t N>
mat<T, N> central_difference(F f, const std::array<T, N>& y, T t, T dt, T e) {
    mat<T, N> d{};
    for (std::size_t j = 0; j < N; ++j) {
        std::array<T, N> plus = y;
        std::array<T, N> minus = y;
        plus[j] += e;
        minus[j] -= e;
        REQUIRE(Plain{}.step(f, plus, t, dt) == odestep::status::ok);
        REQUIRE(Plain{}.step(f, minus, t, dt) == odestep::status::ok);
        for (std::size_t i = 0; i < N; ++i) d[i][j] = (plus[i] - minus[i]) / (T(2) * e);
    }
    return d;
}

// The difference's error is e^2/6 times a third derivative of the step plus round-off: halving e divides it
// by 4 while truncation dominates. Over the sweep e = e0, e0/2, e0/4, e0/8 each halving must divide the error
// by 3 to 5; a Phi off by delta makes the error level out at delta (ratios near 1).
template <class Plain, class Transition, class F, class T, std::size_t N>
void check_against_differences(F f, const std::array<T, N>& y, T t, T dt, T e0) {
    std::array<T, N> y1 = y;
    mat<T, N> phi{};
    REQUIRE(Transition{}.step(f, y1, phi, t, dt) == odestep::status::ok);
    // The new state is the plain step's, bit for bit.
    std::array<T, N> plain = y;
    REQUIRE(Plain{}.step(f, plain, t, dt) == odestep::status::ok);
    CHECK(same_bits(plain, y1));
    T e = e0;
    T previous = max_difference(central_difference<Plain>(f, y, t, dt, e), phi);
    for (int halving = 0; halving < 3; ++halving) {
        e /= T(2);
        const T error = max_difference(central_difference<Plain>(f, y, t, dt, e), phi);
        INFO("e = " << e << ", error " << error << ", previous " << previous);
        CHECK(previous / error > T(3));
        CHECK(previous / error < T(5));
        previous = error;
    }
}

}  // namespace sensitivity_test

#endif
