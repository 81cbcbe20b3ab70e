"""`Impact` pickles (every protocol), copies and compares by value (issue 32: results and
`Impact` are picklable, so they travel to Dask workers and process pools)."""

import concurrent.futures
import copy
import pickle

import numpy as np
import pytest

import bouncelab


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def same_dicts(a, b):
    assert a.keys() == b.keys()
    for k in a:
        if isinstance(a[k], np.ndarray):
            np.testing.assert_array_equal(a[k], b[k])
        else:
            assert a[k] == b[k], k


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_every_protocol_gives_the_same_impact(protocol):
    for r in [
        bouncelab.run(preset="golf", v0=3.0),
        bouncelab.run(preset="tennis", law="elastic-plastic", v0=30.0, history=True, samples=50),
        bouncelab.run_params(m=0.05, k_p=1e5, k_r=1e5, c=50.0, v0=2.0),
    ]:
        back = pickle.loads(pickle.dumps(r, protocol=protocol))
        assert type(back) is bouncelab.Impact
        assert back == r
        same_dicts(back.to_dict(), r.to_dict())
        assert repr(back) == repr(r)


def test_copies_are_equal_and_values_compare():
    r = bouncelab.run(preset="superball", history=True, samples=20)
    shallow, deep = copy.copy(r), copy.deepcopy(r)
    assert shallow == r and deep == r
    # a deep copy owns its arrays
    assert deep.force is not r.force
    np.testing.assert_array_equal(deep.force, r.force)
    # other values, not equal; another type, not equal either
    assert bouncelab.run(preset="superball", v0=3.0) != bouncelab.run(preset="superball", v0=3.1)
    assert r != bouncelab.run(preset="superball")  # the same impact without its history
    assert r != r.to_dict()
    assert bouncelab.run(preset="golf") == bouncelab.run(preset="golf")


def others():
    """Collisions and oblique impacts: a moving target, the wall, a compliant ball target, an
    oblique impact with and without its history."""
    return [
        bouncelab.collide(preset="baseball", v0=40.0, target_mass=0.8, target_speed=30.0),
        bouncelab.collide(preset="golf", v0=3.0, target_mass=float("inf")),
        bouncelab.collide(preset="tennis", target_preset="golf", target_stiffness=1e6,
                          target_damping=5.0),
        bouncelab.oblique("tennis", angle=20.0, friction=0.5, spin=100.0),
        bouncelab.oblique("tennis", angle=20.0, friction=0.5, history=True, samples=20),
    ]


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_collisions_and_oblique_impacts_pickle_copy_and_compare_by_value(protocol):
    # before, each raised TypeError "cannot pickle 'bouncelab.Collision' object" at
    # pickle.dumps, copy.copy and copy.deepcopy, and == was identity
    results = others()
    for r, again in zip(results, others()):
        back = pickle.loads(pickle.dumps(r, protocol=protocol))
        assert type(back) is type(r) and back == r and not back != r and again == r
        same_dicts(back.to_dict(), r.to_dict())
        assert repr(back) == repr(r)
        assert copy.copy(r) == r and copy.deepcopy(r) == r
    for i, r in enumerate(results):
        assert all(r != s for s in results[:i] + results[i + 1:]) and r != r.to_dict()


def test_a_nan_equals_a_nan_in_a_collision_and_an_oblique_impact_as_in_an_impact():
    # a result and its pickled copy compare equal whatever they hold (a NaN is kept by the
    # state; Impact's == already counted NaN equal to NaN)
    for r, key in [(others()[0], "cor"), (others()[3], "spin_out")]:
        state = {**r.to_dict(), key: float("nan")}
        odd = type(r)._from_state(state)
        assert odd == pickle.loads(pickle.dumps(odd)) and odd != r


def test_an_impact_crosses_a_process_pool():
    speeds = [1.0, 2.0, 3.0]
    with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
        got = list(pool.map(run_golf, speeds))
    assert got == [bouncelab.run(preset="golf", v0=v) for v in speeds]


def run_golf(v0):
    return bouncelab.run(preset="golf", v0=v0)


def test_a_fitted_presets_intervals_travel_too(fitted_baseball):
    r = bouncelab.run(preset="bbfit", v0=45)
    assert r.cor_ci95 is not None
    back = pickle.loads(pickle.dumps(r))
    assert back == r and back.cor_ci95 == r.cor_ci95
    assert back.contact_time_ci95 == r.contact_time_ci95
