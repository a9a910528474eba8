// SPDX-License-Identifier: BSL-1.0
// odestep: a forward-mode dual number, so that a right-hand side written as a template gives its Jacobian
// by automatic differentiation (exact to round-off), and the system object that carries that Jacobian.
#ifndef ODESTEP_SENSITIVITY_DUAL_HPP
#define ODESTEP_SENSITIVITY_DUAL_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../state.hpp"
#include "../system.hpp"

namespace odestep {

/// \brief A forward-mode dual number: a value and its K partial derivatives, a + sum_k g_k e_k with
/// e_j e_k = 0. No heap: K + 1 scalars.
///
/// Every operation applies the chain rule to the derivatives (d(ab) = a db + b da, d sin a = cos a da, ...),
/// so a function computed in dual<T, K> returns its derivatives with the rounding of the same function's
/// operations, not a truncation error: exact to round-off, unlike a difference quotient.
///
/// The library's steppers take float, double or long double only (odestep::is_scalar_v); a dual reaches
/// them through the Jacobian it computes (odestep::dual_jacobian, odestep::with_dual_jacobian). Write the
/// function as a template on its scalar and call the elementary functions unqualified after
/// `using std::sin;` (argument-dependent lookup then finds these for a dual): sqrt, sin, cos, tan, exp, log,
/// pow, abs and fabs are provided.
template <class T, std::size_t K>
struct dual {
    static_assert(is_scalar_v<T>, "odestep: a dual number's scalar is float, double or long double");
    /// The scalar type T.
    using value_type = T;
    /// The number of partial derivatives.
    static constexpr std::size_t size = K;

    T value = T(0);           ///< the value a
    std::array<T, K> grad{};  ///< the partial derivatives d a / d p_k

    /// Zero.
    constexpr dual() noexcept = default;
    /// A constant (all derivatives zero): lets T values and literals mix with duals.
    constexpr dual(T a) noexcept : value(a) {}  // NOLINT(google-explicit-constructor): constants convert
    /// The independent variable k with value a: derivative 1 in slot k, 0 in the others.
    static constexpr dual variable(T a, std::size_t k) noexcept {
        dual r(a);
        r.grad[k] = T(1);
        return r;
    }

    /// +a
    friend constexpr dual operator+(const dual& a) noexcept { return a; }
    /// -a
    friend constexpr dual operator-(const dual& a) noexcept {
        dual r = a;
        r.value = -r.value;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) r.grad[k] = -r.grad[k];
        return r;
    }
    /// a + b
    friend constexpr dual operator+(const dual& a, const dual& b) noexcept {
        dual r = a;
        return r += b;
    }
    /// a + c
    friend constexpr dual operator+(const dual& a, T c) noexcept {
        dual r = a;
        r.value += c;
        return r;
    }
    /// c + a
    friend constexpr dual operator+(T c, const dual& a) noexcept { return a + c; }
    /// a - b
    friend constexpr dual operator-(const dual& a, const dual& b) noexcept {
        dual r = a;
        return r -= b;
    }
    /// a - c
    friend constexpr dual operator-(const dual& a, T c) noexcept {
        dual r = a;
        r.value -= c;
        return r;
    }
    /// c - a
    friend constexpr dual operator-(T c, const dual& a) noexcept {
        dual r = -a;
        r.value += c;
        return r;
    }
    /// a b: d(ab) = a db + b da
    friend constexpr dual operator*(const dual& a, const dual& b) noexcept {
        dual r = a;
        return r *= b;
    }
    /// a c
    friend constexpr dual operator*(const dual& a, T c) noexcept {
        dual r = a;
        r.value *= c;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) r.grad[k] *= c;
        return r;
    }
    /// c a
    friend constexpr dual operator*(T c, const dual& a) noexcept { return a * c; }
    /// a / b: d(a/b) = (da - (a/b) db) / b
    friend constexpr dual operator/(const dual& a, const dual& b) noexcept {
        dual r = a;
        return r /= b;
    }
    /// a / c
    friend constexpr dual operator/(const dual& a, T c) noexcept {
        dual r = a;
        r.value /= c;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) r.grad[k] /= c;
        return r;
    }
    /// c / a: d(c/a) = -(c/a) da / a
    friend constexpr dual operator/(T c, const dual& a) noexcept {
        dual r = a;
        r.value = c / a.value;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) r.grad[k] = -r.value * r.grad[k] / a.value;
        return r;
    }
    // The operations work in place on a copy of an operand: a result built from `dual r;` would zero its K
    // derivatives first (the member initializer) only to overwrite them, K stores per operation.
    // Each loop over the K derivatives is unrolled (ODESTEP_UNROLL_UNLESS_SIZE): rolled, the copy stays a copy
    // and each operation a loop of its own; unrolled, the copy folds into the arithmetic (f in duals costs
    // about what the N x N by N x K product it replaces does).
    /// a += b
    constexpr dual& operator+=(const dual& b) noexcept {
        value += b.value;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) grad[k] += b.grad[k];
        return *this;
    }
    /// a -= b
    constexpr dual& operator-=(const dual& b) noexcept {
        value -= b.value;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) grad[k] -= b.grad[k];
        return *this;
    }
    /// a *= b: d(ab) = a db + b da
    constexpr dual& operator*=(const dual& b) noexcept {
        const T a0 = value;
        const T b0 = b.value;  // b may be *this
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) grad[k] = a0 * b.grad[k] + b0 * grad[k];
        value = a0 * b0;
        return *this;
    }
    /// a /= b: d(a/b) = (da - (a/b) db) / b
    constexpr dual& operator/=(const dual& b) noexcept {
        const T b0 = b.value;  // b may be *this
        const T q = value / b0;
        ODESTEP_UNROLL_UNLESS_SIZE
        for (std::size_t k = 0; k < K; ++k) grad[k] = (grad[k] - q * b.grad[k]) / b0;
        value = q;
        return *this;
    }

    // Comparisons compare values (a branch on a value is piecewise: its derivative is the branch taken's).
    /// a == b (values)
    friend constexpr bool operator==(const dual& a, const dual& b) noexcept { return a.value == b.value; }
    /// a != b (values)
    friend constexpr bool operator!=(const dual& a, const dual& b) noexcept { return a.value != b.value; }
    /// a < b (values)
    friend constexpr bool operator<(const dual& a, const dual& b) noexcept { return a.value < b.value; }
    /// a <= b (values)
    friend constexpr bool operator<=(const dual& a, const dual& b) noexcept { return a.value <= b.value; }
    /// a > b (values)
    friend constexpr bool operator>(const dual& a, const dual& b) noexcept { return a.value > b.value; }
    /// a >= b (values)
    friend constexpr bool operator>=(const dual& a, const dual& b) noexcept { return a.value >= b.value; }
};

