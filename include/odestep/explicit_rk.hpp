// SPDX-License-Identifier: BSL-1.0
// odestep: deprecated (removed in 1.0.0): the header's name before the headers moved into folders; include
// <odestep/rk/explicit_rk.hpp> instead, which this one includes.
#ifndef ODESTEP_COMPAT_EXPLICIT_RK_HPP
#define ODESTEP_COMPAT_EXPLICIT_RK_HPP

#include "rk/explicit_rk.hpp"

#endif
