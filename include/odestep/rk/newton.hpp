// SPDX-License-Identifier: BSL-1.0
// odestep: the simplified Newton iteration of the implicit Runge-Kutta methods: its two policies (iterate to
// a tolerance within a cap, or exactly k times), its tolerance and its convergence test.
#ifndef ODESTEP_RK_NEWTON_HPP
#define ODESTEP_RK_NEWTON_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "../detail/ops.hpp"
#include "../status.hpp"

namespace odestep {

/// \brief Newton policy: iterate until the update meets the tolerance (newton_tolerance), at most
/// MaxIterations times; `status::no_convergence` otherwise.
///
/// The default cap is 10. RADAU5 allows 7 (Hairer & Wanner, radau5.f, NIT), but it starts each solve from the
/// previous step's collocation polynomial and halves the step when the iteration is slow; a fixed-step method
/// starts from Z = 0 and cannot shrink its step, so it gets three more (Robertson's step from t = 10 to 14.5,
/// 20 steps per decade, needs 8 with Radau IIA). A step's worst case (the stepper's `rhs_evals_per_step`) is
/// computed at the cap; a step that converges sooner costs less.
template <std::size_t MaxIterations = 10>
struct newton {
    static_assert(MaxIterations >= 1, "odestep: a Newton iteration needs at least one iteration");
    static constexpr std::size_t iterations = MaxIterations;  ///< the cap
    static constexpr bool fixed = false;                      ///< stops when converged
};

/// \brief Newton policy for constant cost: exactly Iterations iterations in every step (every implicit
/// stage), no convergence test and no early exit, so every step makes the same evaluations, the same
/// solves and takes the same time: the mode of Simulink's fixed-step ode14x, for real-time loops.
///
/// The result after the last iteration is accepted if it is finite (`status::non_finite` otherwise, never
/// `no_convergence`). Choose the count for your system and dt by checking, off line, that the iteration has
/// converged by then (for a linear system with an exact Jacobian, 1 is exact; on Robertson's kinetics at
/// dt = 0.1, backward Euler needs 3).
template <std::size_t Iterations>
struct fixed_newton {
    static_assert(Iterations >= 1, "odestep: a Newton iteration needs at least one iteration");
    static constexpr std::size_t iterations = Iterations;  ///< every step makes exactly this many
    static constexpr bool fixed = true;                    ///< no convergence test
};

namespace detail {
/// eps^(3/4) of T as the nearest lower power of two: 2^-17 = 7.6e-6 for float, 2^-39 = 1.8e-12 for double,
/// 2^-47 = 7.1e-15 for the x87 long double. (eps = 2^-p with p = digits - 1.)
template <class T>
constexpr T three_quarter_power_of_epsilon() noexcept {
    const int exponent = (3 * (std::numeric_limits<T>::digits - 1)) / 4;
    T r = T(1);
    for (int i = 0; i < exponent; ++i) r /= T(2);
    return r;
}
}  // namespace detail

/// \brief When a Newton iteration has converged: component i of every update is measured in units of
/// w_i = relative |y_i| + absolute, y the state at the step's start, and the largest of these is the
/// update's norm ||dz||.
///
/// The test is CVODE's (Hindmarsh et al. 2005, ACM TOMS 31, 363-396, Sec. 2.1; cvode_nls.c): with the
/// convergence rate theta_k = max(0.3 theta_{k-1}, ||dz_k|| / ||dz_{k-1}||), theta_0 = 1 (CVODE's value
/// after a new Jacobian, which every step here has), iteration k has converged when
/// ||dz_k|| min(1, theta_k) <= 1, and the iteration is abandoned as diverging (`status::no_convergence`)
/// when ||dz_k|| > 2 ||dz_{k-1}||. The error left after convergence is about theta ||dz_k|| <= w.
/// Defaults: relative = absolute = eps^(3/4) of T (7.6e-6 in float, 1.8e-12 in double), far below a
/// fixed-step method's truncation error and far above the rounding level of the updates.
template <class T>
struct newton_tolerance {
    T relative = detail::three_quarter_power_of_epsilon<T>();  ///< per unit of |y_i|
    T absolute = detail::three_quarter_power_of_epsilon<T>();  ///< the floor for components near zero

    /// Both finite, relative >= 0 and absolute > 0 (so that every weight is positive).
    constexpr bool valid() const noexcept {
        return detail::is_finite(relative) && detail::is_finite(absolute) && relative >= T(0) && absolute > T(0);
    }
};

namespace detail {

/// The convergence test of newton_tolerance, one iteration at a time. `weights` holds 1 / w_i.
template <class T>
class newton_monitor {
public:
    enum class verdict : unsigned char { iterate, converged, diverged };

