// SPDX-License-Identifier: BSL-1.0
// The cost of RK4's Phi (not a test: a program for callgrind, outside the suite; docs/sensitivity.md gives the
// figures and the commands). For N = 2, 4, 8, 16, per call, on two systems:
//   - Lorenz-96, f_i = (y_{i+1} - y_{i-2}) y_{i-1} - y_i + 8 (indices mod N): f costs O(N), J has 4 non-zeros
//     per row (written into a dense N x N matrix);
//   - a dense linear system y' = A y: f costs N^2 multiply-adds, J = A.
// Each measured form is one noinline function: the plain step; the step with Phi (rk4_transition) with the
// hand-written Jacobian and with the Jacobian by dual numbers; and Phi by forward differences, N + 1 plain
// steps, (step(y + h e_j) - step(y)) / h. The same four for backward Euler (hand and dual J) on both systems,
// and for Radau IIA 5 and RODAS3 (N = 2, 4, 8),
// and for velocity Verlet (a fresh stepper per step, as the transition takes it) on a chain of n = N/2 unit
// masses joined by springs with a quartic term, a_i = F(x_{i+1} - x_i) - F(x_i - x_{i-1}), F(d) = d + d^3,
// fixed ends (a Fermi-Pasta-Ulam chain).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace {

template <std::size_t N>
struct lorenz96 {
    template <class S>
    std::array<S, N> operator()(double, const std::array<S, N>& y) const {
        std::array<S, N> d{};
        for (std::size_t i = 0; i < N; ++i)
            d[i] = (y[(i + 1) % N] - y[(i + N - 2) % N]) * y[(i + N - 1) % N] - y[i] + 8.0;
        return d;
    }
};
template <std::size_t N>
struct lorenz96_jacobian {
    void operator()(double, const std::array<double, N>& y, odestep::jacobian_t<std::array<double, N>>& j) const {
        for (auto& row : j)
            for (auto& x : row) x = 0.0;
        for (std::size_t i = 0; i < N; ++i) {
            const std::size_t p = (i + 1) % N, m1 = (i + N - 1) % N, m2 = (i + N - 2) % N;
            j[i][p] += y[m1];
            j[i][m2] -= y[m1];
            j[i][m1] += y[p] - y[m2];
            j[i][i] -= 1.0;
        }
    }
};

template <std::size_t N>
struct dense {
    std::array<std::array<double, N>, N> a;
    template <class S>
    std::array<S, N> operator()(double, const std::array<S, N>& y) const {
        std::array<S, N> d{};
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t k = 0; k < N; ++k) d[i] += a[i][k] * y[k];
        return d;
    }
};
template <std::size_t N>
dense<N> make_dense() {
    dense<N> s{};
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t k = 0; k < N; ++k) s.a[i][k] = (i == k ? -2.0 : 0.0) + 0.1 * std::sin(double(i * N + k));
    return s;
}

constexpr double dt = 0.01;

// Table: odestep::tables::rk4 or odestep::tables::dormand_prince54 (its 5th-order step, no estimate).
template <class Table, class F, std::size_t N>
[[gnu::noinline]] void plain(const F& f, std::array<double, N>& y) {
    if (odestep::explicit_rk<Table, std::array<double, N>>{}.step(f, y, 0.0, dt) != odestep::status::ok) y[0] = 0.0;
}
template <class Table, class F, std::size_t N>
[[gnu::noinline]] void phi_hand(F& sys, std::array<double, N>& y, odestep::jacobian_t<std::array<double, N>>& phi) {
    if (odestep::explicit_rk_transition<Table, std::array<double, N>>{}.step(sys, y, phi, 0.0, dt) !=
        odestep::status::ok)
        y[0] = 0.0;
}
template <class Table, class F, std::size_t N>
[[gnu::noinline]] void phi_dual(F& sys, std::array<double, N>& y, odestep::jacobian_t<std::array<double, N>>& phi) {
    if (odestep::explicit_rk_transition<Table, std::array<double, N>>{}.step(sys, y, phi, 0.0, dt) !=
        odestep::status::ok)
        y[0] = 0.0;
}
template <class Table, class F, std::size_t N>
[[gnu::noinline]] void phi_differences(const F& f, std::array<double, N>& y,
                                       odestep::jacobian_t<std::array<double, N>>& phi) {
    const odestep::explicit_rk<Table, std::array<double, N>> rk4;
    std::array<double, N> base = y;
    if (rk4.step(f, base, 0.0, dt) != odestep::status::ok) return;
    for (std::size_t j = 0; j < N; ++j) {
        std::array<double, N> moved = y;
        const double h = std::sqrt(2.2e-16) * (std::fabs(y[j]) + 1.0);
        moved[j] += h;
        if (rk4.step(f, moved, 0.0, dt) != odestep::status::ok) return;
        for (std::size_t i = 0; i < N; ++i) phi[i][j] = (moved[i] - base[i]) / h;
    }
    y = base;
}

