// SPDX-License-Identifier: BSL-1.0
// The observed order of a method: errors at step sizes h, h/2, h/4, ... and the slope of log(error) against
// log(h), fitted by least squares over all of them, or local between neighbours.
#ifndef ODESTEP_TESTS_SUPPORT_ORDER_FIT_HPP
#define ODESTEP_TESTS_SUPPORT_ORDER_FIT_HPP

#include <doctest/doctest.h>
#include <odestep/integrate.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "compare.hpp"

namespace odestep_test {

/// The least-squares slope of log(y) against log(x) over the first `count` points (all when count is not
/// given; at least 2): the exponent p of y ~ C x^p.
template <std::size_t K>
double log_log_slope(const std::array<double, K>& xs, const std::array<double, K>& ys, std::size_t count = K) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const double x = std::log(xs[i]);
        const double y = std::log(ys[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double n = static_cast<double>(count);
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// The least-squares slope of log(error) against log(h) over the first `count` errors (all when count is
/// not given), errors[i] measured at h_i = h_0 / 2^i: the observed order. count must be at least 2.
template <std::size_t K>
double fitted_order(const std::array<double, K>& errors, std::size_t count = K) {
    std::array<double, K> h{};
    for (std::size_t i = 0; i < K; ++i) h[i] = std::ldexp(1.0, -static_cast<int>(i));  // h_i / h_0
    return log_log_slope(h, errors, count);
}

/// The local slopes log2(errors[i] / errors[i + 1]) between neighbours of the first `count` errors (the
/// rest 0): the order each halving shows, which tells the asymptotic range from the pre-asymptotic one.
template <std::size_t K>
std::array<double, K - 1> local_slopes(const std::array<double, K>& errors, std::size_t count = K) {
    std::array<double, K - 1> slopes{};
    for (std::size_t i = 0; i + 1 < count; ++i) slopes[i] = std::log2(errors[i] / errors[i + 1]);
    return slopes;
}

/// The largest component error at t_end of `steps` steps of Stepper (default-constructed) on Problem from
/// Problem::start<T>() at t = 0, through odestep::integrate_n_steps, against Problem::exact<T>(t_end).
/// Problem is a first-order system with those two (see problems.hpp).
template <class Stepper, class Problem, class T>
T error_after(T t_end, std::size_t steps) {
    Stepper stepper;
    auto y = Problem::template start<T>();
    const auto r = odestep::integrate_n_steps(stepper, Problem{}, y, T(0), t_end / static_cast<T>(steps), steps);
    REQUIRE(r.status == odestep::status::ok);
    return max_abs_difference(y, Problem::template exact<T>(t_end));
}

}  // namespace odestep_test

#endif
