// SPDX-License-Identifier: BSL-1.0
// Stiff test problems shared by the implicit and Rosenbrock tests, with their Jacobians and the published
// reference values they are checked against.
#ifndef ODESTEP_TESTS_STIFF_PROBLEMS_HPP
#define ODESTEP_TESTS_STIFF_PROBLEMS_HPP

#include <odestep/odestep.hpp>

#include "order_fit.hpp"
#include "problems.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace odestep_test {

// ---- Robertson's chemical kinetics (Robertson 1966; Hairer & Wanner, Solving ODE II, Sec. IV.1, (1.3)):
//   y1' = -0.04 y1 + 1e4 y2 y3,  y2' = 0.04 y1 - 1e4 y2 y3 - 3e7 y2^2,  y3' = 3e7 y2^2,  y(0) = (1, 0, 0).
// y1 + y2 + y3 = 1 is a linear invariant, which every Runge-Kutta and Rosenbrock method keeps.

struct robertson {
    template <class T>
    void operator()(T, const state3<T>& y, state3<T>& d) const noexcept {
        d[0] = T(-0.04) * y[0] + T(1e4) * y[1] * y[2];
        d[2] = T(3e7) * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
};
struct robertson_jacobian {
    template <class T>
    void operator()(T, const state3<T>& y, odestep::jacobian_t<state3<T>>& j) const noexcept {
        j[0] = {T(-0.04), T(1e4) * y[2], T(1e4) * y[1]};
        j[2] = {T(0), T(6e7) * y[1], T(0)};
        j[1] = {-j[0][0] - j[2][0], -j[0][1] - j[2][1], -j[0][2] - j[2][2]};
    }
};

// Reference values at t = 40, as Hairer & Wanner give them for this problem (Solving ODE II; the same ten
// digits are quoted by every stiff-solver test suite that uses them).
constexpr std::array<double, 3> robertson_at_40{0.7158270687, 9.185534764e-6, 0.2841637457};
// At t = 1e11: the Test Set for IVP Solvers (F. Mazzia and C. Magherini, release 2.4, University of Bari,
// 2008), problem ROBER, computed with RADAU5 in extended precision.
constexpr std::array<double, 3> robertson_at_1e11{0.2083340149701255e-7, 0.8333360770334713e-13, 0.9999999791665050};

// A fixed-step schedule over [0, t_end]: phases whose step grows with t (a fixed-step user's way through the
// initial layer, where y2 rises from 0 to 3.6e-5 within 1e-4 s; at t = 0 the Jacobian does not yet see the
// 3e7 y2^2 term, so a first step of 0.1 from y2 = 0 cannot converge with a Jacobian frozen there). `per_phase`
// steps in each phase [1e-5 10^k, 1e-5 10^(k+1)] after a first phase [0, 1e-5] of `per_phase` steps too.
template <class Stepper, class System, class T>
odestep::integrate_result<T> robertson_schedule(const Stepper& stepper, System&& f, state3<T>& y, T t_end,
                                                std::size_t per_phase, std::size_t* steps = nullptr) {
    T t = T(0);
    T end = T(1e-5);
    odestep::integrate_result<T> r{odestep::status::ok, T(0), 0};
    std::size_t total = 0;
    for (;;) {
        if (end > t_end) end = t_end;
        r = odestep::integrate(stepper, f, y, t, end, (end - t) / static_cast<T>(per_phase));
        total += static_cast<std::size_t>(r.steps);
        if (r.status != odestep::status::ok || end == t_end) break;
        t = end;
        end = end * T(10);
    }
    if (steps != nullptr) *steps = total;
    return r;
}

template <class T>
using state2 = std::array<T, 2>;
template <class T>
using state8 = std::array<T, 8>;

// ---- Van der Pol with mu = 1000, in the form of the Test Set for IVP Solvers (Mazzia & Magherini, release 2.4,
// 2008, problem VDPOL): y1' = y2, y2' = mu (1 - y1^2) y2 - y1, y(0) = (2, 0), t in [0, 2000]; reference solution
// at t = 2000 computed there with RADAU in extended precision.
struct van_der_pol {
    void operator()(double, const state2<double>& y, state2<double>& d) const noexcept {
        d[0] = y[1];
        d[1] = 1e3 * (1 - y[0] * y[0]) * y[1] - y[0];
    }
};
struct van_der_pol_jacobian {
    void operator()(double, const state2<double>& y, odestep::jacobian_t<state2<double>>& j) const noexcept {
        j[0] = {0, 1};
        j[1] = {-2e3 * y[0] * y[1] - 1, 1e3 * (1 - y[0] * y[0])};
    }
};
constexpr std::array<double, 2> van_der_pol_at_2000{0.1706167732170469e1, -0.8928097010248125e-3};

// ---- HIRES (Schafer 1975; Hairer & Wanner, Solving ODE II, Sec. IV.10; the Test Set for IVP Solvers, problem
// HIRES: reference at t = 321.8122 computed with RADAU5 in extended precision).
struct hires {
    void operator()(double, const state8<double>& y, state8<double>& f) const noexcept {
        f[0] = -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007;
        f[1] = 1.71 * y[0] - 8.75 * y[1];
        f[2] = -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4];
        f[3] = 8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3];
        f[4] = -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6];
        f[5] = -280 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4] - 0.43 * y[5] + 0.69 * y[6];
        f[6] = 280 * y[5] * y[7] - 1.81 * y[6];
        f[7] = -f[6];
    }
};
constexpr std::array<double, 8> hires_at_end{0.7371312573325668e-3, 0.1442485726316185e-3, 0.5888729740967575e-4,
                                             0.1175651343283149e-2, 0.2386356198831331e-2, 0.6238968252742796e-2,
                                             0.2849998395185769e-2, 0.2850001604814231e-2};

