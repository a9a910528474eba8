// SPDX-License-Identifier: BSL-1.0
// odestep: the LU factorization with partial pivoting of a complex N x N matrix held as two real matrices
// (real and imaginary parts), and the solve with it: the complex iteration matrix of Radau IIA 5.
#ifndef ODESTEP_LINALG_COMPLEX_LU_HPP
#define ODESTEP_LINALG_COMPLEX_LU_HPP

#include <array>
#include <cstddef>

#include "../detail/ops.hpp"
#include "../status.hpp"
#include "lu.hpp"

namespace odestep::linalg {

/// \brief A complex N x N matrix as its real and imaginary parts, m = re + i im, each row-major.
///
/// Why not std::complex: a factorization here is a handful of multiply-adds written out, with no library
/// division (std::complex's operator/ calls a run-time routine that rescales for Inf and NaN) and nothing
/// but T in the arithmetic, so float code stays float on a microcontroller. Why not the real 2N x 2N
/// matrix [[re, -im], [im, re]] through lu_factor: it would cost twice the multiply-adds ((2N)^3 / 3 real
/// ones against N^3 / 3 complex ones of four each) and twice the storage (4 N^2 values against 2 N^2), and
/// its pivoting would not keep the complex structure.
template <class T, std::size_t N>
struct complex_matrix {
    matrix<T, N> re{};  ///< real parts
    matrix<T, N> im{};  ///< imaginary parts
};

namespace detail {
// (ar + i ai) / (br + i bi) by Smith's algorithm (Smith 1962, CACM 5(8), 435), which never forms
// br^2 + bi^2 and so neither overflows nor underflows where the quotient is representable.
template <class T>
constexpr void complex_divide(T ar, T ai, T br, T bi, T& qr, T& qi) noexcept {
    if (odestep::detail::abs_value(br) >= odestep::detail::abs_value(bi)) {
        const T r = bi / br;
        const T d = br + bi * r;
        qr = (ar + ai * r) / d;
        qi = (ai - ar * r) / d;
    } else {
        const T r = br / bi;
        const T d = bi + br * r;
        qr = (ar * r + ai) / d;
        qi = (ai * r - ar) / d;
    }
}
}  // namespace detail

/// \brief Factors m = P L U in place (Gaussian elimination with partial pivoting, LAPACK's zgetrf), as
/// lu_factor does for a real matrix.
///
/// The pivot of each column is the entry of largest |re| + |im| on or below the diagonal (LAPACK's izamax
/// measure). Returns `status::singular_matrix` when an entry is NaN or infinite (m untouched), a pivot is
/// exactly zero, or the elimination overflows; m is then not a factorization. Work: N^3 / 3 complex
/// multiply-adds; no loop depends on the values.
template <class T, std::size_t N>
constexpr status complex_lu_factor(complex_matrix<T, N>& m, pivots<N>& pivot) noexcept {
    if (!detail::all_entries_finite(m.re) || !detail::all_entries_finite(m.im)) return status::singular_matrix;
    for (std::size_t k = 0; k < N; ++k) {
        std::size_t p = k;
        T largest = odestep::detail::abs_value(m.re[k][k]) + odestep::detail::abs_value(m.im[k][k]);
        for (std::size_t i = k + 1; i < N; ++i) {
            const T a = odestep::detail::abs_value(m.re[i][k]) + odestep::detail::abs_value(m.im[i][k]);
            if (a > largest) {
                largest = a;
                p = i;
            }
        }
        pivot[k] = p;
        if (largest == T(0)) return status::singular_matrix;
        if (p != k) {
            for (std::size_t j = 0; j < N; ++j) {
                const T sr = m.re[k][j];
                m.re[k][j] = m.re[p][j];
                m.re[p][j] = sr;
                const T si = m.im[k][j];
                m.im[k][j] = m.im[p][j];
                m.im[p][j] = si;
            }
        }
        // 1 / pivot, once per column
        T inv_r = T(0);
        T inv_i = T(0);
        detail::complex_divide(T(1), T(0), m.re[k][k], m.im[k][k], inv_r, inv_i);
        for (std::size_t i = k + 1; i < N; ++i) {
            // l = m[i][k] / m[k][k]
            const T lr = m.re[i][k] * inv_r - m.im[i][k] * inv_i;
            const T li = m.re[i][k] * inv_i + m.im[i][k] * inv_r;
            m.re[i][k] = lr;
            m.im[i][k] = li;
            for (std::size_t j = k + 1; j < N; ++j) {
                // m[i][j] -= l m[k][j]
                m.re[i][j] -= lr * m.re[k][j] - li * m.im[k][j];
                m.im[i][j] -= lr * m.im[k][j] + li * m.re[k][j];
            }
        }
    }
    return detail::all_entries_finite(m.re) && detail::all_entries_finite(m.im) ? status::ok : status::singular_matrix;
}

/// Solves M x = b with the factors of complex_lu_factor (which must have returned `status::ok`), b given
/// as its real part br and imaginary part bi, both replaced by x.
template <class T, std::size_t N>
constexpr void complex_lu_solve(const complex_matrix<T, N>& lu, const pivots<N>& pivot, std::array<T, N>& br,
                                std::array<T, N>& bi) noexcept {
    if constexpr (N > 1) {  // N = 1: no interchange and no L (as in lu_solve)
        for (std::size_t k = 0; k < N; ++k) {
            const std::size_t p = pivot[k];
            if (p != k) {
                const T sr = br[k];
                br[k] = br[p];
                br[p] = sr;
                const T si = bi[k];
                bi[k] = bi[p];
                bi[p] = si;
            }
        }
        for (std::size_t i = 1; i < N; ++i) {
            T sr = br[i];
            T si = bi[i];
            for (std::size_t j = 0; j < i; ++j) {
                sr -= lu.re[i][j] * br[j] - lu.im[i][j] * bi[j];
                si -= lu.re[i][j] * bi[j] + lu.im[i][j] * br[j];
            }
            br[i] = sr;
            bi[i] = si;
        }
    } else {
        (void)pivot;
    }
    for (std::size_t i = N; i-- > 0;) {
        T sr = br[i];
        T si = bi[i];
        for (std::size_t j = i + 1; j < N; ++j) {
            sr -= lu.re[i][j] * br[j] - lu.im[i][j] * bi[j];
            si -= lu.re[i][j] * bi[j] + lu.im[i][j] * br[j];
        }
        detail::complex_divide(sr, si, lu.re[i][i], lu.im[i][i], br[i], bi[i]);
    }
}

}  // namespace odestep::linalg

#endif
