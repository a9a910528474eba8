# SPDX-License-Identifier: BSL-1.0
# Checks harmonic_oscillator's output against closed forms computed here, independently of odestep.
# On x' = v, v' = -x the complex w = x - i v obeys w' = i w, so a Runge-Kutta step multiplies w by the
# method's stability function R(i h): Euler 1 + ih, midpoint 1 + ih - h^2/2, RK4 1 + ih - h^2/2 - ih^3/6
# + h^4/24. With n - 1 steps of dt and a last step h_last = 20 pi - (n - 1) dt, w = R(i dt)^(n-1) R(i h_last).
function stability(method, h) {
    if (method == "euler") { re = 1; im = h }
    else if (method == "euler_richardson") { re = 1 - h * h / 2; im = h }
    else if (method == "rk4") { re = 1 - h * h / 2 + h ^ 4 / 24; im = h - h ^ 3 / 6 }
    else { print "unknown method " method; bad = 1 }
}
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { pi = atan2(0, -1); rows = 0; bad = 0 }
/^#/ || $1 == "method" { next }
{
    method = $1; dt = $2 + 0; n = $3 + 0; x = $4 + 0; v = $5 + 0; amp = $6 + 0; ratio = $7 + 0
    t_end = 20 * pi
    want_n = int(t_end / dt); if (want_n * dt < t_end * (1 - 1e-12)) want_n++
    h_last = t_end - (n - 1) * dt
    stability(method, dt); lnmod = (n - 1) * log(re * re + im * im) / 2; arg = (n - 1) * atan2(im, re)
    stability(method, h_last); lnmod += log(re * re + im * im) / 2; arg += atan2(im, re)
    mod = exp(lnmod); want_x = mod * cos(arg); want_v = -mod * sin(arg)
    ok = (n == want_n) && near(x, want_x, 1e-9 * mod) && near(v, want_v, 1e-9 * mod) \
         && near(amp, mod, 1e-10 * mod) && near(ratio, mod * mod, 1e-10 * mod * mod)
    if (method == "euler") {  # Euler's energy grows as (1 + dt^2) per step
        growth = exp((n - 1) * log(1 + dt * dt)) * (1 + h_last * h_last)
        ok = ok && near(ratio, growth, 1e-10 * growth)
    }
    printf "%-4s %-17s dt=%-5g E/E0 %.10g (closed form %.10g), x %.10g (%.10g)\n", ok ? "ok" : "FAIL", method, dt, ratio, mod * mod, x, want_x
    if (!ok) bad = 1
    rows++
}
END { if (rows != 6) { print "FAIL: expected 6 rows, got " rows; bad = 1 } exit bad }
