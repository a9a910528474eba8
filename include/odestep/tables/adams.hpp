// SPDX-License-Identifier: BSL-1.0
// odestep: the Adams tables (Adams-Bashforth, and Adams-Moulton correctors): the table type and the methods.
#ifndef ODESTEP_TABLES_ADAMS_HPP
#define ODESTEP_TABLES_ADAMS_HPP

#include <array>
#include <cstddef>

namespace odestep {

/// The coefficients of a k-step Adams method with fixed step h, typed in T:
///
///     predictor (Adams-Bashforth):  p       = y_n + h * sum_{j=0}^{k-1} beta_j f_{n-j}
///     corrector (Adams-Moulton, C = k only):
///                                   y_{n+1} = y_n + h * (gamma_0 f(t_{n+1}, p) + sum_{j=1}^{k-1} gamma_j f_{n+1-j})
///
/// with f_m = f(t_m, y_m). Without a corrector (C = 0) the predictor is y_{n+1}. The k-step Adams-Bashforth
/// weights integrate the polynomial through f_n, ..., f_{n-k+1} over [t_n, t_{n+1}] and have order k; the
/// Adams-Moulton weights with k values f_{n+1}, ..., f_{n-k+2} have order k too. One corrector pass with the
/// predicted value (PECE) keeps order k.
template <class T, std::size_t K, std::size_t C = 0>
struct adams_table {
    static_assert(K >= 2, "odestep: an Adams table needs at least two steps (one step is forward Euler)");
    static_assert(C == 0 || C == K, "odestep: the corrector has as many weights as the predictor, or none");
    /// The scalar type T.
    using value_type = T;
    /// How many steps the method reads (k).
    static constexpr std::size_t steps = K;
    /// Whether the table has a corrector.
    static constexpr bool has_corrector = C > 0;

    std::array<T, K> beta{};   ///< weights of f_n, f_{n-1}, ..., f_{n-k+1}
    std::array<T, C> gamma{};  ///< weights of f_{n+1} (at the predicted state), f_n, ..., f_{n-k+2}
    int order = 0;             ///< the order of the method
};

/// The tables. Each is a tag type whose `table<T>` is typed in T, written as exact rationals T(p) / T(q).
///
/// Source of every coefficient: Hairer, Norsett & Wanner, Solving Ordinary Differential Equations I (2nd ed.),
/// Sec. III.1, the tables of the explicit Adams methods (Bashforth & Adams 1883) and of the implicit Adams
/// methods (Moulton 1926). They are the integrals over [0, 1] of the Lagrange basis polynomials through the
/// nodes s = 0, -1, ..., -(k-1) (explicit) and s = 1, 0, ..., -(k-2) (implicit); the test suite checks the
/// order conditions sum_j w_j s_j^q = 1/(q+1), q < k, and that q = k fails.
namespace tables {
// clang-format off  (the tables keep their published layout)

/// Two-step Adams-Bashforth, order 2:  y_{n+1} = y_n + h (3 f_n - f_{n-1}) / 2.
struct bashforth2 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Adams-Bashforth 2";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr adams_table<T, 2> table{{T(3) / T(2), T(-1) / T(2)}, {}, 2};
};

/// Three-step Adams-Bashforth, order 3:  y_{n+1} = y_n + h (23 f_n - 16 f_{n-1} + 5 f_{n-2}) / 12.
struct bashforth3 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Adams-Bashforth 3";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr adams_table<T, 3> table{{T(23) / T(12), T(-16) / T(12), T(5) / T(12)}, {}, 3};
};

/// Four-step Adams-Bashforth, order 4:  y_{n+1} = y_n + h (55 f_n - 59 f_{n-1} + 37 f_{n-2} - 9 f_{n-3}) / 24.
struct bashforth4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Adams-Bashforth 4";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr adams_table<T, 4> table{{T(55) / T(24), T(-59) / T(24), T(37) / T(24), T(-9) / T(24)}, {}, 4};
};

/// Five-step Adams-Bashforth, order 5:
///     y_{n+1} = y_n + h (1901 f_n - 2774 f_{n-1} + 2616 f_{n-2} - 1274 f_{n-3} + 251 f_{n-4}) / 720.
struct bashforth5 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Adams-Bashforth 5";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr adams_table<T, 5> table{
        {T(1901) / T(720), T(-2774) / T(720), T(2616) / T(720), T(-1274) / T(720), T(251) / T(720)}, {}, 5};
};

/// Adams-Bashforth-Moulton of order 4 in PECE mode: the four-step Adams-Bashforth predictor and the
/// three-step (order 4) Adams-Moulton corrector, applied once:
///     p       = y_n + h (55 f_n - 59 f_{n-1} + 37 f_{n-2} - 9 f_{n-3}) / 24
///     y_{n+1} = y_n + h (9 f(t_{n+1}, p) + 19 f_n - 5 f_{n-1} + f_{n-2}) / 24
struct bashforth_moulton4 {
    /// The method's name, for logs and tables.
    static constexpr const char* name = "Adams-Bashforth-Moulton 4 (PECE)";
    /// The table with its coefficients in T.
    template <class T>
    static constexpr adams_table<T, 4, 4> table{{T(55) / T(24), T(-59) / T(24), T(37) / T(24), T(-9) / T(24)},
                                                {T(9) / T(24), T(19) / T(24), T(-5) / T(24), T(1) / T(24)},
                                                4};
};

// clang-format on
}  // namespace tables

}  // namespace odestep

namespace odestep {
/// The namespace of these tables before every table moved to odestep::tables; kept so that code written
/// against it still compiles.
namespace adams_tables = tables;
}  // namespace odestep

#endif
