// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: SUNDIALS ARKODE (ARKStep, implicit part only) as a fixed-step DIRK stepper, for the stiff
// cases; ARKStep's explicit part (arkode_erk, at the end) for the nonstiff ones. Optional: BENCH_HAVE_SUNDIALS
// is defined only where <arkode/arkode_arkstep.h> exists (Debian: libsundials-dev, installed by
// bench/install-deps.sh), so the cases build without it. Link with
//   -lsundials_arkode -lsundials_nvecserial -lsundials_sunlinsoldense -lsundials_sunmatrixdense
//
// The set-up mirrors odestep's implicit steppers as closely as ARKODE allows:
//   - ARKStepCreate(NULL, fi, ...): the implicit part only; a dense SUNMatrix with SUNLinSol_Dense and the
//     exact Jacobian (ARKStepSetJacFn);
//   - ARKStepSetFixedStep(h): no error control; one ARKStepEvolve(..., ARK_ONE_STEP) per benchmark step;
//   - a new Jacobian and one factorization of I - h gamma J every step (ARKStepSetLSetupFrequency(1),
//     ARKStepSetJacEvalFrequency(1)), as odestep's simplified Newton makes them;
//   - each stage's Newton iteration starts from y_n (the trivial predictor, ARKStepSetPredictorMethod(0)),
//     as odestep's starts from Z = 0, and the stage derivative is deduced from the converged stage
//     (ARKStepSetDeduceImplicitRhs), as odestep does, instead of one more evaluation of f;
//   - the Newton test as close to odestep's newton<10> (rk/newton.hpp) as its knobs go: weights
//     1 / (rtol |y_i| + atol) with rtol = atol = 2^-39 (odestep's eps^(3/4) for double), convergence when
//     min(1, rate) ||dz|| / nlscoef <= 1 with nlscoef = 1, rate = max(crdown rate, ||dz_k|| / ||dz_k-1||),
//     crdown = 0.3, divergence when ||dz_k|| > rdiv ||dz_k-1|| with rdiv = 2, at most 10 iterations. The one
//     difference left: ARKODE's norm is the weighted root mean square, odestep's the weighted maximum (at
//     most sqrt(N) times larger), so ARKODE may stop one iteration earlier.
//   - Lagrange interpolation (ARKStepSetInterpolantType): ARKODE always keeps an interpolant for dense output
//     (odestep has none); the Lagrange one stores solutions only. The default Hermite one needs f at the
//     step's end, which ARKODE copies from the last stage for these tables (all stiffly accurate, c_s = 1):
//     measured, it makes no difference in evaluations or time here.
// Define BENCH_NO_SUNDIALS to build the cases without it even where it is installed.
// SUNDIALS allocates when the stepper is created (96 calls to malloc here) and in its first step (34 more,
// workspace made lazily), never after: ARKStepReset() (the start of every run) and the steps reuse it all.
// (Counted with malloc wrapped; the steps' count, zero, with Callgrind as bench/RESULTS.md, "Stiff", shows.)
#ifndef ODESTEP_BENCH_SUNDIALS_HPP
#define ODESTEP_BENCH_SUNDIALS_HPP

#if __has_include(<arkode/arkode_arkstep.h>) && !defined(BENCH_NO_SUNDIALS)
#define BENCH_HAVE_SUNDIALS 1

#include <cstddef>
#include <cstdio>
#include <cstdlib>

#include <arkode/arkode_arkstep.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace bench {

/// A dense SUNMatrix seen through (i, k), for the cases' Jacobian templates (column-major storage).
struct sun_dense {
    SUNMatrix m;
    double& operator()(std::size_t i, std::size_t k) {
        return SM_ELEMENT_D(m, static_cast<sunindextype>(i), static_cast<sunindextype>(k));
    }
};

/// A user Butcher table without embedding (ARKODE allows that with a fixed step): s stages, order q, the
/// matrix a row by row.
struct arkode_user_table {
    int stages;
    int order;
    const double* a;  // s x s, row-major
    const double* b;
    const double* c;
};

