"""Speed of Python's array entry point and of per-call overhead (issue 30 item 5; medians in
BENCHMARKS.md). Run after `pip install ./python`:

    RAYON_NUM_THREADS=1 python benches/impacts_python.py    # per core
    python benches/impacts_python.py                        # all cores
    python benches/impacts_python.py calls                  # the calls alone (CALLS)
    python benches/impacts_python.py laws                   # Hertz, elastic-plastic (LAWS)
    python benches/impacts_python.py flat                   # tennis balls that flatten (FLAT)
    python benches/impacts_python.py past                   # elastic-plastic past yield

Prints the median of 5 runs (wall clock, then CPU time) of `bouncelab.impacts` over 10⁶
linear-law balls (the superball with K_p, c, K_r spread 5 %, no flattening: the closed form),
per impact; and the median cost of one call of each of CALLS (`run(preset=…)` of golf and
tennis, `run_params`, `run_normalized`, a `run` whose energy audit is read, and the
native `run` without bouncelab/_boundary.py's guard, docs/python.md); then, if SciPy is installed, the same impacts with `scipy.integrate.solve_ivp` (RK45, rtol 1e-10, atol 1e-13, terminal event
at F = 0 falling, as benches/scipy_sweep.py) on the first 300 balls, the ratio of the two per
impact and their largest COR difference. Speed is measured here, never asserted in tests.
"""

import os
import statistics
import sys
import time

import numpy as np

import bouncelab
import bouncelab._native as _native

SCIPY_BALLS = 300


def scipy_cor(lam, zeta):
    """The normalized linear impact by solve_ivp (docs/model.md §5): benches/scipy_sweep.py's,
    imported only when the SciPy side runs (the rest of this script needs no SciPy)."""
    from scipy_sweep import one

    return one(lam, zeta)


def scipy_side_by_side(m, k_p, c, k_r, v0, per_impact_ns):
    try:
        import scipy  # noqa: F401
    except ImportError:
        print("SciPy is not installed: no side by side (pip install scipy)")
        return
    k_p, c, k_r = k_p[:SCIPY_BALLS], c[:SCIPY_BALLS], k_r[:SCIPY_BALLS]
    lam, zeta = k_r / k_p, np.sqrt(m * k_p) / (2.0 * c)
    t = median_of(lambda: [scipy_cor(a, b) for a, b in zip(lam, zeta)], runs=3)
    ours = bouncelab.impacts(m=m, k_p=k_p, c=c, k_r=k_r, v0=v0)["cor"]
    theirs = np.array([scipy_cor(a, b) for a, b in zip(lam, zeta)])
    per = t / SCIPY_BALLS * 1e9
    print(
        f"scipy solve_ivp, {SCIPY_BALLS} of the balls: {per / 1e3:.0f} µs per impact; "
        f"bouncelab.impacts {per / per_impact_ns:.0f} x faster; "
        f"max |COR difference| {np.max(np.abs(ours - theirs)):.1e}"
    )


def median_of(f, runs=5, clock=time.perf_counter):
    ts = []
    for _ in range(runs):
        t = clock()
        f()
        ts.append(clock() - t)
    return statistics.median(ts)


def median_of_cpu(f, runs=5):
    return median_of(f, runs, clock=time.process_time)


CALLS = [
    ("run(preset='golf')", lambda: bouncelab.run(preset="golf")),
    ("run(preset='tennis')", lambda: bouncelab.run(preset="tennis")),
    (
        "run_params(m=0.0495, k_p=5.45e4, c=10, k_r=7.08e4, v0=3.12)",
        lambda: bouncelab.run_params(m=0.0495, k_p=5.45e4, c=10.0, k_r=7.08e4, v0=3.12),
    ),
    ("run_normalized(1.0, 0.1)", lambda: bouncelab.run_normalized(1.0, 0.1)),
    ("run(preset='golf').energy (the audit read)", lambda: bouncelab.run(preset="golf").energy),
    # the native function alone, without bouncelab/_boundary.py's guard: the guard's share
    ("_native.run(preset='golf') (no _boundary guard)", lambda: _native.run(preset="golf")),
]


def time_calls(calls=20000):
    """Median wall and CPU time of one call of each of CALLS (medians of 5 runs)."""
    for name, f in CALLS:
        loop = lambda: [f() for _ in range(calls)]  # noqa: E731
        wall, cpu = median_of(loop), median_of_cpu(loop)
        print(f"{name}: {wall / calls * 1e6:.2f} µs per call ({cpu / calls * 1e6:.2f} µs CPU)")


GOLF = dict(m=0.0456, k_p=5.6e5, c=1200.0, k_r=5.6e5, z_p=3e-3)

# 10⁶ golf-like balls under Hertz (v0 1 … 30 m/s: all in the Hertz table) and under the
# elastic-plastic law below yield (v0 0.5 … 3 m/s: the table's answers too)
LAWS = [
    ("hertz, v0 1-30 m/s", "hertz", (1.0, 30.0)),
    ("elastic-plastic below yield, v0 0.5-3 m/s", "elastic-plastic", (0.5, 3.0)),
]


