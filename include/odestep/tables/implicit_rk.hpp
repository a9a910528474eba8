// SPDX-License-Identifier: BSL-1.0
// odestep: the implicit Runge-Kutta tables. Each method is a tag type whose `table<T>` is a constexpr
// butcher_tableau typed in T (the same type as the explicit tables, with a full matrix a), stepped by
// odestep::implicit_rk (rk/implicit_rk.hpp). Rational coefficients are written T(p) / T(q); the irrational
// ones (sqrt 3, sqrt 6, the root gamma of Alexander's cubic) as 40-digit long double literals, computed with
// mpmath at 50 digits and rounded once to T.
#ifndef ODESTEP_TABLES_IMPLICIT_RK_HPP
#define ODESTEP_TABLES_IMPLICIT_RK_HPP

#include "butcher.hpp"

namespace odestep::detail {
/// sqrt(3) and sqrt(6), to 40 digits.
template <class T>
inline constexpr T sqrt3 = T(1.732050807568877293527446341505872366943L);
template <class T>
inline constexpr T sqrt6 = T(2.449489742783178098197284074705891391966L);
/// The root near 0.4359 of gamma^3 - 3 gamma^2 + (3/2) gamma - 1/6 = 0 (Alexander 1977; it makes the
/// three-stage SDIRK of order 3 L-stable), to 40 digits.
template <class T>
inline constexpr T alexander_gamma = T(0.4358665215084589994160194511935568425293L);
}  // namespace odestep::detail

namespace odestep::tables {

// clang-format off  (the tables keep their published layout)

/// Backward (implicit) Euler: y_{n+1} = y_n + h f(t_{n+1}, y_{n+1}). Order 1, L-stable, stiffly accurate.
/// (Euler 1768; Hairer & Wanner, Solving ODE II (HW II), Sec. IV.3; the Radau IIA method with s = 1.)
struct backward_euler {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "backward Euler";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = true;  ///< A-stable and R(infinity) = 0 (tested from the table)
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 1> table{{{{T(1)}}}, {T(1)}, {T(1)}, {}, 1, {}};
};

/// The implicit trapezoidal rule (Crank-Nicolson; the Adams-Moulton method of order 2):
/// y_{n+1} = y_n + h/2 (f(t_n, y_n) + f(t_{n+1}, y_{n+1})). Order 2, A-stable with |R(infinity)| = 1
/// (stiff components are not damped: they flip sign every step), symmetric, stiffly accurate.
/// (Crank & Nicolson 1947, Proc. Camb. Phil. Soc. 43, 50-67; HW II Sec. IV.3; as a Runge-Kutta method the
/// Lobatto IIIA method with s = 2, HW II Sec. IV.5.) The first stage is explicit: k_1 = f(t_n, y_n).
struct trapezoid {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "implicit trapezoid (Crank-Nicolson)";
    static constexpr bool a_stable = true;   ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = false;  ///< |R(infinity)| = 1: stiff modes are not damped
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 2> table{
        {{{T(0), T(0)}, {T(1) / T(2), T(1) / T(2)}}}, {T(1) / T(2), T(1) / T(2)}, {T(0), T(1)}, {}, 2, {}};
};

/// The implicit midpoint rule: y_{n+1} = y_n + h f(t_n + h/2, (y_n + y_{n+1}) / 2). Order 2, A-stable,
/// |R(infinity)| = 1, symmetric and symplectic (the Gauss method with s = 1; HW II Sec. IV.5; Hairer,
/// Lubich & Wanner, Geometric Numerical Integration, Sec. VI.3).
struct implicit_midpoint {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "implicit midpoint";
    static constexpr bool a_stable = true;   ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = false;  ///< |R(infinity)| = 1: stiff modes are not damped
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 1> table{{{{T(1) / T(2)}}}, {T(1)}, {T(1) / T(2)}, {}, 2, {}};
};

/// The two-stage Gauss-Legendre method: order 4 (2s), A-stable, |R(infinity)| = 1, symmetric and
/// symplectic; stage order 2. (Hammer & Hollingsworth 1955, Math. Tables Aids Comput. 9, 92-96;
/// Butcher 1964, Math. Comp. 18, 50-64; Hairer, Norsett & Wanner, Solving ODE I, Sec. II.7; HW II
/// Sec. IV.5.)
struct gauss4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Gauss-Legendre 4";
    static constexpr bool a_stable = true;   ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = false;  ///< |R(infinity)| = 1: stiff modes are not damped
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 2> table{
        {{{T(1) / T(4), T(1) / T(4) - detail::sqrt3<T> / T(6)}, {T(1) / T(4) + detail::sqrt3<T> / T(6), T(1) / T(4)}}},
        {T(1) / T(2), T(1) / T(2)},
        {T(1) / T(2) - detail::sqrt3<T> / T(6), T(1) / T(2) + detail::sqrt3<T> / T(6)},
        {},
        4,
        {}};
};

