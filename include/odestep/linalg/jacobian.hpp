// SPDX-License-Identifier: BSL-1.0
// odestep: the Jacobian d f / d y an implicit method needs: the system's own (odestep::with_jacobian), or
// forward differences of f with an increment that works in float as in double.
#ifndef ODESTEP_LINALG_JACOBIAN_HPP
#define ODESTEP_LINALG_JACOBIAN_HPP

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../system.hpp"

namespace odestep {

/// Evaluations of f that one finite_difference_jacobian makes: one per column (f(t, y) is an argument).
template <class State>
inline constexpr std::size_t finite_difference_jacobian_evals = state_traits<State>::size;

/// Evaluations of f one Jacobian of System costs a stepper: none when the system carries its own Jacobian
/// (has_jacobian_v), otherwise one per column.
template <class System, class State>
inline constexpr std::size_t jacobian_rhs_evals_v =
    has_jacobian_v<std::remove_cv_t<std::remove_reference_t<System>>, State> ? 0
                                                                             : finite_difference_jacobian_evals<State>;

/// The forward-difference increment for a variable of value x: sqrt(eps max(1e-5, |x|)), RADAU5's choice
/// (Hairer & Wanner, radau5.f, the numerical Jacobian; also rodas.f for df/dt). About sqrt(eps) |x|^(1/2):
/// 3.5e-4 in float and 1.5e-8 in double at |x| = 1, and never below sqrt(eps 1e-5) (1.1e-6 in float,
/// 4.7e-11 in double) for small |x|, so that the rounding error of the difference (eps |f| / increment)
/// stays bounded in float as in double. The increment actually used is (x + delta) - x, exact in T.
template <class T>
T difference_increment(T x) noexcept {
    const T floor = T(1e-5);
    const T magnitude = detail::abs_value(x);
    return std::sqrt(std::numeric_limits<T>::epsilon() * (magnitude > floor ? magnitude : floor));
}

/// \brief dfdy = d f / d y at (t, y) by forward differences, given fy = f(t, y): column j is
/// (f(t, y + delta_j e_j) - fy) / delta_j, with delta_j from difference_increment(y_j).
///
/// Costs finite_difference_jacobian_evals<State> = N evaluations of f. A NaN or Inf from any of them (or in
/// a column) returns `status::non_finite`; dfdy is then partly written, y and fy are untouched.
template <class System, class State>
[[nodiscard]] status finite_difference_jacobian(System& f, value_type_t<State> t, const State& y, const State& fy,
                                                jacobian_t<State>& dfdy) {
    using T = value_type_t<State>;
    constexpr std::size_t N = state_traits<State>::size;
    State shifted = y;
    State column;
    for (std::size_t j = 0; j < N; ++j) {
        const T moved = y[j] + difference_increment(y[j]);
        const T delta = moved - y[j];
        shifted[j] = moved;
        detail::evaluate(f, t, static_cast<const State&>(shifted), column);
        shifted[j] = y[j];
        for (std::size_t i = 0; i < N; ++i) column[i] = (column[i] - fy[i]) / delta;
        if (!detail::all_finite(column)) return status::non_finite;
        for (std::size_t i = 0; i < N; ++i) dfdy[i][j] = column[i];
    }
    return status::ok;
}

/// dfdt = d f / d t at (t, y) by a forward difference, given fy = f(t, y): (f(t + delta, y) - fy) / delta
/// with delta from difference_increment(t). One evaluation of f; `status::non_finite` on NaN or Inf.
template <class System, class State>
[[nodiscard]] status finite_difference_time_derivative(System& f, value_type_t<State> t, const State& y,
                                                       const State& fy, State& dfdt) {
    using T = value_type_t<State>;
    const T later = t + difference_increment(t);
    const T delta = later - t;
    State shifted;
    detail::evaluate(f, later, y, shifted);
    for (std::size_t i = 0; i < state_traits<State>::size; ++i) shifted[i] = (shifted[i] - fy[i]) / delta;
    if (!detail::all_finite(shifted)) return status::non_finite;
    dfdt = shifted;
    return status::ok;
}

namespace detail {

/// The Jacobian a stepper uses: the system's own (has_jacobian_v; fy is not read, and a NaN in it is left
/// for the factorization to report as singular_matrix), or forward differences from fy = f(t, y).
template <class System, class State>
status jacobian_of(System& f, value_type_t<State> t, const State& y, const State& fy, jacobian_t<State>& dfdy) {
    if constexpr (has_jacobian_v<System, State>) {
        (void)fy;
        evaluate_jacobian(f, t, y, dfdy);
        return status::ok;
    } else {
        return finite_difference_jacobian(f, t, y, fy, dfdy);
    }
}

}  // namespace detail
}  // namespace odestep

#endif
