// SPDX-License-Identifier: BSL-1.0
// The EKF example's core (examples/ekf_pendulum.hpp) in a short run, so that it runs on the emulated Cortex-M
// cores too: 4 runs of 1 s at 1 kHz, the filter predicting with rk4_transition and dual numbers against the
// one whose Phi comes from central differences, and its consistency by the chi-square regions.
#include <doctest/doctest.h>

#include <array>
#include <cstddef>

#include "../../examples/ekf_pendulum.hpp"

namespace {

TEST_CASE("EKF example, short: consistent by NEES and NIS, and the differences filter gives the same estimates") {
    // The regions are Wilson & Hilferty's chi-square quantiles (checked against Abramowitz & Stegun, Table
    // 26.8, by examples/check/ekf_pendulum.awk); the runs are seeded, so the figures are fixed on every platform
    // up to the rounding of the elementary functions. Host (x86-64, g++ -O1): the 4-run NEES averages at the
    // four checkpoints 5.27, 1.97, 1.44, 1.05 against the 95% region [0.54, 4.38] (the first, at 0.25 s, out:
    // at least 3 of 4 must be in); their average 2.43 in [1.14, 3.09]; the NIS 0.9857 in [0.9567, 1.0443]; the
    // gap between the two filters 8.8e-11.
    constexpr int runs = 4;
    constexpr int steps = 1000;
    constexpr int checkpoints = 4;
    const auto r = ekf_pendulum::simulate<checkpoints>(runs, steps);
    REQUIRE(r.stepped);
    const std::array<double, 2> region = ekf_pendulum::nees_region(runs);
    double average = 0.0;
    int inside = 0;
    for (std::size_t c = 0; c < checkpoints; ++c) {
        const double a = r.nees_sum[c] / runs;
        INFO("checkpoint " << c << ": NEES " << a << " region " << region[0] << " " << region[1]);
        inside += (a >= region[0] && a <= region[1]) ? 1 : 0;
        average += a / checkpoints;
    }
    CHECK(inside >= checkpoints - 1);
    const std::array<double, 2> all = ekf_pendulum::nees_average_region(runs, checkpoints);
    INFO("NEES average " << average);
    CHECK(average >= all[0]);
    CHECK(average <= all[1]);
    const double nis = r.nis_sum / (static_cast<double>(runs) * steps);
    const std::array<double, 2> nr = ekf_pendulum::nis_region(runs, steps);
    INFO("NIS average " << nis);
    CHECK(nis >= nr[0]);
    CHECK(nis <= nr[1]);
    // Central differences of the step with increment 1e-5 carry an error of about 1e-10 in Phi; the filters'
    // estimates stay within 1e-7 of each other (in the full example a 1% error in Phi's dt entry moves them by
    // 1.9e-3).
    CHECK(r.largest_difference <= 1e-7);
}

}  // namespace
