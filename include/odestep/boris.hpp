// SPDX-License-Identifier: BSL-1.0
// odestep: deprecated (removed in 1.0.0): the header's name before the headers moved into folders; include
// <odestep/newtonian/boris.hpp> instead, which this one includes.
#ifndef ODESTEP_COMPAT_BORIS_HPP
#define ODESTEP_COMPAT_BORIS_HPP

#include "newtonian/boris.hpp"

#endif