namespace detail {
// f(a) with derivative df/da: value f, every partial derivative scaled by df/da (the chain rule).
template <class T, std::size_t K>
constexpr dual<T, K> chain(const dual<T, K>& a, T f, T dfda) noexcept {
    dual<T, K> r = a;
    r.value = f;
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t k = 0; k < K; ++k) r.grad[k] *= dfda;
    return r;
}
}  // namespace detail

/// sqrt a: d sqrt a = da / (2 sqrt a)
template <class T, std::size_t K>
dual<T, K> sqrt(const dual<T, K>& a) noexcept {
    const T s = std::sqrt(a.value);
    return detail::chain(a, s, T(1) / (T(2) * s));
}
/// sin a: d sin a = cos a da
template <class T, std::size_t K>
dual<T, K> sin(const dual<T, K>& a) noexcept {
    return detail::chain(a, std::sin(a.value), std::cos(a.value));
}
/// cos a: d cos a = -sin a da
template <class T, std::size_t K>
dual<T, K> cos(const dual<T, K>& a) noexcept {
    return detail::chain(a, std::cos(a.value), -std::sin(a.value));
}
/// tan a: d tan a = (1 + tan^2 a) da
template <class T, std::size_t K>
dual<T, K> tan(const dual<T, K>& a) noexcept {
    const T t = std::tan(a.value);
    return detail::chain(a, t, T(1) + t * t);
}
/// exp a: d exp a = exp a da
template <class T, std::size_t K>
dual<T, K> exp(const dual<T, K>& a) noexcept {
    const T e = std::exp(a.value);
    return detail::chain(a, e, e);
}
/// log a: d log a = da / a
template <class T, std::size_t K>
dual<T, K> log(const dual<T, K>& a) noexcept {
    return detail::chain(a, std::log(a.value), T(1) / a.value);
}
/// a^p for a constant p: d a^p = p a^(p-1) da
template <class T, std::size_t K>
dual<T, K> pow(const dual<T, K>& a, T p) noexcept {
    return detail::chain(a, std::pow(a.value, p), p * std::pow(a.value, p - T(1)));
}
/// a^b = exp(b log a) (a > 0): d a^b = a^b (log a db + b da / a)
template <class T, std::size_t K>
dual<T, K> pow(const dual<T, K>& a, const dual<T, K>& b) noexcept {
    dual<T, K> r;
    r.value = std::pow(a.value, b.value);
    const T log_a = std::log(a.value);
    ODESTEP_UNROLL_UNLESS_SIZE
    for (std::size_t k = 0; k < K; ++k) r.grad[k] = r.value * (log_a * b.grad[k] + b.value * a.grad[k] / a.value);
    return r;
}
/// |a|: d|a| = sign(a) da (the derivative of +a at a = 0)
template <class T, std::size_t K>
constexpr dual<T, K> abs(const dual<T, K>& a) noexcept {
    return a.value < T(0) ? -a : a;
}
/// |a|, as fabs.
template <class T, std::size_t K>
constexpr dual<T, K> fabs(const dual<T, K>& a) noexcept {
    return abs(a);
}

