// SPDX-License-Identifier: BSL-1.0
// odestep: dense output: the state between the ends of an accepted step, from the step's own data.
#ifndef ODESTEP_ADAPTIVE_DENSE_HPP
#define ODESTEP_ADAPTIVE_DENSE_HPP

#include <array>
#include <cstddef>
#include <type_traits>

#include "../detail/hermite.hpp"
#include "../detail/ops.hpp"
#include "../state.hpp"
#include "../status.hpp"
#include "../tables/runge_kutta.hpp"
#include "adaptive_rk.hpp"

namespace odestep {

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

/// DOP853's continuous extension of order 7 (Dormand & Prince; HNW I, Sec. II.6 and II.10), with the
/// coefficients of Hairer's dop853.f (C14..C16, A14x..A16x, D4x..D7x, as 30-digit decimals, also
/// reproduced in SciPy's dop853_coefficients.py) and the form of its CONTD8. Three more stages after an
/// accepted step, which read k1..k12, k13 = f(t + h, y1) (the next step's first stage) and each other:
///     u(theta) = r1 + theta (r2 + (1 - theta)(r3 + theta (r4 + (1 - theta) p)))
///     p        = r5 + theta (r6 + (1 - theta)(r7 + theta r8))
///     r1 = y0, r2 = y1 - y0, r3 = h k1 - r2, r4 = r2 - h k13 - r3, r(5 + i) = h sum_j D[i][j] k_j.
/// Stages and D columns are numbered from 0 (k1 is column 0, k13..k16 columns 12..15).
template <class T>
struct dop853_dense {
    static constexpr std::array<T, 3> c{T(0.1L), T(0.2L), T(0.777777777777777777777777777778L)};
    // a[i][j]: row i is stage 14 + i, column j stage j + 1.
    static constexpr std::array<std::array<T, 15>, 3> a{{
        {T(5.61675022830479523392909219681e-2L), T(0), T(0), T(0), T(0), T(0), T(2.53500210216624811088794765333e-1L),
         T(-2.46239037470802489917441475441e-1L), T(-1.24191423263816360469010140626e-1L),
         T(1.5329179827876569731206322685e-1L), T(8.20105229563468988491666602057e-3L),
         T(7.56789766054569976138603589584e-3L), T(-8.298e-3L), T(0), T(0)},
        {T(3.18346481635021405060768473261e-2L), T(0), T(0), T(0), T(0), T(2.83009096723667755288322961402e-2L),
         T(5.35419883074385676223797384372e-2L), T(-5.49237485713909884646569340306e-2L), T(0), T(0),
         T(-1.08347328697249322858509316994e-4L), T(3.82571090835658412954920192323e-4L),
         T(-3.40465008687404560802977114492e-4L), T(1.41312443674632500278074618366e-1L), T(0)},
        {T(-4.28896301583791923408573538692e-1L), T(0), T(0), T(0), T(0), T(-4.69762141536116384314449447206L),
         T(7.68342119606259904184240953878L), T(4.06898981839711007970213554331L),
         T(3.56727187455281109270669543021e-1L), T(0), T(0), T(0), T(-1.39902416515901462129418009734e-3L),
         T(2.9475147891527723389556272149L), T(-9.15095847217987001081870187138L)},
    }};
    static constexpr std::array<std::array<T, 16>, 4> d{{
        {T(-0.84289382761090128651353491142e1L), T(0), T(0), T(0), T(0), T(0.56671495351937776962531783590L),
         T(-0.30689499459498916912797304727e1L), T(0.23846676565120698287728149680e1L),
         T(0.21170345824450282767155149946e1L), T(-0.87139158377797299206789907490L),
         T(0.22404374302607882758541771650e1L), T(0.63157877876946881815570249290L),
         T(-0.88990336451333310820698117400e-1L), T(0.18148505520854727256656404962e2L),
         T(-0.91946323924783554000451984436e1L), T(-0.44360363875948939664310572000e1L)},
        {T(0.10427508642579134603413151009e2L), T(0), T(0), T(0), T(0), T(0.24228349177525818288430175319e3L),
         T(0.16520045171727028198505394887e3L), T(-0.37454675472269020279518312152e3L),
         T(-0.22113666853125306036270938578e2L), T(0.77334326684722638389603898808e1L),
         T(-0.30674084731089398182061213626e2L), T(-0.93321305264302278729567221706e1L),
         T(0.15697238121770843886131091075e2L), T(-0.31139403219565177677282850411e2L),
         T(-0.93529243588444783865713862664e1L), T(0.35816841486394083752465898540e2L)},
        {T(0.19985053242002433820987653617e2L), T(0), T(0), T(0), T(0), T(-0.38703730874935176555105901742e3L),
         T(-0.18917813819516756882830838328e3L), T(0.52780815920542364900561016686e3L),
         T(-0.11573902539959630126141871134e2L), T(0.68812326946963000169666922661e1L),
         T(-0.10006050966910838403183860980e1L), T(0.77771377980534432092869265740L),
         T(-0.27782057523535084065932004339e1L), T(-0.60196695231264120758267380846e2L),
         T(0.84320405506677161018159903784e2L), T(0.11992291136182789328035130030e2L)},
        {T(-0.25693933462703749003312586129e2L), T(0), T(0), T(0), T(0), T(-0.15418974869023643374053993627e3L),
         T(-0.23152937917604549567536039109e3L), T(0.35763911791061412378285349910e3L),
         T(0.93405324183624310003907691704e2L), T(-0.37458323136451633156875139351e2L),
         T(0.10409964950896230045147246184e3L), T(0.29840293426660503123344363579e2L),
         T(-0.43533456590011143754432175058e2L), T(0.96324553959188282948394950600e2L),
         T(-0.39177261675615439165231486172e2L), T(-0.14972683625798562581422125276e3L)},
    }};
};

/// The completed interpolant of one step: its start t0, its size h (signed) and the coefficients r of
/// DOPRI5's CONTD5 (5 states), DOP853's CONTD8 (8 states) or the cubic Hermite data y0, f0, y1, f1 (4 states);
/// what odestep::dense_step computes and odestep::solution stores per step.
template <class Method, class State>
struct dense_piece {
    using T = value_type_t<State>;
    static constexpr bool dopri5 = std::is_same_v<Method, tables::dormand_prince54>;
    static constexpr bool dop853 = std::is_same_v<Method, tables::dop853>;
    static constexpr std::size_t N = state_traits<State>::size;

