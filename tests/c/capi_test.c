/* SPDX-License-Identifier: BSL-1.0 */
/* The C API (include/odestep/odestep.h) tested from C99: closed forms, bad input and roll-back. Runs on the
 * host and, cross-compiled, on the emulated Cortex-M cores (printf through semihosting there). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "odestep/odestep.h"

int check_failures = 0;

/* ---- systems */

/* y' = -k y (ctx: &k), every component alike. */
static void decay_d(double t, const double* y, double* dydt, void* ctx) {
    const double k = *(const double*)ctx;
    size_t i;
    (void)t;
    for (i = 0; i < 3; ++i) dydt[i] = -k * y[i];
}
static void decay1_d(double t, const double* y, double* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = -y[0];
}
static void decay1_f(float t, const float* y, float* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = -y[0];
}

/* The harmonic oscillator x'' = -x, as a force of position alone. */
static void spring_d(double t, const double* x, double* a, void* ctx) {
    (void)t;
    (void)ctx;
    a[0] = -x[0];
}
static void spring_f(float t, const float* x, float* a, void* ctx) {
    (void)t;
    (void)ctx;
    a[0] = -x[0];
}

/* y' = -y that returns NaN from the call numbered *ctx on (counting from 1); counts its calls. */
typedef struct poison {
    int calls;
    int nan_from;
} poison;
static void poisoned_d(double t, const double* y, double* dydt, void* ctx) {
    poison* p = (poison*)ctx;
    (void)t;
    ++p->calls;
    dydt[0] = p->calls >= p->nan_from ? (double)NAN : -y[0];
    dydt[1] = -y[1];
}

/* ---- closed forms */

/* RK4 on y' = -y: one step multiplies y by R(-h) = 1 - h + h^2/2 - h^3/6 + h^4/24, the stability function
 * of every 4-stage explicit method of order 4 (the degree-4 Taylor polynomial of e^z; Hairer & Wanner,
 * Solving ODEs II, Sect. IV.2), so after m steps y = R(-h)^m y0, and y(t) = exp(-t) y0 to O(h^4). */
static void test_rk4_decay(void) {
    odestep_stepper_d s;
    double k = 1.0;
    const odestep_system_d sys = {decay_d, &k, 3};
    double y[3] = {1.0, 2.0, -0.5};
    const double h = 0.1;
    const double r = 1.0 - h + h * h / 2.0 - h * h * h / 6.0 + h * h * h * h / 24.0;
    double expected = 1.0;
    int i;
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    for (i = 0; i < 10; ++i) {
        CHECK(odestep_step_d(&s, &sys, y, i * h, h) == ODESTEP_OK);
        expected *= r;
    }
    CHECK_CLOSE(y[0], expected, 1e-15);
    CHECK_CLOSE(y[1], 2.0 * expected, 2e-15);
    CHECK_CLOSE(y[2], -0.5 * expected, 1e-15);
    CHECK_CLOSE(y[0], exp(-1.0), 1e-6); /* global error ~ t h^4 / 120 e^-t = 3e-7 */
}

/* Euler on y' = -y: y_m = (1 - h)^m exactly in the arithmetic (each step is y - h y). */
static void test_euler_decay(void) {
    odestep_stepper_d s;
    const odestep_system_d sys = {decay1_d, NULL, 1};
    double y = 1.0;
    double expected = 1.0;
    int i;
    CHECK(odestep_stepper_init_d(&s, &odestep_euler_d) == ODESTEP_OK);
    for (i = 0; i < 20; ++i) {
        CHECK(odestep_step_d(&s, &sys, &y, i * 0.05, 0.05) == ODESTEP_OK);
        expected = expected + 0.05 * -expected;
    }
    CHECK(y == expected);
}

/* Heun and Euler-Richardson on y' = -y: both have the stability function 1 - h + h^2/2 (every 2-stage
 * explicit method of order 2). */
static void test_second_order_decay(void) {
    const odestep_method_d* methods[2];
    const odestep_system_d sys = {decay1_d, NULL, 1};
    const double h = 0.125;
    const double r = 1.0 - h + h * h / 2.0;
    int m;
    methods[0] = &odestep_heun_d;
    methods[1] = &odestep_euler_richardson_d;
    for (m = 0; m < 2; ++m) {
        odestep_stepper_d s;
        double y = 1.0;
        int i;
        CHECK(odestep_stepper_init_d(&s, methods[m]) == ODESTEP_OK);
        for (i = 0; i < 8; ++i) CHECK(odestep_step_d(&s, &sys, &y, i * h, h) == ODESTEP_OK);
        CHECK_CLOSE(y, pow(r, 8.0), 1e-15);
    }
}

/* The embedded pairs: on y' = -y the estimate y - yhat is R(-h) - Rhat(-h) times y, a polynomial in h whose
 * leading term is h^(p+1) times the difference of the two orders' Taylor coefficients; here it is enough
 * that it is small, of the order the pair claims (|err| < C h^(phat+1)), non-zero, and that the estimating
 * step returns the same y as the plain one. */
static void test_error_estimates(void) {
    const odestep_method_d* methods[4];
    const double bound[4] = {0.02 * 0.02 * 1.0, 0.02 * 0.02 * 0.02, 1e-7, 1e-10};
    const odestep_system_d sys = {decay1_d, NULL, 1};
    int m;
    methods[0] = &odestep_euler_richardson_d; /* embedded order 1: err ~ h^2 / 2 */
    methods[1] = &odestep_bs32_d;             /* embedded order 2: err ~ h^3 */
    methods[2] = &odestep_dp54_d;             /* embedded order 4 */
    methods[3] = &odestep_dop853_d;           /* embedded orders 5 and 3 */
    for (m = 0; m < 4; ++m) {
        odestep_stepper_d s;
        double y = 1.0;
        double plain = 1.0;
        double err = 0.0;
        double err2 = 0.0;
        odestep_method_info info;
        CHECK(odestep_stepper_init_d(&s, methods[m]) == ODESTEP_OK);
        CHECK(odestep_method_info_d(methods[m], &info) == ODESTEP_OK);
        CHECK(info.error_estimates == (m == 3 ? 2 : 1));
        CHECK(odestep_step_error_d(&s, &sys, &y, 0.0, 0.02, &err, m == 3 ? &err2 : NULL) == ODESTEP_OK);
        CHECK(odestep_step_d(&s, &sys, &plain, 0.0, 0.02) == ODESTEP_OK);
        CHECK(y == plain);
        CHECK(err != 0.0);
        CHECK(fabs(err) < bound[m]);
        if (m == 3) CHECK(err2 != 0.0 && fabs(err2) < 1e-6);
        CHECK_CLOSE(y, exp(-0.02), 2e-6); /* Euler-Richardson's local error: h^3 / 6 = 1.3e-6 */
    }
    {
        odestep_stepper_d s;
        double y = 1.0;
        double err = 0.0;
        double err2 = 0.0;
        CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
        CHECK(odestep_step_error_d(&s, &sys, &y, 0.0, 0.1, &err, NULL) == ODESTEP_INVALID_SETTING); /* none */
        CHECK(odestep_stepper_init_d(&s, &odestep_dp54_d) == ODESTEP_OK);
        CHECK(odestep_step_error_d(&s, &sys, &y, 0.0, 0.1, &err, &err2) == ODESTEP_INVALID_SETTING); /* one only */
        CHECK(y == 1.0 && err == 0.0 && err2 == 0.0);
    }
}

