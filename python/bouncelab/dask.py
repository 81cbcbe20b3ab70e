"""The Monte Carlo on a Dask cluster (``distributed``): the same samples, the same numbers.

>>> from distributed import Client, LocalCluster
>>> import bouncelab.dask
>>> with LocalCluster(n_workers=2) as cluster, Client(cluster) as client:
...     r = bouncelab.dask.monte_carlo(client, preset="golf",
...                                    vary={"k_p": 0.05, "c": 0.05, "k_r": 0.05},
...                                    samples=10**8, seed=1, chunk=10**7)

Each chunk of ``chunk`` samples is one task, which computes its samples by their global
indices (``bouncelab._native.monte_carlo_chunk``): sample ``i`` is drawn from ChaCha8 keyed by
the seed on stream ``i``, so a task's samples are those the single-process call draws at the
same indices, on any worker.

**The merge** (docs/scale.md, "On a Dask cluster"). Up to ``EXACT_BELOW`` samples the tasks'
values are gathered in index order and summarized by the single-process code
(``_native.monte_carlo_merge``): every number equals ``bouncelab.monte_carlo``'s, bit for
bit. Beyond it the values never leave the workers; the client merges per-task summaries as
they arrive, in memory that does not grow with the samples:

- count, mean and variance by Chan, Golub & LeVeque's pairwise update of (n, mean, M2)
  (each task's own by NumPy: pairwise sums, two passes), the extremes by min/max: mean and
  sd within some 1e-15 (relative) of the single call's compensated sums;
- the quantiles and their intervals from the *exact* order statistics, found by histograms
  refined on the workers: one pass counts each quantity's values in ``BINS`` equal bins
  between its extremes (the tasks' counts summed at the client), the bins holding a rank
  the summary reads (``_native.monte_carlo_order_ranks``) are counted again finer while one
  holds more than ``CAP`` values, then the values of those bins alone are gathered and
  sorted. The order statistics are the single call's values, so every quantile, interval
  end, extreme and count is the same bits.

A pass recomputes its tasks' samples (pure functions of the seed and the indices): a run
costs its samples two or three times (one histogram pass for 10⁸–10¹⁰ samples of a smooth
distribution), in exchange for nothing held but one task's values on a worker. Runs beyond
``MAX_SAMPLES`` are refused before any task is sent.

Arguments are checked on the client before any task is sent: bad input raises ``ValueError``
there with the command line's one-line message, as ``bouncelab.monte_carlo`` does.
"""

from __future__ import annotations

import math
import numbers
from typing import Any, Dict, Iterator, List, Mapping, Optional, Tuple, Union

import numpy as np

from . import _native
from ._boundary import guard

# the client's check through the boundary, as bouncelab.monte_carlo is called: a number out of
# range names its argument ("invalid samples: -1 …"), a panic is a RuntimeError
_check = guard(_native.monte_carlo_chunk)

__all__ = ["monte_carlo", "EXACT_BELOW", "MAX_SAMPLES", "BINS", "CAP"]

Vary = Union[str, Mapping[str, float]]

#: Runs of at most this many samples are gathered and merged as one: the single call's bits
#: (24 bytes a sample at the client: 24 MB).
EXACT_BELOW = 1_000_000
#: The most samples a run may have: 10¹⁰ (1 000 tasks of the largest chunk a pass; some 2 250
#: core-seconds a pass for the linear law, BENCHMARKS.md); beyond, ``ValueError``.
MAX_SAMPLES = 10**10
#: Bins a histogram pass counts in each window (a quantity's range, then a bin to refine).
BINS = 4096
#: The most values a window may hold to be gathered; a fuller one is counted again finer.
CAP = 100_000
#: Tasks sent at a time: the client holds at most this many tasks' summaries.
IN_FLIGHT = 16

QUANTITIES = ("cor", "max_force", "contact_time")


def _chunk(options: Dict[str, Any], start: int, count: int):
    """One task: the samples start … start + count (numpy arrays cor, max_force, contact_time)."""
    return _native.monte_carlo_chunk(**options, start=start, count=count)