class arkode_dirk {
public:
    /// A built-in DIRK table of ARKODE (its own embedding is computed and ignored with a fixed step).
    arkode_dirk(ARKRhsFn fi, ARKLsJacFn jac, std::size_t n, double h, ARKODE_DIRKTableID id) {
        init(fi, jac, n, h, &id, nullptr);
    }
    /// A user table, copied by ARKODE.
    arkode_dirk(ARKRhsFn fi, ARKLsJacFn jac, std::size_t n, double h, const arkode_user_table& table) {
        init(fi, jac, n, h, nullptr, &table);
    }
    ~arkode_dirk() {
        ARKStepFree(&mem_);
        SUNLinSolFree(ls_);
        SUNMatDestroy(a_);
        N_VDestroy(y_);
        SUNContext_Free(&ctx_);
    }
    arkode_dirk(const arkode_dirk&) = delete;
    arkode_dirk& operator=(const arkode_dirk&) = delete;

    /// A new run from y0 at t0 (the harness's start hook): ARKStepReset, which keeps every allocation.
    void start(const double* y0, double t0) {
        double* y = N_VGetArrayPointer(y_);
        for (std::size_t i = 0; i < n_; ++i) y[i] = y0[i];
        must(ARKStepReset(mem_, t0, y_), "ARKStepReset");
    }

    /// One fixed step from ARKODE's current time (t, the harness's, is the same up to rounding) to y.
    int step(double* y, double t, double h) {
        double tret = 0;
        const int flag = ARKStepEvolve(mem_, t + h, y_, &tret, ARK_ONE_STEP);
        const double* v = N_VGetArrayPointer(y_);
        for (std::size_t i = 0; i < n_; ++i) y[i] = v[i];
        return flag < 0 ? 1 : 0;
    }

    /// Newton's weights 1 / (tol |y_i| + tol) instead of odestep's default tol = 2^-39.
    void set_tolerance(double tol) { must(ARKStepSStolerances(mem_, tol, tol), "ARKStepSStolerances"); }

