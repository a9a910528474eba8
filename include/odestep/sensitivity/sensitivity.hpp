// SPDX-License-Identifier: BSL-1.0
// odestep: the step's derivative (state-transition matrices, sensitivities) and the dual numbers that give a
// templated right-hand side its Jacobian. See docs/sensitivity.md.
#ifndef ODESTEP_SENSITIVITY_SENSITIVITY_HPP
#define ODESTEP_SENSITIVITY_SENSITIVITY_HPP

#include "boris.hpp"
#include "dual.hpp"
#include "implicit.hpp"
#include "rosenbrock.hpp"
#include "transition.hpp"

#endif