def _moments(options: Dict[str, Any], start: int, count: int, _extra=None):
    """One task's summary: (n, mean, M2, min, max) of each quantity's finite values, and its
    samples without rebound (NaN contact time)."""
    cols = _chunk(options, start, count)
    out: Dict[str, Any] = {"no_rebound": int(np.isnan(cols[2]).sum())}
    for name, x in zip(QUANTITIES, cols):
        f = x[np.isfinite(x)]
        if f.size == 0:
            out[name] = (0, 0.0, 0.0, math.inf, -math.inf)
            continue
        mean = float(np.mean(f))
        d = f - mean
        out[name] = (int(f.size), mean, float(np.dot(d, d)), float(f.min()), float(f.max()))
    return out


def _chan(a: Tuple, b: Tuple) -> Tuple:
    """Two summaries (n, mean, M2, min, max) as one (Chan, Golub & LeVeque 1979)."""
    na, ma, m2a, lo_a, hi_a = a
    nb, mb, m2b, lo_b, hi_b = b
    if na == 0:
        return b
    if nb == 0:
        return a
    n = na + nb
    d = mb - ma
    return (n, ma + d * (nb / n), m2a + m2b + d * d * (na * nb / n), min(lo_a, lo_b), max(hi_a, hi_b))


def _in_window(x: np.ndarray, lo: float, hi: float) -> np.ndarray:
    return x[(x >= lo) & (x < hi)]


def _histograms(options: Dict[str, Any], start: int, count: int, windows):
    """One task's counts in each window's bins: ``windows[q]`` a list of edge arrays, bin k
    being [edges[k], edges[k + 1])."""
    cols = _chunk(options, start, count)
    out = {}
    for name, x in zip(QUANTITIES, cols):
        counts = []
        for edges in windows.get(name, []):
            sel = _in_window(x, edges[0], edges[-1])
            k = np.searchsorted(edges, sel, side="right") - 1
            counts.append(np.bincount(k, minlength=len(edges) - 1))
        out[name] = counts
    return out


def _gather(options: Dict[str, Any], start: int, count: int, windows):
    """One task's values in each window [lo, hi): ``windows[q]`` a list of (lo, hi)."""
    cols = _chunk(options, start, count)
    return {
        name: [_in_window(x, lo, hi) for lo, hi in windows.get(name, [])]
        for name, x in zip(QUANTITIES, cols)
    }


class _Window:
    """Values of one quantity in [lo, hi): ``count`` of them, ``base`` below lo, holding the
    ranks ``ranks``."""

    def __init__(self, lo: float, hi: float, base: int, count: int, ranks: List[int]):
        self.lo, self.hi, self.base, self.count, self.ranks = lo, hi, base, count, ranks

    def edges(self, bins: int) -> np.ndarray:
        return np.unique(np.linspace(self.lo, self.hi, bins + 1))

    def split(self, edges: np.ndarray, counts: np.ndarray, found: Dict[int, float]):
        """The bins holding this window's ranks, as windows; a bin one float wide holds only
        its lower edge, whose ranks are ``found`` at once."""
        cum = np.concatenate([[0], np.cumsum(counts)])
        by_bin: Dict[int, List[int]] = {}
        for r in self.ranks:
            k = int(np.searchsorted(cum, r - self.base, side="right")) - 1
            by_bin.setdefault(k, []).append(r)
        out = []
        for k, ranks in by_bin.items():
            lo, hi = float(edges[k]), float(edges[k + 1])
            if hi <= np.nextafter(lo, math.inf):
                found.update((r, lo) for r in ranks)
                continue
            out.append(_Window(lo, hi, self.base + int(cum[k]), int(counts[k]), ranks))
        return out


