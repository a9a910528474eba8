# SPDX-License-Identifier: BSL-1.0
# Checks position_force against closed forms computed here, independently of odestep.
# Energy conservation under a = -g / (1 + y/R)^2 (the potential -g R^2 / (R + y)) gives the impact speed
# from rest at h: v^2 = 2 g R h / (R + h), against 2 g h for constant g; so v / sqrt(2 g h) =
# sqrt(R / (R + h)), which is 0.99 at h = R (1 / 0.99^2 - 1).
# Tolerances: velocity Verlet is exact for a constant force; what the varying force adds over the fall is
# below 1e-9 relative here (the step's error, O(dt^2 h / R) in the force), and the event's state lies
# within a few ULPs of the ground. The 1 % height: Brent's tolerance 1e-6 m plus the speed's error
# (1e-9 relative in v is 1e-7 R in h): 1 m; and the two steps must agree to 1 mm.
function abs(v) { return v < 0 ? -v : v }
BEGIN { g = 9.8; R = 6.37e6; bad = 0; seen = 0; h1 = R * (1 / (0.99 * 0.99) - 1) }
$1 == "impact" && $2 != "h" {
    h = $2 + 0; v = $3 + 0; vg = $4 + 0
    want = sqrt(2 * g * R * h / (R + h))
    ok = abs(v - want) <= 1e-9 * want && abs(vg - sqrt(2 * g * h)) <= 1e-15 * vg && abs($5 - sqrt(R / (R + h))) <= 1e-9
    printf "%-4s h = %g m: impact speed %.12g m/s (closed form %.12g; constant g %.12g)\n", ok ? "ok" : "FAIL", h, v, want, vg
    if (!ok) bad = 1; seen++
}
$1 == "one_percent" {
    dt = $3 + 0; h = $5 + 0; ratio = $8 + 0
    ok = abs(h - h1) <= 1 && abs(ratio - 0.99) <= 1e-9
    if (seen_h) ok = ok && abs(h - seen_h) <= 1e-3
    seen_h = h
    printf "%-4s 1%% slower than constant g at h = %.6f m (closed form R (1/0.99^2 - 1) = %.6f m), dt = %g\n", ok ? "ok" : "FAIL", h, h1, dt
    if (!ok) bad = 1; seen++
}
END { if (seen != 7) { print "FAIL: expected 7 lines, got " seen; bad = 1 } exit bad }
