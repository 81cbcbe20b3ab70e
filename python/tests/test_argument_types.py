"""An argument of the wrong type names itself, in every function (the newcomer trial of
2026-12-07): PyO3's own messages ("must be real number, not list", "'str' object is not an
instance of 'bool'") said what was wrong but not of which argument, and a negative count
raised OverflowError ("can't convert negative int to unsigned") where samples=0 raises
ValueError. The boundary (bouncelab/_boundary.py) raises each again naming the argument."""

import importlib
import inspect
import re
import sys

import numpy as np
import pytest

import bouncelab
from bouncelab._boundary import _parameters
from test_bouncelab import no_user_presets  # noqa: F401

pytestmark = pytest.mark.skipif(
    sys.version_info < (3, 11), reason="the argument's name comes in Python 3.11's notes"
)


class Odd:
    """A value no argument takes: not a number, a sequence, a name, a path or a dict."""

    def __repr__(self):
        return "Odd()"


PARAMS = dict(m=0.0577, k_p=1.2e5, c=1.0, k_r=2e5, v0=3.0)
# a trace of one impact pulse, 3 ms of a 60 N half sine
TIME = np.linspace(0.0, 6e-3, 600)
PULSE = (TIME - 1e-3) / 3e-3
FORCE = np.where((PULSE > 0) & (PULSE < 1), 60.0 * np.sin(np.pi * np.clip(PULSE, 0, 1)), 0.0)
# what each function needs besides the argument tried, to come to it (batch's file is
# written by the `needs` fixture)
NEEDS = {
    "batch": dict(preset="tennis"),
    "fit": dict(cor=0.8),
    "fit_cor_table": dict(v0=[1.0, 2.0], cor=[0.8, 0.79]),
    "fit_drops": dict(drop_heights=[1.0], rebound_heights=[0.5]),
    "fit_oblique": dict(v0=[20.0], angle_deg=[30.0], spin_in=[0.0], vx_out=[15.0], vy_out=[5.0]),
    "fit_trace": dict(time=TIME, force=FORCE),
    "impacts": PARAMS,
    "run_params": PARAMS,
    "monte_carlo": dict(vary={"k_p": 0.05}, samples=10),
    "dask.monte_carlo": dict(client=None, vary={"k_p": 0.05}, samples=10),
    "oblique": dict(angle=30.0, friction=0.5),
    "shot": dict(height=1.0, speed=20.0, friction=0.5),
    "shots": dict(height=[1.0], speed=[20.0], friction=0.5),
    "static": dict(load_kg=1.0),
    "sweep_zeta": dict(lambdas=[1.0], zetas=[0.1]),
}
# the arguments whose own check refuses what they cannot read with a ValueError naming them
# ("invalid surface: a surface name or a dict of its numbers")
READ_BY_VALUE = {"surface", "vary", "correlate", "net"}


def function(name):
    if name.startswith("dask."):
        return getattr(importlib.import_module("bouncelab.dask"), name[len("dask."):])
    return getattr(bouncelab, name)


def arguments():
    """(function, argument) for every argument of every public function."""
    for name in bouncelab.__all__:
        f = getattr(bouncelab, name)
        native = getattr(f, "__wrapped__", None)
        if native is not None:
            # (the text signature's bare `*` is no parameter)
            yield from ((name, p) for p in _parameters(native) if p)
    pytest.importorskip("distributed")
    from bouncelab.dask import monte_carlo

    for p in inspect.signature(monte_carlo).parameters:
        if p != "client":
            yield "dask.monte_carlo", p


@pytest.fixture
def needs(tmp_path):
    """NEEDS, with batch's file of one ball."""
    lot = tmp_path / "lot.csv"
    lot.write_text("id,drop_height_m,rebound_height_m\nB1,2.54,1.40\n")
    return {**NEEDS, "batch": {**NEEDS["batch"], "file": lot}}


def refused(name, needs=NEEDS, **kwargs):
    """The error `name(**kwargs)` raises with needs[name] beside them."""
    with pytest.raises(Exception) as e:
        function(name)(**{**needs.get(name, {}), **kwargs})
    return e.value


@pytest.mark.parametrize("name, argument", sorted(arguments()))
def test_an_argument_of_the_wrong_type_names_itself(name, argument, needs):
    error = refused(name, needs, **{argument: Odd()})
    kind = ValueError if argument in READ_BY_VALUE else TypeError
    assert type(error) is kind, repr(error)
    assert re.match(rf"invalid {argument}\b", str(error)), str(error)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: bouncelab.run(preset="golf", v0=[1.0, 2.0]),
         "invalid v0: [1.0, 2.0] (must be real number, not list)"),
        (lambda: bouncelab.run(v0="3"), "invalid v0: '3' (must be real number, not str)"),
        (lambda: bouncelab.run(v0=np.array([1.0, 2.0])),
         "invalid v0: array([1., 2.]) (only 0-dimensional arrays can be converted to Python "
         "scalars)"),
        (lambda: bouncelab.run(history=True, samples=10.5),
         "invalid samples: 10.5 ('float' object cannot be interpreted as an integer)"),
        (lambda: bouncelab.run(history="yes"),
         "invalid history: 'yes' ('str' object is not an instance of 'bool')"),
        (lambda: bouncelab.run(preset=None),
         "invalid preset: None ('None' is not an instance of 'str')"),
        (lambda: bouncelab.run("golf", None, [1, 2]),
         "invalid v0: [1, 2] (must be real number, not list)"),
        (lambda: bouncelab.run(pressure=[1]), "invalid pressure: [1] (must be real number, not list)"),
        # a long value is cut, on one line
        (lambda: bouncelab.run(v0=np.ones((9, 9))),
         "invalid v0: array([[1., 1., 1., 1., 1., 1., 1., 1.,… (only 0-dimensional arrays can be "
         "converted to Python scalars)"),
    ],
)
def test_the_trials_calls_name_their_argument(call, message):
    with pytest.raises(TypeError) as e:
        call()
    assert str(e.value) == message


COUNTS = [
    ("run", "samples"),
    ("run_normalized", "samples"),
    ("run_params", "samples"),
    ("oblique", "samples"),
    ("shot", "samples"),
    ("drop", "bounces"),
    ("shot", "bounces"),
    ("shots", "bounces"),
    ("monte_carlo", "samples"),
    ("monte_carlo", "seed"),
    ("dask.monte_carlo", "samples"),
    ("dask.monte_carlo", "seed"),
]


@pytest.mark.parametrize("name, argument", COUNTS)
@pytest.mark.parametrize("negative", [-5, -(10**30)])
def test_a_negative_count_is_a_value_error_naming_it(name, argument, negative):
    if name.startswith("dask."):
        pytest.importorskip("distributed")
    history = dict(history=True) if name in ("run", "run_normalized", "run_params", "oblique") else {}
    error = refused(name, **history, **{argument: negative})
    assert type(error) is ValueError, repr(error)
    shown = "-5" if negative == -5 else "-an integer of 31 digits"
    assert str(error) == f"invalid {argument}: {shown} (must not be negative)"


def test_a_count_too_large_stays_an_overflow_naming_it():
    with pytest.raises(OverflowError, match=r"^invalid bounces: an integer of 31 digits \("):
        bouncelab.drop(bounces=10**30)
    # a number too large for a float, though negative, is no count
    with pytest.raises(OverflowError, match=r"^invalid v0: -an integer of 401 digits \("):
        bouncelab.run(v0=-(10**400))
