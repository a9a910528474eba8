// SPDX-License-Identifier: BSL-1.0
// The checks every stiff engine's substep form (stiff_substeps: radau5_substeps, rodas4_substeps,
// sdirk4_substeps) passes alike, written once: the smooth problem's error against its closed form over a
// coarse grid, and the failures that leave y bit for bit (NaN from f, NaN in the Jacobian, the attempt cap,
// bad settings). `Substeps` is the form's alias template, Substeps<State, MaxAttempts>.
#ifndef ODESTEP_TESTS_STIFF_ENGINE_CHECKS_HPP
#define ODESTEP_TESTS_STIFF_ENGINE_CHECKS_HPP

#include <doctest/doctest.h>
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "counting.hpp"
#include "stiff_problems.hpp"

namespace odestep_test {

// exp(sin t) on a 1.0 grid to 20 at each rtol: the largest error over the grid against the closed form
// (support/problems.hpp) is at most 100 rtol; the errors are returned (for a slope against rtol).
template <template <class, std::size_t> class Substeps, std::size_t K>
std::array<double, K> check_exp_sin_on_grid(const std::array<double, K>& rtols) {
    using S3 = state3<double>;
    const auto sys = odestep::with_jacobian(exp_sin{}, exp_sin_jacobian{});
    std::array<double, K> errors{};
    for (std::size_t k = 0; k < K; ++k) {
        Substeps<S3, 1000> stepper(odestep::tolerances<S3>::uniform(rtols[k], rtols[k]));
        S3 y = exp_sin::start<double>();
        double worst = 0;
        const auto r = odestep::integrate(stepper, sys, y, 0.0, 20.0, 1.0, [&](double t, const S3& u) {
            const S3 x = exp_sin::exact(t);
            for (std::size_t i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(u[i] - x[i]));
        });
        REQUIRE(r.status == odestep::status::ok);
        errors[k] = worst;
        MESSAGE("rtol " << rtols[k] << ": largest error over the grid " << worst << ", accepted "
                        << stepper.engine().accepted_steps());
        CHECK(worst <= 100 * rtols[k]);
    }
    return errors;
}

// Robertson with f NaN past t = 1.05 on a 0.1 grid to 2: non_finite on the interval that reaches it, and y
// the state of the last good interval, bit for bit (the same run to t = 1).
template <template <class, std::size_t> class Substeps>
void check_nan_past_a_time() {
    using S3 = state3<double>;
    const auto jac = robertson_jacobian{};
    auto f = [](double t, const S3& y, S3& d) {
        robertson{}(t, y, d);
        if (t > 1.05) d[1] = std::numeric_limits<double>::quiet_NaN();
    };
    Substeps<S3, 1000> stepper(odestep::tolerances<S3>::uniform(1e-6, 1e-12));
    S3 y{1, 0, 0};
    const auto r = odestep::integrate(stepper, odestep::with_jacobian(f, jac), y, 0.0, 2.0, 0.1);
    CHECK(r.status == odestep::status::non_finite);
    CHECK(r.t == doctest::Approx(1.0));
    Substeps<S3, 1000> again(odestep::tolerances<S3>::uniform(1e-6, 1e-12));
    S3 z{1, 0, 0};
    REQUIRE(odestep::integrate(again, odestep::with_jacobian(f, jac), z, 0.0, 1.0, 0.1).status == odestep::status::ok);
    CHECK(odestep::detail::same_values(y, z));
}

// The system's Jacobian with a NaN: singular_matrix, y as given.
template <template <class, std::size_t> class Substeps>
void check_nan_jacobian() {
    using S3 = state3<double>;
    auto bad = [](double, const S3&, odestep::jacobian_t<S3>& j) {
        j = {};
        j[1][1] = std::numeric_limits<double>::quiet_NaN();
    };
    Substeps<S3, 1000> stepper;
    S3 y{0.5, 1e-5, 0.5 - 1e-5};
    const S3 before = y;
    CHECK(stepper.step(odestep::with_jacobian(robertson{}, bad), y, 0.0, 0.1) == odestep::status::singular_matrix);
    CHECK(odestep::detail::same_values(y, before));
}

// Cap attempts on Robertson's initial layer at rtol 1e-8 over [0, 1]: substep_limit, y as given; a cap above
// the compile-time one is refused.
template <template <class, std::size_t> class Substeps, std::size_t Cap>
void check_attempt_cap() {
    using S3 = state3<double>;
    Substeps<S3, Cap> stepper(odestep::tolerances<S3>::uniform(1e-8, 1e-14));
    S3 y{1, 0, 0};
    const S3 before = y;
    CHECK(stepper.step(odestep::with_jacobian(robertson{}, robertson_jacobian{}), y, 0.0, 1.0) ==
          odestep::status::substep_limit);
    CHECK(odestep::detail::same_values(y, before));
    CHECK(stepper.set_max_attempts(Cap + 1) == odestep::status::invalid_setting);
}

// Bad settings (a negative rtol; a Jacobian reuse rate outside (0, 1)) are refused before anything is
// evaluated.
template <template <class, std::size_t> class Substeps>
void check_bad_newton_settings() {
    using S3 = state3<double>;
    std::size_t calls = 0;
    auto f = counted(robertson{}, &calls);
    Substeps<S3, 1000> stepper(odestep::tolerances<S3>::uniform(-1.0, 1e-6));
    S3 y{1, 0, 0};
    CHECK(stepper.step(f, y, 0.0, 0.1) == odestep::status::invalid_tolerance);
    stepper.engine().set_tolerance(odestep::tolerances<S3>::uniform(1e-6, 1e-6));
    stepper.engine().set_jacobian_reuse_rate(1.5);
    CHECK(stepper.step(f, y, 0.0, 0.1) == odestep::status::invalid_setting);
    typename Substeps<S3, 1000>::engine_type engine;
    CHECK(odestep::integrate_adaptive(engine, f, y, 0.0, 1.0, 0).status == odestep::status::invalid_setting);
    CHECK(calls == 0);
}

}  // namespace odestep_test

#endif
