/* SPDX-License-Identifier: BSL-1.0 */
/* The C API's stiff and error-controlled steppers and its steps with Phi (odestep_stiff_*,
 * odestep_step_transition_*) tested from C99: Robertson from its natural start, a stiff decay against its closed
 * form, Phi against the stability polynomial, bad input and failures with the state untouched. Runs on the host
 * and, cross-compiled, on the emulated Cortex-M cores. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "odestep/odestep.h"

int check_failures = 0;

/* ---- systems */

/* Robertson's reactions (Robertson 1966; Hairer & Wanner, Solving ODE II, Sec. IV.1):
 * y1' = -0.04 y1 + 1e4 y2 y3, y2' = 0.04 y1 - 1e4 y2 y3 - 3e7 y2^2, y3' = 3e7 y2^2. */
static void robertson_d(double t, const double* y, double* dydt, void* ctx) {
    const double a = 0.04 * y[0];
    const double b = 1e4 * y[1] * y[2];
    const double c = 3e7 * y[1] * y[1];
    (void)t;
    (void)ctx;
    dydt[0] = -a + b;
    dydt[1] = a - b - c;
    dydt[2] = c;
}
static void robertson_jacobian_d(double t, const double* y, double* j, void* ctx) {
    (void)t;
    (void)ctx;
    j[0] = -0.04;
    j[1] = 1e4 * y[2];
    j[2] = 1e4 * y[1];
    j[6] = 0.0;
    j[7] = 6e7 * y[1];
    j[8] = 0.0;
    j[3] = 0.04;
    j[4] = -1e4 * y[2] - 6e7 * y[1];
    j[5] = -1e4 * y[1];
}
static void robertson_f(float t, const float* y, float* dydt, void* ctx) {
    const float a = 0.04f * y[0];
    const float b = 1e4f * y[1] * y[2];
    const float c = 3e7f * y[1] * y[1];
    (void)t;
    (void)ctx;
    dydt[0] = -a + b;
    dydt[1] = a - b - c;
    dydt[2] = c;
}
static void robertson_jacobian_f(float t, const float* y, float* j, void* ctx) {
    (void)t;
    (void)ctx;
    j[0] = -0.04f;
    j[1] = 1e4f * y[2];
    j[2] = 1e4f * y[1];
    j[6] = 0.0f;
    j[7] = 6e7f * y[1];
    j[8] = 0.0f;
    j[3] = 0.04f;
    j[4] = -1e4f * y[2] - 6e7f * y[1];
    j[5] = -1e4f * y[1];
}

/* Robertson at t = 40 from (1, 0, 0): SciPy 1.10.1 solve_ivp(method="Radau", rtol=1e-12, atol=1e-20, exact
 * Jacobian), the values of tests/stiff/radau5_test.cpp; Hairer & Wanner's ten digits at t = 40 (Solving ODE II,
 * the ROBER problem: 0.7158270687, 0.9185534764e-5, 0.2841637457) agree to their last digit. */
static const double robertson_40[3] = {0.7158270687194083, 9.185534764557791e-06, 0.28416374574583075};

/* y' = -1000 (y - cos t), y(0) = 0: a stiff decay onto a slow solution (Hairer & Wanner II, Sec. IV.1's
 * y' = -50 (y - cos x), with 1000). Closed form: y = A cos t + B sin t - A e^(-1000 t) with A = 1e6 / (1e6 + 1),
 * B = 1e3 / (1e6 + 1) (the particular solution A cos t + B sin t solves B + 1000 A = 1000, 1000 B - A = 0). */
static void stiff_decay_d(double t, const double* y, double* dydt, void* ctx) {
    (void)ctx;
    dydt[0] = -1000.0 * (y[0] - cos(t));
}
static void stiff_decay_jacobian_d(double t, const double* y, double* j, void* ctx) {
    (void)t;
    (void)y;
    (void)ctx;
    j[0] = -1000.0;
}
static double stiff_decay_exact(double t) {
    const double a = 1e6 / (1e6 + 1.0);
    const double b = 1e3 / (1e6 + 1.0);
    return a * cos(t) + b * sin(t) - a * exp(-1000.0 * t);
}

