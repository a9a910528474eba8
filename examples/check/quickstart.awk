# SPDX-License-Identifier: BSL-1.0
# Checks the README example: RK4 at dt = 0.01 reaches cos(10) and -sin(10) to 1e-8.
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { bad = 0; seen = 0 }
$1 == "status" { if ($2 != "ok" || $4 != 1000) bad = 1; seen++ }
$1 == "x" { if (!near($3 + 0, cos(10), 1e-8)) bad = 1; seen++ }
$1 == "v" { if (!near($3 + 0, -sin(10), 1e-8)) bad = 1; seen++ }
END { if (seen != 3) bad = 1; print (bad ? "FAIL" : "ok") " quickstart"; exit bad }
