// SPDX-License-Identifier: BSL-1.0
// Course material: stiff problems. The course's solver table recommends Radau 5 "for stiff equations", and
// its text shows why backward Euler is stable where Euler is not. Two models:
//
// (a) RC discharge, V' = -V / RC with RC = 2 ms and V(0) = 1 V, over 0.1 s, at h / RC = 0.5, 2.5, 5 and 25.
//     Every one-step method multiplies V by its stability function R(z), z = -h / RC, per step: Euler
//     1 + z (grows without bound once h / RC > 2), RK4 the 4th Taylor polynomial of e^z (grows past
//     h / RC = 2.785), backward Euler 1 / (1 - z), the trapezoid (1 + z/2) / (1 - z/2) (bounded, but -> -1:
//     a ringing that decays slowly), Radau IIA the (2,3) Pade approximant of e^z (-> 0). The checker
//     recomputes R(z)^n.
// (b) Robertson's chemical kinetics (Robertson 1966; Hairer & Wanner, Solving ODE II, IV.1) from (1, 0, 0) to
//     t = 40, against the reference values Hairer & Wanner give. RK4 fails at dt = 0.01; the implicit methods
//     take a fixed schedule of steps growing tenfold per decade of t (k steps in [0, 1e-5], k in each
//     [1e-5 10^j, 1e-5 10^(j+1)], the last phase ending at 40: 8 k steps), k = 5, 20, 80. The errors fall by
//     4^p when k grows fourfold: the checker reads the order p from them.
//
// Data: stiff_rc.csv (t, the exact V, then each method's V at h / RC = 2.5), stiff_robertson.csv (t, y1,
// 1e4 y2, y3 from Radau IIA with k = 20).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstdio>

#include "support/csv_file.hpp"

namespace {
using volt = std::array<double, 1>;
using species = std::array<double, 3>;

constexpr double rc = 0.002;
struct discharge {
    void operator()(double, const volt& v, volt& dv) const noexcept { dv[0] = -v[0] / rc; }
};
struct discharge_jacobian {
    void operator()(double, const volt&, odestep::jacobian_t<volt>& j) const noexcept { j[0][0] = -1.0 / rc; }
};

struct robertson {
    void operator()(double, const species& y, species& d) const noexcept {
        d[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        d[2] = 3e7 * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
};
struct robertson_jacobian {
    void operator()(double, const species& y, odestep::jacobian_t<species>& j) const noexcept {
        j[0] = {-0.04, 1e4 * y[2], 1e4 * y[1]};
        j[2] = {0.0, 6e7 * y[1], 0.0};
        j[1] = {-j[0][0] - j[2][0], -j[0][1] - j[2][1], -j[0][2] - j[2][2]};
    }
};

constexpr double t_end = 0.1;  // 50 RC

// One RC run: prints the final voltage; on the 2.5 ratio, keeps the trajectory for the CSV.
template <class Stepper>
bool rc_run(const char* name, double ratio, std::array<double, 21>* keep) {
    volt v{1.0};
    const double h = ratio * rc;
    const auto r = odestep::integrate(Stepper{}, odestep::with_jacobian(discharge{}, discharge_jacobian{}), v, 0.0,
                                      t_end, h, [&](double t, const volt& s) {
                                          if (keep == nullptr) return;
                                          const auto i = static_cast<std::size_t>(std::lround(t / h));
                                          if (i < keep->size()) (*keep)[i] = s[0];
                                      });
    std::printf("rc %-15s %5.2f %4llu %-10s %.17g\n", name, ratio, static_cast<unsigned long long>(r.steps),
                odestep::to_string(r.status), v[0]);
    return r.status == odestep::status::ok;
}

// Robertson with k steps per phase; returns false when a phase fails.
template <class Stepper, class Observer>
bool robertson_run(const char* name, int k, Observer&& observe) {
    species y{1.0, 0.0, 0.0};
    double t = 0.0;
    double end = 1e-5;
    unsigned long long steps = 0;
    odestep::status s = odestep::status::ok;
    for (;;) {
        if (end > 40.0) end = 40.0;
        const auto r = odestep::integrate(Stepper{}, odestep::with_jacobian(robertson{}, robertson_jacobian{}), y, t,
                                          end, (end - t) / k, observe);
        steps += r.steps;
        s = r.status;
        if (s != odestep::status::ok || end == 40.0) break;
        t = end;
        end *= 10.0;
    }
    std::printf("robertson %-15s %3d %4llu %-10s %.17g %.17g %.17g\n", name, k, steps, odestep::to_string(s), y[0],
                y[1], y[2]);
    return s == odestep::status::ok;
}
}  // namespace

int main(int argc, char** argv) {
    bool good = true;
    std::printf("# (a) RC discharge, RC = %g s, V(0) = 1 V, to t = %g s: method, h/RC, steps, status, V(end)\n", rc,
                t_end);
    std::array<std::array<double, 21>, 5> kept{};
    for (double ratio : {0.5, 2.5, 5.0, 25.0}) {
        const bool keep = ratio == 2.5;
        good &= rc_run<odestep::euler<volt>>("euler", ratio, keep ? &kept[0] : nullptr);
        good &= rc_run<odestep::rk4<volt>>("rk4", ratio, keep ? &kept[1] : nullptr);
        good &= rc_run<odestep::backward_euler<volt>>("backward_euler", ratio, keep ? &kept[2] : nullptr);
        good &= rc_run<odestep::trapezoid<volt>>("trapezoid", ratio, keep ? &kept[3] : nullptr);
        good &= rc_run<odestep::radau_iia5<volt>>("radau_iia5", ratio, keep ? &kept[4] : nullptr);
    }
    {
        example::csv_file data(argc, argv, "stiff_rc.csv");
        data.csv.header("t", "exact", "euler", "rk4", "backward_euler", "trapezoid", "radau_iia5");
        for (std::size_t i = 0; i < 21; ++i) {
            const double t = static_cast<double>(i) * 2.5 * rc;
            data.csv.row(t, std::exp(-t / rc), kept[0][i], kept[1][i], kept[2][i], kept[3][i], kept[4][i]);
        }
        good &= data.good();
    }

    std::printf("# (b) Robertson to t = 40: method, steps per phase, steps, status, y1, y2, y3\n");
    {
        species y{1.0, 0.0, 0.0};
        const auto r = odestep::integrate(odestep::rk4<species>{}, robertson{}, y, 0.0, 40.0, 0.01);
        std::printf("robertson_rk4 dt 0.01 status %s after %llu steps\n", odestep::to_string(r.status),
                    static_cast<unsigned long long>(r.steps));
    }
    const auto none = [](double, const species&) {};
    for (int k : {5, 20, 80}) {
        good &= robertson_run<odestep::backward_euler<species>>("backward_euler", k, none);
        good &= robertson_run<odestep::trapezoid<species>>("trapezoid", k, none);
        good &= robertson_run<odestep::sdirk3<species>>("sdirk3", k, none);
        good &= robertson_run<odestep::rodas3<species>>("rodas3", k, none);
        good &= robertson_run<odestep::radau_iia5<species>>("radau_iia5", k, none);
    }
    {
        example::csv_file data(argc, argv, "stiff_robertson.csv");
        data.csv.header("t", "y1", "y2_x1e4", "y3");
        std::printf("# the same run, writing its data:\n");
        good &= robertson_run<odestep::radau_iia5<species>>(
            "radau_iia5", 20, [&](double t, const species& y) { data.csv.row(t, y[0], 1e4 * y[1], y[2]); });
        good &= data.good();
    }
    return good ? 0 : 1;
}
