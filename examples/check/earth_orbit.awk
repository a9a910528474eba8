# SPDX-License-Identifier: BSL-1.0
# Checks earth_orbit against what the mechanics says, independently of odestep:
# - angular momentum: Euler-Cromer (x1 x v1 = x x (v + a dt) = L, as x x a = 0 for a central force) and
#   velocity Verlet conserve it exactly, so |dL/L0| is round-off only (< 1e-12 over 10^4 steps); Euler
#   changes it by dt^2 (v x a) > 0 per step on a prograde orbit, so it grows;
# - energy: Euler spirals outward (dE > 0). On a circular orbit v . a = 0, so Euler-Cromer's O(dt) energy
#   oscillation vanishes and its largest error scales as dt^2 (ratio 100 between dt = 0.01 and 0.001), and
#   velocity Verlet's dt^2 term of the modified energy is constant along the orbit, leaving dt^4 (ratio 10^4).
function abs(v) { return v < 0 ? -v : v }
BEGIN { bad = 0; rows = 0 }
/^#/ || $1 == "method" { next }
{
    m = $1; dt = $2; worst[m, dt] = $4 + 0; dl = $6 + 0; de = $5 + 0; rows++
    if (m == "euler") ok = dl > 0 && de > 0
    else ok = abs(dl) < 1e-12
    printf "%-4s %-16s dt=%-6s max|dE/E0| %s dL/L0 %s\n", ok ? "ok" : "FAIL", m, dt, $4, $6
    if (!ok) bad = 1
}
END {
    ec = worst["euler_cromer", "0.01"] / worst["euler_cromer", "0.001"]
    vv = worst["velocity_verlet", "0.01"] / worst["velocity_verlet", "0.001"]
    ok = ec > 80 && ec < 120; printf "%-4s euler_cromer energy error ratio %.1f (dt^2: 100)\n", ok ? "ok" : "FAIL", ec; if (!ok) bad = 1
    ok = vv > 8000 && vv < 12000; printf "%-4s velocity_verlet energy error ratio %.0f (dt^4: 10000)\n", ok ? "ok" : "FAIL", vv; if (!ok) bad = 1
    if (rows != 6) { print "FAIL: expected 6 rows, got " rows; bad = 1 }
    exit bad
}
