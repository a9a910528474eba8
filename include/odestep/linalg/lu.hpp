// SPDX-License-Identifier: BSL-1.0
// odestep: small dense linear algebra for the implicit methods: the LU factorization with partial pivoting
// of an N x N std::array matrix and the solve with it. No heap, no exceptions, constexpr.
#ifndef ODESTEP_LINALG_LU_HPP
#define ODESTEP_LINALG_LU_HPP

#include <array>
#include <cstddef>

#include "../detail/ops.hpp"
#include "../status.hpp"

namespace odestep::linalg {

/// A dense N x N matrix, row-major: m[i][j] is row i, column j. For a state std::array<T, N> this is
/// std::array<State, N>, the type of a Jacobian (see odestep::jacobian_t).
template <class T, std::size_t N>
using matrix = std::array<std::array<T, N>, N>;

/// The row interchanges of a factorization, as LAPACK's getrf records them: at elimination step k, row k
/// was swapped with row pivot[k] (pivot[k] >= k).
template <std::size_t N>
using pivots = std::array<std::size_t, N>;

namespace detail {
// True when every entry of a is finite: one plain sum of all N^2 entries, and the exact test only when
// that sum is not finite (a non-finite entry, or an overflowing sum of finite ones).
template <class T, std::size_t N>
constexpr bool all_entries_finite(const matrix<T, N>& a) noexcept {
    T sum = T(0);
    for (std::size_t i = 0; i < N; ++i) odestep::detail::add_components(sum, a[i]);
    if (odestep::detail::finite_sum(sum)) return true;
    for (std::size_t i = 0; i < N; ++i)
        if (!odestep::detail::each_finite(a[i])) return false;
    return true;
}
}  // namespace detail

/// \brief Factors a = P L U in place (Gaussian elimination with partial pivoting, LAPACK's getrf).
///
/// On return a holds U on and above the diagonal and the multipliers of L (unit diagonal, not stored)
/// below it; pivot holds the row interchanges. Each column's pivot is the entry of largest magnitude on or
/// below the diagonal, so every multiplier has magnitude at most 1.
///
/// Returns `status::singular_matrix` when a has a NaN or infinite entry (a is then untouched), when a
/// pivot is exactly zero (the matrix is singular in T), or when the elimination overflows (a factor is not
/// finite). a is then a partial elimination, not a factorization: solve nothing with it. A matrix that is
/// nearly singular, with a tiny non-zero pivot, is factored; its solutions are as inaccurate as its
/// condition number says (an implicit method then sees a Newton iteration that does not converge).
/// Work: N^3 / 3 multiply-adds; no loop depends on the values.
template <class T, std::size_t N>
constexpr status lu_factor(matrix<T, N>& a, pivots<N>& pivot) noexcept {
    if (!detail::all_entries_finite(a)) return status::singular_matrix;
    for (std::size_t k = 0; k < N; ++k) {
        std::size_t p = k;
        T largest = odestep::detail::abs_value(a[k][k]);
        for (std::size_t i = k + 1; i < N; ++i) {
            const T m = odestep::detail::abs_value(a[i][k]);
            if (m > largest) {
                largest = m;
                p = i;
            }
        }
        pivot[k] = p;
        if (largest == T(0)) return status::singular_matrix;
        if (p != k) {
            for (std::size_t j = 0; j < N; ++j) {
                const T swap = a[k][j];
                a[k][j] = a[p][j];
                a[p][j] = swap;
            }
        }
        const T inverse = T(1) / a[k][k];
        for (std::size_t i = k + 1; i < N; ++i) {
            const T l = a[i][k] * inverse;
            a[i][k] = l;
            for (std::size_t j = k + 1; j < N; ++j) a[i][j] -= l * a[k][j];
        }
    }
    return detail::all_entries_finite(a) ? status::ok : status::singular_matrix;
}

/// Solves A x = b with the factors of lu_factor (which must have returned `status::ok`): b is replaced
/// by x. Forward substitution with L, then back substitution with U; N^2 multiply-adds and N divisions.
template <class T, std::size_t N>
constexpr void lu_solve(const matrix<T, N>& lu, const pivots<N>& pivot, std::array<T, N>& b) noexcept {
    // N = 1 has no interchange and no L: skipped at compile time (GCC 12 at -O2 otherwise reports the swap's
    // b[pivot[0]] as out of bounds once a caller is inlined, not knowing that pivot[0] is 0).
    if constexpr (N > 1) {
        for (std::size_t k = 0; k < N; ++k) {
            const std::size_t p = pivot[k];
            if (p != k) {
                const T swap = b[k];
                b[k] = b[p];
                b[p] = swap;
            }
        }
        for (std::size_t i = 1; i < N; ++i) {
            T sum = b[i];
            for (std::size_t j = 0; j < i; ++j) sum -= lu[i][j] * b[j];
            b[i] = sum;
        }
    } else {
        (void)pivot;
    }
    for (std::size_t i = N; i-- > 0;) {
        T sum = b[i];
        for (std::size_t j = i + 1; j < N; ++j) sum -= lu[i][j] * b[j];
        b[i] = sum / lu[i][i];
    }
}

}  // namespace odestep::linalg

#endif
