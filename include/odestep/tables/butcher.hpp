// SPDX-License-Identifier: BSL-1.0
// odestep: the Butcher table type and the checks every table must pass at compile time.
#ifndef ODESTEP_TABLES_BUTCHER_HPP
#define ODESTEP_TABLES_BUTCHER_HPP

#include <array>
#include <cstddef>
#include <limits>

#include "../detail/ops.hpp"

namespace odestep {

/// A Runge-Kutta method with S stages and E embedded weight vectors:
///
///     k_i     = f(t + c_i h, y + h * sum_j a_ij k_j)
///     y_{n+1} = y_n + h * sum_i b_i k_i                   (order `order`)
///     yhat_e  = y_n + h * sum_i bhat_e,i k_i              (order `embedded_order[e]`)
///
/// An explicit table (is_explicit: a strictly lower triangular) drives odestep::explicit_rk, which reads
/// only that triangle; any other table is implicit and drives odestep::implicit_rk (rk/implicit_rk.hpp).
/// The stepper's error estimate for vector e is y_{n+1} - yhat_e = h * sum_i (b_i - bhat_e,i) k_i.
template <class T, std::size_t S, std::size_t E = 0>
struct butcher_tableau {
    /// The scalar type T.
    using value_type = T;
    /// The number of stages s.
    static constexpr std::size_t stages = S;
    /// The number of embedded weight vectors.
    static constexpr std::size_t embedded = E;

    std::array<std::array<T, S>, S> a{};     ///< the stage coefficients a_ij
    std::array<T, S> b{};                    ///< the weights b_i of the solution
    std::array<T, S> c{};                    ///< the nodes c_i (stage times t + c_i h)
    std::array<std::array<T, S>, E> bhat{};  ///< the weights of each embedded solution
    int order = 0;                           ///< the order of the solution
    std::array<int, E> embedded_order{};     ///< the order of each embedded solution
};

namespace detail {

// |sum - target| within a few rounding errors of the terms that made the sum: the coefficients are
// rounded to T, so exact equality is too strict and a fixed 1e-12 is wrong for float.
template <class T, std::size_t S>
constexpr bool sums_to(const std::array<T, S>& v, std::size_t count, T target) noexcept {
    T sum = T(0);
    T magnitude = abs_value(target);
    for (std::size_t j = 0; j < count; ++j) {
        sum += v[j];
        magnitude += abs_value(v[j]);
    }
    // The floor covers tables published only as decimals (DOP853 gives about 28 digits), which a 128-bit
    // long double resolves; it is far below the epsilon of float, double and x87 long double.
    const T unit = std::numeric_limits<T>::epsilon() > T(1e-26L) ? std::numeric_limits<T>::epsilon() : T(1e-26L);
    const T tolerance = T(4) * T(S + 1) * unit * magnitude;
    return abs_value(sum - target) <= tolerance;
}

// x == y to within a few rounding errors of terms of the given magnitude (the same allowance as sums_to).
template <class T>
constexpr bool nearly_equal(T x, T y, T magnitude) noexcept {
    const T unit = std::numeric_limits<T>::epsilon() > T(1e-26L) ? std::numeric_limits<T>::epsilon() : T(1e-26L);
    return abs_value(x - y) <= T(16) * unit * magnitude;
}

}  // namespace detail

/// Row sums c_i = sum_j a_ij (over the whole row, so for implicit tables too), and
/// sum b = sum bhat_e = 1. The full order conditions (rooted trees) are checked by the test suite.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_consistent(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i)
        if (!detail::sums_to(tab.a[i], S, tab.c[i])) return false;
    if (!detail::sums_to(tab.b, S, T(1))) return false;
    for (std::size_t e = 0; e < E; ++e)
        if (!detail::sums_to(tab.bhat[e], S, T(1))) return false;
    return tab.order >= 1;
}

namespace detail {
/// is_consistent for a table tag's table in float, double and long double (the tables' static_asserts).
template <class Tag>
constexpr bool consistent_in_every_type() noexcept {
    return is_consistent(Tag::template table<float>) && is_consistent(Tag::template table<double>) &&
           is_consistent(Tag::template table<long double>);
}
}  // namespace detail

/// An explicit table: a strictly lower triangular (each stage reads only earlier ones), so c_1 = 0.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_explicit(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i)
        for (std::size_t j = i; j < S; ++j)
            if (tab.a[i][j] != T(0)) return false;
    return true;
}

/// A diagonally implicit table (DIRK): a lower triangular, so the stages can be solved one after the
/// other, each an N-dimensional equation. Explicit tables are the special case of a zero diagonal.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_lower_triangular(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i)
        for (std::size_t j = i + 1; j < S; ++j)
            if (tab.a[i][j] != T(0)) return false;
    return true;
}

