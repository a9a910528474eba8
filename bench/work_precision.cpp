// SPDX-License-Identifier: BSL-1.0
// Work-precision of the adaptive solvers (issue 15): Arenstorf, Lorenz and the Pleiades, each integrated at
// rtol = atol = tol for tol = 1e-3 .. 1e-12 (half decades) by
//   odestep     adaptive_rk + integrate_adaptive, Dormand-Prince 5(4) and DOP853;
//   Odeint      make_controlled(tol, tol, runge_kutta_dopri5) with integrate_adaptive, and
//               make_dense_output(tol, tol, runge_kutta_dopri5) with integrate_adaptive;
//   GSL         gsl_odeiv2_driver (alloc_y_new: rtol = atol = tol on y), rkf45 and rk8pd;
//   ARKODE      ARKStep in explicit mode (bench/sundials.hpp, arkode_erk), the built-in tables
//               ARKODE_DORMAND_PRINCE_7_4_5, ARKODE_VERNER_8_5_6 and ARKODE_FEHLBERG_13_7_8, everything else
//               ARKODE's default; optional (BENCH_NO_SUNDIALS, or SUNDIALS not installed: no ARKODE rows).
// Recorded per run: the error at the end (the largest absolute difference over the components from the
// reference), the evaluations of f (every solver calls the same counting right-hand side, so the first-step
// estimates are counted too; deterministic, and asserted equal over the repeated runs, as is the final state
// bit for bit) and the thread's CPU time of the whole run (bench/cpu_time.hpp), median and minimum over
// `rounds` runs, the solvers interleaved round by round with the order rotated.
//
// Odeint and GSL take the first step from the caller: both get the one odestep's estimate (HNW I, Sec. II.4;
// odestep::initial_step with the method's order) would choose, computed outside the count. odestep and
// ARKODE estimate it themselves, inside the count.
//
// The references, each computed in long double by odestep's DOP853 at tolerance 1e-18 and checked against
// RKF 7(8) at the same tolerance (the two must agree far below the smallest error measured):
//   Arenstorf  HNW I, Sec. II.0, eq. (0.1): mu = 0.012277471, y(0) = (0.994, 0, 0,
//              -2.00158510637908252240537862224), one period T = 17.0652165601579625588917206249: also
//              compared with y(0) (exact periodicity up to the rounding of y(0) and T to double);
//   Lorenz     sigma = 10, rho = 28, beta = 8/3, y(0) = (-8, 8, 27) (HNW I, Sec. I.16), t in [0, 10];
//   Pleiades   HNW I, Sec. II.10 (the problem PLEI of the Bari test set, Mazzia & Magherini, "Test Set for
//              IVP Solvers", release 2.4, plei.pdf), seven bodies with masses 1 .. 7, t in [0, 3]: also
//              compared with the test set's published reference y(3) (16 digits).
//
// Usage: work_precision [csv [rounds]]   (default: work_precision.csv, 11 rounds). Prints the reference
// checks and the markdown tables of bench/RESULTS.md, "Work-precision (adaptive)".
#include <boost/numeric/odeint/integrate/integrate_adaptive.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <odestep/adaptive.hpp>

#include "cpu_time.hpp"
#include "problems.hpp"
#include "sundials.hpp"

