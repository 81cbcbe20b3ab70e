"""The force-time fit of benches/fit.rs with SciPy: least_squares (trust region reflective,
bounds, finite-difference Jacobian) over solve_ivp, for the ratio in BENCHMARKS.md.

Model (docs/model.md §2, linear law below flattening): state (a, a', y), a(0) = y(0) = 0,
a'(0) = v0; F = K_p (a - y); a'' = -F/m; y' = (F - K_r y)/c; contact ends at F = 0 falling
(RK45, rtol 1e-10, atol 1e-14 on the state scale). Residual at each sample time t:
b + F(t - t0) - data, F = 0 outside the contact. Variables: ln K_p, ln c, ln K_r, t0, b,
started like bouncelab from the pulse (t0 where the force first exceeds 5 % of the peak, b the
median of the first tenth) and the same far-off ball (K_p = 2e5, c = 24, K_r = 3.6e4).

Usage: fit_scipy.py TRACE.csv REPEATS. Prints "median_s <seconds>" and the fitted values.
"""
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

M, V0 = 0.05, 2.0


def force_at(params, s):
    kp, c, kr = params
    def rhs(t, x):
        f = kp * (x[0] - x[2])
        return [x[1], -f / M, (f - kr * x[2]) / c]

    def end(t, x):
        return x[0] - x[2]

    end.terminal = True
    end.direction = -1
    t_max = 50.0 * np.pi * np.sqrt(M / kp)
    sol = solve_ivp(rhs, (0.0, t_max), [0.0, V0, 0.0], method="RK45", rtol=1e-10,
                    atol=1e-14, events=end, dense_output=True)
    tf = sol.t[-1]
    out = np.zeros_like(s)
    inside = (s > 0) & (s < tf)
    x = sol.sol(s[inside])
    out[inside] = kp * (x[0] - x[2])
    return out


def main():
    data = np.loadtxt(sys.argv[1], delimiter=",", skiprows=1)
    repeats = int(sys.argv[2])
    t, f = data[:, 0], data[:, 1]
    base = np.median(f[: len(f) // 10])
    peak = np.max(f - base)
    t_start = t[np.argmax(f - base > 0.05 * peak)]
    x0 = np.array([np.log(2e5), np.log(24.0), np.log(3.6e4), t_start, base])

    def residuals(x):
        return x[4] + force_at(np.exp(x[:3]), t - x[3]) - f

    lo = np.concatenate([x0[:3] - 4 * np.log(10), [t[0] - 0.01, base - peak]])
    hi = np.concatenate([x0[:3] + 4 * np.log(10), [t[-1], base + peak]])
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        sol = least_squares(residuals, x0, bounds=(lo, hi), x_scale="jac")
        times.append(time.perf_counter() - t0)
    kp, c, kr = np.exp(sol.x[:3])
    rms = np.sqrt(np.mean(sol.fun ** 2))
    print(f"median_s {np.median(times):.6f} over {repeats} runs, {sol.nfev} evaluations")
    print(f"  scipy: k_p = {kp:.6e}, c = {c:.6e}, k_r = {kr:.6e}, t0 = {sol.x[3]:.6e} s, "
          f"rms {rms:.4f} N, status {sol.status}")


main()
