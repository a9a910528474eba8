// SPDX-License-Identifier: BSL-1.0
// odestep C API: the functions that do not depend on the precision.
#include "odestep/odestep.h"
#include "odestep/status.hpp"

extern "C" {

const char* odestep_status_name(odestep_status s) {
    // Every C value is a C++ status of the same value (tests/c/status_agreement_test.cpp); past the last
    // one, to_string's own fallback is not reached through the cast, so the range is checked here.
    if (static_cast<int>(s) < 0 || static_cast<int>(s) > static_cast<int>(odestep::status::storage_full))
        return "unknown";
    return odestep::to_string(static_cast<odestep::status>(static_cast<int>(s)));
}

size_t odestep_max_states(void) { return ODESTEP_C_MAX_STATES; }

size_t odestep_max_events(void) { return ODESTEP_C_MAX_EVENTS; }

}  // extern "C"