namespace {

namespace oi = boost::numeric::odeint;

long g_evals = 0;  // every evaluation of f by any solver
// The run's accepted and rejected steps, where the solver tells them (-1: it does not; Odeint counts its
// accepted steps only).
long g_accepted = -1, g_rejected = -1;

// --- the problems -------------------------------------------------------------------------------------------

struct arenstorf {
    static constexpr const char* name = "arenstorf";
    static constexpr std::size_t N = 4;
    static constexpr long double mu = 0.012277471L;
    static constexpr long double period = 17.0652165601579625588917206249L;
    static constexpr double t1 = static_cast<double>(period);
    template <class T, class In, class Out>
    static void f(const In& y, Out& d) {
        using std::sqrt;
        const T m = T(mu), m1 = T(1) - T(mu);
        const T a = (y[0] + m) * (y[0] + m) + y[1] * y[1];
        const T b = (y[0] - m1) * (y[0] - m1) + y[1] * y[1];
        const T ra = a * sqrt(a), rb = b * sqrt(b);
        d[0] = y[2];
        d[1] = y[3];
        d[2] = y[0] + T(2) * y[3] - m1 * (y[0] + m) / ra - m * (y[0] - m1) / rb;
        d[3] = y[1] - T(2) * y[2] - m1 * y[1] / ra - m * y[1] / rb;
    }
    static std::array<double, N> y0() { return {0.994, 0.0, 0.0, -2.00158510637908252240537862224}; }
};

struct lorenz {
    static constexpr const char* name = "lorenz";
    static constexpr std::size_t N = 3;
    static constexpr double t1 = 10.0;
    template <class T, class In, class Out>
    static void f(const In& y, Out& d) {
        bench::lorenz<T>(y, d);
    }
    static std::array<double, N> y0() { return {-8.0, 8.0, 27.0}; }
};

struct pleiades {
    static constexpr const char* name = "pleiades";
    static constexpr std::size_t N = 28;
    static constexpr double t1 = 3.0;
    // y = (x_1..x_7, y_1..y_7, x'_1..x'_7, y'_1..y'_7), body i of mass i, G = 1.
    template <class T, class In, class Out>
    static void f(const In& y, Out& d) {
        using std::sqrt;
        for (int i = 0; i < 14; ++i) d[i] = y[i + 14];
        for (int i = 14; i < 28; ++i) d[i] = T(0);
        for (int i = 0; i < 7; ++i)
            for (int j = i + 1; j < 7; ++j) {
                const T dx = y[j] - y[i], dy = y[j + 7] - y[i + 7];
                const T r2 = dx * dx + dy * dy;
                const T s = T(1) / (r2 * sqrt(r2));
                const T mi = T(i + 1), mj = T(j + 1);
                d[14 + i] += mj * dx * s;
                d[21 + i] += mj * dy * s;
                d[14 + j] -= mi * dx * s;
                d[21 + j] -= mi * dy * s;
            }
    }
    static std::array<double, N> y0() {
        return {3, 3, -1, -3, 2, -2, 2, 3, -3, 2, 0, 0, -4, 4, 0, 0, 0, 0, 0, 1.75, -1.5, 0, 0, 0, -1.25, 1, 0, 0};
    }
    // The test set's reference y(3) (Mazzia & Magherini, plei.pdf, 16 digits).
    static std::array<double, N> published() {
        return {0.3706139143970502,  3.237284092057233,   -3.222559032418324,  0.6597091455775310, 0.3425581707156584,
                1.562172101400631,   -0.7003092922212495, -3.943437585517392,  -3.271380973972550, 5.225081843456543,
                -2.590612434977470,  1.198213693392275,   -0.2429682344935824, 1.091449240428980,  3.417003806314313,
                1.354584501625501,   -2.590065597810775,  2.025053734714242,   -1.155815100160448, -0.8072988170223021,
                0.5952396354208710,  -3.741244961234010,  0.3773459685750630,  0.9386858869551073, 0.3667922227200571,
                -0.3474046353808490, 2.344915448180937,   -1.947020434263292};
    }
};

/// max_i |a_i - b_i|, in long double (a reference's digits are not lost); infinite when not finite.
template <class A, class B>
double max_abs_diff(const A& a, const B& b) {
    long double m = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        m = std::max(m, std::fabs(static_cast<long double>(a[i]) - static_cast<long double>(b[i])));
    return m == m ? static_cast<double>(m) : HUGE_VAL;
}

/// y(t1) in long double by odestep's adaptive `Method` at rtol = atol = 1e-18.
template <class P, class Method>
std::array<long double, P::N> long_double_solution() {
    using L = std::array<long double, P::N>;
    L y{};
    const auto y0 = P::y0();
    for (std::size_t i = 0; i < P::N; ++i) y[i] = y0[i];
    odestep::adaptive_rk<Method, L> engine(odestep::tolerances<L>::uniform(1e-18L, 1e-18L));
    const auto r = odestep::integrate_adaptive(
        engine, [](long double, const L& x, L& d) { P::template f<long double>(x, d); }, y, 0.0L,
        static_cast<long double>(P::t1), 10000000);
    if (r.status != odestep::status::ok) {
        std::fprintf(stderr, "work_precision: the %s reference failed\n", P::name);
        std::exit(2);
    }
    return y;
}

// --- the solvers ---------------------------------------------------------------------------------------------

template <class P>
using state_t = std::array<double, P::N>;

template <class P>
struct solver {
    std::string key;
    std::function<void(state_t<P>&)> run;  // y: y(0) in, y(t1) out; counts through g_evals
};

template <class P>
void rhs(double, const state_t<P>& y, state_t<P>& d) {
    ++g_evals;
    P::template f<double>(y, d);
}
template <class P>
void odeint_rhs(const state_t<P>& y, state_t<P>& d, double) {
    ++g_evals;
    P::template f<double>(y, d);
}
template <class P>
int gsl_rhs(double, const double y[], double d[], void*) {
    ++g_evals;
    P::template f<double>(y, d);
    return GSL_SUCCESS;
}
#ifdef BENCH_HAVE_SUNDIALS
template <class P>
int arkode_rhs(double, N_Vector y, N_Vector d, void*) {
    ++g_evals;
    double* out = N_VGetArrayPointer(d);
    P::template f<double>(static_cast<const double*>(N_VGetArrayPointer(y)), out);
    return 0;
}
#endif

/// The first step odestep's estimate gives a method of order p at this tolerance (not counted).
template <class P>
double first_step(double tol, int p) {
    using S = state_t<P>;
    const auto f = [](double, const S& y, S& d) { P::template f<double>(y, d); };
    const S y0 = P::y0();
    S f0;
    f(0.0, y0, f0);
    return odestep::initial_step(f, 0.0, y0, f0, p, odestep::tolerances<S>::uniform(tol, tol), P::t1, 1.0);
}

template <class Method, class P>
solver<P> odestep_solver(const char* key, double tol) {
    return {key, [tol](state_t<P>& y) {
                odestep::adaptive_rk<Method, state_t<P>> engine(odestep::tolerances<state_t<P>>::uniform(tol, tol));
                const auto r = odestep::integrate_adaptive(engine, rhs<P>, y, 0.0, P::t1, 10000000);
                if (r.status != odestep::status::ok) {
                    std::fprintf(stderr, "work_precision: %s odestep failed\n", P::name);
                    std::exit(1);
                }
                g_accepted = static_cast<long>(engine.accepted_steps());
                g_rejected = static_cast<long>(engine.rejected_steps());
            }};
}

struct gsl_driver {
    gsl_odeiv2_system sys;
    gsl_odeiv2_driver* d = nullptr;
    double h0 = 0;
    ~gsl_driver() {
        if (d != nullptr) gsl_odeiv2_driver_free(d);
    }
};

template <class P>
solver<P> gsl_solver(const char* key, const gsl_odeiv2_step_type* type, double tol, int p) {
    auto g = std::make_shared<gsl_driver>();
    g->sys = gsl_odeiv2_system{gsl_rhs<P>, nullptr, P::N, nullptr};
    g->h0 = first_step<P>(tol, p);
    g->d = gsl_odeiv2_driver_alloc_y_new(&g->sys, type, g->h0, tol, tol);
    return {key, [g](state_t<P>& y) {
                gsl_odeiv2_driver_reset_hstart(g->d, g->h0);
                gsl_odeiv2_driver_reset(g->d);
                double t = 0.0;
                if (gsl_odeiv2_driver_apply(g->d, &t, P::t1, y.data()) != GSL_SUCCESS || t != P::t1) {
                    std::fprintf(stderr, "work_precision: %s GSL failed\n", P::name);
                    std::exit(1);
                }
                g_accepted = static_cast<long>(g->d->e->count - g->d->e->failed_steps);
                g_rejected = static_cast<long>(g->d->e->failed_steps);
            }};
}

template <class P>
std::vector<solver<P>> solvers(double tol) {
    using S = state_t<P>;
    std::vector<solver<P>> v;
    v.push_back(odestep_solver<odestep::tables::dormand_prince54, P>("odestep_dp54", tol));
    v.push_back(odestep_solver<odestep::tables::dop853, P>("odestep_dop853", tol));
    const double h5 = first_step<P>(tol, 4);  // odestep's DP 5(4): the estimate's order is 5
    v.push_back({"odeint_dopri5", [tol, h5](S& y) {
                     auto st = oi::make_controlled(tol, tol, oi::runge_kutta_dopri5<S>());
                     g_accepted = static_cast<long>(oi::integrate_adaptive(st, odeint_rhs<P>, y, 0.0, P::t1, h5));
                 }});
    v.push_back({"odeint_dopri5_dense", [tol, h5](S& y) {
                     auto st = oi::make_dense_output(tol, tol, oi::runge_kutta_dopri5<S>());
                     g_accepted = static_cast<long>(oi::integrate_adaptive(st, odeint_rhs<P>, y, 0.0, P::t1, h5));
                 }});
    v.push_back(gsl_solver<P>("gsl_rkf45", gsl_odeiv2_step_rkf45, tol, 4));
    v.push_back(gsl_solver<P>("gsl_rk8pd", gsl_odeiv2_step_rk8pd, tol, 7));
#ifdef BENCH_HAVE_SUNDIALS
    const std::pair<const char*, ARKODE_ERKTableID> tables[] = {{"arkode_dp45", ARKODE_DORMAND_PRINCE_7_4_5},
                                                                {"arkode_verner65", ARKODE_VERNER_8_5_6},
                                                                {"arkode_fehlberg78", ARKODE_FEHLBERG_13_7_8}};
    for (const auto& [key, id] : tables) {
        auto a = std::make_shared<bench::arkode_erk>(arkode_rhs<P>, P::N, id);
        a->set_tolerance(tol);
        v.push_back({key, [a](S& y) {
                         if (a->integrate(y.data(), 0.0, P::t1) < 0) {
                             std::fprintf(stderr, "work_precision: %s ARKODE failed\n", P::name);
                             std::exit(1);
                         }
                         a->steps(g_accepted, g_rejected);
                     }});
    }
#endif
    return v;
}

// --- measuring -----------------------------------------------------------------------------------------------

struct point {
    std::string problem, solver;
    double tol, error;
    long evals, accepted, rejected;
    double cpu_us, cpu_min_us;
};

template <class P>
void measure(const state_t<P>& ref, int rounds, std::vector<point>& out) {
    for (int e = 0; e <= 18; ++e) {
        const double tol = std::pow(10.0, -3.0 - 0.5 * e);
        auto vs = solvers<P>(tol);
        const std::size_t V = vs.size();
        std::vector<long> evals(V), accepted(V), rejected(V);
        std::vector<state_t<P>> end(V);
        std::vector<std::vector<double>> cpu(V);
        for (std::size_t k = 0; k < V; ++k) {  // the first run: evaluations and the final state
            state_t<P> y = P::y0();
            const long before = g_evals;
            g_accepted = g_rejected = -1;
            vs[k].run(y);
            evals[k] = g_evals - before;
            accepted[k] = g_accepted;
            rejected[k] = g_rejected;
            end[k] = y;
        }
        for (int r = 0; r < rounds; ++r)
            for (std::size_t j = 0; j < V; ++j) {
                const std::size_t k = (j + static_cast<std::size_t>(r)) % V;
                state_t<P> y = P::y0();
                const long before = g_evals;
                const double c0 = bench::clock_ns(CLOCK_THREAD_CPUTIME_ID);
                vs[k].run(y);
                const double c1 = bench::clock_ns(CLOCK_THREAD_CPUTIME_ID);
                if (g_evals - before != evals[k] || std::memcmp(y.data(), end[k].data(), sizeof y) != 0) {
                    std::fprintf(stderr, "work_precision: %s %s tol %.1e: a repeated run differs\n", P::name,
                                 vs[k].key.c_str(), tol);
                    std::exit(1);
                }
                cpu[k].push_back((c1 - c0) / 1e3);
            }
        for (std::size_t k = 0; k < V; ++k)
            out.push_back({P::name, vs[k].key, tol, max_abs_diff(end[k], ref), evals[k], accepted[k], rejected[k],
                           bench::median(cpu[k]), *std::min_element(cpu[k].begin(), cpu[k].end())});
    }
}

/// The reference y(t1), and how far it can be off: the difference of the two long double solutions (DOP853
/// and RKF 7(8)). Exits when a check fails: the two solutions apart by more than 1e-11; Arenstorf's y(t1) more
/// than 1e-9 from y(0) (the orbit's period, up to y(0) and T rounded to double: 1.4e-11 measured); the
/// Pleiades' y(3) more than 1e-13 from the test set's published one (rounded to 16 digits: 1e-15 measured).
template <class P>
state_t<P> reference(double& uncertainty) {
    const auto a = long_double_solution<P, odestep::tables::dop853>();
    const auto b = long_double_solution<P, odestep::tables::fehlberg78>();
    state_t<P> ref{};
    for (std::size_t i = 0; i < P::N; ++i) ref[i] = static_cast<double>(a[i]);
    uncertainty = max_abs_diff(a, b);
    bool ok = uncertainty <= 1e-11;
    std::printf("REFERENCE\t%s\tt1=%.17g\tdop853_vs_rkf78=%.2e", P::name, P::t1, uncertainty);
    if constexpr (std::is_same_v<P, arenstorf>) {
        const double d = max_abs_diff(a, P::y0());
        ok = ok && d <= 1e-9;
        std::printf("\tvs_y0=%.2e", d);
    }
    if constexpr (std::is_same_v<P, pleiades>) {
        const double d = max_abs_diff(a, P::published());
        ok = ok && d <= 1e-13;
        std::printf("\tvs_published=%.2e", d);
    }
    std::printf("\n");
    if (!ok) {
        std::fprintf(stderr, "work_precision: the %s reference fails its check\n", P::name);
        std::exit(1);
    }
    return ref;
}

/// Measures P; exits when a run's error is within 100 times the reference's uncertainty (the reference would
/// then not be far enough below the errors it measures).
template <class P>
void problem(int rounds, std::vector<point>& all) {
    double uncertainty = 0;
    const auto ref = reference<P>(uncertainty);
    const std::size_t first = all.size();
    measure<P>(ref, rounds, all);
    for (std::size_t i = first; i < all.size(); ++i)
        if (!(all[i].error >= 100 * uncertainty)) {
            std::fprintf(stderr, "work_precision: %s %s tol %.1e: error %.2e too close to the reference's %.2e\n",
                         P::name, all[i].solver.c_str(), all[i].tol, all[i].error, uncertainty);
            std::exit(1);
        }
}

// --- the tables ----------------------------------------------------------------------------------------------

/// The evaluations and the CPU time a solver needs for error e: interpolated log-log between the two
/// tolerances around the last one at which its error falls through e, so that every tighter tolerance reaches
/// e too (on a curve that is not monotone, the first such tolerance would flatter it). NaN when its tightest
/// run does not reach e, or its loosest is already below it.
struct matched {
    double evals = std::nan(""), cpu_us = std::nan("");
};
matched at_error(const std::vector<const point*>& pts, double e) {
    if (pts.size() < 2 || !(pts.back()->error <= e)) return {};
    for (std::size_t k = pts.size() - 1; k >= 1; --k) {
        const point& a = *pts[k - 1];
        const point& b = *pts[k];
        if (!(a.error > e)) continue;
        const double w = std::log(e / a.error) / std::log(b.error / a.error);
        const auto lerp = [w](double x, double y) { return std::exp(std::log(x) + w * (std::log(y) - std::log(x))); };
        return {lerp(static_cast<double>(a.evals), static_cast<double>(b.evals)), lerp(a.cpu_us, b.cpu_us)};
    }
    return {};
}

void tables(const std::vector<point>& all, const char* problem, const char* what, const std::vector<double>& errors) {
    std::vector<std::string> keys;
    for (const auto& p : all)
        if (p.problem == problem && std::find(keys.begin(), keys.end(), p.solver) == keys.end())
            keys.push_back(p.solver);
    std::printf("\n### %s\n\n%s. Evaluations of f and CPU microseconds (median) at the error shown:\n\n", problem,
                what);
    std::printf("| solver |");
    for (double e : errors) std::printf(" evals at %.0e | us at %.0e |", e, e);
    std::printf("\n|---|");
    for (std::size_t i = 0; i < errors.size(); ++i) std::printf("--:|--:|");
    std::printf("\n");
    std::vector<std::vector<matched>> m(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        std::vector<const point*> pts;
        for (const auto& p : all)
            if (p.problem == problem && p.solver == keys[k]) pts.push_back(&p);
        std::printf("| %s |", keys[k].c_str());
        for (double e : errors) {
            m[k].push_back(at_error(pts, e));
            const matched& x = m[k].back();
            if (x.evals == x.evals)
                std::printf(" %.0f | %.1f |", x.evals, x.cpu_us);
            else
                std::printf(" - | - |");
        }
        std::printf("\n");
    }
    // The target: odestep's better pair against every other solver; then each of odestep's pairs against
    // the peers of its order. Each ratio: the smallest of the first group over the smallest of the second.
    using pick = std::function<bool(const std::string&)>;
    const auto ratios = [&](const pick& is_mine, const pick& is_peer) {
        std::vector<std::pair<double, double>> r;
        for (std::size_t i = 0; i < errors.size(); ++i) {
            double mine_e = HUGE_VAL, mine_t = HUGE_VAL, peer_e = HUGE_VAL, peer_t = HUGE_VAL;
            for (std::size_t k = 0; k < keys.size(); ++k) {
                const matched& x = m[k][i];
                if (!(x.evals == x.evals)) continue;
                if (is_mine(keys[k])) {
                    mine_e = std::min(mine_e, x.evals);
                    mine_t = std::min(mine_t, x.cpu_us);
                } else if (is_peer(keys[k])) {
                    peer_e = std::min(peer_e, x.evals);
                    peer_t = std::min(peer_t, x.cpu_us);
                }
            }
            if (mine_e == HUGE_VAL || peer_e == HUGE_VAL)
                r.emplace_back(std::nan(""), std::nan(""));
            else
                r.emplace_back(mine_e / peer_e, mine_t / peer_t);
        }
        return r;
    };
    const auto row = [&](const char* label, const std::vector<std::pair<double, double>>& r) {
        std::printf("| %s |", label);
        for (const auto& [e, t] : r) {
            if (e == e)
                std::printf(" %.2f | %.2f |", e, t);
            else
                std::printf(" - | - |");
        }
        std::printf("\n");
    };
    const auto named = [](std::vector<std::string> names) -> pick {
        return [names](const std::string& k) { return std::find(names.begin(), names.end(), k) != names.end(); };
    };
    const pick mine = [](const std::string& k) { return k.rfind("odestep", 0) == 0; };
    const pick others = [](const std::string& k) { return k.rfind("odestep", 0) != 0; };
    const auto target = ratios(mine, others);
    row("**odestep (better pair) / best other**", target);
    row("odestep DP 5(4) / best order-5 peer",
        ratios(named({"odestep_dp54"}), named({"odeint_dopri5", "odeint_dopri5_dense", "gsl_rkf45", "arkode_dp45"})));
    row("odestep DOP853 / best order-8 peer",
        ratios(named({"odestep_dop853"}), named({"gsl_rk8pd", "arkode_fehlberg78"})));
    std::printf("\nTarget (odestep's better pair: evaluations <= and time < the best other's):");
    for (std::size_t i = 0; i < errors.size(); ++i) {
        const auto [e, t] = target[i];
        std::printf("%s at %.0e evaluations %s, time %s", i ? ";" : "", errors[i],
                    e == e ? (e <= 1.0 ? "met" : "**missed**") : "-", t == t ? (t < 1.0 ? "met" : "**missed**") : "-");
    }
    std::printf(".\n");
}

}  // namespace

