// SPDX-License-Identifier: BSL-1.0
// odestep: the header's name before the headers moved into folders; it includes events/events.hpp.
#ifndef ODESTEP_COMPAT_EVENTS_HPP
#define ODESTEP_COMPAT_EVENTS_HPP

#include "events/events.hpp"

#endif
