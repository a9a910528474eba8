// SPDX-License-Identifier: BSL-1.0
// odestep: the umbrella header, everything but the host-only utilities.
#ifndef ODESTEP_ODESTEP_HPP
#define ODESTEP_ODESTEP_HPP

#include "adaptive.hpp"
#include "config.hpp"
#include "events/events.hpp"
#include "integrate.hpp"
#include "linalg/complex_lu.hpp"
#include "linalg/jacobian.hpp"
#include "linalg/lu.hpp"
#include "multistep/adams.hpp"
#include "newtonian/boris.hpp"
#include "newtonian/classic.hpp"
#include "newtonian/splitting.hpp"
#include "rk/explicit_rk.hpp"
#include "rk/implicit_rk.hpp"
#include "rk/newton.hpp"
#include "rk/rosenbrock.hpp"
#include "roots/bracket.hpp"
#include "sensitivity/sensitivity.hpp"
#include "state.hpp"
#include "status.hpp"
#include "stepper.hpp"
#include "stiff/integrate.hpp"
#include "stiff/radau5.hpp"
#include "stiff/rosenbrock_adaptive.hpp"
#include "stiff/substeps.hpp"
#include "system.hpp"
#include "tables/adams.hpp"
#include "tables/butcher.hpp"
#include "tables/implicit_rk.hpp"
#include "tables/rosenbrock.hpp"
#include "tables/runge_kutta.hpp"
#include "tables/splitting.hpp"
#include "version.hpp"

#endif
