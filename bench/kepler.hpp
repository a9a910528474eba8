// SPDX-License-Identifier: BSL-1.0
// odestep benchmarks: the planar Kepler problem (mu = 1, eccentricity 0.5, from perihelion) that the
// Newtonian cases share: the harness's state, the force in the three forms the variants call, and the
// closed-form reference.
#ifndef ODESTEP_BENCH_KEPLER_HPP
#define ODESTEP_BENCH_KEPLER_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

#include "harness.hpp"
#include "problems.hpp"

namespace bench::kepler_case {

using vec = std::array<double, 2>;

/// The harness's state: (x, v) as Odeint's std::pair of positions and velocities, seen by the harness as
/// the four numbers x0, x1, v0, v1 (value_type, size, indexing and iteration for its comparisons).
struct phase : std::pair<vec, vec> {
    using value_type = double;
    static constexpr std::size_t size() { return 4; }
    double operator[](std::size_t i) const { return i < 2 ? first[i] : second[i - 2]; }
    struct iterator {
        const phase* p;
        std::size_t i;
        double operator*() const { return (*p)[i]; }
        iterator& operator++() {
            ++i;
            return *this;
        }
        bool operator!=(const iterator& o) const { return i != o.i; }
    };
    iterator begin() const { return {this, 0}; }
    iterator end() const { return {this, 4}; }
};

/// odestep's form, a(t, x) returned.
constexpr auto force = [](double, const vec& x) {
    vec a;
    bench::kepler<double>(x, a);
    return a;
};
/// The hand loops' form, written into a.
constexpr auto hand_force = [](double, const vec& x, vec& a) { bench::kepler<double>(x, a); };

/// The exact state at time t of the orbit with semi-major axis 1, eccentricity e, mu = 1, at perihelion at
/// t = 0 on the positive x axis: E - e sin E = t by Newton's method, in long double.
inline phase exact(long double e, long double t) {
    long double E = t;
    for (int i = 0; i < 50; ++i) E -= (E - e * std::sin(E) - t) / (1.0L - e * std::cos(E));
    const long double b = std::sqrt(1.0L - e * e);
    const long double d = 1.0L - e * std::cos(E);
    phase s{};
    s.first = {static_cast<double>(std::cos(E) - e), static_cast<double>(b * std::sin(E))};
    s.second = {static_cast<double>(-std::sin(E) / d), static_cast<double>(b * std::cos(E) / d)};
    return s;
}

/// The case: half an orbit from perihelion with 1000 steps per orbit (500 steps), the exact state at its
/// end as the reference. tol_same and tol_method as bench::problem (each case says where its come from).
inline bench::problem<phase> problem(const char* name, double tol_same, double tol_method) {
    const long double e = 0.5L;
    const int steps = 500;
    const double dt = 2 * 3.14159265358979323846 / 1000;
    return {name,     exact(e, 0.0L),  // x = (0.5, 0), v = (0, sqrt 3)
            0.0,      dt,
            steps,    exact(e, static_cast<long double>(steps) * static_cast<long double>(dt)),
            tol_same, tol_method,
            false};
}

}  // namespace bench::kepler_case

#endif