/// Alexander's three-stage SDIRK: order 3, L-stable, stiffly accurate (b is the last row of a), every
/// diagonal entry gamma = 0.43586652150845899941... (the root of gamma^3 - 3 gamma^2 + 3/2 gamma - 1/6
/// that makes R(infinity) = 0 with A-stability). a_21 = (1 - gamma)/2, a_31 = -(6 gamma^2 - 16 gamma + 1)/4,
/// a_32 = (6 gamma^2 - 20 gamma + 5)/4, c = (gamma, (1 + gamma)/2, 1); stage order 1. (R. Alexander 1977,
/// "Diagonally implicit Runge-Kutta methods for stiff O.D.E.'s", SIAM J. Numer. Anal. 14, 1006-1021;
/// HW II Sec. IV.6; Kennedy & Carpenter 2016, "Diagonally implicit Runge-Kutta methods for ordinary
/// differential equations. A review", NASA/TM-2016-219173, which lists the same coefficients.)
struct sdirk3 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "SDIRK 3 (Alexander, L-stable)";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = true;  ///< A-stable and R(infinity) = 0 (tested from the table)
    /// gamma, the diagonal entry of every stage, in T.
    template <class T>
    static constexpr T g = detail::alexander_gamma<T>;
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 3> table{
        {{{g<T>, T(0), T(0)},
          {(T(1) - g<T>) / T(2), g<T>, T(0)},
          {-(T(6) * g<T> * g<T> - T(16) * g<T> + T(1)) / T(4), (T(6) * g<T> * g<T> - T(20) * g<T> + T(5)) / T(4),
           g<T>}}},
        {-(T(6) * g<T> * g<T> - T(16) * g<T> + T(1)) / T(4), (T(6) * g<T> * g<T> - T(20) * g<T> + T(5)) / T(4), g<T>},
        {g<T>, (T(1) + g<T>) / T(2), T(1)},
        {},
        3,
        {}};
};