    T t0 = T(0);
    T h = T(0);
    std::array<State, dopri5 ? 5 : dop853 ? 8 : 4> r{};

    /// The interpolated state at t0 + theta h (exactly r[0], the step's start, at theta = 0).
    void at_theta(T theta, State& out) const noexcept {
        const T theta1 = T(1) - theta;
        if constexpr (dopri5) {
            for (std::size_t i = 0; i < N; ++i)
                out[i] = r[0][i] + theta * (r[1][i] + theta1 * (r[2][i] + theta * (r[3][i] + theta1 * r[4][i])));
        } else if constexpr (dop853) {
            for (std::size_t i = 0; i < N; ++i) {
                const T p = r[4][i] + theta * (r[5][i] + theta1 * (r[6][i] + theta * r[7][i]));
                out[i] = r[0][i] + theta * (r[1][i] + theta1 * (r[2][i] + theta * (r[3][i] + theta1 * p)));
            }
        } else {
            hermite_cubic(r[0], r[1], r[2], r[3], h, theta, out);
        }
    }
};

}  // namespace detail

/// \brief The interpolant of one accepted step of odestep::adaptive_rk<Method, State>.
///
/// Dormand-Prince 5(4) gets its continuous extension of order 4 (detail::dopri5_dense: five states kept, no
/// extra evaluation); DOP853 its extension of order 7 (detail::dop853_dense: three more evaluations of f
/// per step interpolated, and f at the step's end, the next step's first stage); every other pair the cubic
/// Hermite interpolant (order 3: four states kept, and f at the step's end, which FSAL tables have already
/// and the others get as the next step's first stage, so it costs an evaluation only at the end of a run).
/// Used as the engine's accept sink: `engine.attempt(f, t, y, t_end, accepted, dense)`, then
/// `dense.complete(f, engine)`, then `dense.at(t, out)` for t in the step.
template <class Method, class State>
class dense_step {
public:
    using state_type = State;                ///< the state
    using value_type = value_type_t<State>;  ///< its scalar T

private:
    using T = value_type;
    using engine_type = adaptive_rk<Method, State>;
    static constexpr bool dopri5 = std::is_same_v<Method, tables::dormand_prince54>;
    static constexpr bool dop853 = std::is_same_v<Method, tables::dop853>;
    static constexpr std::size_t N = state_traits<State>::size;

public:
    /// True for Dormand-Prince 5(4) and DOP853: the pair's own continuous extension; otherwise cubic Hermite.
    static constexpr bool continuous_extension = dopri5 || dop853;
    /// The interpolant's order (its local error is O(h^(order + 1))).
    static constexpr int order = dopri5 ? 4 : dop853 ? 7 : 3;
    /// The most evaluations of f that complete() makes.
    static constexpr std::size_t rhs_evals_to_complete = dopri5 ? 0 : dop853 ? 4 : engine_type::fsal ? 0 : 1;

