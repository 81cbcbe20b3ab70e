"""A 10⁵-point ζ sweep from Python against the same sweep in Rust (BENCHMARKS.md).

    cargo build --release --example sweep_timing
    python python/examples/sweep_timing.py [target/release/examples/sweep_timing]

Both time `sweep_zeta([1.0], ζ log-spaced over 0.01 … 100, 10⁵ points)`: the Rust example
inside one process, Python around the call (numpy arrays in and out, GIL released). The two are
run in turns, several rounds, so that a busy machine slows both alike; medians are printed.
"""

import re
import statistics
import subprocess
import sys
import time

import numpy as np

import bouncelab

POINTS, ROUNDS, RUNS = 100_000, 5, 3


def python_ms():
    zetas = np.logspace(-2, 2, POINTS)
    times = []
    for _ in range(RUNS):
        t = time.perf_counter()
        d = bouncelab.sweep_zeta([1.0], zetas)
        times.append(time.perf_counter() - t)
        assert d["cor"].shape == (POINTS,)
    return statistics.median(times) * 1e3


def rust_ms(exe):
    out = subprocess.run([exe, str(POINTS), str(RUNS)], capture_output=True, text=True, check=True)
    return float(re.search(r"median ([0-9.]+) ms", out.stdout).group(1))


def main(exe):
    py, rs = [], []
    for _ in range(ROUNDS):
        rs.append(rust_ms(exe))
        py.append(python_ms())
    p, r = statistics.median(py), statistics.median(rs)
    print(f"rust   {r:8.1f} ms  (rounds: {', '.join(f'{x:.0f}' for x in rs)})")
    print(f"python {p:8.1f} ms  (rounds: {', '.join(f'{x:.0f}' for x in py)})")
    print(f"python / rust = {p / r:.3f}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "target/release/examples/sweep_timing")
