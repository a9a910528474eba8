// SPDX-License-Identifier: BSL-1.0
// Work-precision of the error-controlled stiff solvers (issue 25): Robertson, Van der Pol (mu = 1000), HIRES and
// POLLU (20 states) from their natural initial states, each integrated at rtol = 1e-4 .. 1e-10 (half decades) by
//   odestep     odestep::radau5 (Radau 5(4), RADAU5's method and control) and
//               odestep::rosenbrock_adaptive<tables::rodas4> (Rodas4 with its embedded order 3 solution),
//               both free-running under integrate_adaptive, the system's exact Jacobian (with_jacobian);
//   CVODE       BDF (CV_BDF, orders 1 to 5), dense matrix and SUNLinSol_Dense, the exact Jacobian, everything
//               else CVODE's default; CVodeReInit before every run, CVodeSetStopTime(t1), CV_NORMAL;
//   ARKODE      ARKStep with the implicit part only (ARKStepCreate(NULL, fi, ...)), adaptive, Kennedy &
//               Carpenter's ESDIRK 4(3)6L[2]SA (ARKODE_ARK436L2SA_DIRK_6_3_4, the implicit part of ARK4(3)6L;
//               Kennedy & Carpenter 2003, Appl. Numer. Math. 44, 139-181) and ESDIRK 5(4)8L[2]SA
//               (ARKODE_ARK548L2SA_DIRK_8_4_5), dense matrix and solver, the exact Jacobian, ARKODE's defaults
//               otherwise; ARKStepReInit before every run, ARKStepSetStopTime(t1), ARK_NORMAL.
// CVODE and ARKODE are optional (BENCH_NO_SUNDIALS, or SUNDIALS not installed: no rows of theirs). SciPy's Radau
// and BDF are measured by bench/stiff_work_precision.py (the same problems, tolerances and columns); that
// script also makes the tables (scripts/bench.sh --stiff-work-precision runs both).
//
// Recorded per run: the error at t1, max_i |y_i - ref_i| / max(|ref_i|, floor) (the largest relative error:
// floor 0, except POLLU's 1e-10, below which its O1D concentration, 4e-18, lies and no tolerance reaches); the
// evaluations of f and of the Jacobian (every solver calls the same counting f and J: deterministic, and
// asserted equal over the repeated runs, as is the final state bit for bit); LU factorizations (odestep's
// Radau: 2 per decomposition, one real N x N and one complex N x N, as SciPy counts its Radau; Rodas4: one per
// attempt, hence one per Jacobian; CVODE and ARKODE: their linear-solver set-ups, each one factorization);
// accepted and rejected steps; the thread's CPU time of one whole run, minimum and median over `rounds` runs,
// the solvers interleaved round by round with the order rotated.
//
// References at t1, each from an independent computation or a publication (not from odestep):
//   Robertson  t1 = 40: SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-13, atol=1e-25, exact Jacobian), run
//              by bench/stiff_work_precision.py (`reference`), which also reruns it and checks it against
//              LSODA at rtol 1e-12 and Hairer & Wanner's ten digits (Solving ODE II, Sec. IV.1);
//   Van der Pol  y1' = y2, y2' = 1000 (1 - y1^2) y2 - y1, y(0) = (2, 0), t1 = 2000: the Test Set for IVP Solvers
//              (F. Mazzia and C. Magherini, release 2.4, University of Bari, 2008), problem VDPOL (eps = 1e-6,
//              t in [0, 2]), its reference y(2) computed with RADAU in extended precision, taken to this
//              time scale (t = 1000 tau, y2 = y2_tau / 1000);
//   HIRES      the Test Set, problem HIRES, t1 = 321.8122, its reference (RADAU5 in extended precision);
//   POLLU      the Test Set, problem POLLU (Verwer 1994, SIAM J. Sci. Comput. 15, 1243-1259), t1 = 60, its
//              reference (RADAU5 in extended precision, rtol = atol = 1.1e-18).
// Tolerances: Robertson and POLLU rtol and atol = 1e-6 rtol (concentrations down to 1e-5 and 1e-8); Van der Pol
// and HIRES rtol = atol (the Test Set's runs use atol = rtol).
//
// Usage: stiff_work_precision [csv [rounds]]   (default: stiff_work_precision.csv, 11 rounds). Prints the
// REFERENCE lines; the CSV has the columns of the header line it writes.
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