/// Stiffly accurate: b is the last row of a (exactly), so y_{n+1} is the last stage's value. With an
/// A-stable table whose a is invertible this makes R(infinity) = 0 (Hairer & Wanner, Solving ODE II,
/// Sec. IV.3).
template <class T, std::size_t S, std::size_t E>
constexpr bool is_stiffly_accurate(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t j = 0; j < S; ++j)
        if (tab.b[j] != tab.a[S - 1][j]) return false;
    return true;
}

/// Symplectic (for Hamiltonian systems in the form y' = f(y)): b_i a_ij + b_j a_ji = b_i b_j for all i, j
/// (Cooper's condition; Sanz-Serna 1988; Hairer, Lubich & Wanner, Geometric Numerical Integration,
/// Thm. VI.4.3), to within the rounding of the coefficients in T. No explicit table meets it.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_symplectic(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i)
        for (std::size_t j = 0; j < S; ++j) {
            const T lhs = tab.b[i] * tab.a[i][j] + tab.b[j] * tab.a[j][i];
            const T size = detail::abs_value(tab.b[i] * tab.a[i][j]) + detail::abs_value(tab.b[j] * tab.a[j][i]) +
                           detail::abs_value(tab.b[i] * tab.b[j]);
            if (!detail::nearly_equal(lhs, tab.b[i] * tab.b[j], size)) return false;
        }
    return true;
}

/// Symmetric (the step with -h undoes the step with h): a_{s+1-i, s+1-j} + a_ij = b_j, b_{s+1-j} = b_j
/// and c_{s+1-i} = 1 - c_i (Hairer, Lubich & Wanner, Geometric Numerical Integration, Thm. V.2.3; stages
/// numbered from 1), to within the rounding of the coefficients in T.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_symmetric(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 0; i < S; ++i) {
        const std::size_t ri = S - 1 - i;
        if (!detail::nearly_equal(tab.b[ri], tab.b[i], detail::abs_value(tab.b[i]))) return false;
        if (!detail::nearly_equal(tab.c[ri], T(1) - tab.c[i], T(1))) return false;
        for (std::size_t j = 0; j < S; ++j) {
            const std::size_t rj = S - 1 - j;
            const T size =
                detail::abs_value(tab.a[ri][rj]) + detail::abs_value(tab.a[i][j]) + detail::abs_value(tab.b[j]);
            if (!detail::nearly_equal(tab.a[ri][rj] + tab.a[i][j], tab.b[j], size)) return false;
        }
    }
    return true;
}

namespace detail {

/// Row i of a is b (the entries a_ij for j >= i read as zero, so b_j = 0 there): stage i's input is
/// y_{n+1} itself, the same sum in the same order.
template <class T, std::size_t S, std::size_t E>
constexpr bool is_b_row(const butcher_tableau<T, S, E>& tab, std::size_t i) noexcept {
    for (std::size_t j = 0; j < S; ++j)
        if (!((j < i ? tab.a[i][j] : T(0)) == tab.b[j])) return false;
    return true;
}

/// The first stage i >= 1 whose row of a is b (is_b_row), S if none: the one first-same-as-last detector.
/// A step that evaluates that stage keeps its input as the new state (Dormand-Prince 5(4)'s seventh).
template <class T, std::size_t S, std::size_t E>
constexpr std::size_t b_row(const butcher_tableau<T, S, E>& tab) noexcept {
    for (std::size_t i = 1; i < S; ++i)
        if (is_b_row(tab, i)) return i;
    return S;
}

/// First same as last: the last stage is f(t + h, y_{n+1}) (its row of a is b, c = 1, b_s = 0), so it is
/// the next step's first stage (Dormand-Prince 5(4), Bogacki-Shampine 3(2)).
template <class T, std::size_t S, std::size_t E>
constexpr bool first_same_as_last(const butcher_tableau<T, S, E>& tab) noexcept {
    return S >= 2 && tab.c[S - 1] == T(1) && is_b_row(tab, S - 1);
}

/// A Butcher table's rows as types, so that each coefficient is a constant expression inside the steppers'
/// sums expanded at compile time (explicit_rk and the adaptive engine's embedded pair):
/// a_row<I>::value(j) = a_Ij (0 for j >= I), b_weights::value(j) = b_j, error_weights<E>::value(j) =
/// b_j - bhat_Ej. `Method` is a table tag (tables/runge_kutta.hpp), T the scalar.
template <class Method, class T>
struct table_rows {
    static constexpr auto tab = Method::template table<T>;
    /// Row I of a.
    template <std::size_t I>
    struct a_row {
        static constexpr T value(std::size_t j) noexcept { return j < I ? tab.a[I][j] : T(0); }
    };
    /// The weights b.
    struct b_weights {
        static constexpr T value(std::size_t j) noexcept { return tab.b[j]; }
    };
    /// b minus the embedded weights of estimate Which.
    template <std::size_t Which>
    struct error_weights {
        static constexpr T value(std::size_t j) noexcept { return tab.b[j] - tab.bhat[Which][j]; }
    };
};

}  // namespace detail

}  // namespace odestep

#endif