/* DOP853 over [0, 1] with the loop: y(1) = exp(-1) to far below RK4's error. */
static void test_dop853_loop(void) {
    odestep_stepper_d s;
    const odestep_system_d sys = {decay1_d, NULL, 1};
    double y = 1.0;
    odestep_run_d run;
    CHECK(odestep_stepper_init_d(&s, &odestep_dop853_d) == ODESTEP_OK);
    CHECK(odestep_integrate_d(&s, &sys, &y, 0.0, 1.0, 0.1, NULL, NULL, &run) == ODESTEP_OK);
    CHECK(run.t == 1.0 && run.steps == 10);
    CHECK_CLOSE(y, exp(-1.0), 1e-13);
}

/* Velocity Verlet on x'' = -x: the step is a linear map that preserves v^2 + x^2 (1 - h^2/4) exactly (its
 * matrix M satisfies M^T Q M = Q for Q = diag(1 - h^2/4, 1): the modified energy of the Stormer-Verlet
 * method, Hairer, Lubich & Wanner, Geometric Numerical Integration, Sect. I.1.4), so over 10^3 steps that
 * quantity moves by rounding only while the true energy x^2 + v^2 oscillates by O(h^2). The loop reuses the
 * last acceleration: 1 evaluation a step (counted by the observer's step count and the method's info). */
static void test_verlet_energy(void) {
    odestep_stepper_d s;
    const odestep_newton_d sys = {spring_d, NULL, 1};
    double x = 1.0;
    double v = 0.0;
    const double h = 0.1;
    odestep_run_d run;
    CHECK(odestep_stepper_init_d(&s, &odestep_velocity_verlet_d) == ODESTEP_OK);
    CHECK(odestep_integrate_newton_d(&s, &sys, &x, &v, 0.0, 100.0, h, NULL, NULL, &run) == ODESTEP_OK);
    CHECK(run.steps == 1000);
    CHECK_CLOSE(v * v + x * x * (1.0 - h * h / 4.0), 1.0 - h * h / 4.0, 1e-13);
    CHECK(fabs(x * x + v * v - 1.0) > 1e-6); /* not the true energy: the test sees the difference */
}

/* Euler-Cromer (kick, then drift) on x'' = -x preserves v^2 + x^2 - h x v exactly (same argument). */
static void test_euler_cromer_energy(void) {
    odestep_stepper_d s;
    const odestep_newton_d sys = {spring_d, NULL, 1};
    double x = 1.0;
    double v = 0.0;
    const double h = 0.1;
    int i;
    CHECK(odestep_stepper_init_d(&s, &odestep_euler_cromer_d) == ODESTEP_OK);
    for (i = 0; i < 1000; ++i) CHECK(odestep_step_newton_d(&s, &sys, &x, &v, i * h, h) == ODESTEP_OK);
    CHECK_CLOSE(v * v + x * x - h * x * v, 1.0, 1e-13);
}

/* Forest-Ruth (order 4) on x'' = -x over one period: x(2 pi) = 1, v(2 pi) = 0 to O(h^4). */
static void test_forest_ruth_period(void) {
    odestep_stepper_d s;
    const odestep_newton_d sys = {spring_d, NULL, 1};
    double x = 1.0;
    double v = 0.0;
    const double two_pi = 6.283185307179586;
    CHECK(odestep_stepper_init_d(&s, &odestep_forest_ruth_d) == ODESTEP_OK);
    CHECK(odestep_integrate_newton_d(&s, &sys, &x, &v, 0.0, two_pi, two_pi / 100.0, NULL, NULL, NULL) == ODESTEP_OK);
    CHECK_CLOSE(x, 1.0, 1e-5);
    CHECK_CLOSE(v, 0.0, 1e-5);
}

/* AB4 and ABM4 over [0, 2] with h = 0.05 (40 steps, the first three by RK4): exp(-2) to O(h^4). A single
 * step off the history's grid is refused, and the loop refuses a run whose last step would be shortened. */
static void test_adams(void) {
    const odestep_method_d* methods[2];
    const odestep_system_d sys = {decay1_d, NULL, 1};
    int m;
    methods[0] = &odestep_ab4_d;
    methods[1] = &odestep_abm4_d;
    for (m = 0; m < 2; ++m) {
        odestep_stepper_d s;
        double y = 1.0;
        odestep_run_d run;
        int i;
        CHECK(odestep_stepper_init_d(&s, methods[m]) == ODESTEP_OK);
        CHECK(odestep_integrate_d(&s, &sys, &y, 0.0, 2.0, 0.05, NULL, NULL, &run) == ODESTEP_OK);
        CHECK(run.steps == 40);
        CHECK_CLOSE(y, exp(-2.0), 2e-6);

        y = 1.0;
        CHECK(odestep_integrate_d(&s, &sys, &y, 0.0, 1.01, 0.05, NULL, NULL, &run) == ODESTEP_STEP_MISMATCH);
        CHECK(y == 1.0 && run.steps == 0 && run.t == 0.0);

        odestep_stepper_reset_d(&s);
        for (i = 0; i < 5; ++i) {
            CHECK(odestep_step_d(&s, &sys, &y, i * 0.05, 0.05) == ODESTEP_OK);
        }
        {
            const double kept = y;
            CHECK(odestep_step_d(&s, &sys, &y, 5 * 0.05, 0.1) == ODESTEP_STEP_MISMATCH); /* another dt */
            CHECK(odestep_step_d(&s, &sys, &y, 0.0, 0.05) == ODESTEP_STEP_MISMATCH);     /* another t */
            CHECK(y == kept);
            odestep_stepper_reset_d(&s);
            CHECK(odestep_step_d(&s, &sys, &y, 0.0, 0.1) == ODESTEP_OK); /* a new history */
        }
    }
}