#include <odestep/odestep.hpp>

#include "cpu_time.hpp"
#include "sundials.hpp"

#ifdef BENCH_HAVE_SUNDIALS
#include <cvode/cvode.h>
#endif

namespace {

long g_f = 0;  // every evaluation of f by any solver
long g_j = 0;  // every evaluation of the Jacobian
struct run_stats {
    long lu = -1, accepted = -1, rejected = -1;
};
run_stats g_stats;

// --- the problems (f and J written once, templated on the containers: std::array or a raw pointer) --------

struct robertson {
    static constexpr const char* name = "robertson";
    static constexpr std::size_t N = 3;
    static constexpr double t1 = 40.0;
    static constexpr double error_floor = 0;
    static double atol(double rtol) { return 1e-6 * rtol; }
    template <class In, class Out>
    static void f(const In& y, Out& d) {
        d[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        d[2] = 3e7 * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
    template <class In, class J>
    static void jac(const In& y, J&& j) {  // j(i, k) = d f_i / d y_k
        j(0, 0) = -0.04, j(0, 1) = 1e4 * y[2], j(0, 2) = 1e4 * y[1];
        j(2, 0) = 0.0, j(2, 1) = 6e7 * y[1], j(2, 2) = 0.0;
        for (std::size_t k = 0; k < 3; ++k) j(1, k) = -j(0, k) - j(2, k);
    }
    static std::array<double, N> y0() { return {1.0, 0.0, 0.0}; }
    // SciPy 1.10.1 Radau at rtol 1e-13, atol 1e-25 (bench/stiff_work_precision.py reference).
    static std::array<double, N> reference() { return {0.7158270687194082, 9.185534764557803e-06, 0.2841637457458302}; }
};

struct vdpol {
    static constexpr const char* name = "vdpol";
    static constexpr std::size_t N = 2;
    static constexpr double t1 = 2000.0;
    static constexpr double error_floor = 0;
    static double atol(double rtol) { return rtol; }
    template <class In, class Out>
    static void f(const In& y, Out& d) {
        d[0] = y[1];
        d[1] = 1e3 * (1 - y[0] * y[0]) * y[1] - y[0];
    }
    template <class In, class J>
    static void jac(const In& y, J&& j) {
        j(0, 0) = 0.0, j(0, 1) = 1.0;
        j(1, 0) = -2e3 * y[0] * y[1] - 1, j(1, 1) = 1e3 * (1 - y[0] * y[0]);
    }
    static std::array<double, N> y0() { return {2.0, 0.0}; }
    // The Test Set's VDPOL reference y(2) = (0.1706167732170469e1, -0.8928097010248125e0), y2 / 1000 here.
    static std::array<double, N> reference() { return {0.1706167732170469e1, -0.8928097010248125e-3}; }
};

struct hires {
    static constexpr const char* name = "hires";
    static constexpr std::size_t N = 8;
    static constexpr double t1 = 321.8122;
    static constexpr double error_floor = 0;
    static double atol(double rtol) { return rtol; }
    template <class In, class Out>
    static void f(const In& y, Out& d) {
        d[0] = -1.71 * y[0] + 0.43 * y[1] + 8.32 * y[2] + 0.0007;
        d[1] = 1.71 * y[0] - 8.75 * y[1];
        d[2] = -10.03 * y[2] + 0.43 * y[3] + 0.035 * y[4];
        d[3] = 8.32 * y[1] + 1.71 * y[2] - 1.12 * y[3];
        d[4] = -1.745 * y[4] + 0.43 * y[5] + 0.43 * y[6];
        d[5] = -280 * y[5] * y[7] + 0.69 * y[3] + 1.71 * y[4] - 0.43 * y[5] + 0.69 * y[6];
        d[6] = 280 * y[5] * y[7] - 1.81 * y[6];
        d[7] = -d[6];
    }
    template <class In, class J>
    static void jac(const In& y, J&& j) {
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t k = 0; k < N; ++k) j(i, k) = 0.0;
        j(0, 0) = -1.71, j(0, 1) = 0.43, j(0, 2) = 8.32;
        j(1, 0) = 1.71, j(1, 1) = -8.75;
        j(2, 2) = -10.03, j(2, 3) = 0.43, j(2, 4) = 0.035;
        j(3, 1) = 8.32, j(3, 2) = 1.71, j(3, 3) = -1.12;
        j(4, 4) = -1.745, j(4, 5) = 0.43, j(4, 6) = 0.43;
        j(5, 3) = 0.69, j(5, 4) = 1.71, j(5, 5) = -0.43 - 280 * y[7], j(5, 6) = 0.69, j(5, 7) = -280 * y[5];
        j(6, 5) = 280 * y[7], j(6, 6) = -1.81, j(6, 7) = 280 * y[5];
        for (std::size_t k = 0; k < N; ++k) j(7, k) = -j(6, k);
    }
    static std::array<double, N> y0() { return {1, 0, 0, 0, 0, 0, 0, 0.0057}; }
    // The Test Set's HIRES reference at t = 321.8122.
    static std::array<double, N> reference() {
        return {0.7371312573325668e-3, 0.1442485726316185e-3, 0.5888729740967575e-4, 0.1175651343283149e-2,
                0.2386356198831331e-2, 0.6238968252742796e-2, 0.2849998395185769e-2, 0.2850001604814231e-2};
    }
};

// POLLU, the chemistry of the RIVM air pollution model (Verwer 1994, SIAM J. Sci. Comput. 15, 1243-1259; the Test
// Set for IVP Solvers, problem POLLU): 20 species, 25 reactions r = k y_a (y_b), each consuming its reactants and
// producing the listed species; the rate constants, the initial state and the reference are the Test Set's.
struct pollu_reaction {
    double k;
    int a, b;         // reactants (b = -1: first order)
    int products[4];  // species produced, -1 for none; a species twice is produced twice
};
constexpr pollu_reaction pollu_reactions[25] = {
    {0.35, 0, -1, {1, 2, -1, -1}},      {26.6, 1, 3, {0, -1, -1, -1}},     {1.23e4, 4, 1, {0, 5, -1, -1}},
    {8.6e-4, 6, -1, {4, 4, 7, -1}},     {8.2e-4, 6, -1, {7, -1, -1, -1}},  {1.5e4, 6, 5, {4, 7, -1, -1}},
    {1.3e-4, 8, -1, {9, 4, 7, -1}},     {2.4e4, 8, 5, {10, -1, -1, -1}},   {1.65e4, 10, 1, {0, 9, 11, -1}},
    {9.0e3, 10, 0, {12, -1, -1, -1}},   {2.2e-2, 12, -1, {10, 0, -1, -1}}, {1.2e4, 9, 1, {13, 0, -1, -1}},
    {1.88, 13, -1, {6, 4, -1, -1}},     {1.63e4, 0, 5, {14, -1, -1, -1}},  {4.8e6, 2, -1, {3, -1, -1, -1}},
    {3.5e-4, 3, -1, {15, -1, -1, -1}},  {1.75e-2, 3, -1, {2, -1, -1, -1}}, {1.0e8, 15, -1, {5, 5, -1, -1}},
    {4.44e11, 15, -1, {2, -1, -1, -1}}, {1240.0, 16, 5, {17, 4, -1, -1}},  {2.1, 18, -1, {1, -1, -1, -1}},
    {5.78, 18, -1, {0, 2, -1, -1}},     {4.74e-2, 0, 3, {18, -1, -1, -1}}, {1780.0, 18, 0, {19, -1, -1, -1}},
    {3.12, 19, -1, {0, 18, -1, -1}},
};

struct pollu {
    static constexpr const char* name = "pollu";
    static constexpr std::size_t N = 20;
    static constexpr double t1 = 60.0;
    static constexpr double error_floor = 1e-10;
    static double atol(double rtol) { return 1e-6 * rtol; }
    template <class In, class Out>
    static void f(const In& y, Out& d) {
        for (std::size_t i = 0; i < N; ++i) d[i] = 0 * y[i];
        for (const auto& r : pollu_reactions) {
            const auto rate = r.b < 0 ? r.k * y[r.a] : r.k * y[r.a] * y[r.b];
            d[r.a] -= rate;
            if (r.b >= 0) d[r.b] -= rate;
            for (int p : r.products)
                if (p >= 0) d[p] += rate;
        }
    }
    template <class In, class J>
    static void jac(const In& y, J&& j) {  // d rate / d y_a = k y_b (or k), d rate / d y_b = k y_a
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t k = 0; k < N; ++k) j(i, k) = 0.0;
        for (const auto& r : pollu_reactions) {
            const int cols[2] = {r.a, r.b};
            for (int c = 0; c < 2; ++c) {
                if (cols[c] < 0) continue;
                const auto dr = r.b < 0 ? r.k + 0 * y[r.a] : r.k * y[cols[1 - c]];
                const auto col = static_cast<std::size_t>(cols[c]);
                j(static_cast<std::size_t>(r.a), col) -= dr;
                if (r.b >= 0) j(static_cast<std::size_t>(r.b), col) -= dr;
                for (int p : r.products)
                    if (p >= 0) j(static_cast<std::size_t>(p), col) += dr;
            }
        }
    }
    static std::array<double, N> y0() {
        return {0, 0.2, 0, 0.04, 0, 0, 0.1, 0.3, 0.01, 0, 0, 0, 0, 0, 0, 0, 0.007, 0, 0, 0};
    }
    // The Test Set's reference at t = 60 (RADAU5 in extended precision, rtol = atol = 1.1e-18).
    static std::array<double, N> reference() {
        return {0.5646255480022769e-01, 0.1342484130422339e+00, 0.4139734331099427e-08, 0.5523140207484359e-02,
                0.2018977262302196e-06, 0.1464541863493966e-06, 0.7784249118997964e-01, 0.3245075353396018e+00,
                0.7494013383880406e-02, 0.1622293157301561e-07, 0.1135863833257075e-07, 0.2230505975721359e-02,
                0.2087162882798630e-03, 0.1396921016840158e-04, 0.8964884856898295e-02, 0.4352846369330103e-17,
                0.6899219696263405e-02, 0.1007803037365946e-03, 0.1772146513969984e-05, 0.5682943292316392e-04};
    }
};

/// The error of y against P's reference: max_i |y_i - ref_i| / max(|ref_i|, P::error_floor), the largest
/// relative error where the floor is 0; infinite when not finite.
template <class P, class A>
double error_of(const A& y) {
    const auto ref = P::reference();
    long double m = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
        const long double r = ref[i];
        m = std::max(m, std::fabs(static_cast<long double>(y[i]) - r) /
                            std::max(std::fabs(r), static_cast<long double>(P::error_floor)));
    }
    return m == m ? static_cast<double>(m) : HUGE_VAL;
}

