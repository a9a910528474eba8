// SPDX-License-Identifier: BSL-1.0
// Course material: the fall of a coffee filter (problem 3.5), with the course's measured heights (27
// readings of a motion sensor, t = 0.2055 ... 0.8466 s, about 0.0247 s apart).
//
// (a) The terminal speed from a straight line through the last ten readings (least squares).
// (b) v and a from the readings by central differences: v_i = (y_{i+1} - y_{i-1}) / (t_{i+1} - t_{i-1}) and
//     the three-point second difference (on an even grid (y_{i+1} - 2 y_i + y_{i-1}) / dt^2).
// (d, e) The fall modelled with quadratic drag, a = -g (1 - v^2 / vt^2), and with linear drag,
//     a = -g (1 - |v| / vt) (v downwards here), each integrated with RK4 (dt <= 1 ms, landing on every
//     reading's time) and fitted to the readings by least squares: the terminal speed vt and the speed
//     at the first reading by nested golden-section searches, the height at the first reading in closed
//     form (the model is y0 minus a distance, so the best y0 makes the residuals' mean zero). Printed: the
//     fitted values and the rms residual of each law, over all readings and over the later ones (from
//     t = 0.4526 s). With g = 9.8 neither law follows the slow start (the readings' a is about -2 m/s^2
//     while v is still small, where both laws give nearly -g), and the best fits put u0 at its bound 0.
//
// Data: coffee_filter.csv (t, y, v, a of the readings, then each fitted model's y), and
// coffee_filter_models.csv (the four fitted curves on a fine grid: quadratic, linear, then both from
// reading 10), coffee_filter_fits.csv (the four fits' parameters).
#include <odestep/odestep.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "support/csv_file.hpp"
#include "support/golden.hpp"

namespace {
using state = std::array<double, 2>;  // y (up), v (up)
constexpr double g = 9.8;
constexpr std::size_t readings = 27;

// The course's Table 3.2 (t in s, y in m), in time order.
constexpr std::array<double, readings> t_data{0.2055, 0.2302, 0.2550, 0.2797, 0.3045, 0.3292, 0.3539, 0.3786, 0.4033,
                                              0.4280, 0.4526, 0.4773, 0.5020, 0.5266, 0.5513, 0.5759, 0.6005, 0.6252,
                                              0.6498, 0.6744, 0.6990, 0.7236, 0.7482, 0.7728, 0.7974, 0.8220, 0.8466};
constexpr std::array<double, readings> y_data{0.4188, 0.4164, 0.4128, 0.4082, 0.4026, 0.3958, 0.3878, 0.3802, 0.3708,
                                              0.3609, 0.3505, 0.3400, 0.3297, 0.3181, 0.3051, 0.2913, 0.2788, 0.2667,
                                              0.2497, 0.2337, 0.2175, 0.2008, 0.1846, 0.1696, 0.1566, 0.1393, 0.1263};

enum class drag { quadratic, linear };

struct falling {
    drag law;
    double vt;
    state operator()(double, const state& s) const noexcept {
        const double v = s[1];  // negative while falling
        const double resist = law == drag::quadratic ? v * std::fabs(v) / (vt * vt) : v / vt;
        return {v, -g * (1.0 + resist)};
    }
};

// The model's distance fallen since reading `first`, at readings first, first + 1, ... (d[first] = 0), from
// a downward speed u0 at that reading. False if a run fails.
bool distances(drag law, double vt, double u0, std::size_t first, std::array<double, readings>& d) {
    state s{0.0, -u0};
    d[first] = 0.0;
    for (std::size_t i = first + 1; i < readings; ++i) {
        const double span = t_data[i] - t_data[i - 1];
        const double steps = std::ceil(span / 1e-3);
        if (odestep::integrate(odestep::rk4<state>{}, falling{law, vt}, s, t_data[i - 1], t_data[i], span / steps)
                .status != odestep::status::ok)
            return false;
        d[i] = -s[0];
    }
    return true;
}

struct fit {
    double vt = 0.0, u0 = 0.0, y0 = 0.0, rms = 0.0;
};

// The rms residual over readings first ... 26 with the best y0 for (vt, u0): y_i = y0 - d_i, so
// y0 = mean(y_i + d_i).
fit residual(drag law, double vt, double u0, std::size_t first) {
    std::array<double, readings> d{};
    fit f{vt, u0, 0.0, 1e9};
    if (!distances(law, vt, u0, first, d)) return f;
    const double n = static_cast<double>(readings - first);
    double sum = 0.0;
    for (std::size_t i = first; i < readings; ++i) sum += y_data[i] + d[i];
    f.y0 = sum / n;
    double squares = 0.0;
    for (std::size_t i = first; i < readings; ++i) {
        const double r = y_data[i] - (f.y0 - d[i]);
        squares += r * r;
    }
    f.rms = std::sqrt(squares / n);
    return f;
}

// The least-squares fit from reading `first` on: vt in [0.1, 3] m/s, u0 in [0, vt) (falling, slower than
// terminal), each to 1e-9 m/s.
fit best_fit(drag law, std::size_t first) {
    int rounds = 0;
    auto best_u0 = [law, first, &rounds](double vt) {
        return example::golden_max([law, vt, first](double u0) { return -residual(law, vt, u0, first).rms; }, 0.0,
                                   0.999 * vt, 1e-9, rounds);
    };
    const double vt =
        example::golden_max([&](double v) { return -residual(law, v, best_u0(v), first).rms; }, 0.1, 3.0, 1e-9, rounds);
    return residual(law, vt, best_u0(vt), first);
}
}  // namespace

