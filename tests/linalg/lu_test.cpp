// SPDX-License-Identifier: BSL-1.0
// The LU factorization with partial pivoting against closed forms, in float and double.
#include <doctest/doctest.h>
#include <odestep/linalg/lu.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

namespace {

using odestep::linalg::lu_factor;
using odestep::linalg::lu_solve;
template <class T, std::size_t N>
using matrix = odestep::linalg::matrix<T, N>;

template <class T>
constexpr T eps = std::numeric_limits<T>::epsilon();

// x = A^-1 b through the library, or a failed status.
template <class T, std::size_t N>
odestep::status solve(matrix<T, N> a, std::array<T, N>& b) {
    odestep::linalg::pivots<N> p{};
    const odestep::status s = lu_factor(a, p);
    if (s == odestep::status::ok) lu_solve(a, p, b);
    return s;
}

template <class T, std::size_t N>
bool same_bits(const matrix<T, N>& a, const matrix<T, N>& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// The second-difference matrix tridiag(-1, 2, -1) of order 3 has the inverse (1/4) [[3, 2, 1], [2, 4, 2],
// [1, 2, 3]] (for tridiag(-1, 2, -1) of order n, (A^-1)_ij = min(i, j) (n + 1 - max(i, j)) / (n + 1)).
template <class T>
void known_inverse() {
    const matrix<T, 3> a{{{T(2), T(-1), T(0)}, {T(-1), T(2), T(-1)}, {T(0), T(-1), T(2)}}};
    const matrix<T, 3> inverse{{{T(0.75), T(0.5), T(0.25)}, {T(0.5), T(1), T(0.5)}, {T(0.25), T(0.5), T(0.75)}}};
    for (std::size_t j = 0; j < 3; ++j) {
        std::array<T, 3> e{};
        e[j] = T(1);
        REQUIRE(solve(a, e) == odestep::status::ok);
        for (std::size_t i = 0; i < 3; ++i) CHECK(std::fabs(e[i] - inverse[i][j]) <= T(4) * eps<T>);
    }
}

// A permutation matrix needs a row interchange at every step (its diagonal is zero), and the solve of
// P x = b is exact: x_j = b_i where P_ij = 1.
template <class T>
void permutation() {
    const matrix<T, 3> p{{{T(0), T(0), T(1)}, {T(1), T(0), T(0)}, {T(0), T(1), T(0)}}};
    std::array<T, 3> b{T(1), T(2), T(3)};
    matrix<T, 3> lu = p;
    odestep::linalg::pivots<3> piv{};
    REQUIRE(lu_factor(lu, piv) == odestep::status::ok);
    CHECK(piv[0] == 1);  // row 1 holds column 0's one
    lu_solve(lu, piv, b);
    CHECK(b[0] == T(2));
    CHECK(b[1] == T(3));
    CHECK(b[2] == T(1));
}

// [[d, 1], [1, 1]] x = (1, 2) with d = 1e-20 has x = (1 / (1 - d), (1 - 2 d) / (1 - d)): both 1 in float and
// double. Without the row interchange the elimination divides by d and returns x0 = 0.
template <class T>
void tiny_leading_entry() {
    const matrix<T, 2> a{{{T(1e-20), T(1)}, {T(1), T(1)}}};
    std::array<T, 2> b{T(1), T(2)};
    REQUIRE(solve(a, b) == odestep::status::ok);
    CHECK(b[0] == T(1));
    CHECK(b[1] == T(1));
}

// A 6 x 6 system with x = (1, -2, 3, -4, 5, -6): b = A x computed exactly in integers, with
// a_ij = ((3 i^2 + 7 j + 2 i j + 1) mod 13) - 6: no structure the factorization could exploit, pivoting
// needed (a_00 = -5 is not the largest of its column), determinant -342732 and 2-norm condition number
// 8.31 (both computed with mpmath), so the error bound is a few tens of ulps.
template <class T>
void six_by_six() {
    matrix<T, 6> a{};
    std::array<long, 6> x{1, -2, 3, -4, 5, -6};
    std::array<T, 6> b{};
    for (std::size_t i = 0; i < 6; ++i) {
        long sum = 0;
        for (std::size_t j = 0; j < 6; ++j) {
            const long entry = static_cast<long>((3 * i * i + 7 * j + 2 * i * j + 1) % 13) - 6;
            a[i][j] = static_cast<T>(entry);
            sum += entry * x[j];
        }
        b[i] = static_cast<T>(sum);
    }
    REQUIRE(solve(a, b) == odestep::status::ok);
    for (std::size_t i = 0; i < 6; ++i) CHECK(std::fabs(b[i] - static_cast<T>(x[i])) <= T(256) * eps<T>);
}

template <class T>
void singular_and_non_finite() {
    odestep::linalg::pivots<2> p{};
    // rank one: the second pivot is exactly zero
    matrix<T, 2> rank_one{{{T(1), T(2)}, {T(2), T(4)}}};
    CHECK(lu_factor(rank_one, p) == odestep::status::singular_matrix);
    // a zero column
    matrix<T, 3> zero_column{{{T(1), T(0), T(3)}, {T(4), T(0), T(6)}, {T(7), T(0), T(9)}}};
    odestep::linalg::pivots<3> p3{};
    CHECK(lu_factor(zero_column, p3) == odestep::status::singular_matrix);
    // NaN and Inf entries: refused before anything is touched
    const matrix<T, 2> with_nan{{{T(1), std::numeric_limits<T>::quiet_NaN()}, {T(3), T(4)}}};
    matrix<T, 2> work = with_nan;
    CHECK(lu_factor(work, p) == odestep::status::singular_matrix);
    CHECK(same_bits(work, with_nan));
    const matrix<T, 2> with_inf{{{T(1), T(2)}, {-std::numeric_limits<T>::infinity(), T(4)}}};
    work = with_inf;
    CHECK(lu_factor(work, p) == odestep::status::singular_matrix);
    CHECK(same_bits(work, with_inf));
    // finite entries whose elimination overflows: max - (-1) max
    const T big = std::numeric_limits<T>::max();
    matrix<T, 2> overflowing{{{T(1), big}, {T(-1), big}}};
    CHECK(lu_factor(overflowing, p) == odestep::status::singular_matrix);
}

// Evaluated by the compiler: [[2, 1], [4, 3]] x = (4, 10) has x = (1, 2), and every operation is exact.
constexpr std::array<double, 2> constant_solution() {
    matrix<double, 2> a{{{2.0, 1.0}, {4.0, 3.0}}};
    odestep::linalg::pivots<2> p{};
    std::array<double, 2> b{4.0, 10.0};
    if (lu_factor(a, p) == odestep::status::ok) lu_solve(a, p, b);
    return b;
}

}  // namespace

TEST_CASE("lu: solves against a matrix with a known inverse, in float and double") {
    known_inverse<float>();
    known_inverse<double>();
}

TEST_CASE("lu: solves a system that needs pivoting (a permutation matrix), exactly") {
    permutation<float>();
    permutation<double>();
}

TEST_CASE("lu: a tiny leading entry is pivoted away, so the solution is right to rounding") {
    tiny_leading_entry<float>();
    tiny_leading_entry<double>();
}

TEST_CASE("lu: a 6 x 6 integer system is solved to a few hundred ulps") {
    six_by_six<float>();
    six_by_six<double>();
}

TEST_CASE("lu: a singular, non-finite or overflowing matrix is singular_matrix, a non-finite one untouched") {
    singular_and_non_finite<float>();
    singular_and_non_finite<double>();
}

TEST_CASE("lu: a 1 x 1 system is a division") {
    std::array<float, 1> b{3.0f};
    CHECK(solve(matrix<float, 1>{{{4.0f}}}, b) == odestep::status::ok);
    CHECK(b[0] == 0.75f);
    CHECK(solve(matrix<float, 1>{{{0.0f}}}, b) == odestep::status::singular_matrix);
}

TEST_CASE("lu: factor and solve are constant expressions") {
    constexpr std::array<double, 2> x = constant_solution();
    static_assert(x[0] == 1.0 && x[1] == 2.0, "[[2, 1], [4, 3]] x = (4, 10)");
    CHECK(x[1] == 2.0);
}
