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
template <class T>
using state4 = std::array<T, 4>;

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

// ---- E5, chemical pyrolysis (Enright, Hull & Lindberg 1975, the stiff DETEST; the Test Set for IVP Solvers,
// problem E5): y(0) = (1.76e-3, 0, 0, 0); its components span 1e-3 to 1e-13, so the Test Set measures them with
// atol 1.7e-24. A = 7.89e-10, B = 1.1e7, C = 1.13e3, M = 1e6.
struct e5 {
    void operator()(double, const state4<double>& y, state4<double>& f) const noexcept {
        const double p1 = 7.89e-10 * y[0];
        const double p2 = 1.1e7 * y[0] * y[2];
        const double p3 = 1.13e9 * y[1] * y[2];
        const double p4 = 1.13e3 * y[3];
        f[0] = -p1 - p2;
        f[1] = p1 - p3;
        f[3] = p2 - p4;
        f[2] = f[1] - f[3];
    }
};
struct e5_jacobian {
    void operator()(double, const state4<double>& y, odestep::jacobian_t<state4<double>>& j) const noexcept {
        j[0] = {-7.89e-10 - 1.1e7 * y[2], 0, -1.1e7 * y[0], 0};
        j[1] = {7.89e-10, -1.13e9 * y[2], -1.13e9 * y[1], 0};
        j[3] = {1.1e7 * y[2], 0, 1.1e7 * y[0], -1.13e3};
        for (std::size_t c = 0; c < 4; ++c) j[2][c] = j[1][c] - j[3][c];
    }
};
// At t = 1e5: SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-12, atol=1e-30, exact Jacobian); LSODA at the same
// tolerances agrees to 1.1e-9 relative in every component. The script (its output, pasted):
//   /usr/bin/python3 -c 'from scipy.integrate import solve_ivp; A,B,C,M=7.89e-10,1.1e7,1.13e3,1e6
//   def f(t,y): p1=A*y[0]; p2=B*y[0]*y[2]; p3=M*C*y[1]*y[2]; p4=C*y[3]; return [-p1-p2,p1-p3,p1-p3-p2+p4,p2-p4]
//   def j(t,y): return [[-A-B*y[2],0,-B*y[0],0],[A,-M*C*y[2],-M*C*y[1],0],
//                       [A-B*y[2],-M*C*y[2],-B*y[0]-M*C*y[1],C],[B*y[2],0,B*y[0],-C]]
//   print(list(solve_ivp(f,(0,1e5),[1.76e-3,0,0,0],method="Radau",rtol=1e-12,atol=1e-30,jac=j).y[:,-1]))'
constexpr state4<double> e5_at_1e5{7.481320825285638e-06, 2.3734781575234385e-12, 2.21235866849074e-12,
                                   1.6111948718990638e-13};

// ---- Van der Pol in Hairer & Wanner's scaled form (HW II Sec. IV.10, (10.2), eps = 1e-6):
// y1' = y2, eps y2' = (1 - y1^2) y2 - y1, y(0) = (2, -0.66), t in [0, 2]: a slow manifold broken by jumps.
struct scaled_van_der_pol {
    void operator()(double, const state2<double>& y, state2<double>& d) const noexcept {
        d[0] = y[1];
        d[1] = ((1 - y[0] * y[0]) * y[1] - y[0]) / 1e-6;
    }
};
struct scaled_van_der_pol_jacobian {
    void operator()(double, const state2<double>& y, odestep::jacobian_t<state2<double>>& j) const noexcept {
        j[0] = {0, 1};
        j[1] = {(-2 * y[0] * y[1] - 1) / 1e-6, (1 - y[0] * y[0]) / 1e-6};
    }
};
// At t = 2: SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-12, atol=1e-12, exact Jacobian); LSODA agrees to
// 8.3e-11 relative. The script (its output, pasted):
//   /usr/bin/python3 -c 'from scipy.integrate import solve_ivp; e=1e-6
//   f=lambda t,y: [y[1],((1-y[0]**2)*y[1]-y[0])/e]; j=lambda t,y: [[0,1],[(-2*y[0]*y[1]-1)/e,(1-y[0]**2)/e]]
//   print(list(solve_ivp(f,(0,2),[2,-0.66],method="Radau",rtol=1e-12,atol=1e-12,jac=j).y[:,-1]))'
constexpr state2<double> scaled_van_der_pol_at_2{1.7061674375431222, -0.8928100165511776};