/* A Jacobian callback that returns NaN: its failure must not touch the state. */
static void nan_jacobian_d(double t, const double* y, double* j, void* ctx) {
    const size_t n = *(const size_t*)ctx;
    size_t i;
    (void)t;
    (void)y;
    for (i = 0; i < n * n; ++i) {
        j[i] = (double)NAN;
    }
}
/* f for the NaN-Jacobian systems: y' = -y (ctx: the size n). */
static void decay_n_d(double t, const double* y, double* dydt, void* ctx) {
    const size_t n = *(const size_t*)ctx;
    size_t i;
    (void)t;
    for (i = 0; i < n; ++i) {
        dydt[i] = -y[i];
    }
}

/* y' = A y with a fixed 3 x 3 A (row-major, ctx unused): the linear system of the Phi tests. */
static const double linear_a[9] = {-1.0, 2.0, 0.5, -3.0, -4.0, 1.0, 0.25, -0.5, -2.0};
static void linear_d(double t, const double* y, double* dydt, void* ctx) {
    size_t i;
    (void)t;
    (void)ctx;
    for (i = 0; i < 3; ++i) dydt[i] = linear_a[3 * i] * y[0] + linear_a[3 * i + 1] * y[1] + linear_a[3 * i + 2] * y[2];
}
static void linear_jacobian_d(double t, const double* y, double* j, void* ctx) {
    (void)t;
    (void)y;
    (void)ctx;
    (void)memcpy(j, linear_a, sizeof linear_a);
}
static const float linear_a_f[9] = {-1.0f, 2.0f, 0.5f, -3.0f, -4.0f, 1.0f, 0.25f, -0.5f, -2.0f};
static void linear_f(float t, const float* y, float* dydt, void* ctx) {
    size_t i;
    (void)t;
    (void)ctx;
    for (i = 0; i < 3; ++i)
        dydt[i] = linear_a_f[3 * i] * y[0] + linear_a_f[3 * i + 1] * y[1] + linear_a_f[3 * i + 2] * y[2];
}
static void linear_jacobian_f(float t, const float* y, float* j, void* ctx) {
    (void)t;
    (void)y;
    (void)ctx;
    (void)memcpy(j, linear_a_f, sizeof linear_a_f);
}

/* ---- helpers */

static double relative_error(double value, double reference) { return fabs(value / reference - 1.0); }

/* c = a b for 3 x 3 row-major matrices. */
static void multiply3(const double* a, const double* b, double* c) {
    size_t i;
    size_t j;
    size_t k;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double sum = 0.0;
            for (k = 0; k < 3; ++k) sum += a[3 * i + k] * b[3 * k + j];
            c[3 * i + j] = sum;
        }
}

/* R(hA) = sum_k coefficient[k] (hA)^k for k = 0 .. degree: a method's stability polynomial at the matrix hA,
 * computed here from its coefficients, independently of the library. */
static void matrix_polynomial(const double* coefficient, size_t degree, double h, double* r) {
    double power[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}; /* (hA)^k */
    double ha[9];
    double next[9];
    size_t i;
    size_t k;
    for (i = 0; i < 9; ++i) {
        ha[i] = h * linear_a[i];
        r[i] = coefficient[0] * power[i];
    }
    for (k = 1; k <= degree; ++k) {
        multiply3(power, ha, next);
        for (i = 0; i < 9; ++i) {
            power[i] = next[i];
            r[i] += coefficient[k] * power[i];
        }
    }
}

/* ---- Robertson from its natural start, through the error-controlled objects */

/* From y0 = (1, 0, 0), the start where every fixed-step implicit stepper fails (issue 25), on the course's 0.1
 * grid to t = 40 (t_i = i / 10 from the counter): every interval ok and the end within 10 rtol of the reference
 * in every component. */