constexpr int reps = 1000;

template <class Table, std::size_t N>
double run_lorenz96() {
    lorenz96<N> f;
    auto hand = odestep::with_jacobian(f, lorenz96_jacobian<N>{});
    auto dual = odestep::with_dual_jacobian(f);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 8.0 + 0.01 * double(i);
    odestep::jacobian_t<std::array<double, N>> phi{};
    double sum = 0.0;
    for (int r = 0; r < reps; ++r) {
        std::array<double, N> a = y, b = y, c = y, d = y;
        plain<Table>(f, a);
        phi_hand<Table>(hand, b, phi);
        sum += phi[0][0];
        phi_dual<Table>(dual, c, phi);
        sum += phi[0][0];
        phi_differences<Table>(f, d, phi);
        sum += phi[0][0] + a[0] + b[0] + c[0] + d[0];
    }
    return sum;
}

template <class Table, std::size_t N>
double run_dense() {
    const dense<N> f = make_dense<N>();
    auto hand = odestep::with_jacobian(
        f, [&f](double, const std::array<double, N>&, odestep::jacobian_t<std::array<double, N>>& j) { j = f.a; });
    auto dual = odestep::with_dual_jacobian(f);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 + 0.01 * double(i);
    odestep::jacobian_t<std::array<double, N>> phi{};
    double sum = 0.0;
    for (int r = 0; r < reps; ++r) {
        std::array<double, N> a = y, b = y, c = y, d = y;
        plain<Table>(f, a);
        phi_hand<Table>(hand, b, phi);
        sum += phi[0][0];
        phi_dual<Table>(dual, c, phi);
        sum += phi[0][0];
        phi_differences<Table>(f, d, phi);
        sum += phi[0][0] + a[0] + b[0] + c[0] + d[0];
    }
    return sum;
}

// ---- the implicit steppers and RODAS3: backward Euler, Radau IIA 5, RODAS3 (a kind names the plain stepper and
// its transition)

struct be_kind {
    template <std::size_t N>
    using plain = odestep::backward_euler<std::array<double, N>>;
    template <std::size_t N>
    using transition = odestep::backward_euler_transition<std::array<double, N>>;
};
struct radau_kind {
    template <std::size_t N>
    using plain = odestep::radau_iia5<std::array<double, N>>;
    template <std::size_t N>
    using transition = odestep::radau_iia5_transition<std::array<double, N>>;
};
struct rodas3_kind {
    template <std::size_t N>
    using plain = odestep::rodas3<std::array<double, N>>;
    template <std::size_t N>
    using transition = odestep::rodas3_transition<std::array<double, N>>;
};

template <class Kind, class F, std::size_t N>
[[gnu::noinline]] void stiff_plain(F& sys, std::array<double, N>& y) {
    if (typename Kind::template plain<N>{}.step(sys, y, 0.0, dt) != odestep::status::ok) y[0] = 0.0;
}
template <class Kind, class F, std::size_t N>
[[gnu::noinline]] void stiff_phi_hand(F& sys, std::array<double, N>& y,
                                      odestep::jacobian_t<std::array<double, N>>& phi) {
    if (typename Kind::template transition<N>{}.step(sys, y, phi, 0.0, dt) != odestep::status::ok) y[0] = 0.0;
}
template <class Kind, class F, std::size_t N>
[[gnu::noinline]] void stiff_phi_dual(F& sys, std::array<double, N>& y,
                                      odestep::jacobian_t<std::array<double, N>>& phi) {
    if (typename Kind::template transition<N>{}.step(sys, y, phi, 0.0, dt) != odestep::status::ok) y[0] = 0.0;
}
template <class Kind, class F, std::size_t N>
[[gnu::noinline]] void stiff_phi_differences(F& sys, std::array<double, N>& y,
                                             odestep::jacobian_t<std::array<double, N>>& phi) {
    const typename Kind::template plain<N> stepper;
    std::array<double, N> base = y;
    if (stepper.step(sys, base, 0.0, dt) != odestep::status::ok) return;
    for (std::size_t j = 0; j < N; ++j) {
        std::array<double, N> moved = y;
        const double h = std::sqrt(2.2e-16) * (std::fabs(y[j]) + 1.0);
        moved[j] += h;
        if (stepper.step(sys, moved, 0.0, dt) != odestep::status::ok) return;
        for (std::size_t i = 0; i < N; ++i) phi[i][j] = (moved[i] - base[i]) / h;
    }
    y = base;
}

