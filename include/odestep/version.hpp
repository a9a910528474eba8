// SPDX-License-Identifier: BSL-1.0
// odestep: the library's version, kept equal to project(VERSION) in CMakeLists.txt by a test.
#ifndef ODESTEP_VERSION_HPP
#define ODESTEP_VERSION_HPP

/// \file
/// The version of odestep this header belongs to (semantic versioning: a new major version may break code
/// written against the last one; a minor version adds; a patch fixes).

#define ODESTEP_VERSION_MAJOR 0  ///< incompatible changes
#define ODESTEP_VERSION_MINOR 2  ///< additions
#define ODESTEP_VERSION_PATCH 0  ///< fixes
/// The version as one number, major * 10000 + minor * 100 + patch, for `#if ODESTEP_VERSION >= 200`.
#define ODESTEP_VERSION (ODESTEP_VERSION_MAJOR * 10000 + ODESTEP_VERSION_MINOR * 100 + ODESTEP_VERSION_PATCH)

#endif