/* The observer sees the initial state and every step, at t0 + i dt. */
typedef struct seen {
    int calls;
    double last_t;
    int times_right;
} seen;
static void observe_d(double t, const double* y, void* ctx) {
    seen* s = (seen*)ctx;
    if (t == 0.0 + s->calls * 0.25 && y[0] > 0.0) ++s->times_right;
    ++s->calls;
    s->last_t = t;
}
static void test_observer(void) {
    odestep_stepper_d s;
    const odestep_system_d sys = {decay1_d, NULL, 1};
    double y = 1.0;
    seen count = {0, -1.0, 0};
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    CHECK(odestep_integrate_d(&s, &sys, &y, 0.0, 2.0, 0.25, observe_d, &count, NULL) == ODESTEP_OK);
    CHECK(count.calls == 9);
    CHECK(count.times_right == 9);
    CHECK(count.last_t == 2.0);
}

/* ---- bad input: a distinct status, nothing touched */

static void test_bad_input(void) {
    odestep_stepper_d s;
    odestep_stepper_d newton;
    double k = 1.0;
    odestep_system_d sys = {decay_d, &k, 3};
    const odestep_newton_d spring = {spring_d, NULL, 1};
    double y[3] = {1.0, 2.0, 3.0};
    double x = 1.0;
    double v = 0.0;
    odestep_run_d run;
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    CHECK(odestep_stepper_init_d(&newton, &odestep_velocity_verlet_d) == ODESTEP_OK);

    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.0) == ODESTEP_INVALID_STEP);
    CHECK(odestep_step_d(&s, &sys, y, 0.0, NAN) == ODESTEP_INVALID_STEP);
    CHECK(odestep_step_d(&s, &sys, y, 0.0, INFINITY) == ODESTEP_INVALID_STEP);
    CHECK(odestep_step_d(&s, &sys, y, NAN, 0.1) == ODESTEP_INVALID_TIME);
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, 0.0, NULL, NULL, &run) == ODESTEP_INVALID_STEP);
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, NAN, NULL, NULL, &run) == ODESTEP_INVALID_STEP);
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, -0.1, NULL, NULL, &run) == ODESTEP_WRONG_DIRECTION);
    CHECK(run.steps == 0 && run.t == 0.0);
    CHECK(odestep_integrate_d(&s, &sys, y, NAN, 1.0, 0.1, NULL, NULL, &run) == ODESTEP_INVALID_TIME);
    CHECK(run.steps == 0 && isnan(run.t)); /* the time of y is the t0 given */
    CHECK(y[0] == 1.0 && y[1] == 2.0 && y[2] == 3.0);

    sys.n = (size_t)ODESTEP_C_MAX_STATES + 1;
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, 0.1, NULL, NULL, NULL) == ODESTEP_INVALID_SETTING);
    sys.n = 0;
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    sys.n = 3;
    sys.f = NULL;
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    sys.f = decay_d;
    CHECK(odestep_step_d(NULL, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_d(&s, NULL, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_d(&s, &sys, NULL, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stepper_init_d(&s, NULL) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    /* the other kind of system */
    CHECK(odestep_step_d(&newton, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_newton_d(&s, &spring, &x, &v, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_integrate_newton_d(&s, &spring, &x, &v, 0.0, 1.0, 0.1, NULL, NULL, NULL) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_newton_d(&newton, &spring, &x, &v, 0.0, 0.0) == ODESTEP_INVALID_STEP);
    CHECK(y[0] == 1.0 && y[1] == 2.0 && y[2] == 3.0 && x == 1.0 && v == 0.0);
    /* and then it works */
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_OK);
    CHECK(y[0] < 1.0);
}

/* ---- NaN: the step is rolled back, the loop stops at the last good state */

static void test_nan_roll_back(void) {
    odestep_stepper_d s;
    poison p = {0, 2}; /* the second evaluation (a stage of the first step) is NaN */
    const odestep_system_d sys = {poisoned_d, &p, 2};
    double y[2] = {1.0, 3.0};
    odestep_run_d run;
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_NON_FINITE);
    CHECK(y[0] == 1.0 && y[1] == 3.0);

    /* In the loop: steps 1 to 4 are good (4 evaluations each), the 5th step's first evaluation is NaN. */
    p.calls = 0;
    p.nan_from = 17;
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, 0.1, NULL, NULL, &run) == ODESTEP_NON_FINITE);
    CHECK(run.steps == 4);
    CHECK_CLOSE(run.t, 0.4, 1e-15);
    {
        /* the same four steps, by hand */
        double z[2] = {1.0, 3.0};
        int i;
        p.calls = 0;
        p.nan_from = 1000;
        for (i = 0; i < 4; ++i) {
            CHECK(odestep_step_d(&s, &sys, z, i * 0.1, 0.1) == ODESTEP_OK);
        }
        CHECK(y[0] == z[0] && y[1] == z[1]);
    }
}

/* ---- n below the maximum: only n values of the caller's arrays are read or written */

typedef struct guarded {
    double y[2];
    double guard[ODESTEP_C_MAX_STATES];
} guarded;
static void swing_d(double t, const double* y, double* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = y[1];
    dydt[1] = -y[0];
}
static void test_n_below_max(void) {
    odestep_stepper_d s;
    const odestep_system_d sys = {swing_d, NULL, 2};
    guarded g;
    double err[2 + ODESTEP_C_MAX_STATES];
    size_t i;
    g.y[0] = 1.0;
    g.y[1] = 0.0;
    for (i = 0; i < ODESTEP_C_MAX_STATES; ++i) {
        g.guard[i] = NAN; /* a NaN past n would fail the step if the library read it */
        err[2 + i] = 42.0;
    }
    CHECK(odestep_stepper_init_d(&s, &odestep_dp54_d) == ODESTEP_OK);
    CHECK(odestep_step_error_d(&s, &sys, g.y, 0.0, 0.1, err, NULL) == ODESTEP_OK);
    for (i = 0; i < ODESTEP_C_MAX_STATES; ++i) CHECK(isnan(g.guard[i]) && err[2 + i] == 42.0);
    CHECK_CLOSE(g.y[0], cos(0.1), 1e-9);
    CHECK_CLOSE(g.y[1], -sin(0.1), 1e-9);
}

/* ---- float */

/* RK4 in float on y' = -y over [0, 1]: exp(-1) to float's rounding (the method's error is 3e-7, about
 * 2 ulp at 0.37). Velocity Verlet in float keeps its modified energy to float rounding. */
static void test_float(void) {
    odestep_stepper_f s;
    const odestep_system_f sys = {decay1_f, NULL, 1};
    const odestep_newton_f spring = {spring_f, NULL, 1};
    float y = 1.0f;
    float x = 1.0f;
    float v = 0.0f;
    const float h = 0.125f;
    odestep_run_f run;
    odestep_method_info info;
    CHECK(odestep_stepper_init_f(&s, &odestep_rk4_f) == ODESTEP_OK);
    CHECK(odestep_integrate_f(&s, &sys, &y, 0.0f, 1.0f, 0.1f, NULL, NULL, &run) == ODESTEP_OK);
    CHECK(run.t == 1.0f && run.steps == 10);
    CHECK_CLOSE(y, exp(-1.0), 2e-6);
    CHECK(odestep_step_f(&s, &sys, &y, 0.0f, 0.0f) == ODESTEP_INVALID_STEP);
    CHECK(odestep_stepper_init_f(&s, &odestep_velocity_verlet_f) == ODESTEP_OK);
    CHECK(odestep_integrate_newton_f(&s, &spring, &x, &v, 0.0f, 100.0f, h, NULL, NULL, &run) == ODESTEP_OK);
    CHECK(run.steps == 800);
    CHECK_CLOSE(v * v + x * x * (1.0f - h * h / 4.0f), 1.0f - h * h / 4.0f, 1e-5);
    CHECK(odestep_method_info_f(&odestep_forest_ruth_f, &info) == ODESTEP_OK);
    CHECK(info.order == 4 && info.newtonian == 1 && strcmp(info.name, "forest_ruth") == 0);
}

/* ---- the rest of the interface */

static void test_names_and_info(void) {
    odestep_method_info info;
    CHECK(strcmp(odestep_status_name(ODESTEP_OK), "ok") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_NON_FINITE), "non_finite") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_INVALID_SETTING), "invalid_setting") == 0);
    CHECK(strcmp(odestep_status_name((odestep_status)99), "unknown") == 0);
    CHECK(odestep_max_states() == ODESTEP_C_MAX_STATES);
    CHECK(odestep_max_events() == ODESTEP_C_MAX_EVENTS);
    CHECK(odestep_method_info_d(&odestep_rk4_d, &info) == ODESTEP_OK);
    CHECK(info.order == 4 && info.error_estimates == 0 && info.newtonian == 0 && info.rhs_evals_per_step == 4);
    CHECK(odestep_method_info_d(&odestep_abm4_d, &info) == ODESTEP_OK);
    CHECK(info.order == 4 && info.uniform_steps == 1);
    CHECK(odestep_method_info_d(&odestep_dop853_d, &info) == ODESTEP_OK);
    CHECK(info.order == 8 && info.error_estimates == 2);
    /* Dormand-Prince 5(4): 7 stages, the 7th f(t + dt, y_new) (first same as last); the plain step does not
     * need it, the estimating step does, and the bound is the larger: 7 (Dormand & Prince 1980, Table 2). */
    CHECK(odestep_method_info_d(&odestep_dp54_d, &info) == ODESTEP_OK);
    CHECK(info.order == 5 && info.error_estimates == 1 && info.rhs_evals_per_step == 7);
    CHECK(odestep_method_info_d(&odestep_velocity_verlet_d, &info) == ODESTEP_OK);
    CHECK(info.order == 2 && info.newtonian == 1);
    CHECK(odestep_method_info_d(NULL, &info) == ODESTEP_INVALID_SETTING);
}

