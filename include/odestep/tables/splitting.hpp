// SPDX-License-Identifier: BSL-1.0
// odestep: the splitting (composition) tables for Newton's equations: the table type, its compile-time
// checks, and the methods.
#ifndef ODESTEP_TABLES_SPLITTING_HPP
#define ODESTEP_TABLES_SPLITTING_HPP

#include <array>
#include <cstddef>

#include "butcher.hpp"  // detail::sums_to

namespace odestep {

/// A splitting method for x' = v, v' = a(t, x): the exact flows of the two halves, the drift
/// x <- x + h v (v fixed) and the kick v <- v + h a(t, x) (x fixed), composed with M coefficients each:
///
///     kick first:   for i = 1..M:  v <- v + b_i dt a(t + c_i dt, x);   x <- x + a_i dt v
///     drift first:  for i = 1..M:  x <- x + a_i dt v;   v <- v + b_i dt a(t + c_i dt, x)
///
/// with a = `drift`, b = `kick`, and c_i, the time of kick i, the sum of the drift coefficients applied
/// before it (time advances with the drifts). A zero coefficient is an update that is not made. Each flow
/// is symplectic when a depends on t and x only, so every such composition is symplectic; it is
/// symmetric (time-reversible) when the sequence of updates reads the same backwards.
template <class T, std::size_t M>
struct splitting_table {
    /// The scalar type T.
    using value_type = T;
    /// The number of coefficients of each kind.
    static constexpr std::size_t size = M;

