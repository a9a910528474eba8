/* SPDX-License-Identifier: BSL-1.0 */
/* The C API from a consumer: y' = -y from 0 to 1 with RK4 through odestep::odestep_c; exits 0 when
 * y(1) = exp(-1) to RK4's accuracy. C99. */
#include <math.h>
#include <stdio.h>

#include <odestep/odestep.h>

static void decay(double t, const double* y, double* dydt, void* ctx) {
    (void)t;
    (void)ctx;
    dydt[0] = -y[0];
}

int main(void) {
    odestep_stepper_d stepper;
    const odestep_system_d system = {decay, NULL, 1};
    double y = 1.0;
    odestep_status s = odestep_stepper_init_d(&stepper, &odestep_rk4_d);
    if (s == ODESTEP_OK) s = odestep_integrate_d(&stepper, &system, &y, 0.0, 1.0, 0.01, NULL, NULL, NULL);
    {
        const int ok = s == ODESTEP_OK && fabs(y - exp(-1.0)) < 1e-9 && odestep_max_states() == ODESTEP_C_MAX_STATES;
        printf("c consumer: y(1) = %.12f %s\n", y, ok ? "ok" : "WRONG");
        return ok ? 0 : 1;
    }
}
