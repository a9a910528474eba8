// SPDX-License-Identifier: BSL-1.0
// odestep: the Rosenbrock (linearly implicit) tables, stepped by odestep::rosenbrock (rk/rosenbrock.hpp).
#ifndef ODESTEP_TABLES_ROSENBROCK_HPP
#define ODESTEP_TABLES_ROSENBROCK_HPP

#include <array>
#include <cstddef>
#include <limits>

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

namespace detail {
// sum v = 1 to the rounding of T, or to 1e-16 relative for a long double table computed from coefficients
// published to 16 digits (Rodas4): its weights sum to 1 only as far as the published digits do.
template <class T, std::size_t S>
constexpr bool weights_sum_to_one(const std::array<T, S>& v) noexcept {
    T sum = T(0);
    T magnitude = T(1);
    for (std::size_t j = 0; j < S; ++j) {
        sum += v[j];
        magnitude += abs_value(v[j]);
    }
    const T unit = std::numeric_limits<T>::epsilon() > T(1e-16L) ? std::numeric_limits<T>::epsilon() : T(1e-16L);
    return abs_value(sum - T(1)) <= T(4) * T(S + 1) * unit * magnitude;
}
}  // namespace detail

/// alpha strictly lower triangular, gamma lower triangular with one non-zero diagonal entry, sum b = 1 (and
/// sum bhat = 1 for a table with an embedded solution).
template <class T, std::size_t S>
constexpr bool is_consistent(const rosenbrock_tableau<T, S>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i) {
        for (std::size_t j = i; j < S; ++j)
            if (tab.alpha[i][j] != T(0)) return false;
        for (std::size_t j = i + 1; j < S; ++j)
            if (tab.gamma[i][j] != T(0)) return false;
        if (tab.gamma[i][i] != tab.gamma[0][0]) return false;
    }
    const bool embedded_ok = tab.embedded_order == 0 || detail::weights_sum_to_one(tab.b_embedded);
    return tab.gamma[0][0] != T(0) && detail::weights_sum_to_one(tab.b) && embedded_ok && tab.order >= 1;
}

namespace detail {
/// \brief A rosenbrock_tableau from the transformed coefficients a method is published in (Hairer & Wanner,
/// Solving ODE II, Sec. IV.7, (7.7)-(7.8); their rodas.f and KPP print these): Gamma^-1 = I / gamma - C (C
/// strictly lower triangular), so Gamma = (I / gamma - C)^-1 by forward substitution, alpha = a Gamma,
/// b = m Gamma, bhat = mhat Gamma. Computed at compile time in T; odestep::rosenbrock transforms back.
template <class T, std::size_t S>
constexpr rosenbrock_tableau<T, S> rosenbrock_from_transformed(T gamma, const std::array<std::array<T, S>, S>& a,
                                                               const std::array<std::array<T, S>, S>& c,
                                                               const std::array<T, S>& m, const std::array<T, S>& mhat,
                                                               int order, int embedded_order) noexcept {
    rosenbrock_tableau<T, S> tab{};
    // g = Gamma, lower triangular, solving (I / gamma - C) g = I column by column
    std::array<std::array<T, S>, S> g{};
    for (std::size_t col = 0; col < S; ++col)
        for (std::size_t i = col; i < S; ++i) {
            T sum = i == col ? T(1) : T(0);
            for (std::size_t j = col; j < i; ++j) sum += c[i][j] * g[j][col];
            g[i][col] = sum * gamma;
        }
    for (std::size_t i = 0; i < S; ++i)
        for (std::size_t j = 0; j < S; ++j) {
            T al = T(0);
            for (std::size_t k = 0; k < S; ++k) al += a[i][k] * g[k][j];
            tab.alpha[i][j] = j < i ? al : T(0);
            tab.gamma[i][j] = j <= i ? (i == j ? gamma : g[i][j]) : T(0);
            tab.b[j] += m[i] * g[i][j];
            tab.b_embedded[j] += mhat[i] * g[i][j];
        }
    tab.order = order;
    tab.embedded_order = embedded_order;
    return tab;
}
}  // namespace detail

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