    /// The completed interpolant (its step and coefficients), valid after complete() returned ok.
    using piece_type = detail::dense_piece<Method, State>;

    /// The accept sink: the step from (t, y) of size h with stages k to y_new.
    template <class Stages>
    void operator()(T t, const State& y, T h, const Stages& k, const State& y_new) noexcept {
        piece_.t0 = t;
        piece_.h = h;
        complete_ = false;
        if constexpr (dopri5) {
            constexpr auto d = detail::dopri5_dense<T>::d;
            for (std::size_t i = 0; i < N; ++i) {
                const T ydiff = y_new[i] - y[i];
                const T bspl = h * k[0][i] - ydiff;
                piece_.r[0][i] = y[i];
                piece_.r[1][i] = ydiff;
                piece_.r[2][i] = bspl;
                piece_.r[3][i] = ydiff - h * k[6][i] - bspl;
                T acc = T(0);
                for (std::size_t j = 0; j < 7; ++j)
                    if (d[j] != T(0)) acc += d[j] * k[j][i];
                piece_.r[4][i] = h * acc;
            }
            complete_ = true;
        } else if constexpr (dop853) {
            detail::assign(piece_.r[0], y);
            detail::assign(piece_.r[1], y_new);
            for (std::size_t j = 0; j < 12; ++j) detail::assign(k_[j], k[j]);
        } else {
            detail::assign(piece_.r[0], y);
            detail::assign(piece_.r[1], k[0]);
            detail::assign(piece_.r[2], y_new);
            if constexpr (engine_type::fsal) {
                detail::assign(piece_.r[3], k[k.size() - 1]);
                complete_ = true;
            }
        }
    }

    /// Makes the interpolant usable: for Hermite without FSAL, f at the step's end (through the engine,
    /// which keeps it as the next step's first stage); for DOP853 that and the three extra stages.
    /// non_finite when f gives NaN or Inf there (the interpolant is then not usable).
    template <class System>
    status complete(System& f, engine_type& engine) {
        if (complete_) return status::ok;
        if constexpr (dop853) {
            using c = detail::dop853_dense<T>;
            std::array<State, 16> k;
            for (std::size_t j = 0; j < 12; ++j) detail::assign(k[j], k_[j]);
            status s = engine.derivative(f, piece_.t0 + piece_.h, piece_.r[1], k[12]);
            if (s != status::ok) return s;
            for (std::size_t e = 0; e < 3; ++e) {
                State input;
                for (std::size_t i = 0; i < N; ++i) {
                    T acc = T(0);
                    for (std::size_t j = 0; j < 13 + e; ++j)
                        if (c::a[e][j] != T(0)) acc += c::a[e][j] * k[j][i];
                    input[i] = piece_.r[0][i] + piece_.h * acc;
                }
                detail::evaluate(f, piece_.t0 + c::c[e] * piece_.h, static_cast<const State&>(input), k[13 + e]);
                if (!detail::all_finite(k[13 + e])) return status::non_finite;
            }
            for (std::size_t i = 0; i < N; ++i) {
                const T ydiff = piece_.r[1][i] - piece_.r[0][i];
                const T bspl = piece_.h * k[0][i] - ydiff;
                piece_.r[1][i] = ydiff;
                piece_.r[2][i] = bspl;
                piece_.r[3][i] = ydiff - piece_.h * k[12][i] - bspl;
                for (std::size_t row = 0; row < 4; ++row) {
                    T acc = T(0);
                    for (std::size_t j = 0; j < 16; ++j)
                        if (c::d[row][j] != T(0)) acc += c::d[row][j] * k[j][i];
                    piece_.r[4 + row][i] = piece_.h * acc;
                }
            }
            complete_ = true;
            return status::ok;
        } else {
            const status s = engine.derivative(f, piece_.t0 + piece_.h, piece_.r[2], piece_.r[3]);
            complete_ = s == status::ok;
            return s;
        }
    }

    /// The step's start time.
    T t_start() const noexcept { return piece_.t0; }
    /// The step's size (signed).
    T step() const noexcept { return piece_.h; }

    /// The interpolated state at t (meant for t inside the step; theta = (t - t_start) / h).
    void at(T t, State& out) const noexcept { at_theta((t - piece_.t0) / piece_.h, out); }

    /// The interpolated state at t_start + theta h.
    void at_theta(T theta, State& out) const noexcept { piece_.at_theta(theta, out); }

    /// The step and its interpolant's coefficients (meaningful after complete() returned ok).
    const piece_type& piece() const noexcept { return piece_; }

private:
    piece_type piece_{};
    bool complete_ = false;
    std::array<State, dop853 ? 12 : 0> k_{};  // DOP853: the step's stages, until complete()
};

}  // namespace odestep

#endif