static void run_robertson_d(const odestep_stiff_method_d* method, odestep_jacobian_d jacobian, double rtol,
                            double atol) {
    odestep_stiff_stepper_d s;
    const odestep_jac_system_d sys = {robertson_d, jacobian, NULL, 3};
    double y[3] = {1.0, 0.0, 0.0};
    int i;
    int failed = 0;
    CHECK(odestep_stiff_init_d(&s, method, 3, rtol, atol) == ODESTEP_OK);
    for (i = 0; i < 400 && failed == 0; ++i) {
        const odestep_status r = odestep_stiff_step_d(&s, &sys, y, i * 0.1, 0.1);
        CHECK(r == ODESTEP_OK);
        if (r != ODESTEP_OK) {
            failed = 1;
        }
    }
    CHECK(relative_error(y[0], robertson_40[0]) <= 10.0 * rtol);
    CHECK(relative_error(y[1], robertson_40[1]) <= 10.0 * rtol);
    CHECK(relative_error(y[2], robertson_40[2]) <= 10.0 * rtol);
    CHECK_CLOSE(y[0] + y[1] + y[2], 1.0, 1e-12); /* the reactions conserve the total mass */
}

static void test_robertson_radau5(void) {
    run_robertson_d(&odestep_radau5_substeps_d, robertson_jacobian_d, 1e-6, 1e-10);
    /* A null Jacobian: forward differences of f (linalg/jacobian.hpp). */
    run_robertson_d(&odestep_radau5_substeps_d, NULL, 1e-6, 1e-10);
}

static void test_robertson_rodas4(void) {
    run_robertson_d(&odestep_rodas4_substeps_d, robertson_jacobian_d, 1e-6, 1e-10);
}

/* float: rtol 1e-3, within 1e-2 of the reference (issue 25's float criterion). */
static void test_robertson_radau5_float(void) {
    odestep_stiff_stepper_f s;
    const odestep_jac_system_f sys = {robertson_f, robertson_jacobian_f, NULL, 3};
    float y[3] = {1.0f, 0.0f, 0.0f};
    int i;
    int failed = 0;
    CHECK(odestep_stiff_init_f(&s, &odestep_radau5_substeps_f, 3, 1e-3f, 1e-7f) == ODESTEP_OK);
    for (i = 0; i < 400 && failed == 0; ++i) {
        const odestep_status r = odestep_stiff_step_f(&s, &sys, y, (float)i * 0.1f, 0.1f);
        CHECK(r == ODESTEP_OK);
        if (r != ODESTEP_OK) {
            failed = 1;
        }
    }
    CHECK(relative_error((double)y[0], robertson_40[0]) <= 1e-2);
    CHECK(relative_error((double)y[1], robertson_40[1]) <= 1e-2);
    CHECK(relative_error((double)y[2], robertson_40[2]) <= 1e-2);
}

/* ---- the stiff decay against its closed form */

/* Every interval of a 0.1 grid to t = 2 ok, each grid value within the given bound of the closed form. */
static double worst_stiff_decay(const odestep_stiff_method_d* method, double rtol, double atol, double dt) {
    odestep_stiff_stepper_d s;
    const odestep_jac_system_d sys = {stiff_decay_d, stiff_decay_jacobian_d, NULL, 1};
    double y = 0.0;
    double worst = 0.0;
    const int steps = (int)(2.0 / dt + 0.5);
    int i;
    CHECK(odestep_stiff_init_d(&s, method, 1, rtol, atol) == ODESTEP_OK);
    for (i = 0; i < steps && worst < (double)INFINITY; ++i) {
        const odestep_status r = odestep_stiff_step_d(&s, &sys, &y, i * dt, dt);
        CHECK(r == ODESTEP_OK);
        worst = r == ODESTEP_OK ? fmax(worst, fabs(y - stiff_decay_exact((i + 1) * dt))) : (double)INFINITY;
    }
    return worst;
}

