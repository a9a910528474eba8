# SPDX-License-Identifier: BSL-1.0
# Checks curveball by integrating every printed pitch again here, independently of odestep: RK4 on the
# six first-order equations (x' = v, v' = g - C_D |v| v + C_M omega x v) with dt = 1e-4 s, the plate
# crossing x = 18 m located by the secant method on the length of the last step. RK4's error there is
# about 1e-13 m; the example's Euler-Richardson at the same dt is second order, about 1e-8 m: allowed 1e-6 m
# in height and side, 1e-7 s in time. And for (a), no drag and no spin, the closed form: the parabola
# z = 1.8 + 18 tan(angle) - g 18^2 / (2 v0^2 cos^2(angle)) is 1.5 m at the angle found here by bisection.
function abs(v) { return v < 0 ? -v : v }
function deriv(s, d,    sp) {   # s[1..6] = x y z vx vy vz; d[1..6] its derivative
    sp = sqrt(s[4] ^ 2 + s[5] ^ 2 + s[6] ^ 2)
    d[1] = s[4]; d[2] = s[5]; d[3] = s[6]
    d[4] = -CD * sp * s[4] + CM * (WY * s[6] - WZ * s[5])
    d[5] = -CD * sp * s[5] + CM * (WZ * s[4] - WX * s[6])
    d[6] = -CD * sp * s[6] + CM * (WX * s[5] - WY * s[4]) - 9.8
}
function rk4(s, h, out,    i, k1, k2, k3, k4, tmp) {
    deriv(s, k1); for (i = 1; i <= 6; i++) tmp[i] = s[i] + h / 2 * k1[i]
    deriv(tmp, k2); for (i = 1; i <= 6; i++) tmp[i] = s[i] + h / 2 * k2[i]
    deriv(tmp, k3); for (i = 1; i <= 6; i++) tmp[i] = s[i] + h * k3[i]
    deriv(tmp, k4); for (i = 1; i <= 6; i++) out[i] = s[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i])
}
function fly(v0, angle,    s, nxt, t, h, a, b, fa, fb, m, fm, i, it) {
    s[1] = 0; s[2] = 0; s[3] = 1.8; s[4] = v0 * cos(angle); s[5] = 0; s[6] = v0 * sin(angle); t = 0; h = 1e-4
    for (;;) { rk4(s, h, nxt); if (nxt[1] >= 18) break; for (i = 1; i <= 6; i++) s[i] = nxt[i]; t += h }
    a = 0; fa = s[1] - 18; b = h; fb = nxt[1] - 18
    for (it = 0; it < 30 && abs(fb) > 1e-14; it++) { m = b - fb * (b - a) / (fb - fa); rk4(s, m, nxt); fm = nxt[1] - 18; a = b; fa = fb; b = m; fb = fm }
    rk4(s, b, nxt); T = t + b; Y = nxt[2]; Z = nxt[3]
}
function parabola(angle, v0) { return 1.8 + 18 * sin(angle) / cos(angle) - 9.8 * 18 * 18 / (2 * v0 * v0 * cos(angle) ^ 2) - 1.5 }
BEGIN { bad = 0; seen = 0 }
$1 == "pitch" && $2 != "case" {
    name = $2; v0 = $3 + 0; CD = $4 + 0; CM = $5 + 0; WX = $6 + 0; WY = $7 + 0; WZ = $8 + 0; angle = $9 + 0
    fly(v0, angle)
    ok = abs($10 - T) <= 1e-7 && abs($11 - Y) <= 1e-6 && abs($12 - Z) <= 1e-6
    extra = ""
    if (name == "a_nodrag") {
        lo = -0.2; hi = 0.3; for (i = 0; i < 100; i++) { mid = (lo + hi) / 2; if (parabola(mid, v0) < 0) lo = mid; else hi = mid }
        ok = ok && abs(angle - lo) <= 1e-9; extra = sprintf(", closed-form angle %.12f", lo)
    }
    if (name ~ /^(b_drag|d_nospin)$/) ok = ok && abs($12 - 1.5) <= 1e-6
    if (name ~ /^[bcd]/) ok = ok && CD == 0.006
    if (name ~ /^[cd]_(topspin|backspin|curve)/) ok = ok && CM == 0.0004 && abs(WX) + abs(WY) + abs(WZ) == 200
    printf "%-4s %-12s angle %.9f rad (%.4f deg): at the plate after %.6f s, side %.6f m, height %.6f m (recomputed %.6f s, %.6f m, %.6f m)%s\n", ok ? "ok" : "FAIL", name, angle, angle * 45 / atan2(1, 1), $10, $11, $12, T, Y, Z, extra
    if (!ok) bad = 1; seen++
}
END { if (seen != 7) { print "FAIL: expected 7 pitches, got " seen; bad = 1 } exit bad }
