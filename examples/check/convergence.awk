# SPDX-License-Identifier: BSL-1.0
# Checks convergence: every method's observed order and its cost, independently of odestep.
# - The exact position after 1.25 periods of the e = 0.5 Kepler orbit (GM = a = 1) from perihelion is
#   recomputed here from Kepler's equation (mean anomaly pi/2 = E - e sin E, by Newton's method): x =
#   cos E - e, y = sqrt(1 - e^2) sin E; each printed error must be the distance of the printed final
#   position from it.
# - Order: the local slopes log(e_k / e_k+1) / log(N_k+1 / N_k) over the consecutive runs whose finer error
#   lies in [5e-11, 1e-2] (above round-off, past the coarsest steps); their median must be the method's
#   published order to 0.3 (0.5 for orders 6 and 8, whose window in double is two or three halvings wide).
# - Cost: the evaluations of the right-hand side counted by the example must be the published cost per step
#   (README: the methods' tables) times N, plus what starting costs: one more evaluation for the methods
#   that keep an acceleration (velocity Verlet, half-step, Stormer's leapfrog, Beeman, Blanes-Moan), and
#   for Adams-Bashforth k (k - 1) RK4 starting steps of 4 evaluations, then 1 per step (2 for the
#   Adams-Bashforth-Moulton PECE). The predictor-corrector's iterations vary: between 2 and 17 per step.
function abs(v) { return v < 0 ? -v : v }
function median(a, n,    i, j, t) {
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
function finish(    m, tol) {
    if (method == "") return
    m = count ? median(slopes, count) : -99
    tol = order >= 6 ? 0.5 : 0.3
    ok = count >= 2 && abs(m - order) <= tol && cost_ok
    printf "%-4s %-9s %-26s order %d, observed %.2f (median of %d slopes), evaluations as published\n", ok ? "ok" : "FAIL", family, method, order, m, count
    if (!ok) bad = 1
    methods++
}
BEGIN {
    e = 0.5; M = atan2(1, 0); E = M
    for (i = 0; i < 50; i++) E -= (E - e * sin(E) - M) / (1 - e * cos(E))
    ex = cos(E) - e; ey = sqrt(1 - e * e) * sin(E)
    split("euler 1 midpoint 2 heun 2 ralston2 2 kutta3 3 ssprk3 3 bogacki_shampine32 3 rk4 4 rk38 4 fehlberg45 6 cash_karp54 6 dormand_prince54 6 fehlberg78 12 dop853 12 newtonian_euler 1 newtonian_midpoint 1 euler_cromer 1 euler_cromer_drift_first 1 half_step 1 newtonian_euler_richardson 2 velocity_verlet 1 position_verlet 1 leapfrog_position_form 1 beeman 1 forest_ruth 3 blanes_moan4 6 yoshida6 7", w, " ")
    for (i = 1; i in w; i += 2) per[w[i]] = w[i + 1]
    split("half_step velocity_verlet leapfrog_position_form beeman blanes_moan4", w, " "); for (i in w) extra[w[i]] = 1
    split("adams_bashforth2 2 adams_bashforth3 3 adams_bashforth4 4 adams_bashforth5 5 adams_bashforth_moulton4 4", w, " ")
    for (i = 1; i in w; i += 2) adams_k[w[i]] = w[i + 1]
    bad = 0; methods = 0
}
$1 == "conv" && $3 != "method" {
    if ($3 != method) { finish(); method = $3; family = $2; order = $4 + 0; count = 0; prev_n = 0; cost_ok = 1 }
    n = $5 + 0; evals = $7 + 0; err = $8 + 0; x = $9 + 0; y = $10 + 0
    if (abs(err - sqrt((x - ex) ^ 2 + (y - ey) ^ 2)) > 1e-6 * err + 1e-15) { printf "FAIL: %s N %d: error %g is not |x - exact|\n", method, n, err; cost_ok = 0 }
    if (method in per) want = per[method] * n + (method in extra ? 1 : 0)
    else if (method in adams_k) { k = adams_k[method]; want = 4 * (k - 1) + (method ~ /moulton/ ? 2 : 1) * (n - (k - 1)) }
    else if (method == "predictor_corrector") want = (evals >= 2 * n && evals <= 17 * n) ? evals : -1
    else want = -1
    if (evals != want) { printf "FAIL: %s N %d: %d evaluations, published cost %d\n", method, n, evals, want; cost_ok = 0 }
    if (prev_n > 0 && err >= 5e-11 && err <= 1e-2) slopes[++count] = log(prev_err / err) / log(n / prev_n)
    prev_n = n; prev_err = err
}
$1 == "conv_stopped" { if ($3 != "predictor_corrector" || $5 != "no_convergence") { print "FAIL: unexpected stop: " $0; bad = 1 } }
END { finish(); if (methods != 33) { print "FAIL: expected 33 methods, got " methods; bad = 1 } exit bad }