def time_laws(n=10**6):
    """Median wall and CPU time of `impacts` over `n` elements of each of LAWS, per element."""
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    for name, law, (lo, hi) in LAWS:
        v0 = np.linspace(lo, hi, n)
        f = lambda: bouncelab.impacts(v0=v0, law=law, **GOLF)  # noqa: E731
        try:
            f()
        except ValueError as e:
            print(f"impacts, 1e6 {name}: refused ({str(e)[:90]}…)")
            continue
        wall, cpu = median_of(f), median_of_cpu(f)
        print(
            f"impacts, 1e6 {name}, {threads} threads: {wall * 1e3:.1f} ms, "
            f"{wall / n * 1e9:.0f} ns per element ({cpu / n * 1e9:.0f} ns CPU)"
        )


# 10⁶ tennis-like balls (the tennis preset, K_p, c, K_r spread 5 %) at 8 … 40 m/s: every one
# flattens (z_m > z_p), the linear law's flattening rows (issue 30 item 2)
FLAT = dict(m=0.0577, z_p=0.0060342)


def time_flat(n=10**6):
    """Median wall and CPU time of `impacts` over `n` tennis balls that flatten, per element."""
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    rng = np.random.default_rng(2)
    k_p = 24713.0 * (1 + 0.05 * rng.standard_normal(n))
    c = 210.1329 * (1 + 0.05 * rng.standard_normal(n))
    k_r = 24713.0 * (1 + 0.05 * rng.standard_normal(n))
    v0 = np.linspace(8.0, 40.0, n)
    f = lambda: bouncelab.impacts(k_p=k_p, c=c, k_r=k_r, v0=v0, **FLAT)  # noqa: E731
    r = f()
    flat = int(np.count_nonzero(r["permanent_indentation"] > 0))
    wall, cpu = median_of(f), median_of_cpu(f)
    print(
        f"impacts, 1e6 tennis flattening ({flat} flatten), {threads} threads: {wall * 1e3:.1f} "
        f"ms, {wall / n * 1e9:.0f} ns per element ({cpu / n * 1e9:.0f} ns CPU)"
    )


def time_past(n=20000, calls=15):
    """Best of `calls` calls' wall and CPU time of `impacts` over `n` superball elements past
    yield (benches/solver.rs `PAST_YIELD`'s spreads of K_p, c, K_r at 9.36 m/s), per element."""
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    i = np.arange(n)
    spread = lambda m: 1.0 + 0.05 * (2.0 * ((i * m) % 97) / 96.0 - 1.0)  # noqa: E731
    args = dict(
        m=0.0374, k_p=5.45e4 * spread(31), c=140.0 * spread(59), k_r=7.08e4 * spread(83),
        v0=9.36, z_p=4e-3, law="elastic-plastic",
    )
    past = int(np.count_nonzero(bouncelab.impacts(**args)["permanent_indentation"] > 0))
    wall = cpu = float("inf")
    for _ in range(calls):
        c0, w0 = time.process_time(), time.perf_counter()
        bouncelab.impacts(**args)
        cpu = min(cpu, time.process_time() - c0)
        wall = min(wall, time.perf_counter() - w0)
    print(
        f"impacts, {n} superball elements ({past} past yield), {threads} threads: "
        f"{wall / n * 1e6:.3f} µs wall per element ({cpu / n * 1e6:.3f} µs CPU)"
    )


def main():
    if sys.argv[1:] == ["past"]:  # elastic-plastic elements past yield only
        time_past()
        return
    if sys.argv[1:] == ["flat"]:  # tennis balls that flatten only
        time_flat()
        return
    if sys.argv[1:] == ["calls"]:  # the per-call overheads only
        time_calls()
        return
    if sys.argv[1:] == ["laws"]:  # Hertz and elastic-plastic arrays only
        time_laws()
        return
    n = 10**6
    rng = np.random.default_rng(1)
    k_p = 5.45e4 * (1 + 0.05 * rng.standard_normal(n))
    c = 10.0 * (1 + 0.05 * rng.standard_normal(n))
    k_r = 7.08e4 * (1 + 0.05 * rng.standard_normal(n))
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    t = wall = median_of(lambda: bouncelab.impacts(m=0.0495, k_p=k_p, c=c, k_r=k_r, v0=3.12))
    print(f"impacts, 1e6 linear, {threads} threads: {t * 1e3:.1f} ms, {t / n * 1e9:.0f} ns per impact")
    cpu = median_of_cpu(lambda: bouncelab.impacts(m=0.0495, k_p=k_p, c=c, k_r=k_r, v0=3.12))
    print(f"  the same in CPU time (all threads): {cpu / n * 1e9:.0f} ns per impact")
    time_calls()
    # wall clock on both sides: the ratio of two times taken in the same run
    scipy_side_by_side(0.0495, k_p, c, k_r, 3.12, wall / n * 1e9)


if __name__ == "__main__":
    main()
