// SPDX-License-Identifier: BSL-1.0
// odestep: events, the moments when a function of the state crosses zero (the top of a flight, a ball
// reaching the floor, coffee cooling to drinking temperature), located by re-stepping the integrator from the
// start of the step, acted on, and paid for with a bounded, published amount of work per step. The loop is
// split into its phases, one header each:
//   event.hpp      the description of an event and its settings, the set of a run, what a run or tick reports
//   bounds.hpp     the work bounds (max_rhs_evals_per_step, ..._per_tick) and the check of the limits
//   arming.hpp     the crossing test and each event's memory (armed, last g, last firing)
//   engine_base.hpp  the engine's types, each event's memory, and the evaluation of the set
//   location.hpp   the state at a point of a step (re-stepping or the interpolant) and the narrowing to a crossing
//   engine.hpp     one step with events: the quiet step, the scan's passes, probes, firing rounds, commit, restart
//   integrate.hpp  integrate with events (the driving loop over [t0, t1])
//   stepper.hpp    event_stepper, the per-tick loop
//   free_running.hpp  integrate_adaptive and integrate_times with events (the free-running loops)
#ifndef ODESTEP_EVENTS_EVENTS_HPP
#define ODESTEP_EVENTS_EVENTS_HPP

#include "arming.hpp"
#include "bounds.hpp"
#include "engine.hpp"
#include "engine_base.hpp"
#include "event.hpp"
#include "free_running.hpp"
#include "integrate.hpp"
#include "location.hpp"
#include "stepper.hpp"

#endif