/* ---- the per-tick event loop */

/* A ball dropped from h0 = 1 m under g = 9.81 m/s^2, bouncing with restitution e = 0.8: y = (height,
 * velocity). Between bounces the motion is a parabola, which RK4 integrates exactly (y'' is constant: the
 * method is exact on polynomials of degree <= 4), so the bounce times are the closed form's to the root
 * finder's tolerance: t1 = sqrt(2 h0 / g), impact speed v1 = g t1, and bounce k+1 comes 2 e^k v1 / g after
 * bounce k. */
static const double gravity = 9.81;
static void ball_d(double t, const double* y, double* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = y[1];
    dydt[1] = -gravity;
}
static double height_d(double t, const double* y, void* ctx) {
    (void)t;
    (void)ctx;
    return y[0];
}
static double height_minus_half_d(double t, const double* y, void* ctx) {
    (void)t;
    (void)ctx;
    return y[0] - 0.5;
}
static odestep_event_result bounce_d(double t, double* y, void* ctx) {
    int* bounces = (int*)ctx;
    (void)t;
    y[1] = -0.8 * y[1];
    ++*bounces;
    return ODESTEP_PROCEED;
}
static double nan_g_d(double t, const double* y, void* ctx) {
    (void)t;
    (void)y;
    (void)ctx;
    return (double)NAN;
}

static void test_bouncing_ball(void) {
    odestep_event_loop_d loop;
    const odestep_system_d sys = {ball_d, NULL, 2};
    odestep_event_d ground;
    int bounces = 0;
    double y[2] = {1.0, 0.0};
    const double t1 = sqrt(2.0 * 1.0 / gravity);
    const double v1 = gravity * t1;
    double expected[3];
    int found = 0;
    int k;
    expected[0] = t1;
    expected[1] = t1 + 2.0 * 0.8 * v1 / gravity;
    expected[2] = expected[1] + 2.0 * 0.64 * v1 / gravity;
    (void)memset(&ground, 0, sizeof ground);
    ground.g = height_d;
    ground.direction = ODESTEP_FALLING;
    ground.action = bounce_d;
    ground.ctx = &bounces;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, &ground, 1, NULL, &sys, y, 0.0, 0.01) == ODESTEP_OK);
    for (k = 0; k < 200; ++k) { /* 2 s of 10 ms ticks: three bounces (at 0.45, 1.17 and 1.75 s) */
        odestep_tick_d tick;
        CHECK(odestep_event_loop_tick_d(&loop, &sys, y, &tick) == ODESTEP_OK);
        CHECK_CLOSE(tick.t, (k + 1) * 0.01, 1e-12);
        if (tick.fired > 0 && found < 3) {
            CHECK(tick.fired == 1 && tick.firings[0].event == 0);
            CHECK_CLOSE(tick.firings[0].t, expected[found], 1e-9);
            ++found;
        }
    }
    CHECK(found == 3 && bounces == 3);
    CHECK(odestep_event_loop_firings_d(&loop, 0) == 3);
    CHECK_CLOSE(odestep_event_loop_time_d(&loop), 2.0, 1e-12);
}

