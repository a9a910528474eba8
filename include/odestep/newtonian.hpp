// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes newtonian/classic.hpp.
#ifndef ODESTEP_COMPAT_NEWTONIAN_HPP
#define ODESTEP_COMPAT_NEWTONIAN_HPP

#include "newtonian/classic.hpp"

#endif
