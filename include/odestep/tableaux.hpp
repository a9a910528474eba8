// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes tables/runge_kutta.hpp.
#ifndef ODESTEP_COMPAT_TABLEAUX_HPP
#define ODESTEP_COMPAT_TABLEAUX_HPP

#include "tables/runge_kutta.hpp"

#endif
