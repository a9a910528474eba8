// SPDX-License-Identifier: BSL-1.0
// version.hpp says the same version as CMakeLists.txt's project(VERSION), which the build passes in.
#include <doctest/doctest.h>
#include <odestep/version.hpp>

TEST_CASE("version: the header's macros are the project's version") {
    CHECK(ODESTEP_VERSION_MAJOR == ODESTEP_PROJECT_VERSION_MAJOR);
    CHECK(ODESTEP_VERSION_MINOR == ODESTEP_PROJECT_VERSION_MINOR);
    CHECK(ODESTEP_VERSION_PATCH == ODESTEP_PROJECT_VERSION_PATCH);
    CHECK(ODESTEP_VERSION ==
          ODESTEP_PROJECT_VERSION_MAJOR * 10000 + ODESTEP_PROJECT_VERSION_MINOR * 100 + ODESTEP_PROJECT_VERSION_PATCH);
}