int main(int argc, char** argv) {
    example::csv_file data(argc, argv, "coffee_filter.csv");
    example::csv_file curves(argc, argv, "coffee_filter_models.csv");
    example::csv_file fitted(argc, argv, "coffee_filter_fits.csv");
    std::printf("# coffee filter, %zu readings (course Table 3.2), g = %g\n", readings, g);

    // (a) least-squares line through the last ten readings
    double st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
    for (std::size_t i = readings - 10; i < readings; ++i) {
        st += t_data[i];
        sy += y_data[i];
        stt += t_data[i] * t_data[i];
        sty += t_data[i] * y_data[i];
    }
    const double slope = (10 * sty - st * sy) / (10 * stt - st * st);
    std::printf("line_last_10 slope %.17g m/s terminal_speed %.17g m/s\n", slope, -slope);

    // (d, e) the fits, over all readings and over the later ones (from reading 10, t = 0.4526 s)
    constexpr std::size_t late = 10;
    const fit quad = best_fit(drag::quadratic, 0);
    const fit lin = best_fit(drag::linear, 0);
    const fit quad_late = best_fit(drag::quadratic, late);
    const fit lin_late = best_fit(drag::linear, late);
    std::printf("%-3s %-9s %-5s %22s %22s %22s %22s\n", "fit", "drag", "from", "vt", "u0", "y0", "rms");
    const char* names[] = {"quadratic", "linear", "quadratic", "linear"};
    const fit* fits[] = {&quad, &lin, &quad_late, &lin_late};
    fitted.csv.header("first_reading", "quadratic", "vt", "u0", "y0", "rms");
    for (int k = 0; k < 4; ++k) {
        fitted.csv.row(k < 2 ? std::size_t{0} : late, k % 2 == 0, fits[k]->vt, fits[k]->u0, fits[k]->y0, fits[k]->rms);
        std::printf("%-3s %-9s %-5zu %22.15g %22.15g %22.15g %22.15g\n", "fit", names[k], k < 2 ? std::size_t{0} : late,
                    fits[k]->vt, fits[k]->u0, fits[k]->y0, fits[k]->rms);
    }
    std::printf("better_fit all %s late %s\n", quad.rms < lin.rms ? "quadratic" : "linear",
                quad_late.rms < lin_late.rms ? "quadratic" : "linear");

    // (b) central differences, and the readings with both models
    std::array<double, readings> dq{}, dl{};
    if (!distances(drag::quadratic, quad.vt, quad.u0, 0, dq) || !distances(drag::linear, lin.vt, lin.u0, 0, dl))
        return 1;
    data.csv.header("t", "y", "v", "a", "y_quadratic", "y_linear");
    std::printf("%-10s %-7s %8s %22s %22s\n", "reading", "t", "y", "v", "a");
    for (std::size_t i = 0; i < readings; ++i) {
        double v = std::nan("");
        double a = std::nan("");
        if (i > 0 && i + 1 < readings) {
            const double h1 = t_data[i] - t_data[i - 1];
            const double h2 = t_data[i + 1] - t_data[i];
            v = (y_data[i + 1] - y_data[i - 1]) / (h1 + h2);
            a = 2.0 * ((y_data[i + 1] - y_data[i]) / h2 - (y_data[i] - y_data[i - 1]) / h1) / (h1 + h2);
        }
        std::printf("%-10s %-7g %8g %22.15g %22.15g\n", "reading", t_data[i], y_data[i], v, a);
        data.csv.row(t_data[i], y_data[i], v, a, quad.y0 - dq[i], lin.y0 - dl[i]);
    }

    // the fitted curves on a fine grid, from the first reading of each fit: one data set per fit
    curves.csv.header("t", "y", "v");
    for (int k = 0; k < 4; ++k) {
        const fit& f = *fits[k];
        const std::size_t first = k < 2 ? 0 : late;
        state s{f.y0, -f.u0};
        if (odestep::integrate(odestep::rk4<state>{}, falling{k % 2 == 0 ? drag::quadratic : drag::linear, f.vt}, s,
                               t_data[first], t_data[readings - 1], 2e-3, curves.csv)
                .status != odestep::status::ok)
            return 1;
        curves.next_block();
    }
    return data.good() && curves.good() && fitted.good() ? 0 : 1;
}