/// \brief Rodas4: six stages, order 4, stiffly accurate and L-stable, gamma = 1/4, with an embedded solution of
/// order 3 (the fifth stage's output) for error control.
///
/// Hairer & Wanner, Solving ODE II, 2nd ed., Sec. VI.4 (Table 4.1's method 1) and their code rodas.f (ROCOE,
/// METH = 1), which print the transformed coefficients a, C, m = (a_51, a_52, a_53, a_54, 1, 1) and
/// mhat = (a_51, a_52, a_53, a_54, 1, 0) to 16 digits, the same numbers as KPP's Rodas4; here the table is
/// computed from them at compile time (detail::rosenbrock_from_transformed). tests/rk/rosenbrock_test.cpp checks
/// its order conditions, its nodes alpha_i = (0, 0.386, 0.21, 0.63, 1, 1) and gamma_i = (1/4, -0.1043, 0.1035,
/// -0.0362, 0, 0), and that the transformation gives the published a, C, m back.
struct rodas4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Rodas4";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (Hairer & Wanner, Table VI.4.1)
    static constexpr bool l_stable = true;  ///< R(infinity) = 0
    /// The published transformed coefficients a (rodas.f's A21 .. A54; row 6 = row 5 with a_65 = 1).
    template <class T>
    static constexpr std::array<std::array<T, 6>, 6> a{{
        {T(0), T(0), T(0), T(0), T(0), T(0)},
        {T(0.1544000000000000e+01L), T(0), T(0), T(0), T(0), T(0)},
        {T(0.9466785280815826e+00L), T(0.2557011698983284e+00L), T(0), T(0), T(0), T(0)},
        {T(0.3314825187068521e+01L), T(0.2896124015972201e+01L), T(0.9986419139977817e+00L), T(0), T(0), T(0)},
        {T(0.1221224509226641e+01L), T(0.6019134481288629e+01L), T(0.1253708332932087e+02L),
         T(-0.6878860361058950e+00L), T(0), T(0)},
        {T(0.1221224509226641e+01L), T(0.6019134481288629e+01L), T(0.1253708332932087e+02L),
         T(-0.6878860361058950e+00L), T(1), T(0)},
    }};
    /// The published C (rodas.f's C21 .. C65).
    template <class T>
    static constexpr std::array<std::array<T, 6>, 6> c{{
        {T(0), T(0), T(0), T(0), T(0), T(0)},
        {T(-0.5668800000000000e+01L), T(0), T(0), T(0), T(0), T(0)},
        {T(-0.2430093356833875e+01L), T(-0.2063599157091915e+00L), T(0), T(0), T(0), T(0)},
        {T(-0.1073529058151375e+00L), T(-0.9594562251023355e+01L), T(-0.2047028614809616e+02L), T(0), T(0), T(0)},
        {T(0.7496443313967647e+01L), T(-0.1024680431464352e+02L), T(-0.3399990352819905e+02L),
         T(0.1170890893206160e+02L), T(0), T(0)},
        {T(0.8083246795921522e+01L), T(-0.7981132988064893e+01L), T(-0.3152159432874371e+02L),
         T(0.1631930543123136e+02L), T(-0.6058818238834054e+01L), T(0)},
    }};
    /// The table with its coefficients in T.
    template <class T>
    static constexpr rosenbrock_tableau<T, 6> table = detail::rosenbrock_from_transformed<T, 6>(
        T(1) / T(4), a<T>, c<T>, {a<T>[4][0], a<T>[4][1], a<T>[4][2], a<T>[4][3], T(1), T(1)},
        {a<T>[4][0], a<T>[4][1], a<T>[4][2], a<T>[4][3], T(1), T(0)}, 4, 3);
};

static_assert(is_consistent(rodas4::table<float>) && is_consistent(rodas4::table<double>) &&
                  is_consistent(rodas4::table<long double>),
              "tables::rodas4 is not consistent");

// clang-format on
}  // namespace tables
}  // namespace odestep

#endif
