"""The dicts the bindings hand out as a library type's serde form (python/src/answer.rs `dict`,
pythonize): the keys in the command line's JSON order, and Python's own values where the
JSON cannot carry them: ∞ a float `inf` (the JSON's null), an int an int, a list a list, a
fixed pair a tuple."""

import math

import numpy as np
import pytest

import bouncelab
from test_bouncelab import no_user_presets  # noqa: F401

SURFACE_KEYS = ["name", "origin", "stiffness", "damping", "mass", "friction",
                "tangential_stiffness", "tangential_damping", "overrides"]
LAUNCH = dict(height=2.8, speed=50.0, spin=200.0, friction=0.6)


def history():
    return bouncelab.run(preset="golf", v0=3.0, history=True, samples=200)


# every answer on the rigid plate whose surface dict the suite did not check for inf yet
# (test_surfaces.py: run, collide, drop, oblique, static, fit, sweep_velocity, batch,
# monte_carlo, fit_oblique)
ON_THE_PLATE = {
    "Impact.to_dict": lambda: history().to_dict(),
    "Collision.to_dict": lambda: bouncelab.collide("tennis", target_mass=math.inf).to_dict(),
    "ObliqueImpact.to_dict": lambda: bouncelab.oblique("tennis", angle=30.0,
                                                       friction=0.5).to_dict(),
    "shot": lambda: bouncelab.shot("tennis", samples=0, **LAUNCH),
    "shots": lambda: bouncelab.shots("tennis", elevation=[-5.0, 3.0], **LAUNCH),
    "fit_trace": lambda: bouncelab.fit_trace(history().t, history().force, preset="golf",
                                             v0=3.0),
    "fit_cor_table": lambda: bouncelab.fit_cor_table([1.0, 2.0, 4.0, 8.0],
                                                     [0.85, 0.84, 0.83, 0.8]),
    "fit_drops": lambda: bouncelab.fit_drops([1.0, 2.0], [0.6, 1.1]),
}


@pytest.mark.parametrize("name", ON_THE_PLATE)
def test_the_rigid_plate_is_inf_in_the_json_order(name):
    s = ON_THE_PLATE[name]()["surface"]
    assert list(s) == SURFACE_KEYS, list(s)
    for k in ("stiffness", "mass"):
        assert type(s[k]) is float and s[k] == math.inf, (k, s[k])
    assert type(s["damping"]) is float and type(s["overrides"]) is list


def test_a_surface_that_gives_keeps_its_numbers_and_overrides_as_a_list():
    s = bouncelab.run(preset="tennis", surface={"stiffness": 1e6, "damping": 20.0}).surface
    assert list(s) == SURFACE_KEYS
    assert (s["stiffness"], s["damping"], s["mass"]) == (1e6, 20.0, math.inf)
    assert s["overrides"] == ["stiffness", "damping"] and type(s["overrides"]) is list


def test_a_fits_estimates_and_lack_of_fit():
    drop = np.array([0.2, 0.5, 0.8, 1.2, 1.8])
    fit = bouncelab.fit_drops(drop, 0.6 * drop, preset="superball", rebound_height_sd=0.003)
    for e in fit["fitted"].values():
        assert list(e) == ["value", "std_error", "ci95"]
        assert type(e["ci95"]) is tuple and len(e["ci95"]) == 2
        assert all(type(x) is float for x in (e["value"], e["std_error"], *e["ci95"]))
    assert list(fit["lack_of_fit"]) == ["test", "statistic", "p_value"]
    assert fit["lack_of_fit"]["test"] == "chi2"
    trace = bouncelab.fit_trace(history().t, history().force, preset="golf", v0=3.0)
    assert list(trace["nuisance"]) == ["time_offset", "baseline"]
    assert all(list(e) == ["value", "std_error", "ci95"] for e in trace["nuisance"].values())


def test_a_shots_end_and_net():
    r = bouncelab.shot("tennis", samples=0, elevation=-5.0, net=11.89, **LAUNCH)
    assert list(r["end"]) == ["reason", "t", "x", "y", "vx", "vy", "spin", "speed"]
    assert r["end"]["reason"] == "landing"
    assert all(type(v) is float for k, v in r["end"].items() if k != "reason")
    net = r["net"]
    assert list(net) == ["x", "height", "clearance", "cleared", "t", "y", "bounces_before",
                         "warnings"]
    assert type(net["bounces_before"]) is int and type(net["cleared"]) is bool
    assert type(net["warnings"]) is list
    # a net the shot does not reach: None where the JSON has null
    short = bouncelab.shot("tennis", samples=0, elevation=-5.0, net=60.0, time=0.1, **LAUNCH)
    assert short["end"]["reason"] == "time"
    n = short["net"]
    assert (n["clearance"], n["t"], n["y"], n["bounces_before"]) == (None,) * 4
    assert n["cleared"] is False
