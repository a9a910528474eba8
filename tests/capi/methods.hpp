// SPDX-License-Identifier: BSL-1.0
// The C method tables the tests/capi/ programs step with, made from the C++ steppers as src/ makes them, and
// src/capi_impl.hpp compiled with ODESTEP_C_EXACT_STATES 2, so that both forms of a single step run: n = 1
// and 2 compiled for n, n = 3 .. ODESTEP_C_MAX_STATES over a run-time n (padded for Adams and the Newtonian
// methods). Included first
// by every file of tests/capi/ (one program: the same definitions everywhere).
#ifndef ODESTEP_TESTS_CAPI_METHODS_HPP
#define ODESTEP_TESTS_CAPI_METHODS_HPP

#define ODESTEP_C_EXACT_STATES 2
#include "../../src/capi_impl.hpp"

namespace capi_test {

struct rk4_family {
    template <class S>
    using type = odestep::rk4<S>;
};
struct dp54_family {
    template <class S>
    using type = odestep::dormand_prince54<S>;
};
struct dop853_family {
    template <class S>
    using type = odestep::dop853<S>;
};
struct midpoint_family {
    template <class S>
    using type = odestep::euler_richardson<S>;
};
struct ab4_family {
    template <class S>
    using type = odestep::adams_bashforth4<S>;
};
struct verlet_family {
    template <class S>
    using type = odestep::velocity_verlet<S>;
};
inline const odestep_method_d rk4_method{odestep::capi::make_ops<double, rk4_family>("rk4")};
inline const odestep_method_d dp54_method{odestep::capi::make_ops<double, dp54_family>("dp54")};
inline const odestep_method_d dop853_method{odestep::capi::make_ops<double, dop853_family>("dop853")};
inline const odestep_method_d midpoint_method{odestep::capi::make_ops<double, midpoint_family>("euler_richardson")};
inline const odestep_method_d ab4_method{odestep::capi::make_ops<double, ab4_family>("ab4")};
inline const odestep_method_d verlet_method{odestep::capi::make_ops<double, verlet_family>("velocity_verlet")};

}  // namespace capi_test

#endif