    bool kick_first = true;        ///< the sequence starts with a kick (else with a drift)
    std::array<T, M> drift{};      ///< the drift coefficients a_i
    std::array<T, M> kick{};       ///< the kick coefficients b_i
    int order = 0;                 ///< the order of the composition
    bool time_reversible = false;  ///< claimed symmetric; is_consistent checks it against the sequence
};

namespace detail {

// Update k of the sequence (k = 0 .. 2M-1): kick first, the even ones are kicks; drift first, the odd ones.
template <class T, std::size_t M>
constexpr bool is_kick_update(const splitting_table<T, M>& tab, std::size_t k) noexcept {
    return (k % 2 == 0) == tab.kick_first;
}
template <class T, std::size_t M>
constexpr T update_coefficient(const splitting_table<T, M>& tab, std::size_t k) noexcept {
    return is_kick_update(tab, k) ? tab.kick[k / 2] : tab.drift[k / 2];
}
template <class T, std::size_t M>
constexpr std::size_t first_update(const splitting_table<T, M>& tab) noexcept {
    for (std::size_t k = 0; k < 2 * M; ++k)
        if (update_coefficient(tab, k) != T(0)) return k;
    return 2 * M;
}
template <class T, std::size_t M>
constexpr std::size_t last_update(const splitting_table<T, M>& tab) noexcept {
    for (std::size_t k = 2 * M; k-- > 0;)
        if (update_coefficient(tab, k) != T(0)) return k;
    return 2 * M;
}

/// The updates made, in order, are the same read backwards (same kind, same coefficient, exactly): then
/// the step with -dt undoes the step with dt, update by update.
template <class T, std::size_t M>
constexpr bool is_palindrome(const splitting_table<T, M>& tab) noexcept {
    const std::size_t first = first_update(tab);
    const std::size_t last = last_update(tab);
    if (first > last || last >= 2 * M) return false;
    for (std::size_t i = 0; first + i <= last; ++i) {
        const std::size_t k = first + i;
        const std::size_t mirror = last - i;
        if (is_kick_update(tab, k) != is_kick_update(tab, mirror)) return false;
        if (update_coefficient(tab, k) != update_coefficient(tab, mirror)) return false;
    }
    return true;
}

}  // namespace detail

/// The drift coefficients and the kick coefficients each sum to 1 (to a few rounding errors of T), the
/// order is given, and the table is time-reversible exactly when it claims so.
template <class T, std::size_t M>
constexpr bool is_consistent(const splitting_table<T, M>& tab) noexcept {
    return detail::sums_to(tab.drift, M, T(1)) && detail::sums_to(tab.kick, M, T(1)) && tab.order >= 1 &&
           tab.time_reversible == detail::is_palindrome(tab);
}

namespace detail::splitting_coefficients {
// Computed once in long double and rounded once to the table's T. (Not templated: the long double
// literals here never meet a float.)

// 2^(1/3), to 40 digits.
inline constexpr long double cbrt2 = 1.259921049894873164767210607278228350570L;
// Forest & Ruth's gamma = 1 / (2 - 2^(1/3)), also Yoshida's (1990) fourth-order triple-jump weight.
inline constexpr long double fr_gamma = 1.0L / (2.0L - cbrt2);
inline constexpr long double fr_drift_outer = fr_gamma / 2.0L;           // gamma / 2
inline constexpr long double fr_drift_inner = (1.0L - fr_gamma) / 2.0L;  // (1 - gamma) / 2 = -(2^(1/3) - 1) gamma / 2
inline constexpr long double fr_kick_inner = 1.0L - 2.0L * fr_gamma;     // 1 - 2 gamma = -2^(1/3) gamma

// Yoshida's solution A (see yoshida6 below).
inline constexpr long double y6_w1 = -1.17767998417887100694641568096431573L;
inline constexpr long double y6_w2 = 0.235573213359358133684793182978534602L;
inline constexpr long double y6_w3 = 0.784513610477557263819497633866349876L;
inline constexpr long double y6_w0 = 1.0L - 2.0L * (y6_w1 + y6_w2 + y6_w3);
// The drifts of the merged position-Verlet steps: half of each pair of neighbouring weights.
inline constexpr long double y6_d1 = y6_w3 / 2.0L;
inline constexpr long double y6_d2 = (y6_w3 + y6_w2) / 2.0L;
inline constexpr long double y6_d3 = (y6_w2 + y6_w1) / 2.0L;
inline constexpr long double y6_d4 = (y6_w1 + y6_w0) / 2.0L;

// Blanes & Moan's SRKN_6^b (see blanes_moan4 below), as published; a3 and b4 from the sum conditions.
inline constexpr long double bm_a1 = 0.245298957184271L;
inline constexpr long double bm_a2 = 0.604872665711080L;
inline constexpr long double bm_a3 = 0.5L - (bm_a1 + bm_a2);
inline constexpr long double bm_b1 = 0.0829844064174052L;
inline constexpr long double bm_b2 = 0.396309801498368L;
inline constexpr long double bm_b3 = -0.0390563049223486L;
inline constexpr long double bm_b4 = 1.0L - 2.0L * (bm_b1 + bm_b2 + bm_b3);
}  // namespace detail::splitting_coefficients

/// The splitting tables. Each method is a tag type whose `table<T>` is a constexpr splitting table in T.
namespace tables {
// clang-format off  (the tables keep their published layout)

/// Euler-Cromer, symplectic Euler with the kick first (Cromer 1981, "Stable solutions using the Euler
/// approximation", Am. J. Phys. 49, 455-459; Hairer, Lubich & Wanner, Geometric Numerical Integration
/// (HLW), Sect. VI.3):  v_{n+1} = v_n + dt a(t_n, x_n),  x_{n+1} = x_n + dt v_{n+1}.  Order 1; not
/// symmetric (its adjoint is the drift-first form below).
struct euler_cromer {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Euler-Cromer (symplectic Euler, kick then drift)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 1> table{true, {T(1)}, {T(1)}, 1, false};
};

/// Symplectic Euler with the drift first, the adjoint of Euler-Cromer (HLW, Sect. VI.3, the other
/// variant):  x_{n+1} = x_n + dt v_n,  v_{n+1} = v_n + dt a(t_n + dt, x_{n+1}).  Order 1; not symmetric.
struct euler_cromer_drift_first {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "symplectic Euler, drift then kick (adjoint Euler-Cromer)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 1> table{false, {T(1)}, {T(1)}, 1, false};
};

/// Velocity Verlet = leapfrog in kick-drift-kick form (Verlet 1967, Phys. Rev. 159, 98; Swope, Andersen,
/// Berens & Wilson 1982, J. Chem. Phys. 76, 637; HLW Sect. VI.3):
///     v_{n+1/2} = v_n + dt/2 a(t_n, x_n),  x_{n+1} = x_n + dt v_{n+1/2},  v_{n+1} = v_{n+1/2} + dt/2 a(t_{n+1}, x_{n+1}),
/// that is x_{n+1} = x_n + dt v_n + dt^2/2 a_n and v_{n+1} = v_n + dt/2 (a_n + a_{n+1}). Order 2, symmetric;
/// first same as last: one evaluation of a per step.
struct velocity_verlet {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "velocity Verlet (leapfrog, kick-drift-kick)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 2> table{true, {T(1), T(0)}, {T(1) / T(2), T(1) / T(2)}, 2, true};
};

/// Position Verlet, leapfrog in drift-kick-drift form (HLW Sect. VI.3, the adjoint splitting):
///     x_{n+1/2} = x_n + dt/2 v_n,  v_{n+1} = v_n + dt a(t_n + dt/2, x_{n+1/2}),  x_{n+1} = x_{n+1/2} + dt/2 v_{n+1}.
/// Order 2, symmetric; one evaluation of a per step, no state.
struct position_verlet {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "position Verlet (leapfrog, drift-kick-drift)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 2> table{false, {T(1) / T(2), T(1) / T(2)}, {T(1), T(0)}, 2, true};
};

/// Forest-Ruth, the fourth-order triple jump of position Verlet with gamma = 1 / (2 - 2^(1/3)) (Forest &
/// Ruth 1990, "Fourth-order symplectic integration", Physica D 43, 105-117; found independently by Candy &
/// Rozmus 1991, J. Comput. Phys. 92, 230, and by Yoshida 1990, Phys. Lett. A 150, 262, as the composition
/// S(gamma dt) S((1 - 2 gamma) dt) S(gamma dt) of a second-order S):
///     drift gamma/2, kick gamma, drift (1-gamma)/2, kick 1-2gamma, drift (1-gamma)/2, kick gamma, drift gamma/2.
/// Order 4, symmetric; three evaluations of a per step, no state.
struct forest_ruth {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Forest-Ruth 4th order";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 4> table{
        false,
        {T(detail::splitting_coefficients::fr_drift_outer), T(detail::splitting_coefficients::fr_drift_inner),
         T(detail::splitting_coefficients::fr_drift_inner), T(detail::splitting_coefficients::fr_drift_outer)},
        {T(detail::splitting_coefficients::fr_gamma), T(detail::splitting_coefficients::fr_kick_inner),
         T(detail::splitting_coefficients::fr_gamma), T(0)},
        4,
        true};
};

/// Yoshida's sixth order, solution A (Yoshida 1990, "Construction of higher order symplectic integrators",
/// Phys. Lett. A 150, 262-268, Table 1): the symmetric composition of seven position-Verlet steps of
/// w3, w2, w1, w0, w1, w2, w3 times dt, w0 = 1 - 2 (w1 + w2 + w3); adjacent half drifts merged:
///     drift w3/2, kick w3, drift (w3+w2)/2, kick w2, drift (w2+w1)/2, kick w1, drift (w1+w0)/2, kick w0, ... mirrored.
/// Yoshida prints w1 = -0.117767998417887E1, w2 = 0.235573213359357E0, w3 = 0.784513610477560E0: 15
/// digits, of which the last of w2 and w3 is off by up to 3e-15. The w here are the root of his order
/// equations to 36 digits (w1 = -1.1776799841788710069..., w2 = 0.23557321335935813368..., w3 =
/// 0.78451361047755726382...), as in Principia's integrators/methods.hpp ("derived from equations 5.4
/// through 5.17" of the paper) and in independent lattice codes; they agree with the printed ones to
/// those 15 digits. Checked in __float128 on the Kepler orbit: with these w the error falls as h^6.00 down
/// to 1.6e-22; with the printed ones it leaves h^6 below 1e-18 (invisible in double and x87 long double).
/// Order 6, symmetric; seven evaluations of a per step, no state.
struct yoshida6 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Yoshida 6th order (solution A)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 8> table{
        false,
        {T(detail::splitting_coefficients::y6_d1), T(detail::splitting_coefficients::y6_d2),
         T(detail::splitting_coefficients::y6_d3), T(detail::splitting_coefficients::y6_d4),
         T(detail::splitting_coefficients::y6_d4), T(detail::splitting_coefficients::y6_d3),
         T(detail::splitting_coefficients::y6_d2), T(detail::splitting_coefficients::y6_d1)},
        {T(detail::splitting_coefficients::y6_w3), T(detail::splitting_coefficients::y6_w2),
         T(detail::splitting_coefficients::y6_w1), T(detail::splitting_coefficients::y6_w0),
         T(detail::splitting_coefficients::y6_w1), T(detail::splitting_coefficients::y6_w2),
         T(detail::splitting_coefficients::y6_w3), T(0)},
        6,
        true};
};

