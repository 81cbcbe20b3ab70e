"""The Monte Carlo on a Dask cluster (``distributed``): the same samples, the same numbers.

>>> from distributed import Client, LocalCluster
>>> import bouncelab.dask
>>> with LocalCluster(n_workers=2) as cluster, Client(cluster) as client:
...     r = bouncelab.dask.monte_carlo(client, preset="golf",
...                                    vary={"k_p": 0.05, "c": 0.05, "k_r": 0.05},
...                                    samples=10**7, seed=1, chunk=10**6)

Each chunk of ``chunk`` samples is one task, which computes its samples by their global
indices (``bouncelab._native.monte_carlo_chunk``): sample ``i`` is drawn from ChaCha8 keyed by
the seed on stream ``i``, so a task's samples are those the single-process call draws at the
same indices, on any worker. The merge is exact: the tasks' values are gathered in index
order and summarized by the same code as ``bouncelab.monte_carlo``
(``bouncelab._native.monte_carlo_merge``), so every number of the result equals the
single-process call's, bit for bit. The client holds 24 bytes a sample while it merges
(240 MB for 10⁷ samples, 24 GB for 10⁹): docs/scale.md.

Arguments are checked on the client before any task is sent: bad input raises ``ValueError``
there with the command line's one-line message, as ``bouncelab.monte_carlo`` does.
"""

from __future__ import annotations

from typing import Any, Dict, Mapping, Optional, Union

import numpy as np

from . import _native
from ._boundary import guard

# the client's check through the boundary, as bouncelab.monte_carlo is called: a number out of
# range names its argument ("invalid samples: -1 …"), a panic is a RuntimeError
_check = guard(_native.monte_carlo_chunk)

__all__ = ["monte_carlo"]

Vary = Union[str, Mapping[str, float]]


def _chunk(options: Dict[str, Any], start: int, count: int):
    """One task: the samples start … start + count (numpy arrays cor, max_force, contact_time)."""
    return _native.monte_carlo_chunk(**options, start=start, count=count)


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
) -> Dict[str, Any]:
    """``bouncelab.monte_carlo`` with its samples computed on the workers of ``client`` (a
    ``distributed.Client``), ``chunk`` samples a task; the same dict, the same numbers.

    With ``client=None`` the tasks go to Dask's current scheduler as a ``dask.delayed`` graph
    (``dask.compute``): Dask's local schedulers, or Ray's once ``ray.util.dask.
    enable_dask_on_ray()`` made it the default."""
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
    if not isinstance(chunk, int) or chunk < 1:
        raise ValueError(f"invalid chunk: {chunk!r} (must be a whole number ≥ 1)")
    # every argument, and a chunk's size against the work limit, checked here on the client
    # before a task leaves
    _check(**options, start=0, count=min(chunk, samples), check_only=True)
    starts = list(range(0, samples, chunk))
    counts = [min(chunk, samples - s) for s in starts]
    if client is None:
        import dask

        tasks = [dask.delayed(_chunk, pure=True)(options, s, c) for s, c in zip(starts, counts)]
        parts = dask.compute(*tasks)
    else:
        # pure tasks: a key is a hash of the arguments, so equal requests share their results
        futures = client.map(_chunk, [options] * len(starts), starts, counts)
        parts = client.gather(futures)
    cor, max_force, contact_time = (
        np.concatenate([p[k] for p in parts]) for k in range(3)
    )
    return _native.monte_carlo_merge(
        **options, cor=cor, max_force=max_force, contact_time=contact_time
    )