template <class Kind, class H, class D, std::size_t N>
double run_stiff(H& hand, D& dual, const std::array<double, N>& y) {
    odestep::jacobian_t<std::array<double, N>> phi{};
    double sum = 0.0;
    for (int r = 0; r < reps; ++r) {
        std::array<double, N> a = y, b = y, c = y, d = y;
        stiff_plain<Kind>(hand, a);  // the plain step with the hand Jacobian (as an implicit stepper is used)
        stiff_phi_hand<Kind>(hand, b, phi);
        sum += phi[0][0];
        stiff_phi_dual<Kind>(dual, c, phi);
        sum += phi[0][0];
        stiff_phi_differences<Kind>(hand, d, phi);
        sum += phi[0][0] + a[0] + b[0] + c[0] + d[0];
    }
    return sum;
}

// ---- velocity Verlet on the chain

template <std::size_t n>
struct chain {
    template <class S>
    std::array<S, n> operator()(double, const std::array<S, n>& x) const {
        std::array<S, n> a{};
        for (std::size_t i = 0; i < n; ++i) {
            const S left = i > 0 ? x[i] - x[i - 1] : x[i];
            const S right = i + 1 < n ? x[i + 1] - x[i] : -x[i];
            a[i] = right + right * right * right - left - left * left * left;
        }
        return a;
    }
};
template <std::size_t n>
struct chain_jacobian {
    void operator()(double, const std::array<double, n>& x, odestep::jacobian_t<std::array<double, n>>& j) const {
        for (auto& row : j)
            for (auto& e : row) e = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double left = i > 0 ? x[i] - x[i - 1] : x[i];
            const double right = i + 1 < n ? x[i + 1] - x[i] : -x[i];
            const double kl = 1 + 3 * left * left;
            const double kr = 1 + 3 * right * right;
            j[i][i] = -kl - kr;
            if (i > 0) j[i][i - 1] = kl;
            if (i + 1 < n) j[i][i + 1] = kr;
        }
    }
};

template <class A, std::size_t n>
[[gnu::noinline]] void vv_plain(A& a, std::array<double, n>& x, std::array<double, n>& v) {
    odestep::velocity_verlet<std::array<double, n>> s;  // fresh: both kicks evaluated
    if (s.step(a, x, v, 0.0, dt) != odestep::status::ok) x[0] = 0.0;
}
template <class A, std::size_t n>
[[gnu::noinline]] void vv_phi_hand(A& a, std::array<double, n>& x, std::array<double, n>& v,
                                   odestep::phase_matrix_t<std::array<double, n>>& phi) {
    if (odestep::velocity_verlet_transition<std::array<double, n>>{}.step(a, x, v, phi, 0.0, dt) != odestep::status::ok)
        x[0] = 0.0;
}
template <class A, std::size_t n>
[[gnu::noinline]] void vv_phi_dual(A& a, std::array<double, n>& x, std::array<double, n>& v,
                                   odestep::phase_matrix_t<std::array<double, n>>& phi) {
    if (odestep::velocity_verlet_transition<std::array<double, n>>{}.step(a, x, v, phi, 0.0, dt) != odestep::status::ok)
        x[0] = 0.0;
}
template <class A, std::size_t n>
[[gnu::noinline]] void vv_phi_differences(A& a, std::array<double, n>& x, std::array<double, n>& v,
                                          odestep::phase_matrix_t<std::array<double, n>>& phi) {
    std::array<double, n> bx = x, bv = v;
    odestep::velocity_verlet<std::array<double, n>> s0;
    if (s0.step(a, bx, bv, 0.0, dt) != odestep::status::ok) return;
    for (std::size_t j = 0; j < 2 * n; ++j) {
        std::array<double, n> mx = x, mv = v;
        double& e = j < n ? mx[j] : mv[j - n];
        const double h = std::sqrt(2.2e-16) * (std::fabs(e) + 1.0);
        e += h;
        odestep::velocity_verlet<std::array<double, n>> s;
        if (s.step(a, mx, mv, 0.0, dt) != odestep::status::ok) return;
        for (std::size_t i = 0; i < n; ++i) {
            phi[i][j] = (mx[i] - bx[i]) / h;
            phi[n + i][j] = (mv[i] - bv[i]) / h;
        }
    }
    x = bx;
    v = bv;
}

