"""The 4 x 400-point COR-vs-zeta sweep with SciPy's solve_ivp, for the ratio in BENCHMARKS.md.

Normalized linear law below flattening (docs/model.md §5): x = (a, a', y), x(0) = (0, 1, 0),
    a'' = -(a - y),  y' = 2 zeta ((a - y) - lam y),  F = a - y,
RK45 at rtol 1e-10 (atol 1e-13), terminal event at F = 0 falling. Prints one JSON object:
median wall time of the sweep over REPEATS runs, and the COR values (for the accuracy check).
"""
import json
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

LAMBDAS = [0.0, 0.4, 1.0, 1.3]
ZETAS = np.logspace(-2, 2, 400)
# the command line's repeats; imported (benches/impacts_python.py takes `one`), 3
REPEATS = int(sys.argv[1]) if __name__ == "__main__" and len(sys.argv) > 1 else 3
T_MAX = 100.0  # no event by then: no rebound


def one(lam, zeta):
    """The COR of the normalized ball (lam, zeta) by solve_ivp, 0 without a rebound."""
    def rhs(t, x):
        f = x[0] - x[2]
        return [x[1], -f, 2.0 * zeta * (f - lam * x[2])]

    def contact_force(t, x):
        return x[0] - x[2]

    contact_force.terminal = True
    contact_force.direction = -1
    sol = solve_ivp(rhs, (0.0, T_MAX), [0.0, 1.0, 0.0], method="RK45", rtol=1e-10, atol=1e-13,
                    events=contact_force)
    if sol.t_events[0].size == 0:
        return 0.0
    return max(0.0, -sol.y_events[0][0][1])


def sweep():
    return [one(lam, z) for lam in LAMBDAS for z in ZETAS]


if __name__ == "__main__":
    times = []
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        cors = sweep()
        times.append(time.perf_counter() - t0)
    print(json.dumps({"median_s": float(np.median(times)), "runs": REPEATS, "cor": cors}))
