# SPDX-License-Identifier: BSL-1.0
# Checks bouncing_ball's output against the closed forms of the bouncing ball (any mechanics text; derived
# here): falling from h at rest the ball lands at t_1 = sqrt(2 h / g) with speed v_1 = sqrt(2 g h); it leaves
# impact k with speed e^k v_1 and flies 2 e^k v_1 / g, so t_{k+1} = t_k + 2 e^k v_1 / g. Summing the
# geometric series, the impacts accumulate at the Zeno time t_1 + 2 v_1 e / (g (1 - e)) = t_1 (1 + e) / (1 - e).
# RK4 is exact for constant gravity and each impact is located to a few ULPs: every time to 1e-12.
#  (a) No latch: the loop allows 8 firings per step (event_limits' default), so the run stops with status
#      event_limit at the 8th impact of the first step [i dt, (i + 1) dt] that holds a 9th; recomputed here
#      from the closed-form times (the time reported is that of the last impact that fired).
#  (b) Latch: impact k arrives at e^(k-1) v_1 and would leave at e^k v_1; the first with e^k v_1 < 0.1 is
#      k = ceil(ln(0.1 / v_1) / ln e), which puts the ball at rest: status ok at t = 5, y = v = 0.
function abs(v) { return v < 0 ? -v : v }
function report(ok, text) { printf "%-4s %s\n", ok ? "ok" : "FAIL", text; if (!ok) bad = 1; seen++ }
function ceil(x) { return x == int(x) ? x : (x > 0 ? int(x) + 1 : int(x)) }
BEGIN {
    g = 9.8; e = 0.7; h = 1; dt = 0.01; bad = 0; seen = 0
    v1 = sqrt(2 * g * h); t[1] = sqrt(2 * h / g)
    for (k = 1; k < 200; k++) t[k + 1] = t[k] + 2 * e ^ k * v1 / g
    zeno = t[1] * (1 + e) / (1 - e)
    # (a): the first grid step with more than 8 impacts, and the 8th impact in it
    for (k = 1; k < 200; k++) {
        step = int(t[k] / dt); if (step != last_step) { in_step = 0; last_step = step }
        if (++in_step == 9) { limit_at = k - 1; break }
    }
    # (b)
    latch_k = ceil(log(0.1 / v1) / log(e))
}
$1 == "impact" { k = $2; report(abs($3 - t[k]) <= 1e-12, sprintf("impact %2d at %.15g (closed form %.15g)", k, $3, t[k])) }
$1 == "nolatch" { n = $7
    report($3 == "event_limit", "no latch: status " $3 " (event_limit)")
    report($5 < zeno, sprintf("no latch: stopped at %.15g, before the Zeno time %.15g", $5, zeno))
    report(n == limit_at, sprintf("no latch: %d impacts (the 8th of the first step with 9: impact %d)", n, limit_at))
    report(abs($5 - t[n]) <= 1e-12, sprintf("no latch: stop time %.15g is impact %d's, %.15g", $5, n, t[n]))
    report($9 >= 0, "no latch: the ball is not below the floor, y = " $9) }
$1 == "latch" { n = $7
    report($3 == "ok" && $5 == 5, "latch: status " $3 " at t = " $5 " (ok at 5)")
    report(n == latch_k, sprintf("latch: %d impacts (ceil(ln(0.1/v1)/ln e) = %d)", n, latch_k))
    report(abs($9 - t[n]) <= 1e-12, sprintf("latch: at rest from %.15g, impact %d's time %.15g", $9, n, t[n]))
    report($11 == 0 && $13 == 0 && $15 == 1, "latch: the ball lies still, y = " $11 ", v = " $13) }
END { if (seen != 19) { print "FAIL: expected 19 checks, got " seen; bad = 1 } exit bad }
