// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes newtonian/boris.hpp.
#ifndef ODESTEP_COMPAT_BORIS_HPP
#define ODESTEP_COMPAT_BORIS_HPP

#include "newtonian/boris.hpp"

#endif