// --- the solvers -------------------------------------------------------------------------------------------

template <class P>
using state_t = std::array<double, P::N>;

template <class P>
struct solver {
    std::string key;
    // y: y(0) in, y(t1) out; counts through g_f, g_j, g_stats. false: the solver gave up (a recorded result).
    std::function<bool(state_t<P>&)> run;
};

template <class P>
struct odestep_system {
    void operator()(double, const state_t<P>& y, state_t<P>& d) const {
        ++g_f;
        P::f(y, d);
    }
};
template <class P>
struct odestep_jacobian {
    void operator()(double, const state_t<P>& y, odestep::jacobian_t<state_t<P>>& m) const {
        ++g_j;
        P::jac(y, [&m](std::size_t i, std::size_t k) -> double& { return m[i][k]; });
    }
};

[[noreturn]] void failed(const char* problem, const std::string& key, double rtol, const char* what) {
    std::fprintf(stderr, "stiff_work_precision: %s %s rtol %.1e: %s\n", problem, key.c_str(), rtol, what);
    std::exit(1);
}

template <class P>
solver<P> odestep_radau5(double rtol) {
    return {"odestep_radau5", [rtol](state_t<P>& y) {
                using S = state_t<P>;
                odestep::radau5<S> engine(odestep::tolerances<S>::uniform(rtol, P::atol(rtol)));
                const auto r = odestep::integrate_adaptive(
                    engine, odestep::with_jacobian(odestep_system<P>{}, odestep_jacobian<P>{}), y, 0.0, P::t1,
                    10000000);
                g_stats = {static_cast<long>(2 * engine.decompositions()), static_cast<long>(engine.accepted_steps()),
                           static_cast<long>(engine.rejected_steps())};
                return r.status == odestep::status::ok;
            }};
}

