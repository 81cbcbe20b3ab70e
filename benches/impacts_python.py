"""Speed of Python's array entry point and of per-call overhead (issue 30 item 5; medians in
BENCHMARKS.md). Run after `pip install ./python`:

    RAYON_NUM_THREADS=1 python benches/impacts_python.py    # per core
    python benches/impacts_python.py                        # all cores

Prints the median of 5 runs of `bouncelab.impacts` over 10⁶ linear-law balls (the superball
with K_p, c, K_r spread 5 %, no flattening: the closed form), per impact; and the median cost
of one `run(preset="golf")` and one `run_params(…)` call. Speed is measured here, never
asserted in tests.
"""

import os
import statistics
import time

import numpy as np

import bouncelab


def median_of(f, runs=5):
    ts = []
    for _ in range(runs):
        t = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts)


def main():
    n = 10**6
    rng = np.random.default_rng(1)
    k_p = 5.45e4 * (1 + 0.05 * rng.standard_normal(n))
    c = 10.0 * (1 + 0.05 * rng.standard_normal(n))
    k_r = 7.08e4 * (1 + 0.05 * rng.standard_normal(n))
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    t = median_of(lambda: bouncelab.impacts(m=0.0495, k_p=k_p, c=c, k_r=k_r, v0=3.12))
    print(f"impacts, 1e6 linear, {threads} threads: {t * 1e3:.1f} ms, {t / n * 1e9:.0f} ns per impact")
    calls = 2000
    t = median_of(lambda: [bouncelab.run(preset="golf") for _ in range(calls)])
    print(f"run(preset='golf'): {t / calls * 1e6:.2f} µs per call")
    t = median_of(
        lambda: [
            bouncelab.run_params(m=0.0495, k_p=5.45e4, c=10.0, k_r=7.08e4, v0=3.12)
            for _ in range(calls)
        ]
    )
    print(f"run_params(...): {t / calls * 1e6:.2f} µs per call")


if __name__ == "__main__":
    main()
