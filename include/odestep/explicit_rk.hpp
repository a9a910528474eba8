// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes rk/explicit_rk.hpp.
#ifndef ODESTEP_COMPAT_EXPLICIT_RK_HPP
#define ODESTEP_COMPAT_EXPLICIT_RK_HPP

#include "rk/explicit_rk.hpp"

#endif