    /// Takes the norm of the latest update (already known to be finite) and says what to do next.
    constexpr verdict next(T norm) noexcept {
        if (iteration_ > 0) {
            const T ratio = norm / previous_;  // previous_ > 0: an update of norm 0 has converged
            rate_ = max_value(T(0.3) * rate_, ratio);
        }
        ++iteration_;
        const T damped = rate_ < T(1) ? norm * rate_ : norm;
        if (damped <= T(1)) return verdict::converged;
        if (iteration_ > 1 && norm > T(2) * previous_) return verdict::diverged;
        previous_ = norm;
        return verdict::iterate;
    }

private:
    T previous_ = T(0);
    T rate_ = T(1);
    std::size_t iteration_ = 0;
};

/// \brief Hairer's convergence monitor of one simplified Newton solve in an error-controlled stiff engine
/// (radau5.f; Hairer & Wanner, Solving ODE II, Sec. IV.8, (8.10)-(8.13)): odestep::radau5 and
/// odestep::sdirk_adaptive run their iterations through it.
///
/// Fed the scaled norm of every update (already known to be finite), it estimates the contraction theta (the
/// ratio of successive norms, from the third iteration the geometric mean of the last two ratios) and says:
/// `diverged` when theta >= 0.99 (the caller rejects the step, h halved); `slow` when the rate predicts no
/// convergence within the cap (theta^(iterations left) theta / (1 - theta) ||dz|| > kappa; the caller rejects
/// with h times shrink(), radau5.f's formula); else the update is to be applied, and `converged` once
/// theta / (1 - theta) ||dz|| <= kappa. Before a rate is known theta / (1 - theta) is the previous solve's, to
/// the power 0.8 (radau5.f's FACCON).
template <class T>
class theta_monitor {
public:
    enum class verdict : unsigned char { iterate, converged, diverged, slow };

    /// A new solve: `faccon` the previous solve's theta / (1 - theta) (1 at a start), `theta` the rate assumed
    /// until one is measured, `kappa` the tolerance on the remaining error, `cap` the iteration cap.
    theta_monitor(T faccon, T theta, T kappa, std::size_t cap) noexcept
        : faccon_(std::pow(max_value(faccon, std::numeric_limits<T>::epsilon()), T(4) / T(5))),
          theta_(theta),
          kappa_(kappa),
          cap_(cap) {}

    /// Takes the norm of the latest update.
    verdict next(T norm) noexcept {
        ++iterations_;
        if (iterations_ > 1 && iterations_ < cap_) {
            const T ratio = norm / previous_;
            theta_ = iterations_ == 2 ? ratio : std::sqrt(ratio * ratio_old_);
            ratio_old_ = ratio;
            if (!(theta_ < T(99) / T(100))) return verdict::diverged;
            faccon_ = theta_ / (T(1) - theta_);
            const std::size_t left = cap_ - 1 - iterations_;
            const T predicted = faccon_ * norm * std::pow(theta_, static_cast<T>(left)) / kappa_;
            if (predicted >= T(1)) {
                // radau5.f: h * 0.8 q^(-1 / (4 + left)), q the predicted excess within [1e-4, 20]
                const T q = predicted < T(1e-4f) ? T(1e-4f) : (predicted > T(20) ? T(20) : predicted);
                shrink_ = T(4) / T(5) * std::pow(q, -T(1) / static_cast<T>(4 + left));
                return verdict::slow;
            }
        }
        previous_ = max_value(norm, std::numeric_limits<T>::epsilon());
        return faccon_ * norm <= kappa_ ? verdict::converged : verdict::iterate;
    }
    /// Iterations so far.
    std::size_t iterations() const noexcept { return iterations_; }
    /// The latest contraction estimate.
    T theta() const noexcept { return theta_; }
    /// theta / (1 - theta), carried to the next solve.
    T faccon() const noexcept { return faccon_; }
    /// After `slow`: the factor for h.
    T shrink() const noexcept { return shrink_; }

private:
    T faccon_;
    T theta_;
    T kappa_;
    std::size_t cap_;
    T previous_ = T(0);
    T ratio_old_ = T(0);
    T shrink_ = T(1) / T(2);
    std::size_t iterations_ = 0;
};

/// 1 / (relative |y_i| + absolute) for every component: the update's units.
template <class T, std::size_t N>
constexpr std::array<T, N> newton_weights(const newton_tolerance<T>& tol, const std::array<T, N>& y) noexcept {
    std::array<T, N> w;
    for (std::size_t i = 0; i < N; ++i) w[i] = T(1) / (tol.relative * abs_value(y[i]) + tol.absolute);
    return w;
}

/// max_i |dz_i| w_i over one N-vector (the caller has checked that dz is finite).
template <class T, std::size_t N>
constexpr T weighted_max(const std::array<T, N>& dz, const std::array<T, N>& w) noexcept {
    T m = T(0);
    for (std::size_t i = 0; i < N; ++i) m = max_value(m, abs_value(dz[i]) * w[i]);
    return m;
}

}  // namespace detail
}  // namespace odestep

#endif