template <std::size_t n>
double run_chain() {
    chain<n> a;
    auto hand = odestep::with_jacobian(a, chain_jacobian<n>{});
    auto dual = odestep::with_dual_jacobian(a);
    std::array<double, n> x0{};
    std::array<double, n> v0{};
    for (std::size_t i = 0; i < n; ++i) x0[i] = 0.1 * std::sin(double(i + 1));
    odestep::phase_matrix_t<std::array<double, n>> phi{};
    double sum = 0.0;
    for (int r = 0; r < reps; ++r) {
        std::array<double, n> x1 = x0, x2 = x0, x3 = x0, x4 = x0, v1 = v0, v2 = v0, v3 = v0, v4 = v0;
        vv_plain(a, x1, v1);
        vv_phi_hand(hand, x2, v2, phi);
        sum += phi[0][0];
        vv_phi_dual(dual, x3, v3, phi);
        sum += phi[0][0];
        vv_phi_differences(a, x4, v4, phi);
        sum += phi[0][0] + x1[0] + x2[0] + x3[0] + x4[0];
    }
    return sum;
}

template <class Kind, std::size_t N>
double run_stiff_lorenz96() {
    lorenz96<N> f;
    auto hand = odestep::with_jacobian(f, lorenz96_jacobian<N>{});
    auto dual = odestep::with_dual_jacobian(f);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 8.0 + 0.01 * double(i);
    return run_stiff<Kind>(hand, dual, y);
}
template <class Kind, std::size_t N>
double run_stiff_dense() {
    const dense<N> f = make_dense<N>();
    auto hand = odestep::with_jacobian(
        f, [&f](double, const std::array<double, N>&, odestep::jacobian_t<std::array<double, N>>& j) { j = f.a; });
    auto dual = odestep::with_dual_jacobian(f);
    std::array<double, N> y{};
    for (std::size_t i = 0; i < N; ++i) y[i] = 1.0 + 0.01 * double(i);
    return run_stiff<Kind>(hand, dual, y);
}

}  // namespace

template <class Table>
double run_explicit() {
    return run_lorenz96<Table, 2>() + run_lorenz96<Table, 4>() + run_lorenz96<Table, 8>() + run_lorenz96<Table, 16>() +
           run_dense<Table, 2>() + run_dense<Table, 4>() + run_dense<Table, 8>() + run_dense<Table, 16>();
}

// -DSENS_EXPLICIT_ONLY: only RK4, DP 5(4) and velocity Verlet (a quicker run).
int main() {
    double s = run_explicit<odestep::tables::rk4>() + run_explicit<odestep::tables::dormand_prince54>() +
               run_chain<1>() + run_chain<2>() + run_chain<4>() + run_chain<8>();
#ifndef SENS_EXPLICIT_ONLY

    s += run_stiff_lorenz96<be_kind, 2>() + run_stiff_lorenz96<be_kind, 4>() + run_stiff_lorenz96<be_kind, 8>() +
         run_stiff_lorenz96<be_kind, 16>() + run_stiff_dense<be_kind, 2>() + run_stiff_dense<be_kind, 4>() +
         run_stiff_dense<be_kind, 8>() + run_stiff_dense<be_kind, 16>();
    s += run_stiff_lorenz96<radau_kind, 2>() + run_stiff_lorenz96<radau_kind, 4>() +
         run_stiff_lorenz96<radau_kind, 8>() + run_stiff_dense<radau_kind, 2>() + run_stiff_dense<radau_kind, 4>() +
         run_stiff_dense<radau_kind, 8>();
    s += run_stiff_lorenz96<rodas3_kind, 2>() + run_stiff_lorenz96<rodas3_kind, 4>() +
         run_stiff_lorenz96<rodas3_kind, 8>() + run_stiff_dense<rodas3_kind, 2>() + run_stiff_dense<rodas3_kind, 4>() +
         run_stiff_dense<rodas3_kind, 8>();
#endif
    std::printf("%g\n", s);
    return 0;
}