/* A terminal event (no action): the tick stops where the height is 0.5, t = sqrt(2 (1 - 0.5) / g), and y is
 * the state then; the next tick completes the stopped period (to 0.4) and then its own, to 0.5 (the per-tick
 * contract: one call is one period, docs/events.md). A second event in the array that never fires
 * (rising) does not disturb it. */
static void test_terminal_event(void) {
    odestep_event_loop_d loop;
    const odestep_system_d sys = {ball_d, NULL, 2};
    odestep_event_d events[2];
    double y[2] = {1.0, 0.0};
    const double t_half = sqrt(2.0 * 0.5 / gravity);
    odestep_tick_d tick;
    odestep_status s = ODESTEP_OK;
    int k;
    (void)memset(&tick, 0, sizeof tick);
    (void)memset(events, 0, sizeof events);
    events[0].g = height_d;
    events[0].direction = ODESTEP_RISING;
    events[1].g = height_minus_half_d;
    events[1].direction = ODESTEP_FALLING;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_dp54_d, events, 2, NULL, &sys, y, 0.0, 0.1) == ODESTEP_OK);
    for (k = 0; k < 10 && s == ODESTEP_OK; ++k) s = odestep_event_loop_tick_d(&loop, &sys, y, &tick);
    CHECK(s == ODESTEP_STOPPED_BY_EVENT);
    CHECK(k == 4 && tick.event == 1 && tick.fired == 1);
    CHECK_CLOSE(tick.t, t_half, 1e-9);
    CHECK_CLOSE(y[0], 0.5, 1e-9);
    CHECK_CLOSE(odestep_event_loop_time_d(&loop), t_half, 1e-9);
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, &tick) == ODESTEP_OK);
    CHECK_CLOSE(tick.t, 0.5, 1e-15);
}

static void test_event_bad_input(void) {
    odestep_event_loop_d loop;
    const odestep_system_d sys = {ball_d, NULL, 2};
    odestep_system_d other = {ball_d, NULL, 1};
    odestep_event_d events[ODESTEP_C_MAX_EVENTS + 1];
    double y[2] = {1.0, 0.0};
    size_t i;
    (void)memset(&loop, 0, sizeof loop);
    (void)memset(events, 0, sizeof events);
    for (i = 0; i <= ODESTEP_C_MAX_EVENTS; ++i) {
        events[i].g = height_d;
        events[i].direction = ODESTEP_FALLING;
    }
    /* a zeroed loop refuses to tick */
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, NULL) == ODESTEP_INVALID_TIME);
    CHECK(isnan(odestep_event_loop_time_d(&loop)));
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 0, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_INVALID_SETTING);
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, ODESTEP_C_MAX_EVENTS + 1, NULL, &sys, y, 0.0,
                                     0.01) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_event_loop_start_d(&loop, &odestep_velocity_verlet_d, events, 1, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_INVALID_SETTING);
    events[0].direction = (odestep_direction)7;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_INVALID_SETTING);
    events[0].direction = ODESTEP_FALLING;
    events[0].g = NULL;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_INVALID_SETTING);
    events[0].g = height_d;
    events[0].tolerance = -1.0;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_INVALID_TOLERANCE);
    events[0].tolerance = 0.0;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.0) ==
          ODESTEP_INVALID_STEP);
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, NAN, 0.01) ==
          ODESTEP_INVALID_TIME);
    events[0].g = nan_g_d;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.01) ==
          ODESTEP_NON_FINITE_EVENT);
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, NULL) == ODESTEP_INVALID_TIME); /* not started */
    events[0].g = height_d;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &sys, y, 0.0, 0.01) == ODESTEP_OK);
    CHECK(odestep_event_loop_tick_d(&loop, &other, y, NULL) == ODESTEP_INVALID_SETTING); /* another n */
    CHECK(y[0] == 1.0 && y[1] == 0.0);
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, NULL) == ODESTEP_OK);
    CHECK(y[0] < 1.0);
}

/* NaN from the right-hand side inside a tick: the tick is rolled back, y stays at the last tick's end. */
static void test_event_nan(void) {
    odestep_event_loop_d loop;
    poison p = {0, 1000};
    const odestep_system_d sys = {poisoned_d, &p, 2};
    odestep_event_d e;
    double y[2] = {1.0, 3.0};
    double kept[2];
    odestep_tick_d tick;
    (void)memset(&e, 0, sizeof e);
    e.g = height_minus_half_d;
    e.direction = ODESTEP_EITHER;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, &e, 1, NULL, &sys, y, 0.0, 0.1) == ODESTEP_OK);
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, &tick) == ODESTEP_OK);
    kept[0] = y[0];
    kept[1] = y[1];
    p.nan_from = p.calls + 2;
    CHECK(odestep_event_loop_tick_d(&loop, &sys, y, &tick) == ODESTEP_NON_FINITE);
    CHECK(y[0] == kept[0] && y[1] == kept[1]);
    CHECK_CLOSE(tick.t, 0.1, 1e-15);
}

/* A tick rolled back after the stepper stepped (g NaN at the step's end: ODESTEP_NON_FINITE_EVENT) leaves the
 * stepper as it was, as the C++ loops leave it: an Adams-Bashforth 4 history goes on, and the ticks after the
 * failed one give, bit for bit, what a loop that never had it gives (a stepper reset there would restart
 * its history and step differently). g never crosses zero here (y[0] stays in [-1, 1]). */
