// SPDX-License-Identifier: BSL-1.0
// Everything a unit of bench/m4f/steppers.cpp includes, in one header that scripts/bench-m4f.sh precompiles
// once per -O (the 42 units then skip parsing the library: about 0.3 s of compiler time each).
#ifndef ODESTEP_BENCH_M4F_UNITS_HPP
#define ODESTEP_BENCH_M4F_UNITS_HPP

#include <odestep/odestep.hpp>

#include "hand.hpp"
#include "m4f/common.hpp"
#include "m4f/hand_more.hpp"

#endif
