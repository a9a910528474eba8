# SPDX-License-Identifier: BSL-1.0
# Checks examples/own_stepper.cpp against y = e^-t. Heun's global error for y' = -y is, to leading order,
# t e^-t h^2 / 6 (its local error is h^3 y / 6), so at h = 0.01: 6.1e-6 at t = 1, and the event y = 1/2 is
# late by (ln 2 / 6) h^2 = 1.2e-5 in t. Each must be within 1.5 times that.
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { bad = 0; seen = 0; h = 0.01 }
$1 == "integrate:" { if ($3 != "ok," || !near($6 + 0, exp(-1), 1.5 * exp(-1) * h * h / 6)) bad = 1; seen++ }
$1 == "event:" { if ($3 != "stopped_by_event" || !near($7 + 0, log(2), 1.5 * log(2) * h * h / 6)) bad = 1; seen++ }
END { if (seen != 2) bad = 1; print (bad ? "FAIL" : "ok") " own_stepper"; exit bad }
