"""Exact dynamic FORM of tests/cli/dynamic-form-sdof.prm, by a second
implementation: the Newmark average-acceleration recurrence of the SDOF
m x'' + c x' + k x = -m a_g(t), from rest, with the held white noise
a_g(t_n) = sqrt(2 pi S0 / D) u_k, k = floor(t_n / D) (ground_motion.cc).
The final drift ratio r = x(T)/h is linear in u: r = s . u, s_k the response
to u = e_k, so G(u) = c - s . u and FORM's answer is exact:
beta = c / |s|, alpha = s / |s|, u* = beta alpha.
Usage: dynamic_form_check.py summary.json c"""
import json
import math
import sys

m, k, c_damp, h = 1000.0, 39478.417604357434, 628.31853071795865, 3.0
s0, hold, dt, duration = 0.01, 0.1, 0.01, 2.0
gamma, beta_n = 0.5, 0.25


def final_drift(values):
    """x(T)/h of the SDOF under the held samples `values` (m/s^2)."""
    n_steps = int(round(duration / dt))

    def ground(n):
        i = int(n * dt / hold + 1e-9)
        return values[i] if i < len(values) else 0.0

    x, v = 0.0, 0.0
    a = -ground(0)
    k_hat = k + gamma / (beta_n * dt) * c_damp + m / (beta_n * dt * dt)
    for n in range(n_steps):
        p = -m * ground(n + 1)
        p_hat = (p + m * (x / (beta_n * dt * dt) + v / (beta_n * dt) + (0.5 / beta_n - 1) * a)
                 + c_damp * (gamma * x / (beta_n * dt) + (gamma / beta_n - 1) * v
                             + dt * (gamma / (2 * beta_n) - 1) * a))
        x_new = p_hat / k_hat
        a_new = (x_new - x) / (beta_n * dt * dt) - v / (beta_n * dt) - (0.5 / beta_n - 1) * a
        v = v + dt * ((1 - gamma) * a + gamma * a_new)
        x, a = x_new, a_new
    return x / h


summary = json.load(open(sys.argv[1]))
threshold = float(sys.argv[2])
n = len(summary["variables"])
scale = math.sqrt(2 * math.pi * s0 / hold)
s = [final_drift([scale if j == i else 0.0 for j in range(n)]) for i in range(n)]
norm = math.sqrt(sum(x * x for x in s))
beta = threshold / norm
pf = 0.5 * math.erfc(beta / math.sqrt(2))
got = summary["beta"]
assert summary["converged"], summary
assert abs(got / beta - 1) < 1e-6, (got, beta)
assert abs(summary["failure_probability"] / pf - 1) < 1e-5, (summary["failure_probability"], pf)
for i in range(n):
    assert abs(summary["alpha"][i] - s[i] / norm) < 1e-6, (i, summary["alpha"][i], s[i] / norm)
    assert abs(summary["design_point_u"][i] - beta * s[i] / norm) < 1e-5
print("beta %.10g (exact %.10g), Pf %.6g, %d variables, %d time histories"
      % (got, beta, summary["failure_probability"], n, summary["time_histories"]))
