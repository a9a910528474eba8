// SPDX-License-Identifier: BSL-1.0
// Holds mutable static state on purpose: check_static_state.cmake must reject this object.
static int counter;
int bump() { return ++counter; }