static void test_stiff_decay(void) {
    double e;
    /* Error-controlled, rtol 1e-6: within 10 rtol of the closed form at every grid point (|y| <= 1). */
    e = worst_stiff_decay(&odestep_radau5_substeps_d, 1e-6, 1e-9, 0.1);
    CHECK(e <= 1e-5);
    e = worst_stiff_decay(&odestep_rodas4_substeps_d, 1e-6, 1e-9, 0.1);
    CHECK(e <= 1e-5);
    /* The explicit pair under error control: stable only for steps below about 3.3 / 1000, which its
     * controller finds by itself (30 or more attempts per interval of 0.1). */
    e = worst_stiff_decay(&odestep_dp54_substeps_d, 1e-6, 1e-9, 0.1);
    CHECK(e <= 1e-5);
    /* Fixed steps of 0.01 (h lambda = -10: only an L-stable method damps the transient). */
    {
        odestep_stiff_stepper_d s;
        const odestep_jac_system_d sys = {stiff_decay_d, stiff_decay_jacobian_d, NULL, 1};
        const odestep_stiff_method_d* const fixed[4] = {&odestep_backward_euler_d, &odestep_sdirk3_d,
                                                        &odestep_radau_iia5_d, &odestep_rodas3_d};
        /* At t = 2, the transient long gone: backward Euler's error on the slow solution is about
         * h |y''| / (2 * 1000) <= 5e-6 (its local error h^2 |y''| / 2, divided by the damping 1000 h of each
         * step); the L-stable methods of higher order must do better than that bound, and Radau IIA 5 (local
         * error O(h^4) on a stiff component, stage order 3) better than h^4 / (1000 h) = 1e-9. */
        const double bound[4] = {5e-6, 5e-6, 1e-9, 5e-6};
        size_t m;
        for (m = 0; m < 4; ++m) {
            double y = 0.0;
            double recursion = 0.0;
            int i;
            int ok = 1;
            CHECK(odestep_stiff_init_d(&s, fixed[m], 1, 0.0, 0.0) == ODESTEP_OK);
            for (i = 0; i < 200 && ok; ++i) {
                if (odestep_stiff_step_d(&s, &sys, &y, i * 0.01, 0.01) != ODESTEP_OK) {
                    ok = 0;
                }
                /* Backward Euler on this linear equation is y_{k+1} = (y_k + 10 cos t_{k+1}) / 11, which Newton
                 * solves in one iteration: the C steps follow that recursion to round-off. */
                recursion = (recursion + 10.0 * cos((i + 1) * 0.01)) / 11.0;
                if (m == 0) CHECK_CLOSE(y, recursion, 1e-14);
            }
            CHECK(ok);
            CHECK_CLOSE(y, stiff_decay_exact(2.0), bound[m]);
        }
    }
}

/* ---- Phi against the stability polynomial */

/* On y' = A y a Runge-Kutta step is y_{n+1} = R(hA) y_n with R the method's stability function (Hairer & Wanner,
 * Solving ODE II, Sec. IV.2), so the step's derivative is R(hA) exactly (to round-off). RK4: the degree-4
 * Taylor polynomial of e^z. Dormand-Prince 5(4)'s 5th-order solution: 1 + z + ... + z^5 / 120 + z^6 / 600
 * (computed from its Butcher table as 1 + z b^T (I - zA)^-1 1 in exact rational arithmetic, once, for this
 * test; Hairer, Norsett & Wanner, Solving ODE I, Sec. II.5 give the same). */
static void test_transition_polynomial(void) {
    static const double rk4[5] = {1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0};
    static const double dp5[7] = {1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0, 1.0 / 600.0};
    const odestep_jac_system_d sys = {linear_d, linear_jacobian_d, NULL, 3};
    const double h = 0.1;
    double r[9];
    double phi[9];
    double y[3] = {1.0, -2.0, 0.5};
    double expected[3];
    size_t i;
    matrix_polynomial(rk4, 4, h, r);
    for (i = 0; i < 3; ++i) expected[i] = r[3 * i] * y[0] + r[3 * i + 1] * y[1] + r[3 * i + 2] * y[2];
    CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &sys, y, phi, 0.0, h) == ODESTEP_OK);
    for (i = 0; i < 9; ++i) CHECK_CLOSE(phi[i], r[i], 1e-15);
    for (i = 0; i < 3; ++i) CHECK_CLOSE(y[i], expected[i], 1e-15);

    matrix_polynomial(dp5, 6, h, r);
    CHECK(odestep_step_transition_d(&odestep_dp54_transition_d, &sys, y, phi, 0.1, h) == ODESTEP_OK);
    for (i = 0; i < 9; ++i) CHECK_CLOSE(phi[i], r[i], 1e-15);

    {
        /* The new y is the plain step's, bit for bit. */
        odestep_stepper_d plain;
        const odestep_system_d plain_sys = {linear_d, NULL, 3};
        double a[3] = {0.3, 0.2, -0.1};
        double b[3] = {0.3, 0.2, -0.1};
        CHECK(odestep_stepper_init_d(&plain, &odestep_rk4_d) == ODESTEP_OK);
        CHECK(odestep_step_d(&plain, &plain_sys, a, 0.0, h) == ODESTEP_OK);
        CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &sys, b, phi, 0.0, h) == ODESTEP_OK);
        CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
    }
}

