// odestep: dense output: the state between the ends of an accepted step, from the step's own data.
#ifndef ODESTEP_ADAPTIVE_DENSE_HPP
#define ODESTEP_ADAPTIVE_DENSE_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../tables/runge_kutta.hpp"
#include "adaptive_rk.hpp"

namespace odestep {

/// The cubic Hermite interpolant of a step from (t0, y0) to (t0 + h, y1) with slopes f0 = f(t0, y0) and
/// f1 = f(t0 + h, y1), at t0 + theta h:
///     u(theta) = (1 - theta) y0 + theta y1
///                + theta (theta - 1) ((1 - 2 theta)(y1 - y0) + (theta - 1) h f0 + theta h f1)
/// (HNW I, Sec. II.6, eq. (6.7)). It matches y and y' at both ends; its error is O(h^4) locally (order 3),
/// whatever the stepper that made the step, so it serves any stepper of the library.
template <class State>
void hermite_cubic(const State& y0, const State& f0, const State& y1, const State& f1, value_type_t<State> h,
                   value_type_t<State> theta, State& out) noexcept {
    using T = value_type_t<State>;
    const T a = theta * (theta - T(1));
    const T p = T(1) - T(2) * theta;
    const T q = (theta - T(1)) * h;
    const T r = theta * h;
    for (std::size_t i = 0; i < state_traits<State>::size; ++i) {
        const T d = y1[i] - y0[i];
        out[i] = y0[i] + theta * d + a * (p * d + q * f0[i] + r * f1[i]);
    }
}

namespace detail {

/// Dormand-Prince 5(4)'s continuous extension of order 4 (Dormand & Prince 1986, "Runge-Kutta triples",
/// Comp. & Maths. with Appls. 12A, 1007-1017, with Shampine's choice of the free parameter; HNW I,
/// Sec. II.6, Table 6.2), in the form of Hairer's DOPRI5 (dopri5.f, the coefficients D1..D7 and CONTD5):
///     u(theta) = r1 + theta (r2 + (1 - theta)(r3 + theta (r4 + (1 - theta) r5)))
///     r1 = y0, r2 = y1 - y0, r3 = h k1 - r2, r4 = r2 - h k7 - r3, r5 = h sum_i d_i k_i.
template <class T>
struct dopri5_dense {
    static constexpr std::array<T, 7> d{T(-12715105075.0L) / T(11282082432.0L),  T(0),
                                        T(87487479700.0L) / T(32700410799.0L),   T(-10690763975.0L) / T(1880347072.0L),
                                        T(701980252875.0L) / T(199316789632.0L), T(-1453857185.0L) / T(822651844.0L),
                                        T(69997945.0L) / T(29380423.0L)};
};

}  // namespace detail

/// \brief The interpolant of one accepted step of odestep::adaptive_rk<Method, State>.
///
/// Dormand-Prince 5(4) gets its continuous extension of order 4 (detail::dopri5_dense: five states kept,
/// no extra evaluation); every other pair the cubic Hermite interpolant (order 3: four states kept, and
/// f at the step's end, which is the next step's first stage, so it costs an evaluation only at the end of
/// a run; FSAL tables have it already). Used as the engine's accept sink: `engine.attempt(f, t, y, t_end,
/// accepted, dense)`, then `dense.complete(f, engine)`, then `dense.at(t, out)` for t in the step.
template <class Method, class State>
class dense_step {
public:
    using state_type = State;                ///< the state
    using value_type = value_type_t<State>;  ///< its scalar T

private:
    using T = value_type;
    using engine_type = adaptive_rk<Method, State>;

public:
    /// True for Dormand-Prince 5(4): its own continuous extension; otherwise cubic Hermite.
    static constexpr bool continuous_extension = std::is_same_v<Method, tables::dormand_prince54>;
    /// The interpolant's order (its local error is O(h^(order + 1))).
    static constexpr int order = continuous_extension ? 4 : 3;

    /// The accept sink: the step from (t, y) of size h with stages k to y_new.
    template <class Stages>
    void operator()(T t, const State& y, T h, const Stages& k, const State& y_new) noexcept {
        t0_ = t;
        h_ = h;
        complete_ = false;
        constexpr std::size_t N = state_traits<State>::size;
        if constexpr (continuous_extension) {
            constexpr auto d = detail::dopri5_dense<T>::d;
            for (std::size_t i = 0; i < N; ++i) {
                const T ydiff = y_new[i] - y[i];
                const T bspl = h * k[0][i] - ydiff;
                r_[0][i] = y[i];
                r_[1][i] = ydiff;
                r_[2][i] = bspl;
                r_[3][i] = ydiff - h * k[6][i] - bspl;
                T acc = T(0);
                for (std::size_t j = 0; j < 7; ++j)
                    if (d[j] != T(0)) acc += d[j] * k[j][i];
                r_[4][i] = h * acc;
            }
            complete_ = true;
        } else {
            detail::assign(r_[0], y);
            detail::assign(r_[1], k[0]);
            detail::assign(r_[2], y_new);
            if constexpr (engine_type::fsal) {
                detail::assign(r_[3], k[k.size() - 1]);
                complete_ = true;
            }
        }
    }

    /// Makes the interpolant usable: for Hermite without FSAL, f at the step's end (through the engine,
    /// which keeps it as the next step's first stage). non_finite when f gives NaN or Inf there.
    template <class System>
    status complete(System& f, engine_type& engine) {
        if (complete_) return status::ok;
        const status s = engine.derivative(f, t0_ + h_, r_[2], r_[3]);
        complete_ = s == status::ok;
        return s;
    }

    /// The step's start time.
    T t_start() const noexcept { return t0_; }
    /// The step's size (signed).
    T step() const noexcept { return h_; }

    /// The interpolated state at t (meant for t inside the step; theta = (t - t_start) / h).
    void at(T t, State& out) const noexcept { at_theta((t - t0_) / h_, out); }

    /// The interpolated state at t_start + theta h.
    void at_theta(T theta, State& out) const noexcept {
        if constexpr (continuous_extension) {
            const T theta1 = T(1) - theta;
            for (std::size_t i = 0; i < state_traits<State>::size; ++i)
                out[i] = r_[0][i] + theta * (r_[1][i] + theta1 * (r_[2][i] + theta * (r_[3][i] + theta1 * r_[4][i])));
        } else {
            hermite_cubic(r_[0], r_[1], r_[2], r_[3], h_, theta, out);
        }
    }

private:
    T t0_ = T(0);
    T h_ = T(0);
    bool complete_ = false;
    std::array<State, continuous_extension ? 5 : 4> r_{};
};

}  // namespace odestep

#endif
