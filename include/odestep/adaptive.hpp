// SPDX-License-Identifier: BSL-1.0
// odestep: error-controlled stepping: the controller (adaptive/control.hpp), the engine and the course's
// adaptive stepper (adaptive/adaptive_rk.hpp), dense output (adaptive/dense.hpp) and the free-running loops
// (adaptive/integrate_adaptive.hpp), the solution object and the one-at-a-time sampler (adaptive/solution.hpp).
#ifndef ODESTEP_ADAPTIVE_HPP
#define ODESTEP_ADAPTIVE_HPP

#include "adaptive/adaptive_rk.hpp"
#include "adaptive/control.hpp"
#include "adaptive/dense.hpp"
#include "adaptive/integrate_adaptive.hpp"
#include "adaptive/solution.hpp"

#endif