static void test_transition_float(void) {
    static const double rk4[5] = {1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0};
    const odestep_jac_system_f sys = {linear_f, linear_jacobian_f, NULL, 3};
    double r[9];
    float phi[9];
    float y[3] = {1.0f, -2.0f, 0.5f};
    size_t i;
    matrix_polynomial(rk4, 4, 0.1, r);
    CHECK(odestep_step_transition_f(&odestep_rk4_transition_f, &sys, y, phi, 0.0f, 0.1f) == ODESTEP_OK);
    for (i = 0; i < 9; ++i) CHECK_CLOSE(phi[i], r[i], 1e-6);
}

/* ---- failures: distinct statuses, the state untouched */

static void test_nan_jacobian(void) {
    size_t n = 2;
    const odestep_jac_system_d sys = {decay_n_d, nan_jacobian_d, &n, 2};
    odestep_stiff_stepper_d s;
    const odestep_stiff_method_d* const methods[4] = {&odestep_radau5_substeps_d, &odestep_rodas4_substeps_d,
                                                      &odestep_backward_euler_d, &odestep_rodas3_d};
    size_t m;
    for (m = 0; m < 4; ++m) {
        double y[2] = {1.0, -0.5};
        CHECK(odestep_stiff_init_d(&s, methods[m], 2, 0.0, 0.0) == ODESTEP_OK);
        /* The Jacobian has NaN: the iteration matrix cannot be factored. */
        CHECK(odestep_stiff_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_SINGULAR_MATRIX);
        CHECK(y[0] == 1.0 && y[1] == -0.5);
    }
    {
        double y[2] = {1.0, -0.5};
        double phi[4] = {7.0, 7.0, 7.0, 7.0};
        CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &sys, y, phi, 0.0, 0.1) == ODESTEP_NON_FINITE);
        CHECK(y[0] == 1.0 && y[1] == -0.5);
        CHECK(phi[0] == 7.0 && phi[1] == 7.0 && phi[2] == 7.0 && phi[3] == 7.0);
        CHECK(odestep_step_transition_d(&odestep_dp54_transition_d, &sys, y, phi, 0.0, 0.1) == ODESTEP_NON_FINITE);
        CHECK(y[0] == 1.0 && phi[3] == 7.0);
    }
}

static void test_substep_limit(void) {
    /* The explicit pair on the stiff decay over one interval of 100: about 30 000 stable steps needed, 1000
     * attempts allowed. */
    odestep_stiff_stepper_d s;
    const odestep_jac_system_d sys = {stiff_decay_d, NULL, NULL, 1};
    double y = 0.5;
    CHECK(odestep_stiff_init_d(&s, &odestep_dp54_substeps_d, 1, 1e-6, 1e-9) == ODESTEP_OK);
    CHECK(odestep_stiff_step_d(&s, &sys, &y, 0.0, 100.0) == ODESTEP_SUBSTEP_LIMIT);
    CHECK(y == 0.5);
}

