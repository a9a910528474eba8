// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes roots/bracket.hpp.
#ifndef ODESTEP_COMPAT_BRACKET_HPP
#define ODESTEP_COMPAT_BRACKET_HPP

#include "roots/bracket.hpp"

#endif