typedef struct flaky {
    int calls;
    int nan_at; /* the call of g that returns NaN (0: none) */
} flaky;
static double flaky_g_d(double t, const double* y, void* ctx) {
    flaky* f = (flaky*)ctx;
    (void)t;
    ++f->calls;
    return f->calls == f->nan_at ? (double)NAN : y[0] + 10.0;
}
static void test_event_roll_back_keeps_history(void) {
    odestep_event_loop_d plain;
    odestep_event_loop_d failing;
    const odestep_system_d sys = {swing_d, NULL, 2};
    odestep_event_d e_plain;
    odestep_event_d e_failing;
    flaky f_plain = {0, 0};
    flaky f_failing = {0, 0};
    double y_plain[2] = {1.0, 0.0};
    double y_failing[2] = {1.0, 0.0};
    double kept[2];
    odestep_tick_d tick;
    int k;
    (void)memset(&e_plain, 0, sizeof e_plain);
    e_plain.g = flaky_g_d;
    e_plain.direction = ODESTEP_EITHER;
    e_failing = e_plain;
    e_plain.ctx = &f_plain;
    e_failing.ctx = &f_failing;
    CHECK(odestep_event_loop_start_d(&plain, &odestep_ab4_d, &e_plain, 1, NULL, &sys, y_plain, 0.0, 0.1) == ODESTEP_OK);
    CHECK(odestep_event_loop_start_d(&failing, &odestep_ab4_d, &e_failing, 1, NULL, &sys, y_failing, 0.0, 0.1) ==
          ODESTEP_OK);
    for (k = 0; k < 6; ++k) { /* past AB4's start: its history is full */
        CHECK(odestep_event_loop_tick_d(&plain, &sys, y_plain, &tick) == ODESTEP_OK);
        CHECK(odestep_event_loop_tick_d(&failing, &sys, y_failing, &tick) == ODESTEP_OK);
    }
    kept[0] = y_failing[0];
    kept[1] = y_failing[1];
    f_failing.nan_at = f_failing.calls + 1; /* the next g: at the next step's end */
    CHECK(odestep_event_loop_tick_d(&failing, &sys, y_failing, &tick) == ODESTEP_NON_FINITE_EVENT);
    CHECK(y_failing[0] == kept[0] && y_failing[1] == kept[1]);
    for (k = 0; k < 6; ++k) {
        CHECK(odestep_event_loop_tick_d(&plain, &sys, y_plain, &tick) == ODESTEP_OK);
        CHECK(odestep_event_loop_tick_d(&failing, &sys, y_failing, &tick) == ODESTEP_OK);
    }
    CHECK(y_plain[0] == y_failing[0] && y_plain[1] == y_failing[1]);
    CHECK_CLOSE(odestep_event_loop_time_d(&failing), 1.2, 1e-15);
}

/* The ball again as Newton's equations, x'' = -g, with velocity Verlet: its step is exact for a constant
 * acceleration (x + v h + a h^2 / 2, v + a h), so the bounce times are the closed form's as above. */
static void fall_d(double t, const double* x, double* a, void* ctx) {
    (void)t;
    (void)x;
    (void)ctx;
    a[0] = -gravity;
}
static double floor_d(double t, const double* x, const double* v, void* ctx) {
    (void)t;
    (void)v;
    (void)ctx;
    return x[0];
}
static odestep_event_result kick_d(double t, double* x, double* v, void* ctx) {
    (void)t;
    (void)x;
    (void)ctx;
    v[0] = -0.8 * v[0];
    return ODESTEP_PROCEED;
}
static void test_newton_events(void) {
    odestep_newton_event_loop_d loop;
    const odestep_newton_d sys = {fall_d, NULL, 1};
    const odestep_system_d first_order = {ball_d, NULL, 2};
    odestep_newton_event_d ground;
    double x = 1.0;
    double v = 0.0;
    const double t1 = sqrt(2.0 * 1.0 / gravity);
    const double v1 = gravity * t1;
    double expected = t1;
    double gap = 2.0 * 0.8 * v1 / gravity;
    int found = 0;
    int k;
    (void)memset(&ground, 0, sizeof ground);
    ground.g = floor_d;
    ground.direction = ODESTEP_FALLING;
    ground.action = kick_d;
    (void)first_order;
    CHECK(odestep_newton_event_loop_start_d(&loop, &odestep_rk4_d, &ground, 1, NULL, &sys, &x, &v, 0.0, 0.01) ==
          ODESTEP_INVALID_SETTING); /* a first-order method */
    CHECK(odestep_newton_event_loop_tick_d(&loop, &sys, &x, &v, NULL) == ODESTEP_INVALID_TIME);
    CHECK(odestep_newton_event_loop_start_d(&loop, &odestep_velocity_verlet_d, &ground, 1, NULL, &sys, &x, NULL, 0.0,
                                            0.01) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_newton_event_loop_start_d(&loop, &odestep_velocity_verlet_d, &ground, 1, NULL, &sys, &x, &v, 0.0,
                                            0.01) == ODESTEP_OK);
    for (k = 0; k < 200; ++k) {
        odestep_tick_d tick;
        CHECK(odestep_newton_event_loop_tick_d(&loop, &sys, &x, &v, &tick) == ODESTEP_OK);
        if (tick.fired > 0 && found < 3) {
            CHECK_CLOSE(tick.firings[0].t, expected, 1e-9);
            ++found;
            expected += gap;
            gap *= 0.8;
        }
    }
    CHECK(found == 3 && odestep_newton_event_loop_firings_d(&loop, 0) == 3);
    CHECK_CLOSE(odestep_newton_event_loop_time_d(&loop), 2.0, 1e-12);
    /* a terminal event: stop at the floor, x = 0 there */
    x = 1.0;
    v = 0.0;
    ground.action = NULL;
    CHECK(odestep_newton_event_loop_start_d(&loop, &odestep_forest_ruth_d, &ground, 1, NULL, &sys, &x, &v, 0.0, 0.01) ==
          ODESTEP_OK);
    for (k = 0; k < 100; ++k) {
        odestep_tick_d tick;
        const odestep_status s = odestep_newton_event_loop_tick_d(&loop, &sys, &x, &v, &tick);
        if (s != ODESTEP_OK) {
            CHECK(s == ODESTEP_STOPPED_BY_EVENT && tick.event == 0);
            CHECK_CLOSE(tick.t, t1, 1e-9);
            CHECK_CLOSE(x, 0.0, 1e-9);
            CHECK_CLOSE(v, -v1, 1e-9);
            break;
        }
    }
    CHECK(k == 45); /* t1 = 0.4515 s: in the 46th tick */
    CHECK(odestep_newton_event_loop_rearm_d(&loop, &x, &v) == ODESTEP_OK);
}

/* Velocity Verlet with the acceleration kept by the caller: one evaluation a step, and the same x and v, bit
 * for bit, as the loop (which keeps it itself). A method that keeps nothing refuses the form. */
