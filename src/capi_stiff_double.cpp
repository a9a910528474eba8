// SPDX-License-Identifier: BSL-1.0
// odestep C API, double: the stiff steppers and the steps with Phi of include/odestep/odestep.h with the suffix _d.
#include "capi_stiff_impl.hpp"

#define ODESTEP_CAPI_T double
#define ODESTEP_CAPI_NAME(name) name##_d
#include "capi_stiff.inc"
