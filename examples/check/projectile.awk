# SPDX-License-Identifier: BSL-1.0
# Checks projectile's output.
#  - Without drag, from the ground: x = v0 cos(a) t, y = v0 sin(a) t - g t^2 / 2 is back at 0 at
#    t = 2 v0 sin(a) / g, so the range is v0^2 sin(2a) / g, v0^2 / g at 45 degrees. RK4 is exact for a
#    constant acceleration and the event is located to a few ULPs: to 1e-9 relative.
#  - With drag there is no closed form; the example's reference is the range at the optimum with a ten times
#    smaller step (RK4's error falls by 10^4) and with DOP853 (eighth order): all three must agree to 1e-7
#    relative (RK4 at dt = 0.01 is about 6e-9 from both here).
#  - Drag lowers the best angle below 45 degrees (the drag-free optimum from the ground, or a little less
#    from h = 2 m), and the optimum must beat its neighbours at +-0.01 rad.
#  - The golden-section search shrinks [0, pi/2] by 1/phi per round: ceil(ln(1e-6 / (pi/2)) / ln(1/phi))
#    rounds to reach 1e-6 rad.
function abs(v) { return v < 0 ? -v : v }
function rel(got, want) { return abs(got - want) / abs(want) }
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
BEGIN { g = 9.8; v0 = 30; pi = atan2(0, -1); bad = 0; seen = 0 }
$1 == "nodrag45" { want = v0 * v0 / g
    report(rel($3, want) <= 1e-9, sprintf("drag-free range at 45 deg %.15g (v0^2/g = %.15g, rel %.1e <= 1e-9)", $3, want, rel($3, want))) }
$1 == "drag" { angle = $7 + 0; rounds = $12
    report(angle > 0 && angle < pi / 4, sprintf("optimum angle %.9f rad = %.6f deg, below 45 deg", angle, angle * 180 / pi))
    want = log(1e-6 / (pi / 2)) / log((sqrt(5) - 1) / 2); want = int(want) + (want > int(want))
    report(rounds == want, sprintf("golden-section rounds %d (ceil(ln(1e-6 / (pi/2)) / ln(1/phi)) = %d)", rounds, want)) }
$1 == "range_opt" { r[$2] = $3 + 0 }
$1 == "range_minus" { minus = $3 + 0 }
$1 == "range_plus" { plus = $3 + 0 }
END {
    report(("rk4" in r) && ("rk4_dt/10" in r) && ("dop853" in r), "three ranges at the optimum printed")
    report(rel(r["rk4"], r["rk4_dt/10"]) <= 1e-7, sprintf("range %.12g vs dt/10 %.12g (rel %.1e <= 1e-7)", r["rk4"], r["rk4_dt/10"], rel(r["rk4"], r["rk4_dt/10"])))
    report(rel(r["rk4"], r["dop853"]) <= 1e-7, sprintf("range %.12g vs DOP853 %.12g (rel %.1e <= 1e-7)", r["rk4"], r["dop853"], rel(r["rk4"], r["dop853"])))
    report(rel(r["rk4_dt/10"], r["dop853"]) <= 1e-7, sprintf("dt/10 vs DOP853 (rel %.1e <= 1e-7)", rel(r["rk4_dt/10"], r["dop853"])))
    report(minus != "" && plus != "" && r["rk4"] >= minus && r["rk4"] >= plus,
           sprintf("range(opt) %.12g >= range(opt - 0.01) %.12g and range(opt + 0.01) %.12g", r["rk4"], minus, plus))
    if (seen != 8) { print "FAIL: expected 8 checks, got " seen; bad = 1 }
    exit bad
}
