// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: GSL odeiv2 as a benchmark variant calls it, gsl_odeiv2_step_apply directly on a
// stepper allocated once (no driver, no evolve object, no step control). GSL is double only, takes the
// right-hand side through a function pointer (so it is never inlined) and lives in the shared library as
// Debian compiled it: the -O level of the benchmark build does not reach it.
#ifndef ODESTEP_BENCH_GSL_HPP
#define ODESTEP_BENCH_GSL_HPP

#include <cstddef>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace bench {

class gsl_stepper {
public:
    using rhs = int (*)(double t, const double y[], double dydt[], void* params);
    gsl_stepper(const gsl_odeiv2_step_type* type, rhs f, std::size_t dim)
        : sys_{f, nullptr, dim, nullptr}, step_{gsl_odeiv2_step_alloc(type, dim)} {}
    ~gsl_stepper() { gsl_odeiv2_step_free(step_); }
    gsl_stepper(const gsl_stepper&) = delete;
    gsl_stepper& operator=(const gsl_stepper&) = delete;

    /// y <- y(t + h), yerr <- GSL's error estimate (every GSL explicit stepper computes one).
    int apply(double* y, double* yerr, double t, double h) {
        return gsl_odeiv2_step_apply(step_, t, h, y, yerr, nullptr, nullptr, &sys_);
    }

private:
    gsl_odeiv2_system sys_;
    gsl_odeiv2_step* step_;
};

}  // namespace bench

#endif