    /// ARKODE's counters since the stepper was created (not reset by start()).
    void stats(long& steps, long& fi, long& setups, long& jacs, long& newton) const {
        long fe = 0;
        ARKStepGetNumSteps(mem_, &steps);
        ARKStepGetNumRhsEvals(mem_, &fe, &fi);
        ARKStepGetNumLinSolvSetups(mem_, &setups);
        ARKStepGetNumJacEvals(mem_, &jacs);
        ARKStepGetNumNonlinSolvIters(mem_, &newton);
    }

private:
    static void must(int flag, const char* what) {
        if (flag < 0) {
            std::fprintf(stderr, "bench: SUNDIALS %s failed (%d)\n", what, flag);
            std::exit(2);
        }
    }
    void init(ARKRhsFn fi, ARKLsJacFn jac, std::size_t n, double h, const ARKODE_DIRKTableID* id,
              const arkode_user_table* user) {
        n_ = n;
        must(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
        y_ = N_VNew_Serial(static_cast<sunindextype>(n), ctx_);
        N_VConst(0.0, y_);
        mem_ = ARKStepCreate(nullptr, fi, 0.0, y_, ctx_);
        if (mem_ == nullptr) must(-1, "ARKStepCreate");
        a_ = SUNDenseMatrix(static_cast<sunindextype>(n), static_cast<sunindextype>(n), ctx_);
        ls_ = SUNLinSol_Dense(y_, a_, ctx_);
        must(ARKStepSetLinearSolver(mem_, ls_, a_), "ARKStepSetLinearSolver");
        must(ARKStepSetJacFn(mem_, jac), "ARKStepSetJacFn");
        if (user != nullptr) {
            ARKodeButcherTable b =
                ARKodeButcherTable_Create(user->stages, user->order, 0, const_cast<double*>(user->c),
                                          const_cast<double*>(user->a), const_cast<double*>(user->b), nullptr);
            if (b == nullptr) must(-1, "ARKodeButcherTable_Create");
            must(ARKStepSetTables(mem_, user->order, 0, b, nullptr), "ARKStepSetTables");
            ARKodeButcherTable_Free(b);
        } else {
            must(ARKStepSetTableNum(mem_, *id, ARKODE_ERK_NONE), "ARKStepSetTableNum");
        }
        must(ARKStepSetFixedStep(mem_, h), "ARKStepSetFixedStep");
        must(ARKStepSetInterpolantType(mem_, ARK_INTERP_LAGRANGE), "ARKStepSetInterpolantType");
        must(ARKStepSetLSetupFrequency(mem_, 1), "ARKStepSetLSetupFrequency");
        must(ARKStepSetJacEvalFrequency(mem_, 1), "ARKStepSetJacEvalFrequency");
        must(ARKStepSetPredictorMethod(mem_, 0), "ARKStepSetPredictorMethod");
        must(ARKStepSetDeduceImplicitRhs(mem_, SUNTRUE), "ARKStepSetDeduceImplicitRhs");
        const double tol = 1.0 / 549755813888.0;  // 2^-39, odestep's newton_tolerance<double>
        must(ARKStepSStolerances(mem_, tol, tol), "ARKStepSStolerances");
        must(ARKStepSetNonlinConvCoef(mem_, 1.0), "ARKStepSetNonlinConvCoef");
        must(ARKStepSetNonlinCRDown(mem_, 0.3), "ARKStepSetNonlinCRDown");
        must(ARKStepSetNonlinRDiv(mem_, 2.0), "ARKStepSetNonlinRDiv");
        must(ARKStepSetMaxNonlinIters(mem_, 10), "ARKStepSetMaxNonlinIters");
        must(ARKStepSetMaxNumSteps(mem_, -1), "ARKStepSetMaxNumSteps");  // no limit (one step per call anyway)
    }

    std::size_t n_ = 0;
    SUNContext ctx_ = nullptr;
    N_Vector y_ = nullptr;
    SUNMatrix a_ = nullptr;
    SUNLinearSolver ls_ = nullptr;
    void* mem_ = nullptr;
};

/// ARKODE's explicit Runge-Kutta through ARKStep (ARKStepCreate(fe, NULL, ...): the explicit part only, no
/// linear solver), for the nonstiff cases. Not ERKStep: in SUNDIALS 6.4.1 ERKStep has a bug (upstream issue
/// 311) that ARKStep in explicit mode does not share. Two uses:
///   - adaptive (work-precision, bench/work_precision.cpp): a built-in ERK table with its embedding and
///     everything else ARKODE's default (its error norm, controller and first-step estimate), run from t0 to
///     t1 with ARKStepSetStopTime(t1) and ARK_NORMAL, so the last step lands on t1 (no interpolation);
///   - fixed step (bench/lorenz_rk4.cpp): a user table without embedding, ARKStepSetFixedStep(h), one
///     ARKStepEvolve(..., ARK_ONE_STEP) per benchmark step, as arkode_dirk.
/// Memory is allocated once here (and lazily in the first step); every run starts with ARKStepReset, which
/// keeps it (ARKStepReInit in the adaptive use, see integrate()). The interpolant is ARKODE's default
/// (Hermite) unless set_lagrange() is called.
class arkode_erk {
public:
    /// Adaptive, built-in table `id` (e.g. ARKODE_DORMAND_PRINCE_7_4_5), tolerances rtol = atol = 1e-6 until
    /// set_tolerance().
    arkode_erk(ARKRhsFn fe, std::size_t n, ARKODE_ERKTableID id) {
        init(fe, n);
        must(ARKStepSetTableNum(mem_, ARKODE_DIRK_NONE, id), "ARKStepSetTableNum");
    }
    /// Fixed step h, user table (no embedding), copied by ARKODE.
    arkode_erk(ARKRhsFn fe, std::size_t n, double h, const arkode_user_table& table) {
        init(fe, n);
        ARKodeButcherTable b =
            ARKodeButcherTable_Create(table.stages, table.order, 0, const_cast<double*>(table.c),
                                      const_cast<double*>(table.a), const_cast<double*>(table.b), nullptr);
        if (b == nullptr) must(-1, "ARKodeButcherTable_Create");
        must(ARKStepSetTables(mem_, table.order, 0, nullptr, b), "ARKStepSetTables");
        ARKodeButcherTable_Free(b);
        must(ARKStepSetFixedStep(mem_, h), "ARKStepSetFixedStep");
    }
    ~arkode_erk() {
        ARKStepFree(&mem_);
        N_VDestroy(y_);
        SUNContext_Free(&ctx_);
    }
    arkode_erk(const arkode_erk&) = delete;
    arkode_erk& operator=(const arkode_erk&) = delete;

