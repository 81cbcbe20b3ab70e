"""`run`, `run_params` and `run_normalized` on the linear law take the closed forms where they
answer and leave the energy audit to its first read (docs/python.md): every value is the
exact solver's — the numbers to 1e-12, the energy budget and the warnings exactly, as
`bouncelab run` computes them — whether the audit is read first or last."""

import math
import pickle

import numpy as np
import pytest

import bouncelab
from test_bouncelab import cli_json, no_user_presets  # noqa: F401

HISTORY = {"t", "force", "indentation", "displacement"}


def solver(run, **kw):
    """The same call through the solver with its audit (a history asked for takes it)."""
    return run(**kw, history=True, samples=2)


def same_answer(fast, full):
    a, b = fast.to_dict(), full.to_dict()
    assert set(a) - HISTORY == set(b) - HISTORY
    for k in set(b) - HISTORY:
        x, y = a[k], b[k]
        if k in ("energy", "warnings", "measured"):
            assert x == y, (k, x, y)  # the audit is the solver's own, bit for bit
        elif isinstance(y, float):
            assert abs(x - y) <= 1e-12 * abs(y) or x == y, (k, x, y)
        else:
            assert x == y, (k, x, y)


def presets():
    return [p["name"] for p in bouncelab.presets()]


@pytest.mark.parametrize("scale", [1.0, 0.3, 3.0])
def test_every_preset_is_the_solvers_answer(scale):
    for name in presets():
        v0 = bouncelab.run(preset=name).v0 * scale
        for law in (None, "linear"):
            fast = bouncelab.run(preset=name, law=law, v0=v0)
            same_answer(fast, solver(bouncelab.run, preset=name, law=law, v0=v0))


def test_random_balls_are_the_solvers_answer():
    rng = np.random.default_rng(30)
    for _ in range(300):
        spread = lambda v: float(v * 10 ** rng.uniform(-1, 1))  # noqa: E731
        kw = dict(m=spread(0.0495), k_p=spread(5.45e4), c=spread(10.0), k_r=spread(7.08e4),
                  v0=spread(3.12))
        if rng.uniform() < 0.5:
            kw["z_p"] = spread(2e-3)
        same_answer(bouncelab.run_params(**kw), solver(bouncelab.run_params, **kw))
    for lam, zeta, zp in [(1.0, 0.1, None), (0.4, 0.61, 0.5), (0.0, 0.3, None), (3.0, 2.0, 0.2)]:
        kw = dict(lambda_=lam, zeta=zeta, zp_bar=zp)
        same_answer(bouncelab.run_normalized(**kw), solver(bouncelab.run_normalized, **kw))


def test_the_audit_read_first_last_or_never_is_the_same():
    a = bouncelab.run(preset="golf")
    budget = a.energy  # read first
    b = bouncelab.run(preset="golf")
    assert b.cor == a.cor and b.max_force == a.max_force
    assert b.energy == budget and b.warnings == a.warnings == []
    c = bouncelab.run(preset="golf")
    # a copy carries the audit, computed for it on the way
    back = pickle.loads(pickle.dumps(c))
    assert back == c and back.energy == budget
    assert budget["relative_residual"] < 1e-12


def test_warnings_are_there_when_read():
    # the superball at 45 m/s indents past its radius: a warning run's JSON carries
    expected = cli_json("run", "--v0", "45", "--format", "json")
    r = bouncelab.run(v0=45.0)
    assert r.warnings == expected["warnings"]
    assert r.warnings[0].startswith("peak indentation 31.05 mm exceeds the ball's radius")
    assert r.to_dict()["warnings"] == expected["warnings"]
    assert math.isclose(r.cor, expected["cor"], rel_tol=1e-12)


def test_an_audit_read_from_several_threads_is_one_answer():
    import concurrent.futures

    rs = [bouncelab.run_params(m=0.05, k_p=1e5, c=5.0 + i, k_r=8e4, v0=2.0) for i in range(40)]
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        twice = list(pool.map(lambda r: (r.energy, r.warnings, r.energy), rs + rs))
    for r, (e1, w, e2) in zip(rs + rs, twice):
        assert e1 == e2 == r.energy and w == r.warnings == []
