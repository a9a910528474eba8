# SPDX-License-Identifier: BSL-1.0
# Checks kepler_orbits: a circular orbit of radius 4 with GM = 1 has period 2 pi 4^(3/2) = 16 pi (Kepler's
# third law) and x(t) = 4 cos(t / 8) turns at t / 8 = k pi: 20 turning points in 10 1/4 orbits. Velocity
# Verlet at dt = 0.01 keeps the radius to O(dt^2) and the period to O(dt^2): both within 1e-5 relative.
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { pi = atan2(0, -1); bad = 0; seen = 0 }
$1 == "turning_points" { seen++; ok = ($2 == 20); printf "%-4s turning points %d (closed form 20)\n", ok ? "ok" : "FAIL", $2; if (!ok) bad = 1 }
$1 == "orbits" { seen++; ok = ($2 == 10); printf "%-4s orbits %d (10)\n", ok ? "ok" : "FAIL", $2; if (!ok) bad = 1 }
$1 == "period" { seen++; ok = near($2 + 0, 16 * pi, 1e-5 * 16 * pi); printf "%-4s period %s (16 pi = %.9f)\n", ok ? "ok" : "FAIL", $2, 16 * pi; if (!ok) bad = 1 }
$1 == "radius" { seen++; ok = near($2 + 0, 4, 4e-5); printf "%-4s radius %s (4)\n", ok ? "ok" : "FAIL", $2; if (!ok) bad = 1 }
END { if (seen != 4) { print "FAIL: expected 4 lines, got " seen; bad = 1 } exit bad }
