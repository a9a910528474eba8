# SPDX-License-Identifier: BSL-1.0
# Checks steel_ball against closed forms and an integration of its own (RK4, dt = 1e-3 s, the ground
# located by the secant method on the last step's length), independently of odestep.
# - No drag (3.7a, b): the range from height h at angle a is (v0 cos a / g) (v0 sin a + sqrt(v0^2 sin^2 a +
#   2 g h)); it is largest at sin a = v0 / sqrt(2 (v0^2 + g h)) (45 degrees from the ground), where it is
#   (v0 / g) sqrt(v0^2 + 2 g h). The search is golden-section on a flat maximum: the angle to 1e-3 degrees,
#   the range to 1e-9 m (Euler-Richardson is exact for a constant force; the event to a few ULPs).
# - Drag (3.7c): the range at the printed angle (Euler-Richardson at dt = 1e-4 s: about 1e-8 m from RK4's;
#   allowed 1e-6 m), and no longer range half a degree either side.
# - Falls (3.8): without drag both take sqrt(2 h / g). Quadratic drag, dropped: (vt / g) acosh(exp(h g / vt^2))
#   (from v = -vt tanh(g t / vt)); thrown: this script's RK4, and later than dropped. Linear drag: both obey
#   y = h - (g/b) t + (g/b^2) (1 - exp(-b t)) (b = C1/m), solved here by bisection, and land together;
#   the thrown one's x is (v0 / b) (1 - exp(-b t)). Allowed 1e-7 s and 1e-6 m.
function abs(v) { return v < 0 ? -v : v }
function acc(vx, vy) {   # sets AX, AY for the current LAW, K
    if (LAW == "quadratic") { sp = sqrt(vx * vx + vy * vy); AX = -K * sp * vx; AY = -9.8 - K * sp * vy }
    else if (LAW == "linear") { AX = -K * vx; AY = -9.8 - K * vy }
    else { AX = 0; AY = -9.8 }
}
function step(h,    k1x, k1y, k1u, k1w, k2x, k2y, k2u, k2w, k3x, k3y, k3u, k3w, k4x, k4y, k4u, k4w) {
    acc(U, W); k1x = U; k1y = W; k1u = AX; k1w = AY
    acc(U + h / 2 * k1u, W + h / 2 * k1w); k2x = U + h / 2 * k1u; k2y = W + h / 2 * k1w; k2u = AX; k2w = AY
    acc(U + h / 2 * k2u, W + h / 2 * k2w); k3x = U + h / 2 * k2u; k3y = W + h / 2 * k2w; k3u = AX; k3w = AY
    acc(U + h * k3u, W + h * k3w); k4x = U + h * k3u; k4y = W + h * k3w; k4u = AX; k4w = AY
    NX = X + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x); NY = Y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y)
    NU = U + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u); NW = W + h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)
}
function fly(h0, vx, vy,    t, a, b, fa, fb, m, it, dt) {   # sets FT, FX
    X = 0; Y = h0; U = vx; W = vy; t = 0; dt = 1e-3
    for (;;) { step(dt); if (NY < 0 && (t > 0 || h0 > 0)) break; X = NX; Y = NY; U = NU; W = NW; t += dt }
    a = 0; fa = Y; b = dt; fb = NY
    for (it = 0; it < 40 && abs(fb) > 1e-13; it++) { m = b - fb * (b - a) / (fb - fa); step(m); a = b; fa = fb; b = m; fb = NY }
    step(b); FT = t + b; FX = NX
}
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
BEGIN { bad = 0; seen = 0; g = 9.8; deg = atan2(1, 1) / 45 }
$1 == "range" {
    name = $2; K = $4 + 0; h = $6 + 0; v0 = $8 + 0; angle = $10 + 0; r = $13 + 0
    if (K == 0) {
        a = atan2(v0, sqrt(2 * (v0 * v0 + g * h) - v0 * v0)); want = v0 / g * sqrt(v0 * v0 + 2 * g * h)
        best_a[name] = a; H[name] = h; V[name] = v0
        report(abs(angle - a / deg) <= 1e-3 && abs(r - want) <= 1e-9, sprintf("%s: best angle %.6f deg (closed form %.6f), range %.10f m (closed form %.10f)", name, angle, a / deg, r, want))
    } else {
        LAW = "quadratic"; fly(h, v0 * cos(angle * deg), v0 * sin(angle * deg)); mid = FX
        fly(h, v0 * cos((angle - 0.5) * deg), v0 * sin((angle - 0.5) * deg)); lo = FX
        fly(h, v0 * cos((angle + 0.5) * deg), v0 * sin((angle + 0.5) * deg)); hi = FX
        report(abs(r - mid) <= 1e-6 && lo < mid && hi < mid, sprintf("%s (C2/m = %.6f): best angle %.4f deg, range %.6f m (RK4 here %.6f; %.6f and %.6f half a degree either side)", name, K, angle, r, mid, lo, hi))
    }
}
$1 == "range_2%" {
    name = $2; a = best_a[name]; h = H[name]; v0 = V[name]
    lo = v0 * cos(0.98 * a) / g * (v0 * sin(0.98 * a) + sqrt(v0 ^ 2 * sin(0.98 * a) ^ 2 + 2 * g * h))
    hi = v0 * cos(1.02 * a) / g * (v0 * sin(1.02 * a) + sqrt(v0 ^ 2 * sin(1.02 * a) ^ 2 + 2 * g * h))
    report(abs($4 - lo) <= 1e-6 && abs($7 - hi) <= 1e-6, sprintf("%s: 2%% off the best angle the range is %.8f and %.8f m (closed form %.8f, %.8f)", name, $4, $7, lo, hi))
}
$1 == "fall" {
    LAW = $2; K = $4 + 0; td = $6 + 0; tt = $9 + 0; xt = $12 + 0; h = 10; v0 = 30
    if (LAW == "nodrag") { want = sqrt(2 * h / g); ok = abs(td - want) <= 1e-7 && abs(tt - want) <= 1e-7 && abs(xt - v0 * want) <= 1e-6; text = sprintf("both %.9f s", want) }
    else if (LAW == "quadratic") {
        vt = sqrt(g / K); want = vt / g * log(exp(h * g / vt ^ 2) + sqrt(exp(2 * h * g / vt ^ 2) - 1))
        fly(h, v0, 0); ok = abs(td - want) <= 1e-7 && abs(tt - FT) <= 1e-7 && abs(xt - FX) <= 1e-6 && tt > td
        text = sprintf("dropped %.9f s (closed form), thrown %.9f s at x = %.6f m (RK4 here)", want, FT, FX)
    } else {
        lo = 0; hi = 10; for (i = 0; i < 200; i++) { m = (lo + hi) / 2; if (h - g / K * m + g / K ^ 2 * (1 - exp(-K * m)) > 0) lo = m; else hi = m }
        want = lo; ok = abs(td - want) <= 1e-7 && abs(tt - want) <= 1e-7 && abs(xt - v0 / K * (1 - exp(-K * want))) <= 1e-6
        text = sprintf("both %.9f s, thrown to x = %.6f m (closed form)", want, v0 / K * (1 - exp(-K * want)))
    }
    report(ok, sprintf("fall, %s: dropped %.9f s, thrown %.9f s; %s", LAW, td, tt, text))
}
END { if (seen != 7) { print "FAIL: expected 7 checks, got " seen; bad = 1 } exit bad }
