// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes multistep/adams.hpp.
#ifndef ODESTEP_COMPAT_MULTISTEP_HPP
#define ODESTEP_COMPAT_MULTISTEP_HPP

#include "multistep/adams.hpp"

#endif
