// SPDX-License-Identifier: BSL-1.0
// odestep: deprecated (removed in 1.0.0): the header's name before the headers moved into folders; include
// <odestep/tables/runge_kutta.hpp> instead, which this one includes.
#ifndef ODESTEP_COMPAT_TABLEAUX_HPP
#define ODESTEP_COMPAT_TABLEAUX_HPP

#include "tables/runge_kutta.hpp"

#endif
