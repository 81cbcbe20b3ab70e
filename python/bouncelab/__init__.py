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
"""

from ._native import (
    Collision,
    Impact,
    NoAnswerError,
    collide,
    drop,
    fit,
    fit_cor_table,
    fit_drops,
    fit_trace,
    presets,
    run,
    run_normalized,
    run_params,
    sweep_velocity,
    sweep_zeta,
)

__all__ = [
    "Collision",
    "Impact",
    "NoAnswerError",
    "collide",
    "drop",
    "fit",
    "fit_cor_table",
    "fit_drops",
    "fit_trace",
    "presets",
    "run",
    "run_normalized",
    "run_params",
    "sweep_velocity",
    "sweep_zeta",
]
