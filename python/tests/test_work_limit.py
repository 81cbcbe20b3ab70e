"""The sweeps keep the command line's work limit (src/analysis/work.rs): refused before any
work, with the command line's message."""

import time

import numpy as np
import pytest

import bouncelab
from test_bouncelab import cli_error, no_user_presets  # noqa: F401

LAMBDAS = [0.1 * k for k in range(1, 12)]  # 11 values


def test_a_zeta_sweep_beyond_the_limit_is_the_clis_refusal():
    zetas = np.logspace(-2, 2, 100_000)
    start = time.perf_counter()
    with pytest.raises(ValueError) as e:
        bouncelab.sweep_zeta(LAMBDAS, zetas)
    # refused before the work: 1.1e6 impacts would take seconds
    assert time.perf_counter() - start < 0.5
    args = ["sweep", "zeta", "--points", "100000"]
    for lam in LAMBDAS:
        args += ["--lambda", repr(lam)]
    assert str(e.value) == cli_error(*args)
    assert str(e.value).startswith("too much work: 11 λ values × 100000 points is 1100000 ")


def test_the_limit_weighs_the_law():
    with pytest.raises(ValueError, match=r"^too much work: 25001 speeds is 25001 hertz-law"):
        bouncelab.sweep_velocity("golf", np.linspace(1, 5, 25_001), law="hertz")
    # just under it on the linear law: the whole limit is there to use
    assert bouncelab.sweep_zeta([1.0], np.logspace(-2, 2, 1000))["cor"].shape == (1000,)