namespace detail {
// f(t, y) called in dual numbers, whichever form f has (written as a template on its scalar).
template <class F, class T, class DState>
constexpr DState evaluate_dual(F& f, T t, const DState& y) {
    if constexpr (std::is_invocable_v<F&, T, const DState&, DState&>) {
        DState dydt{};
        f(t, y, dydt);
        return dydt;
    } else {
        static_assert(std::is_invocable_v<F&, T, const DState&>,
                      "odestep: for a Jacobian by dual numbers, f must be written as a template on its scalar, "
                      "callable as f(T t, const std::array<S, N>& y) (or f(t, y, dydt)) with S = odestep::dual<T, N>");
        return f(t, y);
    }
}
}  // namespace detail

/// \brief dfdy = d f / d y at (t, y) by forward-mode automatic differentiation: one evaluation of f in
/// dual<T, N> (N derivatives carried through every operation, about N + 1 times the work of f in T).
///
/// f is written as a template on its scalar S, `std::array<S, N> f(T t, const std::array<S, N>& y)` or
/// `void f(T t, const std::array<S, N>& y, std::array<S, N>& dydt)` (a generic lambda taking `auto`); t
/// is passed as T. The result is the derivative of what f computes, to round-off.
template <class F, class T, std::size_t N>
void dual_jacobian(F& f, T t, const std::array<T, N>& y, jacobian_t<std::array<T, N>>& dfdy) {
    using d = dual<T, N>;
    std::array<d, N> yd;
    for (std::size_t j = 0; j < N; ++j) yd[j] = d::variable(y[j], j);
    const std::array<d, N> fd = detail::evaluate_dual(f, t, static_cast<const std::array<d, N>&>(yd));
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = 0; j < N; ++j) dfdy[i][j] = fd[i].grad[j];
}

/// \brief A right-hand side f written as a template on its scalar, as a system that carries its Jacobian
/// (odestep::has_jacobian_v), computed by odestep::dual_jacobian. Made by odestep::with_dual_jacobian.
///
/// Called as f in T (either form) it goes wherever a system goes; its `jacobian(t, y, dfdy)` is what the
/// transitions (explicit_rk_transition, splitting_transition) and the implicit steppers read.
template <class F>
struct system_with_dual_jacobian {
    F f;  ///< the right-hand side, a template on its scalar

    /// dydt = f(t, y) (when f returns the derivative).
    template <class T, class State>
    constexpr auto operator()(T t, const State& y) -> decltype(std::declval<F&>()(t, y)) {
        return f(t, y);
    }
    /// f(t, y, dydt) (when f writes the derivative).
    template <class T, class State>
    constexpr auto operator()(T t, const State& y, State& dydt) -> decltype(std::declval<F&>()(t, y, dydt)) {
        return f(t, y, dydt);
    }
    /// dfdy = d f / d y at (t, y), by dual numbers.
    template <class T, std::size_t N>
    void jacobian(T t, const std::array<T, N>& y, jacobian_t<std::array<T, N>>& dfdy) {
        dual_jacobian(f, t, y, dfdy);
    }
    /// jz = (d f / d y) z at (t, y) for an N x M matrix z: one evaluation of f in dual<T, M> whose
    /// derivative parts are z's rows (the directional derivatives of f along z's columns), with no N x N
    /// Jacobian and no product formed. What the explicit transitions read for a stage's K = J Z.
    template <class T, std::size_t N, std::size_t M>
    void jacobian_times(T t, const std::array<T, N>& y, const std::array<std::array<T, M>, N>& z,
                        std::array<std::array<T, M>, N>& jz) {
        using d = dual<T, M>;
        std::array<d, N> yd;
        for (std::size_t j = 0; j < N; ++j) {
            yd[j].value = y[j];
            yd[j].grad = z[j];
        }
        const std::array<d, N> fd = detail::evaluate_dual(f, t, static_cast<const std::array<d, N>&>(yd));
        for (std::size_t i = 0; i < N; ++i) jz[i] = fd[i].grad;
    }
};

/// Makes the system of f with its Jacobian by dual numbers. A callable given as an lvalue is held by
/// reference, one given as an rvalue is moved in:
///
/// \code
/// auto pendulum = [](double, const auto& y) {
///     using std::sin;
///     using S = std::decay_t<decltype(y[0])>;
///     return std::array<S, 2>{y[1], -9.81 * sin(y[0])};
/// };
/// auto sys = odestep::with_dual_jacobian(pendulum);
/// \endcode
template <class F>
constexpr system_with_dual_jacobian<F> with_dual_jacobian(F&& f) {
    return {std::forward<F>(f)};
}

}  // namespace odestep

#endif