def _tasks(client, fn, options, spans, extra) -> Iterator[Any]:
    """``fn(options, start, count, extra)`` of every span, their results as they arrive, at
    most ``IN_FLIGHT`` tasks sent at a time; pending tasks are cancelled if the caller stops
    (Ctrl-C, an error)."""
    spans = list(spans)
    if client is None:
        import dask

        for i in range(0, len(spans), IN_FLIGHT):
            batch = spans[i : i + IN_FLIGHT]
            tasks = [dask.delayed(fn, pure=True)(options, s, c, extra) for s, c in batch]
            yield from dask.compute(*tasks)
        return
    from distributed import as_completed

    pending = iter(spans)
    live = set()

    def send(k):
        futures = [client.submit(fn, options, s, c, extra, pure=False) for s, c in _take(pending, k)]
        live.update(futures)
        return futures

    done = as_completed(send(IN_FLIGHT))
    try:
        for future in done:
            result = future.result()
            live.discard(future)
            future.release()
            for f in send(1):
                done.add(f)
            yield result
    finally:
        if live:
            client.cancel(list(live))


def _take(it, k):
    out = []
    for _ in range(k):
        try:
            out.append(next(it))
        except StopIteration:
            break
    return out


def _order_statistics(client, options, spans, moments, bins: int, cap: int):
    """Each quantity's order statistics at ``monte_carlo_order_ranks(n)``, exact: histogram
    passes until every window holding a rank has at most ``cap`` values, then those gathered."""
    found: Dict[str, Dict[int, float]] = {q: {} for q in QUANTITIES}
    windows: Dict[str, List[_Window]] = {}
    ranks_of: Dict[str, List[int]] = {}
    for q in QUANTITIES:
        n, _, _, lo, hi = moments[q]
        ranks_of[q] = list(_native.monte_carlo_order_ranks(n))
        windows[q] = [_Window(lo, float(np.nextafter(hi, math.inf)), 0, n, ranks_of[q])] if n else []
    while True:
        full = {q: [w for w in ws if w.count > cap] for q, ws in windows.items()}
        if not any(full.values()):
            break
        edges = {q: [w.edges(bins) for w in ws] for q, ws in full.items()}
        counts = {q: [np.zeros(len(e) - 1, dtype=np.int64) for e in es] for q, es in edges.items()}
        for part in _tasks(client, _histograms, options, spans, edges):
            for q in QUANTITIES:
                for total, c in zip(counts[q], part[q]):
                    total += c
        for q in QUANTITIES:
            kept = [w for w in windows[q] if w.count <= cap]
            for w, e, c in zip(full[q], edges[q], counts[q]):
                kept.extend(w.split(e, c, found[q]))
            windows[q] = kept
    bounds = {q: [(w.lo, w.hi) for w in ws] for q, ws in windows.items()}
    values: Dict[str, List[List[np.ndarray]]] = {q: [[] for _ in ws] for q, ws in windows.items()}
    if any(bounds.values()):
        for part in _tasks(client, _gather, options, spans, bounds):
            for q in QUANTITIES:
                for acc, v in zip(values[q], part[q]):
                    acc.append(v)
    for q in QUANTITIES:
        for w, parts in zip(windows[q], values[q]):
            v = np.sort(np.concatenate(parts)) if parts else np.empty(0)
            if v.size != w.count:
                raise RuntimeError(
                    f"bouncelab.dask: {q} window [{w.lo}, {w.hi}) gathered {v.size} values, "
                    f"counted {w.count} (a worker ran another bouncelab?)"
                )
            found[q].update((r, float(v[r - w.base])) for r in w.ranks)
    return {q: [found[q][r] for r in ranks_of[q]] for q in QUANTITIES}


def _streamed(client, options, spans, bins: int, cap: int) -> Dict[str, Any]:
    """The merge of docs/scale.md beyond ``EXACT_BELOW``: per-task moments merged by Chan's
    update, the order statistics by refined histograms."""
    empty = (0, 0.0, 0.0, math.inf, -math.inf)
    moments = {q: empty for q in QUANTITIES}
    no_rebound = 0
    for part in _tasks(client, _moments, options, spans, None):
        no_rebound += part["no_rebound"]
        for q in QUANTITIES:
            moments[q] = _chan(moments[q], part[q])
    order = _order_statistics(client, options, spans, moments, bins, cap)
    stats = {}
    for q in QUANTITIES:
        n, mean, m2, lo, hi = moments[q]
        sd = math.sqrt(m2 / (n - 1)) if n > 1 else math.nan
        stats[q] = dict(n=n, mean=mean, sd=sd, min=lo, max=hi, order=order[q])
    return _native.monte_carlo_report(**options, **stats, no_rebound=no_rebound)