static int spring_calls = 0;
static void counted_spring_d(double t, const double* x, double* a, void* ctx) {
    (void)t;
    (void)ctx;
    ++spring_calls;
    a[0] = -x[0];
}
static void test_verlet_kept(void) {
    odestep_stepper_d s;
    const odestep_newton_d sys = {counted_spring_d, NULL, 1};
    double x = 1.0;
    double v = 0.0;
    double acc = 0.0;
    double xl = 1.0;
    double vl = 0.0;
    int i;
    CHECK(odestep_stepper_init_d(&s, &odestep_velocity_verlet_d) == ODESTEP_OK);
    counted_spring_d(0.0, &x, &acc, NULL); /* a(t0, x0), once */
    spring_calls = 0;
    for (i = 0; i < 100; ++i) {
        CHECK(odestep_step_newton_kept_d(&s, &sys, &x, &v, &acc, i * 0.1, 0.1) == ODESTEP_OK);
    }
    CHECK(spring_calls == 100);
    CHECK(acc == -x);
    CHECK(odestep_integrate_newton_d(&s, &sys, &xl, &vl, 0.0, 10.0, 0.1, NULL, NULL, NULL) == ODESTEP_OK);
    CHECK(x == xl && v == vl);
    CHECK(odestep_step_newton_kept_d(&s, &sys, &x, &v, NULL, 10.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stepper_init_d(&s, &odestep_euler_cromer_d) == ODESTEP_OK);
    CHECK(odestep_step_newton_kept_d(&s, &sys, &x, &v, &acc, 10.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(x == xl && v == vl);
}

/* ---- every status the C API returns, each reached by a call whose cause is plain, and told apart by value */

static double after_first_d(double t, const double* y, void* ctx) {
    (void)y;
    (void)ctx;
    return t - 0.25;
}
static double after_second_d(double t, const double* y, void* ctx) {
    (void)y;
    (void)ctx;
    return t - 0.75;
}
static odestep_event_result proceed_d(double t, double* y, void* ctx) {
    (void)t;
    (void)y;
    (void)ctx;
    return ODESTEP_PROCEED;
}

/* The statuses a C method can give, one call each (the C++ statuses no_convergence, singular_matrix,
 * substep_limit and step_too_small come from the implicit, Rosenbrock and adaptive steppers, which the C API
 * does not offer: no C call returns them, and the names below are all a C caller can meet of them). */
static void test_every_status(void) {
    odestep_stepper_d s;
    odestep_stepper_d adams;
    odestep_event_loop_d loop;
    double k = 1.0;
    const odestep_system_d sys = {decay_d, &k, 3};
    const odestep_system_d ball = {ball_d, NULL, 2};
    const odestep_system_d null_f = {NULL, NULL, 3};
    poison p = {0, 1};
    const odestep_system_d poisoned = {poisoned_d, &p, 2};
    odestep_event_d events[2];
    odestep_event_limits one_firing = {0, 1, 0};
    odestep_tick_d tick;
    double y[3] = {1.0, 2.0, 3.0};
    double h[2] = {1.0, 0.0};
    odestep_run_d run;
    (void)memset(&tick, 0, sizeof tick);
    (void)memset(events, 0, sizeof events);
    CHECK(odestep_stepper_init_d(&s, &odestep_rk4_d) == ODESTEP_OK);
    CHECK(odestep_stepper_init_d(&adams, &odestep_ab4_d) == ODESTEP_OK);

    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_OK);
    CHECK(odestep_step_d(&s, &sys, y, INFINITY, 0.1) == ODESTEP_INVALID_TIME);
    CHECK(odestep_step_d(&s, &sys, y, 0.0, 0.0) == ODESTEP_INVALID_STEP);
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1.0, -0.1, NULL, NULL, &run) == ODESTEP_WRONG_DIRECTION);
    /* 1e300 / 1e-300 steps: past the 2^62 the step counter allows (detail/grid_clock.hpp, plan_run) */
    CHECK(odestep_integrate_d(&s, &sys, y, 0.0, 1e300, 1e-300, NULL, NULL, &run) == ODESTEP_TOO_MANY_STEPS);
    CHECK(run.steps == 0 && run.t == 0.0);
    /* the first evaluation is NaN */
    CHECK(odestep_step_d(&s, &poisoned, h, 0.0, 0.1) == ODESTEP_NON_FINITE);
    CHECK(p.calls >= 1 && h[0] == 1.0 && h[1] == 0.0);
    /* AB4 needs one dt for its whole history: 1 / 0.3 ends on a shorter step */
    CHECK(odestep_integrate_d(&adams, &sys, y, 0.0, 1.0, 0.3, NULL, NULL, &run) == ODESTEP_STEP_MISMATCH);
    CHECK(odestep_step_d(&s, &null_f, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);

    /* the event loop: a negative tolerance; a g that is NaN at the start */
    events[0].g = after_first_d;
    events[0].direction = ODESTEP_RISING;
    events[0].tolerance = -1.0;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &ball, h, 0.0, 1.0) ==
          ODESTEP_INVALID_TOLERANCE);
    events[0].tolerance = 0.0;
    events[0].g = nan_g_d;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &ball, h, 0.0, 1.0) ==
          ODESTEP_NON_FINITE_EVENT);
    /* a terminal event at t = 0.25 inside the tick [0, 1] */
    events[0].g = after_first_d;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 1, NULL, &ball, h, 0.0, 1.0) == ODESTEP_OK);
    CHECK(odestep_event_loop_tick_d(&loop, &ball, h, &tick) == ODESTEP_STOPPED_BY_EVENT);
    CHECK_CLOSE(tick.t, 0.25, 1e-12);
    /* two events that proceed, at t = 0.25 and 0.75, in a tick that allows one firing */
    events[0].action = proceed_d;
    events[1].g = after_second_d;
    events[1].direction = ODESTEP_RISING;
    events[1].action = proceed_d;
    h[0] = 1.0;
    h[1] = 0.0;
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, events, 2, &one_firing, &ball, h, 0.0, 1.0) == ODESTEP_OK);
    CHECK(odestep_event_loop_tick_d(&loop, &ball, h, &tick) == ODESTEP_EVENT_LIMIT);
    CHECK(tick.fired == 1 && tick.firings[0].event == 0);

    /* each value has its own name */
    CHECK(strcmp(odestep_status_name(ODESTEP_TOO_MANY_STEPS), "too_many_steps") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_EVENT_LIMIT), "event_limit") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_NO_CONVERGENCE), "no_convergence") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_SINGULAR_MATRIX), "singular_matrix") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_SUBSTEP_LIMIT), "substep_limit") == 0);
    CHECK(strcmp(odestep_status_name(ODESTEP_STEP_TOO_SMALL), "step_too_small") == 0);
}