template <class P>
solver<P> odestep_rodas4(double rtol) {
    return {"odestep_rodas4", [rtol](state_t<P>& y) {
                using S = state_t<P>;
                odestep::rosenbrock_adaptive<odestep::tables::rodas4, S> engine(
                    odestep::tolerances<S>::uniform(rtol, P::atol(rtol)));
                const long j0 = g_j;
                const auto r = odestep::integrate_adaptive(
                    engine, odestep::with_jacobian(odestep_system<P>{}, odestep_jacobian<P>{}), y, 0.0, P::t1,
                    10000000);
                g_stats = {g_j - j0, static_cast<long>(engine.accepted_steps()),
                           static_cast<long>(engine.rejected_steps())};
                return r.status == odestep::status::ok;
            }};
}

#ifdef BENCH_HAVE_SUNDIALS
template <class P>
int sun_rhs(double, N_Vector y, N_Vector d, void*) {
    ++g_f;
    double* out = N_VGetArrayPointer(d);
    P::f(static_cast<const double*>(N_VGetArrayPointer(y)), out);
    return 0;
}
template <class P>
int sun_jac(double, N_Vector y, N_Vector, SUNMatrix m, void*, N_Vector, N_Vector, N_Vector) {
    ++g_j;
    bench::sun_dense d{m};
    P::jac(static_cast<const double*>(N_VGetArrayPointer(y)), d);
    return 0;
}

