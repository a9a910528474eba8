// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes newtonian/splitting.hpp.
#ifndef ODESTEP_COMPAT_SYMPLECTIC_HPP
#define ODESTEP_COMPAT_SYMPLECTIC_HPP

#include "newtonian/splitting.hpp"

#endif
