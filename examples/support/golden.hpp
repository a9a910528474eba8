// SPDX-License-Identifier: BSL-1.0
// Golden-section search for the examples that look for a best launch angle or a best fit.
#ifndef ODESTEP_EXAMPLES_GOLDEN_HPP
#define ODESTEP_EXAMPLES_GOLDEN_HPP

#include <cmath>

namespace example {

// Golden-section search for the maximum of a unimodal f on [a, b], until b - a <= tol (Kiefer 1953; as in
// Press et al., Numerical Recipes, Sec. 10.2): each round keeps the larger of the two interior points,
// which is one of the next round's points, so one new evaluation per round.
template <class F>
double golden_max(F f, double a, double b, double tol, int& rounds) {
    const double w = (std::sqrt(5.0) - 1.0) / 2.0;  // 1/phi
    double c = b - w * (b - a);
    double d = a + w * (b - a);
    double fc = f(c);
    double fd = f(d);
    rounds = 0;
    while (b - a > tol) {
        ++rounds;
        if (fc >= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - w * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + w * (b - a);
            fd = f(d);
        }
    }
    return (a + b) / 2;
}

}  // namespace example

#endif