/* ---- counts: the run's counts against the system's own count of its calls */

/* y' = -y and x'' = -x that count their calls in *ctx. */
static void counted_decay_d(double t, const double* y, double* dydt, void* ctx) {
    (void)t;
    ++*(uint64_t*)ctx;
    dydt[0] = -y[0];
}
static void counted_decay_f(float t, const float* y, float* dydt, void* ctx) {
    (void)t;
    ++*(uint64_t*)ctx;
    dydt[0] = -y[0];
}
static void spring_counting_ctx_d(double t, const double* x, double* a, void* ctx) {
    (void)t;
    ++*(uint64_t*)ctx;
    a[0] = -x[0];
}

/* Every loop's run.counts: f's evaluations as f counted them (RK4: 4 a step; Adams-Bashforth 4: RK4's 4 for
 * its first three steps, then 1; velocity Verlet in the loop: 1 a step and the first acceleration), the
 * completed steps as accepted, zero for what a fixed-step explicit method does not do. */
static void test_counts(void) {
    const odestep_method_d* methods[3] = {&odestep_rk4_d, &odestep_ab4_d, &odestep_dop853_d};
    size_t m;
    for (m = 0; m < 3; ++m) {
        uint64_t calls = 0;
        const odestep_system_d sys = {counted_decay_d, &calls, 1};
        odestep_stepper_d s;
        double y = 1.0;
        odestep_run_d run;
        CHECK(odestep_stepper_init_d(&s, methods[m]) == ODESTEP_OK);
        CHECK(odestep_integrate_d(&s, &sys, &y, 0.0, 1.0, 0.05, NULL, NULL, &run) == ODESTEP_OK);
        CHECK(run.counts.rhs_evals == calls);
        CHECK(run.counts.accepted_steps == run.steps && run.steps == 20);
        CHECK(run.counts.rejected_steps == 0 && run.counts.jacobian_evals == 0 && run.counts.factorizations == 0);
        CHECK(run.counts.newton_iterations == 0 && run.counts.event_evals == 0 && run.counts.firings == 0);
        if (m == 0u) {
            CHECK(calls == 80u); /* RK4: 4 evaluations a step, 20 steps */
        }
    }
    {
        uint64_t calls = 0;
        const odestep_newton_d sys = {spring_counting_ctx_d, &calls, 1};
        odestep_stepper_d s;
        double x = 1.0;
        double v = 0.0;
        odestep_run_d run;
        CHECK(odestep_stepper_init_d(&s, &odestep_velocity_verlet_d) == ODESTEP_OK);
        CHECK(odestep_integrate_newton_d(&s, &sys, &x, &v, 0.0, 1.0, 0.1, NULL, NULL, &run) == ODESTEP_OK);
        CHECK(run.counts.rhs_evals == calls);
        CHECK(run.counts.accepted_steps == 10);
    }
    {
        uint64_t calls = 0;
        const odestep_system_f sys = {counted_decay_f, &calls, 1};
        odestep_stepper_f s;
        float y = 1.0f;
        odestep_run_f run;
        CHECK(odestep_stepper_init_f(&s, &odestep_rk4_f) == ODESTEP_OK);
        CHECK(odestep_integrate_f(&s, &sys, &y, 0.0f, 1.0f, 0.25f, NULL, NULL, &run) == ODESTEP_OK);
        CHECK(run.counts.rhs_evals == calls && calls == 16);
        CHECK(run.counts.accepted_steps == 4);
    }
}

/* The event loop's counts since start: f and g counted by themselves (ctx), the bounces by the action. */
typedef struct counted_ball {
    uint64_t f_calls;
    uint64_t g_calls;
    int bounces;
} counted_ball;
static void counted_ball_d(double t, const double* y, double* dydt, void* ctx) {
    ++((counted_ball*)ctx)->f_calls;
    ball_d(t, y, dydt, NULL);
}
static double counted_height_d(double t, const double* y, void* ctx) {
    ++((counted_ball*)ctx)->g_calls;
    return height_d(t, y, NULL);
}
static odestep_event_result counted_bounce_d(double t, double* y, void* ctx) {
    return bounce_d(t, y, &((counted_ball*)ctx)->bounces);
}
static void test_event_counts(void) {
    odestep_event_loop_d loop;
    counted_ball c = {0, 0, 0};
    const odestep_system_d sys = {counted_ball_d, &c, 2};
    odestep_event_d ground;
    odestep_counts counts;
    double y[2] = {1.0, 0.0};
    int k;
    (void)memset(&ground, 0, sizeof ground);
    ground.g = counted_height_d;
    ground.direction = ODESTEP_FALLING;
    ground.action = counted_bounce_d;
    ground.ctx = &c;
    (void)memset(&loop, 0, sizeof loop);
    CHECK(odestep_event_loop_counts_d(&loop, &counts) == ODESTEP_INVALID_TIME); /* before start */
    CHECK(odestep_event_loop_counts_d(&loop, NULL) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_event_loop_start_d(&loop, &odestep_rk4_d, &ground, 1, NULL, &sys, y, 0.0, 0.01) == ODESTEP_OK);
    for (k = 0; k < 200; ++k) {
        CHECK(odestep_event_loop_tick_d(&loop, &sys, y, NULL) == ODESTEP_OK);
    }
    CHECK(odestep_event_loop_counts_d(&loop, &counts) == ODESTEP_OK);
    CHECK(counts.rhs_evals == c.f_calls);
    CHECK(counts.event_evals == c.g_calls);
    CHECK(counts.firings == (uint64_t)c.bounces && c.bounces == 3);
    CHECK(counts.accepted_steps == 200);
    CHECK(counts.jacobian_evals == 0 && counts.factorizations == 0 && counts.rejected_steps == 0);
}

int main(void) {
    test_rk4_decay();
    test_euler_decay();
    test_second_order_decay();
    test_error_estimates();
    test_dop853_loop();
    test_verlet_energy();
    test_euler_cromer_energy();
    test_forest_ruth_period();
    test_adams();
    test_observer();
    test_bad_input();
    test_nan_roll_back();
    test_n_below_max();
    test_float();
    test_names_and_info();
    test_bouncing_ball();
    test_terminal_event();
    test_event_bad_input();
    test_event_nan();
    test_event_roll_back_keeps_history();
    test_newton_events();
    test_verlet_kept();
    test_every_status();
    test_counts();
    test_event_counts();
    (void)printf("c api tests: %d failed checks\n", check_failures);
    return check_failures == 0 ? 0 : 1;
}