/// \brief Hairer & Wanner's SDIRK4: five stages, every diagonal entry 1/4, order 4, L-stable, stiffly accurate
/// (b is the last row of a), with an embedded solution of order 3 for error control; every coefficient a
/// small rational (HW II, 2nd ed., Sec. IV.6, Table 6.5, the method (6.16); their code sdirk4.f).
///
///     c = (1/4, 3/4, 11/20, 1/2, 1)
///     a = 1/4
///         1/2        1/4
///         17/50     -1/25       1/4
///         371/1360  -137/2720   15/544    1/4
///         25/24     -49/48      125/16   -85/12   1/4
///     b = (25/24, -49/48, 125/16, -85/12, 1/4),  bhat = (59/48, -17/96, 225/32, -85/12, 0)
///
/// tests/tables/order_conditions_test.cpp checks both orders (all rooted trees, and that each fails the next
/// order); tests/rk/implicit_rk_test.cpp checks its stability function against the closed form and its A- and
/// L-stability. Stepped with error control by odestep::sdirk_adaptive (odestep::sdirk4_substeps).
struct sdirk4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "SDIRK4 (Hairer & Wanner, L-stable)";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = true;  ///< A-stable and R(infinity) = 0 (tested from the table)
    /// The table with its coefficients in T (one embedded weight vector, of order 3).
    template <class T>
    static constexpr butcher_tableau<T, 5, 1> table{
        {{{T(1) / T(4), T(0), T(0), T(0), T(0)},
          {T(1) / T(2), T(1) / T(4), T(0), T(0), T(0)},
          {T(17) / T(50), T(-1) / T(25), T(1) / T(4), T(0), T(0)},
          {T(371) / T(1360), T(-137) / T(2720), T(15) / T(544), T(1) / T(4), T(0)},
          {T(25) / T(24), T(-49) / T(48), T(125) / T(16), T(-85) / T(12), T(1) / T(4)}}},
        {T(25) / T(24), T(-49) / T(48), T(125) / T(16), T(-85) / T(12), T(1) / T(4)},
        {T(1) / T(4), T(3) / T(4), T(11) / T(20), T(1) / T(2), T(1)},
        {{{T(59) / T(48), T(-17) / T(96), T(225) / T(32), T(-85) / T(12), T(0)}}},
        4,
        {3}};
};

/// Radau IIA with three stages: order 5 (2s - 1), L-stable, stiffly accurate, stage order 3; the method of
/// Hairer & Wanner's RADAU5. (Ehle 1969, Research Report CSRR 2010, Univ. Waterloo; Butcher 1964; HW II
/// Sec. IV.5, Table 5.6, p. 74 of the 2nd edition.)
struct radau_iia5 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Radau IIA 5";
    static constexpr bool a_stable = true;  ///< |R(z)| <= 1 for Re z <= 0 (tested from the table)
    static constexpr bool l_stable = true;  ///< A-stable and R(infinity) = 0 (tested from the table)
    /// The table with its coefficients in T.
    template <class T>
    static constexpr butcher_tableau<T, 3> table{
        {{{(T(88) - T(7) * detail::sqrt6<T>) / T(360), (T(296) - T(169) * detail::sqrt6<T>) / T(1800),
           (T(-2) + T(3) * detail::sqrt6<T>) / T(225)},
          {(T(296) + T(169) * detail::sqrt6<T>) / T(1800), (T(88) + T(7) * detail::sqrt6<T>) / T(360),
           (T(-2) - T(3) * detail::sqrt6<T>) / T(225)},
          {(T(16) - detail::sqrt6<T>) / T(36), (T(16) + detail::sqrt6<T>) / T(36), T(1) / T(9)}}},
        {(T(16) - detail::sqrt6<T>) / T(36), (T(16) + detail::sqrt6<T>) / T(36), T(1) / T(9)},
        {(T(4) - detail::sqrt6<T>) / T(10), (T(4) + detail::sqrt6<T>) / T(10), T(1)},
        {},
        5,
        {}};
};

