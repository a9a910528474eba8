// SPDX-License-Identifier: BSL-1.0
// The one error channel.
#include <doctest/doctest.h>
#include <odestep/status.hpp>

#include <cstddef>
#include <cstring>
#include <iterator>

TEST_CASE("status: every value has its own name") {
    using odestep::status;
    const status all[] = {status::ok,
                          status::invalid_time,
                          status::invalid_step,
                          status::wrong_direction,
                          status::too_many_steps,
                          status::non_finite,
                          status::no_convergence,
                          status::step_mismatch,
                          status::invalid_tolerance,
                          status::stopped_by_event,
                          status::event_limit,
                          status::non_finite_event,
                          status::singular_matrix,
                          status::substep_limit,
                          status::step_too_small,
                          status::invalid_setting,
                          status::storage_full};
    for (std::size_t i = 0; i < std::size(all); ++i)
        for (std::size_t j = i + 1; j < std::size(all); ++j)
            CHECK(std::strcmp(to_string(all[i]), to_string(all[j])) != 0);
    CHECK(std::strcmp(to_string(status::non_finite), "non_finite") == 0);
}

TEST_CASE("status: ok is the zero value, so a status converts to a plain error code for C callers") {
    CHECK(static_cast<int>(odestep::status::ok) == 0);
}