static void test_bad_input(void) {
    odestep_stiff_stepper_d s;
    odestep_method_info info;
    const odestep_jac_system_d sys = {robertson_d, robertson_jacobian_d, NULL, 3};
    const odestep_jac_system_d no_f = {NULL, robertson_jacobian_d, NULL, 3};
    const odestep_jac_system_d other_n = {robertson_d, robertson_jacobian_d, NULL, 2};
    const odestep_jac_system_d no_jacobian = {linear_d, NULL, NULL, 3};
    double y[3] = {1.0, 0.0, 0.0};
    double phi[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    /* init: each argument refused once, the stepper then refusing steps */
    CHECK(odestep_stiff_init_d(NULL, &odestep_radau5_substeps_d, 3, 0.0, 0.0) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_init_d(&s, NULL, 3, 0.0, 0.0) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_init_d(&s, &odestep_radau5_substeps_d, 0, 0.0, 0.0) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_init_d(&s, &odestep_radau5_substeps_d, ODESTEP_C_MAX_STATES + 1, 0.0, 0.0) ==
          ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_init_d(&s, &odestep_radau5_substeps_d, 3, -1e-6, 0.0) == ODESTEP_INVALID_TOLERANCE);
    CHECK(odestep_stiff_init_d(&s, &odestep_rodas4_substeps_d, 3, 1e-6, (double)NAN) == ODESTEP_INVALID_TOLERANCE);
    CHECK(odestep_stiff_init_d(&s, &odestep_dp54_substeps_d, 3, (double)INFINITY, 1e-6) == ODESTEP_INVALID_TOLERANCE);
    /* Newton's absolute tolerance must be positive. */
    CHECK(odestep_stiff_init_d(&s, &odestep_backward_euler_d, 3, 1e-6, 0.0) == ODESTEP_INVALID_TOLERANCE);
    CHECK(s.method == NULL);
    CHECK(odestep_stiff_step_d(&s, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    /* steps */
    CHECK(odestep_stiff_init_d(&s, &odestep_radau5_substeps_d, 3, 0.0, 0.0) == ODESTEP_OK);
    CHECK(odestep_stiff_step_d(NULL, &sys, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_step_d(&s, NULL, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_step_d(&s, &sys, NULL, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_step_d(&s, &no_f, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_step_d(&s, &other_n, y, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_stiff_step_d(&s, &sys, y, (double)NAN, 0.1) == ODESTEP_INVALID_TIME);
    CHECK(odestep_stiff_step_d(&s, &sys, y, 1e308, 1e308) == ODESTEP_INVALID_TIME);
    CHECK(odestep_stiff_step_d(&s, &sys, y, 0.0, 0.0) == ODESTEP_INVALID_STEP);
    CHECK(odestep_stiff_step_d(&s, &sys, y, 0.0, (double)INFINITY) == ODESTEP_INVALID_STEP);
    CHECK(y[0] == 1.0 && y[1] == 0.0 && y[2] == 0.0);
    /* transitions: no difference form, so a null Jacobian is refused */
    CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &no_jacobian, y, phi, 0.0, 0.1) ==
          ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_transition_d(NULL, &sys, y, phi, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &sys, y, NULL, 0.0, 0.1) == ODESTEP_INVALID_SETTING);
    CHECK(odestep_step_transition_d(&odestep_rk4_transition_d, &sys, y, phi, 0.0, 0.0) == ODESTEP_INVALID_STEP);
    CHECK(y[0] == 1.0 && y[1] == 0.0 && y[2] == 0.0 && phi[0] == 0.0);
    /* info */
    CHECK(odestep_stiff_method_info_d(&odestep_radau5_substeps_d, &info) == ODESTEP_OK);
    CHECK(strcmp(info.name, "radau5_substeps") == 0 && info.order == 5);
    CHECK(odestep_stiff_method_info_d(&odestep_rodas3_d, &info) == ODESTEP_OK);
    CHECK(strcmp(info.name, "rodas3") == 0 && info.order == 3);
    CHECK(odestep_stiff_method_info_d(NULL, &info) == ODESTEP_INVALID_SETTING);
}

int main(void) {
    test_robertson_radau5();
    test_robertson_rodas4();
    test_robertson_radau5_float();
    test_stiff_decay();
    test_transition_polynomial();
    test_transition_float();
    test_nan_jacobian();
    test_substep_limit();
    test_bad_input();
    (void)printf("c stiff api tests: %d failed checks\n", check_failures);
    return check_failures == 0 ? 0 : 1;
}