/// \brief The constants of Hairer & Wanner's RADAU5 for tables::radau_iia5, typed in T: the eigen-decomposition
/// of A^-1 that splits the 3N-dimensional Newton system into one real and one complex N x N system, the
/// embedded error estimate and the collocation polynomial's nodes.
///
/// With A the Radau IIA 5 matrix, T^-1 A^-1 T = [[gamma, 0, 0], [0, alpha, -beta], [0, beta, alpha]]: gamma is
/// the real eigenvalue of A^-1 and alpha +- i beta the complex pair. Closed forms (radau5.f, HW II Sec. IV.8):
/// gamma = 30 / (6 + 81^(1/3) - 9^(1/3)), alpha + i beta = 1 / (a + i b) with a = (12 - 81^(1/3) + 9^(1/3)) / 60
/// and b = (81^(1/3) + 9^(1/3)) sqrt(3) / 60, here to 40 digits (mpmath, 50 digits). T and T^-1 are radau5.f's
/// (Hairer's normalization, 20 digits: the third row of T is (t31, 1, 0)). The error estimate (HW II
/// (8.19)-(8.20)) is err = (I - h gamma0 J)^-1 gamma0 (h f(t_n, y_n) + e_1 Z_1 + e_2 Z_2 + e_3 Z_3), gamma0 =
/// 1 / gamma, with e = (-(13 + 7 sqrt 6) / 3, (-13 + 7 sqrt 6) / 3, -1/3) (radau5.f's DD1..DD3): the unique e
/// with 1 + e.c = 0, e.c^2 = 0, e.c^3 = 0, so that the bracket is O(h^4). tests/stiff/radau5_test.cpp checks
/// every one of these against the table by an independent computation.
template <class T>
struct radau5_coefficients {
    /// gamma, the real eigenvalue of A^-1.
    static constexpr T gamma = T(3.637834252744495732208418513577775797946L);
    /// alpha, the real part of the complex eigenvalues of A^-1.
    static constexpr T alpha = T(2.681082873627752133895790743211112101027L);
    /// beta, the imaginary part of the complex eigenvalues of A^-1.
    static constexpr T beta = T(3.050430199247410569426377624787567904441L);
    /// The transformation T (radau5.f: T11 .. T31, T32 = 1, T33 = 0).
    static constexpr std::array<std::array<T, 3>, 3> t{{
        {T(9.1232394870892942792e-02L), T(-0.14125529502095420843L), T(-3.0029194105147424492e-02L)},
        {T(0.24171793270710701896L), T(0.20412935229379993199L), T(0.38294211275726193779L)},
        {T(0.96604818261509293619L), T(1), T(0)},
    }};
    /// Its inverse (radau5.f: TI11 .. TI33).
    static constexpr std::array<std::array<T, 3>, 3> t_inv{{
        {T(4.3255798900631553510L), T(0.33919925181580986954L), T(0.54177053993587487119L)},
        {T(-4.1787185915519047273L), T(-0.32768282076106238708L), T(0.47662355450055045196L)},
        {T(-0.50287263494578687595L), T(2.5719269498556054292L), T(-0.59603920482822492497L)},
    }};
    /// The error estimate's weights on the stage increments (radau5.f: DD1, DD2, DD3), 40 digits.
    static constexpr std::array<T, 3> e{T(-10.04880939982741556246032950764707991459L),
                                        T(1.382142733160748895793662840980413247921L), T(-1) / T(3)};
};

/// The implicit trapezoid under the name numerical analysts of PDEs use.
using crank_nicolson = trapezoid;

// Every table's nodes are the row sums of a and its weights sum to 1, in each floating type. The order
// conditions, the stability functions and the symplectic and symmetric structure are checked by the tests
// (tests/tables/order_conditions_test.cpp, tests/rk/implicit_rk_test.cpp).
static_assert(detail::consistent_in_every_type<backward_euler>(), "tables::backward_euler is not consistent");
static_assert(detail::consistent_in_every_type<trapezoid>(), "tables::trapezoid is not consistent");
static_assert(detail::consistent_in_every_type<implicit_midpoint>(), "tables::implicit_midpoint is not consistent");
static_assert(detail::consistent_in_every_type<gauss4>(), "tables::gauss4 is not consistent");
static_assert(detail::consistent_in_every_type<sdirk3>(), "tables::sdirk3 is not consistent");
static_assert(detail::consistent_in_every_type<radau_iia5>(), "tables::radau_iia5 is not consistent");
static_assert(detail::consistent_in_every_type<sdirk4>(), "tables::sdirk4 is not consistent");

// clang-format on
}  // namespace odestep::tables

#endif