int main(int argc, char** argv) {
    const char* csv = argc > 1 ? argv[1] : "work_precision.csv";
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 11;
    gsl_set_error_handler_off();
    std::vector<point> all;
    problem<arenstorf>(rounds, all);
    problem<lorenz>(rounds, all);
    problem<pleiades>(rounds, all);

    FILE* out = std::fopen(csv, "w");
    if (out == nullptr) {
        std::fprintf(stderr, "work_precision: cannot write %s\n", csv);
        return 2;
    }
    // One block per problem and solver (blank lines between, a gnuplot index each), in the order above.
    std::fprintf(out, "# problem,solver,tol,error,evals,cpu_us_median,cpu_us_min,accepted,rejected\n");
    std::string last;
    for (const auto& p : all) {
        const std::string block = p.problem + "/" + p.solver;
        if (!last.empty() && block != last) std::fprintf(out, "\n\n");
        last = block;
        std::fprintf(out, "%s,%s,%.3e,%.6e,%ld,%.3f,%.3f,%ld,%ld\n", p.problem.c_str(), p.solver.c_str(), p.tol,
                     p.error, p.evals, p.cpu_us, p.cpu_min_us, p.accepted, p.rejected);
    }
    std::fclose(out);

    tables(all, "arenstorf", "Arenstorf orbit, one period (t1 = 17.065...)", {1e-2, 1e-4, 1e-6});
    tables(all, "lorenz", "Lorenz, t in [0, 10]", {1e-3, 1e-5, 1e-7});
    tables(all, "pleiades", "Pleiades, t in [0, 3]", {1e-4, 1e-6, 1e-8});
    return 0;
}