/// Blanes & Moan's optimized fourth-order Runge-Kutta-Nystrom splitting SRKN_6^b (Blanes & Moan 2002,
/// "Practical symplectic partitioned Runge-Kutta and Runge-Kutta-Nystrom methods", J. Comput. Appl.
/// Math. 142, 313-330, Table 3): kick first, seven kicks and six drifts,
///     kick b1, drift a1, kick b2, drift a2, kick b3, drift a3, kick b4, drift a3, kick b3, drift a2, kick b2, drift a1, kick b1,
/// a1 = 0.245298957184271, a2 = 0.604872665711080, a3 = 1/2 - (a1 + a2), b1 = 0.0829844064174052,
/// b2 = 0.396309801498368, b3 = -0.0390563049223486, b4 = 1 - 2 (b1 + b2 + b3) (all the published
/// digits; the same in Principia's integrators/methods.hpp, BlanesMoan2002SRKN6B, composition BAB).
/// Checked in __float128 on the Kepler orbit: slope 4.00 down to an error of 1.3e-16. Order 4, symmetric,
/// with an error constant far below Forest-Ruth's; first same as last: six evaluations of a per step.
struct blanes_moan4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Blanes-Moan SRKN6b 4th order";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr splitting_table<T, 7> table{
        true,
        {T(detail::splitting_coefficients::bm_a1), T(detail::splitting_coefficients::bm_a2),
         T(detail::splitting_coefficients::bm_a3), T(detail::splitting_coefficients::bm_a3),
         T(detail::splitting_coefficients::bm_a2), T(detail::splitting_coefficients::bm_a1), T(0)},
        {T(detail::splitting_coefficients::bm_b1), T(detail::splitting_coefficients::bm_b2),
         T(detail::splitting_coefficients::bm_b3), T(detail::splitting_coefficients::bm_b4),
         T(detail::splitting_coefficients::bm_b3), T(detail::splitting_coefficients::bm_b2),
         T(detail::splitting_coefficients::bm_b1)},
        4,
        true};
};

// clang-format on
}  // namespace tables

}  // namespace odestep

namespace odestep {
/// The namespace of these tables before every table moved to odestep::tables; kept so that code written
/// against it still compiles.
namespace splittings = tables;
}  // namespace odestep

#endif