void must(int flag, const char* what) {
    if (flag < 0) {
        std::fprintf(stderr, "stiff_work_precision: SUNDIALS %s failed (%d)\n", what, flag);
        std::exit(2);
    }
}

/// The SUNDIALS objects of one solver (created once per tolerance, reinitialized before every run).
struct sun_objects {
    SUNContext ctx = nullptr;
    N_Vector y = nullptr;
    SUNMatrix a = nullptr;
    SUNLinearSolver ls = nullptr;
    void* mem = nullptr;
    bool cvode = true;
    explicit sun_objects(std::size_t n) {
        must(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
        y = N_VNew_Serial(static_cast<sunindextype>(n), ctx);
        N_VConst(0.0, y);
        a = SUNDenseMatrix(static_cast<sunindextype>(n), static_cast<sunindextype>(n), ctx);
        ls = SUNLinSol_Dense(y, a, ctx);
    }
    ~sun_objects() {
        if (cvode)
            CVodeFree(&mem);
        else
            ARKStepFree(&mem);
        SUNLinSolFree(ls);
        SUNMatDestroy(a);
        N_VDestroy(y);
        SUNContext_Free(&ctx);
    }
    sun_objects(const sun_objects&) = delete;
    sun_objects& operator=(const sun_objects&) = delete;
    void load(const double* v, std::size_t n) {
        double* p = N_VGetArrayPointer(y);
        for (std::size_t i = 0; i < n; ++i) p[i] = v[i];
    }
    void store(double* v, std::size_t n) const {
        const double* p = N_VGetArrayPointer(y);
        for (std::size_t i = 0; i < n; ++i) v[i] = p[i];
    }
};

template <class P>
solver<P> cvode_bdf(double rtol) {
    auto s = std::make_shared<sun_objects>(P::N);
    s->mem = CVodeCreate(CV_BDF, s->ctx);
    if (s->mem == nullptr) must(-1, "CVodeCreate");
    must(CVodeInit(s->mem, sun_rhs<P>, 0.0, s->y), "CVodeInit");
    must(CVodeSStolerances(s->mem, rtol, P::atol(rtol)), "CVodeSStolerances");
    must(CVodeSetLinearSolver(s->mem, s->ls, s->a), "CVodeSetLinearSolver");
    must(CVodeSetJacFn(s->mem, sun_jac<P>), "CVodeSetJacFn");
    must(CVodeSetMaxNumSteps(s->mem, -1), "CVodeSetMaxNumSteps");  // no limit (the default is 500)
    must(CVodeSetErrFile(s->mem, nullptr), "CVodeSetErrFile");     // a failure is recorded, not printed
    return {"cvode_bdf", [s](state_t<P>& y) {
                s->load(y.data(), P::N);
                must(CVodeReInit(s->mem, 0.0, s->y), "CVodeReInit");
                must(CVodeSetStopTime(s->mem, P::t1), "CVodeSetStopTime");
                long lu0 = 0, lu1 = 0, steps = 0, fails = 0;
                must(CVodeGetNumLinSolvSetups(s->mem, &lu0), "CVodeGetNumLinSolvSetups");
                double t = 0;
                const bool ok = CVode(s->mem, P::t1, s->y, &t, CV_NORMAL) >= 0 && t == P::t1;
                s->store(y.data(), P::N);
                must(CVodeGetNumLinSolvSetups(s->mem, &lu1), "CVodeGetNumLinSolvSetups");
                must(CVodeGetNumSteps(s->mem, &steps), "CVodeGetNumSteps");
                must(CVodeGetNumErrTestFails(s->mem, &fails), "CVodeGetNumErrTestFails");
                long conv = 0;
                must(CVodeGetNumNonlinSolvConvFails(s->mem, &conv), "CVodeGetNumNonlinSolvConvFails");
                // CVodeReInit sets the step counters to zero; steps counts the accepted ones.
                g_stats = {lu1 - lu0, steps, fails + conv};
                return ok;
            }};
}

template <class P>
solver<P> arkode_esdirk(const char* key, ARKODE_DIRKTableID table, double rtol) {
    auto s = std::make_shared<sun_objects>(P::N);
    s->cvode = false;
    s->mem = ARKStepCreate(nullptr, sun_rhs<P>, 0.0, s->y, s->ctx);
    if (s->mem == nullptr) must(-1, "ARKStepCreate");
    must(ARKStepSetTableNum(s->mem, table, ARKODE_ERK_NONE), "ARKStepSetTableNum");
    must(ARKStepSStolerances(s->mem, rtol, P::atol(rtol)), "ARKStepSStolerances");
    must(ARKStepSetLinearSolver(s->mem, s->ls, s->a), "ARKStepSetLinearSolver");
    must(ARKStepSetJacFn(s->mem, sun_jac<P>), "ARKStepSetJacFn");
    must(ARKStepSetMaxNumSteps(s->mem, -1), "ARKStepSetMaxNumSteps");
    must(ARKStepSetErrFile(s->mem, nullptr), "ARKStepSetErrFile");  // a failure is recorded, not printed
    return {key, [s](state_t<P>& y) {
                s->load(y.data(), P::N);
                // ReInit, not Reset: a fresh start (first step estimated again, counters zero), options kept.
                must(ARKStepReInit(s->mem, nullptr, sun_rhs<P>, 0.0, s->y), "ARKStepReInit");
                must(ARKStepSetStopTime(s->mem, P::t1), "ARKStepSetStopTime");
                long lu0 = 0, lu1 = 0, steps = 0, fails = 0, conv = 0;
                must(ARKStepGetNumLinSolvSetups(s->mem, &lu0), "ARKStepGetNumLinSolvSetups");
                double t = 0;
                const bool ok = ARKStepEvolve(s->mem, P::t1, s->y, &t, ARK_NORMAL) >= 0 && t == P::t1;
                s->store(y.data(), P::N);
                must(ARKStepGetNumLinSolvSetups(s->mem, &lu1), "ARKStepGetNumLinSolvSetups");
                must(ARKStepGetNumSteps(s->mem, &steps), "ARKStepGetNumSteps");
                must(ARKStepGetNumErrTestFails(s->mem, &fails), "ARKStepGetNumErrTestFails");
                must(ARKStepGetNumNonlinSolvConvFails(s->mem, &conv), "ARKStepGetNumNonlinSolvConvFails");
                g_stats = {lu1 - lu0, steps, fails + conv};
                return ok;
            }};
}
#endif

template <class P>
std::vector<solver<P>> solvers(double rtol) {
    std::vector<solver<P>> v;
    v.push_back(odestep_radau5<P>(rtol));
    v.push_back(odestep_rodas4<P>(rtol));
#ifdef BENCH_HAVE_SUNDIALS
    v.push_back(cvode_bdf<P>(rtol));
    v.push_back(arkode_esdirk<P>("arkode_esdirk43", ARKODE_ARK436L2SA_DIRK_6_3_4, rtol));
    v.push_back(arkode_esdirk<P>("arkode_esdirk54", ARKODE_ARK548L2SA_DIRK_8_4_5, rtol));
#endif
    return v;
}

// --- measuring ---------------------------------------------------------------------------------------------

struct point {
    std::string problem, solver;
    double rtol, error;
    long f, jac, lu, accepted, rejected;
    double cpu_us_min, cpu_us_median;
};

template <class P>
void measure(int rounds, std::vector<point>& out) {
    for (int e = 0; e <= 12; ++e) {
        const double rtol = std::pow(10.0, -4.0 - 0.5 * e);
        auto vs = solvers<P>(rtol);
        const std::size_t V = vs.size();
        std::vector<long> fs(V), js(V);
        std::vector<run_stats> st(V);
        std::vector<state_t<P>> end(V);
        std::vector<std::vector<double>> cpu(V);
        std::vector<bool> ok(V);
        for (std::size_t k = 0; k < V; ++k) {  // the first run: the counts and the final state
            state_t<P> y = P::y0();
            const long f0 = g_f, j0 = g_j;
            g_stats = {};
            ok[k] = vs[k].run(y);
            fs[k] = g_f - f0;
            js[k] = g_j - j0;
            st[k] = g_stats;
            end[k] = y;
        }
        for (int r = 0; r < rounds; ++r)
            for (std::size_t j = 0; j < V; ++j) {
                const std::size_t k = (j + static_cast<std::size_t>(r)) % V;
                if (!ok[k]) continue;
                state_t<P> y = P::y0();
                const long f0 = g_f, j0 = g_j;
                const double c0 = bench::clock_ns(CLOCK_THREAD_CPUTIME_ID);
                vs[k].run(y);
                const double c1 = bench::clock_ns(CLOCK_THREAD_CPUTIME_ID);
                if (g_f - f0 != fs[k] || g_j - j0 != js[k] || std::memcmp(y.data(), end[k].data(), sizeof y) != 0)
                    failed(P::name, vs[k].key, rtol, "a repeated run differs");
                cpu[k].push_back((c1 - c0) / 1e3);
            }
        for (std::size_t k = 0; k < V; ++k) {
            if (!ok[k]) {  // a failed run: error "inf" in the CSV, its counts up to the failure, no time
                std::fprintf(stderr, "stiff_work_precision: %s %s rtol %.1e: the solver gave up (recorded)\n", P::name,
                             vs[k].key.c_str(), rtol);
                out.push_back({P::name, vs[k].key, rtol, HUGE_VAL, fs[k], js[k], st[k].lu, st[k].accepted,
                               st[k].rejected, 0.0, 0.0});
                continue;
            }
            out.push_back({P::name, vs[k].key, rtol, error_of<P>(end[k]), fs[k], js[k], st[k].lu, st[k].accepted,
                           st[k].rejected, *std::min_element(cpu[k].begin(), cpu[k].end()), bench::median(cpu[k])});
        }
    }
}

/// A consistency check of the hard-coded reference, not the reference itself: odestep's Radau 5(4) in long
/// double at rtol 1e-16 must agree with it to `within` (its digits, relative).
template <class P>
void check_reference(double within) {
    using L = std::array<long double, P::N>;
    L y{};
    const auto y0 = P::y0();
    for (std::size_t i = 0; i < P::N; ++i) y[i] = y0[i];
    odestep::radau5<L> engine(odestep::tolerances<L>::uniform(1e-16L, 1e-16L * P::atol(1.0)));
    const auto f = [](long double, const L& x, L& d) { P::f(x, d); };
    const auto j = [](long double, const L& x, odestep::jacobian_t<L>& m) {
        P::jac(x, [&m](std::size_t i, std::size_t k) -> long double& { return m[i][k]; });
    };
    const auto r = odestep::integrate_adaptive(engine, odestep::with_jacobian(f, j), y, 0.0L,
                                               static_cast<long double>(P::t1), 10000000);
    const double d = error_of<P>(y);
    std::printf("REFERENCE\t%s\tt1=%.10g\tlong_double_radau5_vs_reference=%.2e\n", P::name, P::t1, d);
    if (r.status != odestep::status::ok || !(d <= within)) {
        std::fprintf(stderr, "stiff_work_precision: the %s reference fails its check (%.2e > %.1e)\n", P::name, d,
                     within);
        std::exit(1);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const char* csv = argc > 1 ? argv[1] : "stiff_work_precision.csv";
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 11;
    check_reference<robertson>(1e-12);
    check_reference<vdpol>(1e-10);
    check_reference<hires>(1e-10);
    check_reference<pollu>(1e-10);
    std::vector<point> all;
    measure<robertson>(rounds, all);
    measure<vdpol>(rounds, all);
    measure<hires>(rounds, all);
    measure<pollu>(rounds, all);

    FILE* out = std::fopen(csv, "w");
    if (out == nullptr) {
        std::fprintf(stderr, "stiff_work_precision: cannot write %s\n", csv);
        return 2;
    }
    std::fprintf(out, "# problem,solver,rtol,error,f,jac,lu,accepted,rejected,cpu_us_min,cpu_us_median\n");
    for (const auto& p : all)
        std::fprintf(out, "%s,%s,%.3e,%.6e,%ld,%ld,%ld,%ld,%ld,%.3f,%.3f\n", p.problem.c_str(), p.solver.c_str(),
                     p.rtol, p.error, p.f, p.jac, p.lu, p.accepted, p.rejected, p.cpu_us_min, p.cpu_us_median);
    std::fclose(out);
    return 0;
}
