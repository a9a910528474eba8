// SPDX-License-Identifier: BSL-1.0
// odestep C API, float: the stiff steppers and the steps with Phi of include/odestep/odestep.h with the suffix _f.
#include "capi_stiff_impl.hpp"

#define ODESTEP_CAPI_T float
#define ODESTEP_CAPI_NAME(name) name##_f
#include "capi_stiff.inc"