// ---- POLL, the air pollution model of the Dutch RIVM (Verwer 1994, SIAM J. Sci. Comput. 15, 1243-1259; the Test
// Set for IVP Solvers, problem POLL): 20 species, 25 reactions with rates from 1e-3 to 4e11, t in [0, 60].
template <class T>
using state20 = std::array<T, 20>;
struct pollution {
    void operator()(double, const state20<double>& y, state20<double>& d) const noexcept {
        const double r1 = 0.35 * y[0], r2 = 26.6 * y[1] * y[3], r3 = 1.23e4 * y[4] * y[1], r4 = 8.6e-4 * y[6];
        const double r5 = 8.2e-4 * y[6], r6 = 1.5e4 * y[6] * y[5], r7 = 1.3e-4 * y[8], r8 = 2.4e4 * y[8] * y[5];
        const double r9 = 1.65e4 * y[10] * y[1], r10 = 9.0e3 * y[10] * y[0], r11 = 2.2e-2 * y[12];
        const double r12 = 1.2e4 * y[9] * y[1], r13 = 1.88 * y[13], r14 = 1.63e4 * y[0] * y[5];
        const double r15 = 4.8e6 * y[2], r16 = 3.5e-4 * y[3], r17 = 1.75e-2 * y[3], r18 = 1.0e8 * y[15];
        const double r19 = 4.44e11 * y[15], r20 = 1.24e3 * y[16] * y[5], r21 = 2.1 * y[18], r22 = 5.78 * y[18];
        const double r23 = 4.74e-2 * y[0] * y[3], r24 = 1.78e3 * y[18] * y[0], r25 = 3.12 * y[19];
        d[0] = -r1 - r10 - r14 - r23 - r24 + r2 + r3 + r9 + r11 + r12 + r22 + r25;
        d[1] = -r2 - r3 - r9 - r12 + r1 + r21;
        d[2] = -r15 + r1 + r17 + r19 + r22;
        d[3] = -r2 - r16 - r17 - r23 + r15;
        d[4] = -r3 + r4 + r4 + r6 + r7 + r13 + r20;
        d[5] = -r6 - r8 - r14 - r20 + r3 + r18 + r18;
        d[6] = -r4 - r5 - r6 + r13;
        d[7] = r4 + r5 + r6 + r7;
        d[8] = -r7 - r8;
        d[9] = -r12 + r7 + r9;
        d[10] = -r9 - r10 + r8 + r11;
        d[11] = r9;
        d[12] = -r11 + r10;
        d[13] = -r13 + r12;
        d[14] = r14;
        d[15] = -r18 - r19 + r16;
        d[16] = -r20;
        d[17] = r20;
        d[18] = -r21 - r22 - r24 + r23 + r25;
        d[19] = -r25 + r24;
    }
};
// The initial state and the reference at t = 60 (the Test Set's pollu.f, subroutine solut: RADAU5 in true double
// precision on a Cray C90, uround 1.01e-19, rtol = atol = h0 = 1.1e-18).
constexpr state20<double> pollution_start{0, 0.2, 0, 0.04, 0, 0, 0.1, 0.3, 0.01, 0, 0, 0, 0, 0, 0, 0, 0.007, 0, 0, 0};
constexpr state20<double> pollution_at_60{
    0.5646255480022769e-01, 0.1342484130422339e+00, 0.4139734331099427e-08, 0.5523140207484359e-02,
    0.2018977262302196e-06, 0.1464541863493966e-06, 0.7784249118997964e-01, 0.3245075353396018e+00,
    0.7494013383880406e-02, 0.1622293157301561e-07, 0.1135863833257075e-07, 0.2230505975721359e-02,
    0.2087162882798630e-03, 0.1396921016840158e-04, 0.8964884856898295e-02, 0.4352846369330103e-17,
    0.6899219696263405e-02, 0.1007803037365946e-03, 0.1772146513969984e-05, 0.5682943292316392e-04};

}  // namespace odestep_test

#endif
