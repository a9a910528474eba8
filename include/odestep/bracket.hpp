// SPDX-License-Identifier: BSL-1.0
// odestep: deprecated (removed in 1.0.0): the header's name before the headers moved into folders; include
// <odestep/roots/bracket.hpp> instead, which this one includes.
#ifndef ODESTEP_COMPAT_BRACKET_HPP
#define ODESTEP_COMPAT_BRACKET_HPP

#include "roots/bracket.hpp"

#endif
