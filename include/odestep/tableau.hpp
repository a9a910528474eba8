// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes tables/butcher.hpp.
#ifndef ODESTEP_COMPAT_TABLEAU_HPP
#define ODESTEP_COMPAT_TABLEAU_HPP

#include "tables/butcher.hpp"

#endif
