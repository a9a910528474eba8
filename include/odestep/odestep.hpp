// odestep: the umbrella header.
#ifndef ODESTEP_ODESTEP_HPP
#define ODESTEP_ODESTEP_HPP

#include "status.hpp"
#include "state.hpp"
#include "system.hpp"
#include "tableau.hpp"
#include "tableaux.hpp"
#include "explicit_rk.hpp"
#include "integrate.hpp"
#include "multistep.hpp"
#include "newtonian.hpp"
#include "symplectic.hpp"
#include "boris.hpp"
#include "bracket.hpp"
#include "events.hpp"

#endif
