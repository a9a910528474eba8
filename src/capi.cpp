// SPDX-License-Identifier: BSL-1.0
// odestep C API: the functions that do not depend on the precision.
#include "odestep/odestep.h"
#include "odestep/status.hpp"

namespace {

// Every C status has the C++ enum's value, checked where the library is compiled: the C API converts a
// C++ status by its value (capi_impl.hpp, to_c), so a C value that differed would name another status.
template <odestep_status C, odestep::status Cpp>
constexpr bool same_value() {
    return static_cast<int>(C) == static_cast<int>(Cpp);
}
static_assert(same_value<ODESTEP_OK, odestep::status::ok>());
static_assert(same_value<ODESTEP_INVALID_TIME, odestep::status::invalid_time>());
static_assert(same_value<ODESTEP_INVALID_STEP, odestep::status::invalid_step>());
static_assert(same_value<ODESTEP_WRONG_DIRECTION, odestep::status::wrong_direction>());
static_assert(same_value<ODESTEP_TOO_MANY_STEPS, odestep::status::too_many_steps>());
static_assert(same_value<ODESTEP_NON_FINITE, odestep::status::non_finite>());
static_assert(same_value<ODESTEP_NO_CONVERGENCE, odestep::status::no_convergence>());
static_assert(same_value<ODESTEP_STEP_MISMATCH, odestep::status::step_mismatch>());
static_assert(same_value<ODESTEP_INVALID_TOLERANCE, odestep::status::invalid_tolerance>());
static_assert(same_value<ODESTEP_STOPPED_BY_EVENT, odestep::status::stopped_by_event>());
static_assert(same_value<ODESTEP_EVENT_LIMIT, odestep::status::event_limit>());
static_assert(same_value<ODESTEP_NON_FINITE_EVENT, odestep::status::non_finite_event>());
static_assert(same_value<ODESTEP_SINGULAR_MATRIX, odestep::status::singular_matrix>());
static_assert(same_value<ODESTEP_SUBSTEP_LIMIT, odestep::status::substep_limit>());
static_assert(same_value<ODESTEP_STEP_TOO_SMALL, odestep::status::step_too_small>());
static_assert(same_value<ODESTEP_INVALID_SETTING, odestep::status::invalid_setting>());
static_assert(same_value<ODESTEP_STORAGE_FULL, odestep::status::storage_full>());
// storage_full is the last C++ status: a status added after it must be added to the C header too.
constexpr bool same_text(const char* a, const char* b) {
    while (*a != '\0' && *a == *b) {
        ++a;
        ++b;
    }
    return *a == *b;
}
static_assert(same_text(odestep::to_string(static_cast<odestep::status>(17)), "unknown"),
              "a C++ status past storage_full has no C counterpart");

}  // namespace

extern "C" {

const char* odestep_status_name(odestep_status s) {
    // Every C value is a C++ status of the same value (the static_asserts above); past the last
    // one, to_string's own fallback is not reached through the cast, so the range is checked here.
    if (static_cast<int>(s) < 0 || static_cast<int>(s) > static_cast<int>(odestep::status::storage_full))
        return "unknown";
    return odestep::to_string(static_cast<odestep::status>(static_cast<int>(s)));
}

size_t odestep_max_states(void) { return ODESTEP_C_MAX_STATES; }

size_t odestep_max_events(void) { return ODESTEP_C_MAX_EVENTS; }

}  // extern "C"
