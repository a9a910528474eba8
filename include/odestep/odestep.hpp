// odestep: the umbrella header, everything but the host-only utilities.
#ifndef ODESTEP_ODESTEP_HPP
#define ODESTEP_ODESTEP_HPP

#include "config.hpp"
#include "version.hpp"
#include "status.hpp"
#include "state.hpp"
#include "system.hpp"
#include "stepper.hpp"
#include "tables/butcher.hpp"
#include "tables/runge_kutta.hpp"
#include "tables/adams.hpp"
#include "tables/splitting.hpp"
#include "rk/explicit_rk.hpp"
#include "multistep/adams.hpp"
#include "newtonian/classic.hpp"
#include "newtonian/splitting.hpp"
#include "newtonian/boris.hpp"
#include "roots/bracket.hpp"
#include "integrate.hpp"
#include "events/events.hpp"

#endif
