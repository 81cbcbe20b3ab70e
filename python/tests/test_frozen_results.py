"""A result's arrays and dicts cannot be changed through what it hands out: a history array is
read-only (numpy's ``flags.writeable`` False, for good: its memory is not numpy's to give
back), and a dict is a new one at each read. Before, ``r.t[0] = 99`` changed ``r.t``,
``r.to_dict()``, ``==`` and the pickle of the result that handed the array out."""

import copy
import pickle

import numpy as np
import pytest

import bouncelab
from cli_binary import reach

HISTORY = ["t", "force", "indentation", "displacement"]
OBLIQUE_HISTORY = ["t", "normal_force", "friction_force", "slip_velocity", "spin"]


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def assert_frozen(a):
    assert isinstance(a, np.ndarray) and not a.flags.writeable
    before = a.copy()
    with pytest.raises(ValueError, match="read-only"):
        a[0] = 99.0
    with pytest.raises(ValueError):
        a.flags.writeable = True
    np.testing.assert_array_equal(a, before)


def impacts():
    r = bouncelab.run(preset="golf", v0=3.0, history=True, samples=20)
    return [r, pickle.loads(pickle.dumps(r)), copy.deepcopy(r), copy.copy(r)]


@pytest.mark.parametrize("which", ["run", "unpickled", "deepcopy", "copy"])
def test_an_impacts_history_cannot_be_written(which):
    r = impacts()[["run", "unpickled", "deepcopy", "copy"].index(which)]
    fresh = bouncelab.run(preset="golf", v0=3.0, history=True, samples=20)
    for k in HISTORY:
        assert_frozen(getattr(r, k))
    assert r == fresh
    for k in HISTORY:
        np.testing.assert_array_equal(r.to_dict()[k], getattr(fresh, k))


def test_an_impacts_dicts_are_new_at_each_read():
    r = bouncelab.run(preset="golf", v0=3.0)
    energy = r.energy["relative_residual"]
    r.energy["relative_residual"] = 99.0
    r.warnings.append("mine")
    assert r.energy["relative_residual"] == energy and reach(r.warnings) == []


def test_an_oblique_impacts_history_and_energy_cannot_be_changed():
    o = bouncelab.oblique("tennis", angle=20.0, friction=0.5, spin=100.0, history=True, samples=20)
    for k in OBLIQUE_HISTORY:
        assert_frozen(getattr(o, k))
        assert_frozen(pickle.loads(pickle.dumps(o)).__getattribute__(k))
    residual = o.energy["residual"]
    o.energy["residual"] = 99.0
    o.warnings.append("mine")
    assert o.energy["residual"] == residual and reach(o.warnings) == []
