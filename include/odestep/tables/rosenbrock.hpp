// SPDX-License-Identifier: BSL-1.0
// odestep: the Rosenbrock (linearly implicit) tables, stepped by odestep::rosenbrock (rk/rosenbrock.hpp).
#ifndef ODESTEP_TABLES_ROSENBROCK_HPP
#define ODESTEP_TABLES_ROSENBROCK_HPP

#include <array>
#include <cstddef>

#include "butcher.hpp"

namespace odestep {

/// \brief A Rosenbrock method with S stages in Hairer & Wanner's form (Solving ODE II, Sec. IV.7, (7.4)):
///
///     (I - h gamma J) k_i = h f(t + alpha_i h, y_n + sum_{j<i} alpha_ij k_j) + h J sum_{j<i} gamma_ij k_j
///                           + gamma_i h^2 df/dt
///     y_{n+1} = y_n + sum_i b_i k_i
///
/// with J = df/dy(t_n, y_n), alpha_i = sum_j alpha_ij and gamma_i = sum_{j<=i} gamma_ij. `alpha` is strictly
/// lower triangular; `gamma` is lower triangular with every diagonal entry gamma. Each stage is one linear
/// solve with the same matrix: one factorization per step and no iteration, so the work of a step is fixed.
template <class T, std::size_t S>
struct rosenbrock_tableau {
    using value_type = T;                     ///< the coefficients' type
    static constexpr std::size_t stages = S;  ///< stages (linear solves per step)
    std::array<std::array<T, S>, S> alpha{};  ///< alpha_ij, strictly lower triangular
    std::array<std::array<T, S>, S> gamma{};  ///< gamma_ij, lower triangular, constant diagonal
    std::array<T, S> b{};                     ///< weights
    int order = 0;                            ///< classical order (Hairer & Wanner, Table IV.7.1)
    std::array<T, S> b_embedded{};            ///< weights of the embedded solution (all zero: none)
    int embedded_order = 0;                   ///< its order (0: no embedded solution)
};

/// alpha strictly lower triangular, gamma lower triangular with one non-zero diagonal entry, sum b = 1.
template <class T, std::size_t S>
constexpr bool is_consistent(const rosenbrock_tableau<T, S>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i) {
        for (std::size_t j = i; j < S; ++j)
            if (tab.alpha[i][j] != T(0)) return false;
        for (std::size_t j = i + 1; j < S; ++j)
            if (tab.gamma[i][j] != T(0)) return false;
        if (tab.gamma[i][i] != tab.gamma[0][0]) return false;
    }
    return tab.gamma[0][0] != T(0) && detail::sums_to(tab.b, S, T(1)) && tab.order >= 1;
}

namespace tables {
// clang-format off  (the tables keep their published layout)

/// \brief RODAS3: four stages, order 3, stiffly accurate and L-stable, gamma = 1/2, every coefficient a
/// small rational (exact in float).
///
/// Sandu, Verwer, Blom, Spee, Carmichael & Potra (1997), "Benchmarking stiff ODE solvers for atmospheric
/// chemistry problems II: Rosenbrock solvers", Atmos. Environ. 31(20), 3459-3472 (the same coefficients are
/// PETSc's TSROSWRODAS3, and, transformed to Hairer & Wanner's (a, C, m) form, KPP's Rodas3: a_31 = a_41 = 2,
/// a_43 = 1, C = (4; 1, -1; 1, -1, -8/3), m = (2, 0, 1, 1), which tests/rk/rosenbrock_test.cpp checks).
/// The embedded solution of order 2 is the input of the fourth stage, bhat = (3/4, -1/4, 1/2, 0) (the last
/// row of alpha: the method's own, as KPP's Rodas3 error weights E = m - mhat = (0, 0, 0, 1) give it).
///
/// Why this one (and not ROS3P): a fixed-step user cannot shrink the step when a fast mode appears, so the
/// method must damp it: L-stability (R(infinity) = 0) and stiff accuracy (y_{n+1} is the last stage, which
/// holds the algebraic relations of the stiff limit). ROS3P (Lang & Verwer 2001) is only A-stable with
/// R(infinity) = -0.73: a fast mode loses a quarter of its amplitude per step and flips sign, visibly
/// ringing at the step sizes Robertson and Van der Pol are run at. RODAS3 costs one stage more (three
/// evaluations of f, because stages 1 and 2 share theirs) and is exact in float.
struct rodas3 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "RODAS3";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = true;  ///< A-stable and R(infinity) = 0 (tested from the table)
    /// The table with its coefficients in T.
    template <class T>
    static constexpr rosenbrock_tableau<T, 4> table{{{{T(0), T(0), T(0), T(0)},
                                                      {T(0), T(0), T(0), T(0)},
                                                      {T(1), T(0), T(0), T(0)},
                                                      {T(3) / T(4), T(-1) / T(4), T(1) / T(2), T(0)}}},
                                                    {{{T(1) / T(2), T(0), T(0), T(0)},
                                                      {T(1), T(1) / T(2), T(0), T(0)},
                                                      {T(-1) / T(4), T(-1) / T(4), T(1) / T(2), T(0)},
                                                      {T(1) / T(12), T(1) / T(12), T(-2) / T(3), T(1) / T(2)}}},
                                                    {T(5) / T(6), T(-1) / T(6), T(-1) / T(6), T(1) / T(2)},
                                                    3,
                                                    {T(3) / T(4), T(-1) / T(4), T(1) / T(2), T(0)},
                                                    2};
};

static_assert(is_consistent(rodas3::table<float>) && is_consistent(rodas3::table<double>) &&
                  is_consistent(rodas3::table<long double>),
              "tables::rodas3 is not consistent");

// clang-format on
}  // namespace tables
}  // namespace odestep

#endif