def monte_carlo(
    client,
    *,
    preset: str = "superball",
    vary: Vary,
    samples: int,
    seed: int = 0,
    dist: str = "normal",
    chunk: int = 1_000_000,
    v0: Optional[float] = None,
    law: Optional[str] = None,
    params: Optional[str] = None,
    correlate: Optional[Any] = None,
    mass: Optional[float] = None,
    radius: Optional[float] = None,
    k_p: Optional[float] = None,
    damping: Optional[float] = None,
    k_r: Optional[float] = None,
    z_p: Optional[float] = None,
    exact_below: int = EXACT_BELOW,
    bins: int = BINS,
    cap: int = CAP,
) -> Dict[str, Any]:
    """``bouncelab.monte_carlo`` with its samples computed on the workers of ``client`` (a
    ``distributed.Client``), ``chunk`` samples a task; the same dict: bit for bit up to
    ``exact_below`` samples, beyond it the same quantiles, intervals, extremes and counts with
    the mean and sd within some 1e-15 (the streaming merge, in the module's docstring).

    With ``client=None`` the tasks go to Dask's current scheduler as ``dask.delayed`` graphs
    (``dask.compute``, ``IN_FLIGHT`` tasks at a time): Dask's local schedulers, or Ray's once
    ``ray.util.dask.enable_dask_on_ray()`` made it the default."""
    if isinstance(vary, Mapping):
        vary = dict(vary)
    options = dict(
        preset=preset,
        vary=vary,
        samples=samples,
        seed=seed,
        dist=dist,
        v0=v0,
        law=law,
        params=params,
        correlate=dict(correlate) if isinstance(correlate, Mapping) else correlate,
        mass=mass,
        radius=radius,
        k_p=k_p,
        damping=damping,
        k_r=k_r,
        z_p=z_p,
    )
    for name, value, least in (
        ("chunk", chunk, 1), ("bins", bins, 2), ("cap", cap, 2), ("exact_below", exact_below, 0)
    ):
        if not isinstance(value, numbers.Integral) or isinstance(value, bool):
            raise TypeError(f"invalid {name}: {value!r} (must be a whole number ≥ {least})")
        if value < least:
            raise ValueError(f"invalid {name}: {value!r} (must be a whole number ≥ {least})")
    # every argument, and a chunk's size against the work limit, checked here on the client
    # before a task leaves (a `samples` that is no whole number is the check's to name: it
    # reads samples before count)
    count = min(chunk, samples) if isinstance(samples, numbers.Integral) else chunk
    _check(**options, start=0, count=count, check_only=True)
    if samples > MAX_SAMPLES:
        raise ValueError(
            f"invalid samples: {samples} is beyond the most a Dask run takes, {MAX_SAMPLES:.0e} "
            "(docs/scale.md: split the run by seed and merge the reports yourself)"
        )
    spans = [(s, min(chunk, samples - s)) for s in range(0, samples, chunk)]
    if samples > exact_below:
        return _streamed(client, options, spans, bins, cap)
    if client is None:
        import dask

        tasks = [dask.delayed(_chunk, pure=True)(options, s, c) for s, c in spans]
        parts = dask.compute(*tasks)
    else:
        # pure tasks: a key is a hash of the arguments, so equal requests share their results
        futures = client.map(_chunk, [options] * len(spans), [s for s, _ in spans], [c for _, c in spans])
        parts = client.gather(futures)
    cor, max_force, contact_time = (np.concatenate([p[k] for p in parts]) for k in range(3))
    return _native.monte_carlo_merge(**options, cor=cor, max_force=max_force, contact_time=contact_time)
