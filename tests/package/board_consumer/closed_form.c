// SPDX-License-Identifier: BSL-1.0
// A C translation unit in the image: the consumer's C flags (CMAKE_C_FLAGS) must keep the core's flags.
#include <math.h>

double closed_form(double t);

// y' = -y, y(0) = 1: y(t) = exp(-t).
double closed_form(double t) { return exp(-t); }
