"""bouncelab: the Christoforou–Yigit model of a deformable ball hitting a rigid wall.

Coefficient of restitution (COR), peak force, contact time and flattening of one impact, and
sweeps and fits over many, computed by the bouncelab Rust library. Keyword arguments in, SI
units, the names of the command line's JSON and CSV output, numpy arrays out.

>>> import bouncelab
>>> r = bouncelab.run(preset="golf", v0=3.0)
>>> round(r.cor, 4)
0.8404

Every error raises ``ValueError`` with the one-line message ``bouncelab`` prints on the
command line (without its ``bouncelab: error:`` prefix); an impact the solver could not bring
to an end raises ``NoAnswerError``, a ``ValueError`` too.

``bouncelab.monte_carlo`` spreads a ball's parameters over their tolerances (as ``bouncelab
mc``); ``bouncelab.dask.monte_carlo`` runs the same on a Dask cluster (docs/scale.md; the
``dask`` submodule needs ``distributed`` and is imported on first use).
"""

from ._native import (
    Collision,
    Impact,
    NoAnswerError,
    ObliqueImpact,
    batch,
    collide,
    court,
    drop,
    fit,
    fit_cor_table,
    fit_drops,
    fit_oblique,
    fit_trace,
    impacts,
    monte_carlo,
    oblique,
    presets,
    run,
    run_normalized,
    run_params,
    shot,
    shots,
    standards,
    static,
    sweep_velocity,
    sweep_zeta,
)

from ._boundary import guard as _guard

# every function of the native module through the boundary: panics raise RuntimeError, and
# numbers too large for it name their argument (bouncelab/_boundary.py)
batch = _guard(batch)
collide = _guard(collide)
court = _guard(court)
drop = _guard(drop)
fit = _guard(fit)
fit_cor_table = _guard(fit_cor_table)
fit_drops = _guard(fit_drops)
fit_oblique = _guard(fit_oblique)
fit_trace = _guard(fit_trace)
impacts = _guard(impacts)
monte_carlo = _guard(monte_carlo)
oblique = _guard(oblique)
presets = _guard(presets)
run = _guard(run)
run_normalized = _guard(run_normalized)
run_params = _guard(run_params)
shot = _guard(shot)
shots = _guard(shots)
standards = _guard(standards)
static = _guard(static)
sweep_velocity = _guard(sweep_velocity)
sweep_zeta = _guard(sweep_zeta)

__all__ = [
    "Collision",
    "Impact",
    "NoAnswerError",
    "ObliqueImpact",
    "batch",
    "collide",
    "court",
    "drop",
    "fit",
    "fit_cor_table",
    "fit_drops",
    "fit_oblique",
    "fit_trace",
    "impacts",
    "monte_carlo",
    "oblique",
    "presets",
    "run",
    "run_normalized",
    "run_params",
    "shot",
    "shots",
    "standards",
    "static",
    "sweep_velocity",
    "sweep_zeta",
]


def __getattr__(name):
    # ``bouncelab.dask`` without an explicit import, and without importing Dask before it is
    # asked for (it is an optional dependency)
    if name == "dask":
        import importlib

        return importlib.import_module(".dask", __name__)
    raise AttributeError(f"module 'bouncelab' has no attribute {name!r}")
