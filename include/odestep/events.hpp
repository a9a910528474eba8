// SPDX-License-Identifier: BSL-1.0
// odestep: deprecated (removed in 1.0.0): the header's name before the headers moved into folders; include
// <odestep/events/events.hpp> instead, which this one includes.
#ifndef ODESTEP_COMPAT_EVENTS_HPP
#define ODESTEP_COMPAT_EVENTS_HPP

#include "events/events.hpp"

#endif
