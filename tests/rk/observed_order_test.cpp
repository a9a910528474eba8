// SPDX-License-Identifier: BSL-1.0
// Every method shows its order on a problem with a closed-form solution, in double, and works in float.
#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>

#include "support/methods.hpp"
#include "support/order_fit.hpp"
#include "support/problems.hpp"

namespace {

using odestep_test::exp_sin;
using odestep_test::state3;

// Largest component error at t_end after `steps` steps of the method in T, on exp_sin (problems.hpp: over
// many periods its truncation error grows linearly with time and round-off only like the square root of the
// step count, which leaves room to see order 8 in double).
template <class Method, class T>
T error_after(T t_end, std::size_t steps) {
    return odestep_test::error_after<odestep::explicit_rk<Method, state3<T>>, exp_sin>(t_end, steps);
}

// Where each order is in its asymptotic regime yet, at the finest step, far above double round-off
// (found by tabulating the local slopes for N = 8 ... 8192: lower-order methods need t_end = 20 and
// the steps below; the eighth-order pairs need the longer t_end = 100 to reach 1e-13 before round-off).
struct fit_plan {
    double t_end;
    std::size_t coarsest_steps;
    std::size_t halvings;
};
constexpr fit_plan plan_for(int order) {
    switch (order) {
        case 1: return {20.0, 1024, 3};
        case 2: return {20.0, 256, 3};
        case 3: return {20.0, 256, 3};
        case 4: return {20.0, 128, 3};
        case 5: return {20.0, 128, 3};
        default: return {100.0, 160, 3};
    }
}

template <class M, class T>
void check_order(const fit_plan& plan) {
    constexpr int order = odestep::explicit_rk<M, state3<T>>::order;
    std::array<double, 4> errors{};
    const std::size_t points = plan.halvings + 1;
    for (std::size_t i = 0; i < points; ++i)
        errors[i] = static_cast<double>(error_after<M, T>(static_cast<T>(plan.t_end), plan.coarsest_steps << i));
    const double slope = odestep_test::fitted_order(errors, points);
    const auto local = odestep_test::local_slopes(errors, points);
    INFO(doctest::String(M::name), ": errors ", errors[0], " ", errors[1], " ", errors[2], " ", errors[3],
         "; local slopes ", local[0], " ", local[1], " ", local[2]);
    MESSAGE(doctest::String(M::name), ": order ", order, ", fitted slope ", slope, " (",
            doctest::String(sizeof(T) == sizeof(double) ? "double" : "long double"), ", error ", errors[0], " to ",
            errors[points - 1], ")");
    CHECK(std::fabs(slope - order) < 0.2);
    CHECK(errors[points - 1] > 100.0 * static_cast<double>(std::numeric_limits<T>::epsilon()));  // above round-off
}

}  // namespace

TEST_CASE("every method reaches its nominal order on y0' = y0 y1, y1' = -y2, y2' = y1 (slope within 0.2)") {
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        if constexpr (std::is_same_v<M, odestep::tables::dop853>) {
            // DOP853's eighth-order error coefficients are so small that in double its error reaches
            // round-off (1e-14) while the ninth-order terms still dominate: local slopes 8.5 to 8.9 for
            // N = 80 to 640 at t_end = 100. Its asymptotic order shows in long double, N = 640 to 2560.
            if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
                check_order<M, long double>({100.0, 640, 2});
            } else {
                MESSAGE("DOP853's asymptotic order needs a long double wider than double; not on this target");
            }
        } else {
            check_order<M, double>(plan_for(odestep::explicit_rk<M, state3<double>>::order));
        }
    });
}

TEST_CASE("every method works in float: its error is its double error to within float round-off") {
    odestep_test::for_each_method([](auto method) {
        using M = decltype(method);
        constexpr int order = odestep::explicit_rk<M, state3<float>>::order;
        const std::size_t n = plan_for(order).coarsest_steps;
        const double err_double = error_after<M, double>(20.0, n);
        const double err_float = static_cast<double>(error_after<M, float>(20.0f, n));
        // Round-off in float: a few ULPs of the solution (|y| <= e) per step, growing at most like the step count.
        const double roundoff =
            8.0 * static_cast<double>(n) * static_cast<double>(std::numeric_limits<float>::epsilon());
        INFO(doctest::String(M::name), ": float error ", err_float, ", double error ", err_double, ", allowance ",
             roundoff);
        CHECK(std::fabs(err_float - err_double) <= roundoff);  // float tracks double to its own round-off
    });
}
