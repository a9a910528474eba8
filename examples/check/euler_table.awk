# SPDX-License-Identifier: BSL-1.0
# Checks euler_table's output: Euler on y' = -x y gives y_{k+1} = y_k (1 - x_k h) exactly, x_k = k h,
# against the printed y and the errors against exp(-x^2/2).
function abs(v) { return v < 0 ? -v : v }
function near(got, want, tol) { return (got - want) <= tol && (want - got) <= tol }
BEGIN { h = 0.5; y = 1; k = 0; bad = 0 }
/^#/ || $1 == "x" { next }
{
    x = $1 + 0; got = $2 + 0; abs_err = $4 + 0; rel_err = $5 + 0
    exact = exp(-x * x / 2)
    ok = near(x, k * h, 1e-15) && near(got, y, 1e-12) && near(abs_err, abs(y - exact), 1e-4 * abs(y - exact) + 1e-15) \
         && near(rel_err, abs(y - exact) / exact, 1e-4 * abs(y - exact) / exact + 1e-15)
    printf "%-4s x=%-3g y %.12g (product %.12g) exact %.12g\n", ok ? "ok" : "FAIL", x, got, y, exact
    if (!ok) bad = 1
    y = y * (1 - x * h); k++
}
END { if (k != 7) { print "FAIL: expected 7 rows, got " k; bad = 1 } exit bad }