    /// rtol = atol = tol (ARKODE's weights 1 / (tol |y_i| + tol), weighted root-mean-square norm).
    void set_tolerance(double tol) { must(ARKStepSStolerances(mem_, tol, tol), "ARKStepSStolerances"); }
    /// Lagrange interpolation (solutions only) instead of the default Hermite one.
    void set_lagrange() { must(ARKStepSetInterpolantType(mem_, ARK_INTERP_LAGRANGE), "ARKStepSetInterpolantType"); }

    /// A new run from y0 at t0: ARKStepReset, which keeps every allocation.
    void start(const double* y0, double t0) {
        double* y = N_VGetArrayPointer(y_);
        for (std::size_t i = 0; i < n_; ++i) y[i] = y0[i];
        must(ARKStepReset(mem_, t0, y_), "ARKStepReset");
    }

    /// One fixed step from ARKODE's current time to y (the fixed-step use).
    int step(double* y, double t, double h) {
        double tret = 0;
        const int flag = ARKStepEvolve(mem_, t + h, y_, &tret, ARK_ONE_STEP);
        copy_out(y);
        return flag < 0 ? 1 : 0;
    }

    /// The adaptive use: y (in: the state at t0, out: at t1) from t0 to exactly t1. Returns ARKODE's flag.
    /// ARKStepReInit, not ARKStepReset: Reset keeps the last step size and the controller's history, so a
    /// second run from the same y0 would take other steps than the first; ReInit starts afresh (the first
    /// step estimated again), keeps the options and every allocation.
    int integrate(double* y, double t0, double t1) {
        double* v = N_VGetArrayPointer(y_);
        for (std::size_t i = 0; i < n_; ++i) v[i] = y[i];
        must(ARKStepReInit(mem_, fe_, nullptr, t0, y_), "ARKStepReInit");
        must(ARKStepSetStopTime(mem_, t1), "ARKStepSetStopTime");
        double tret = 0;
        const int flag = ARKStepEvolve(mem_, t1, y_, &tret, ARK_NORMAL);
        copy_out(y);
        return flag;
    }

    /// The last run's accepted steps and rejected attempts (error test failures), ARKODE's counters (which
    /// ARKStepReInit sets to zero).
    void steps(long& accepted, long& rejected) const {
        ARKStepGetNumSteps(mem_, &accepted);
        ARKStepGetNumErrTestFails(mem_, &rejected);
    }

private:
    static void must(int flag, const char* what) {
        if (flag < 0) {
            std::fprintf(stderr, "bench: SUNDIALS %s failed (%d)\n", what, flag);
            std::exit(2);
        }
    }
    void init(ARKRhsFn fe, std::size_t n) {
        n_ = n;
        fe_ = fe;
        must(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
        y_ = N_VNew_Serial(static_cast<sunindextype>(n), ctx_);
        N_VConst(0.0, y_);
        mem_ = ARKStepCreate(fe, nullptr, 0.0, y_, ctx_);
        if (mem_ == nullptr) must(-1, "ARKStepCreate");
        must(ARKStepSStolerances(mem_, 1e-6, 1e-6), "ARKStepSStolerances");
        must(ARKStepSetMaxNumSteps(mem_, -1), "ARKStepSetMaxNumSteps");  // no limit (the default is 500)
    }
    void copy_out(double* y) const {
        const double* v = N_VGetArrayPointer(y_);
        for (std::size_t i = 0; i < n_; ++i) y[i] = v[i];
    }

    std::size_t n_ = 0;
    ARKRhsFn fe_ = nullptr;
    SUNContext ctx_ = nullptr;
    N_Vector y_ = nullptr;
    void* mem_ = nullptr;
};

}  // namespace bench

#endif
#endif
