// SPDX-License-Identifier: BSL-1.0
// The complex LU factorization (linalg/complex_lu.hpp) against the real 2N x 2N form of the same system solved
// by the real LU (an independent path), and its singular and non-finite cases.
#include <doctest/doctest.h>
#include <odestep/linalg/complex_lu.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

TEST_CASE("complex_lu: solves (A + i B) x = b as the real system [[A, -B], [B, A]] does") {
    constexpr std::size_t N = 4;
    odestep::linalg::complex_matrix<double, N> m{};
    // a fixed, well-conditioned matrix with a zero leading entry (pivoting needed)
    const double re[N][N] = {{0, 2, -1, 0.5}, {3, -1, 0.25, 2}, {1, 1, 4, -2}, {-2, 0.5, 1, 3}};
    const double im[N][N] = {{1, -0.5, 0, 2}, {0.5, 1, -3, 0}, {-1, 2, 0.5, 1}, {0, -1, 1, -0.75}};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) {
            m.re[i][j] = re[i][j];
            m.im[i][j] = im[i][j];
        }
    std::array<double, N> br{1, -2, 0.5, 3};
    std::array<double, N> bi{0, 1, -1, 2};
    odestep::linalg::matrix<double, 2 * N> big{};
    std::array<double, 2 * N> rhs{};
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = 0; j < N; ++j) {
            big[i][j] = re[i][j];
            big[i][N + j] = -im[i][j];
            big[N + i][j] = im[i][j];
            big[N + i][N + j] = re[i][j];
        }
        rhs[i] = br[i];
        rhs[N + i] = bi[i];
    }
    odestep::linalg::pivots<N> piv{};
    REQUIRE(odestep::linalg::complex_lu_factor(m, piv) == odestep::status::ok);
    odestep::linalg::complex_lu_solve(m, piv, br, bi);
    odestep::linalg::pivots<2 * N> piv2{};
    REQUIRE(odestep::linalg::lu_factor(big, piv2) == odestep::status::ok);
    odestep::linalg::lu_solve(big, piv2, rhs);
    for (std::size_t i = 0; i < N; ++i) {
        CHECK(br[i] == doctest::Approx(rhs[i]).epsilon(1e-13));
        CHECK(bi[i] == doctest::Approx(rhs[N + i]).epsilon(1e-13));
    }
}

TEST_CASE("complex_lu: a singular matrix and a NaN entry are singular_matrix") {
    odestep::linalg::complex_matrix<float, 2> m{};
    m.re = {{{1, 2}, {2, 4}}};
    m.im = {{{1, 1}, {2, 2}}};  // row 2 = 2 row 1
    odestep::linalg::pivots<2> piv{};
    CHECK(odestep::linalg::complex_lu_factor(m, piv) == odestep::status::singular_matrix);
    odestep::linalg::complex_matrix<float, 2> n{};
    n.re = {{{1, 0}, {0, 1}}};
    n.im[1][0] = std::numeric_limits<float>::quiet_NaN();
    const auto before = n;
    CHECK(odestep::linalg::complex_lu_factor(n, piv) == odestep::status::singular_matrix);
    CHECK(n.re == before.re);
}