// The Jacobian of HIRES.
struct hires_jacobian {
    void operator()(double, const state8<double>& y, odestep::jacobian_t<state8<double>>& j) const noexcept {
        j = {};
        j[0][0] = -1.71;
        j[0][1] = 0.43;
        j[0][2] = 8.32;
        j[1][0] = 1.71;
        j[1][1] = -8.75;
        j[2][2] = -10.03;
        j[2][3] = 0.43;
        j[2][4] = 0.035;
        j[3][1] = 8.32;
        j[3][2] = 1.71;
        j[3][3] = -1.12;
        j[4][4] = -1.745;
        j[4][5] = 0.43;
        j[4][6] = 0.43;
        j[5][3] = 0.69;
        j[5][4] = 1.71;
        j[5][5] = -0.43 - 280 * y[7];
        j[5][6] = 0.69;
        j[5][7] = -280 * y[5];
        j[6][5] = 280 * y[7];
        j[6][6] = -1.81;
        j[6][7] = 280 * y[5];
        for (std::size_t c = 0; c < 8; ++c) j[7][c] = -j[6][c];
    }
};
// HIRES's initial state.
constexpr state8<double> hires_start{1, 0, 0, 0, 0, 0, 0, 0.0057};

// ---- OREGO, the Oregonator (Field & Noyes 1974; Hairer & Wanner, Solving ODE II, Sec. IV.1; the Test Set for
// IVP Solvers, problem OREGO): y(0) = (1, 2, 3), t in [0, 360].
struct orego {
    void operator()(double, const state3<double>& y, state3<double>& d) const noexcept {
        d[0] = 77.27 * (y[1] + y[0] * (1 - 8.375e-6 * y[0] - y[1]));
        d[1] = (y[2] - (1 + y[0]) * y[1]) / 77.27;
        d[2] = 0.161 * (y[0] - y[2]);
    }
};
struct orego_jacobian {
    void operator()(double, const state3<double>& y, odestep::jacobian_t<state3<double>>& j) const noexcept {
        j[0] = {77.27 * (1 - 2 * 8.375e-6 * y[0] - y[1]), 77.27 * (1 - y[0]), 0};
        j[1] = {-y[1] / 77.27, -(1 + y[0]) / 77.27, 1 / 77.27};
        j[2] = {0.161, 0, -0.161};
    }
};
// At t = 360: the reference file of Hairer & Wanner's test drivers for OREGO (ore_exact.txt, as distributed
// with the Fortran drivers, e.g. github.com/cpmech/hwode tests/data), the Test Set's values to 13 digits.
constexpr std::array<double, 3> orego_at_360{0.1000814870318523e1, 0.1228178521549889e4, 0.1320554942846513e3};

// ---- RC discharge: Q' = -Q / RC. Backward Euler gives Q_n = Q0 / (1 + h/RC)^n, the trapezoid
// Q0 ((1 - z/2) / (1 + z/2))^n with z = h/RC: the methods' stability functions at -h/RC.
template <class T>
using state1 = std::array<T, 1>;

template <class T>
struct rc_circuit {
    T rc;
    state1<T> operator()(T, const state1<T>& q) const noexcept { return {-q[0] / rc}; }
};
template <class T>
struct rc_jacobian {
    T rc;
    void operator()(T, const state1<T>&, odestep::jacobian_t<state1<T>>& j) const noexcept { j[0][0] = T(-1) / rc; }
};

// ---- The Jacobian of exp_sin (support/problems.hpp): y0' = y0 y1, y1' = -y2, y2' = y1.
struct exp_sin_jacobian {
    template <class T>
    void operator()(T, const state3<T>& y, odestep::jacobian_t<state3<T>>& j) const noexcept {
        j[0] = {y[1], y[0], T(0)};
        j[1] = {T(0), T(0), T(-1)};
        j[2] = {T(0), T(1), T(0)};
    }
};

// ---- Prothero-Robinson (Prothero & Robinson 1974, Math. Comp. 28, 145-162; Hairer & Wanner, Solving ODE II,
// Sec. IV.15): y' = L (y - phi(t)) + phi'(t), y(0) = phi(0), solution y = phi(t) = sin t for every L.
template <class T>
struct prothero_robinson {
    T lambda;
    state1<T> operator()(T t, const state1<T>& y) const noexcept {
        return {lambda * (y[0] - std::sin(t)) + std::cos(t)};
    }
};
template <class T>
struct prothero_robinson_jacobian {
    T lambda;
    void operator()(T, const state1<T>&, odestep::jacobian_t<state1<T>>& j) const noexcept { j[0][0] = lambda; }
};

}  // namespace odestep_test

#endif
