"""bouncelab.shot and bouncelab.shots (docs/flight.md): the command line's numbers, arrays
out, and the vectorised form element by element the single one."""

import json
import subprocess

import numpy as np
import pytest

import bouncelab
from cli_binary import binary


SERVE = dict(height=2.8, speed=50.0, elevation=-6.0, spin=200.0, friction=0.6)


def test_a_serve_lands_and_bounces_as_the_command_line_says():
    r = bouncelab.shot("tennis", samples=3, **SERVE)
    out = subprocess.run(
        [binary(), "shot", "--preset", "tennis", "--height", "2.8", "--speed", "50",
         "--elevation", "-6", "--spin", "200", "--friction", "0.6", "--format", "json",
         "--samples", "3"],
        capture_output=True, text=True, check=True,
    )
    cli = json.loads(out.stdout)
    assert r["bounces"]["x"][0] == cli["bounces"][0]["x"]
    assert r["bounces"]["spin_out"][0] == cli["bounces"][0]["spin_out"]
    assert r["end"]["x"] == cli["end"]["x"]
    assert r["end"]["reason"] == "landing"
    assert list(r["trajectory"]["t"]) == [p["t"] for p in cli["trajectory"]]


def test_shots_is_shot_element_by_element():
    speeds = np.array([45.0, 50.0, 55.0])
    spins = np.array([[100.0], [300.0]])
    many = bouncelab.shots("tennis", height=2.8, speed=speeds, elevation=-6.0, spin=spins,
                           friction=0.6)
    assert many["landing_x"].shape == (2, 3)
    for i, w in enumerate(spins[:, 0]):
        for j, v in enumerate(speeds):
            one = bouncelab.shot("tennis", height=2.8, speed=v, elevation=-6.0, spin=w,
                                 friction=0.6, samples=0)
            assert many["landing_x"][i, j] == one["bounces"]["x"][0]
            assert many["end_x"][i, j] == one["end"]["x"]
    # topspin brings the ball down sooner
    assert np.all(many["landing_x"][1] < many["landing_x"][0])


def test_bad_input_names_the_field():
    with pytest.raises(ValueError, match="height"):
        bouncelab.shot("tennis", height=0.0, speed=50.0, friction=0.6)
    with pytest.raises(ValueError, match="element 1: invalid speed"):
        bouncelab.shots("tennis", height=2.0, speed=np.array([10.0, -1.0]), friction=0.6)


# a steep landing that grips (the serve slides throughout: K_t and c_t change nothing there)
GRIP = dict(height=2.0, speed=15.0, elevation=-40.0, spin=0.0, friction=0.9)


def cli_shot(*flags):
    out = subprocess.run(
        [binary(), "shot", "--preset", "tennis", "--height", "2", "--speed", "15",
         "--elevation", "-40", "--spin", "0", "--friction", "0.9", "--format", "json",
         *flags],
        capture_output=True, text=True, check=True,
    )
    return json.loads(out.stdout)


def test_every_override_of_the_command_line_is_taken():
    # each keyword is the flag of `bouncelab shot --help` of the same name (issue 57 item 4);
    # each changes the answer, and shot and shots give what the command line gives
    overrides = [
        (dict(drag_coefficient=0.3), ["--drag-coefficient", "0.3"]),
        (dict(lift_coefficient=0.1), ["--lift-coefficient", "0.1"]),
        (dict(spin_decay=0.5), ["--spin-decay", "0.5"]),
        (dict(air_density=1.0), ["--air-density", "1.0"]),
        (dict(tangential_stiffness=2e4), ["--tangential-stiffness", "20000"]),
        (dict(inertia_factor=0.6), ["--inertia-factor", "0.6"]),
        (dict(tangential_damping=5.0), ["--tangential-damping", "5"]),
        (dict(mass=0.06), ["--mass", "0.06"]),
        (dict(radius=0.034), ["--radius", "0.034"]),
        (dict(k_p=3e4), ["--k-p", "30000"]),
        (dict(damping=10.0), ["--damping", "10"]),
        (dict(k_r=4e4), ["--k-r", "40000"]),
        (dict(z_p=0.004), ["--z-p", "0.004"]),
    ]
    plain = bouncelab.shot("tennis", samples=0, **GRIP)
    for kw, flags in overrides:
        r = bouncelab.shot("tennis", samples=0, **GRIP, **kw)
        cli = cli_shot(*flags)
        assert r["end"]["x"] == cli["end"]["x"], kw
        assert r["bounces"]["v_out"][0] == cli["bounces"][0]["v_out"], kw
        assert (r["end"]["x"], r["bounces"]["v_out"][0]) != (
            plain["end"]["x"], plain["bounces"]["v_out"][0]), kw
        many = bouncelab.shots("tennis", **GRIP, **kw)
        assert many["end_x"] == r["end"]["x"], kw


# the average tour drive of docs/flight.md §4, to its landing
DRIVE = dict(height=0.05, speed=74.97, elevation=10.8, spin=-272.2, friction=0.4, bounces=0,
             samples=0)


def test_the_driver_and_mlb_balls_fly_on_their_kinds_models():
    # each preset names its ball's published model (`aerodynamics`, docs/flight.md §2), not
    # its name: golf-driver flew as a smooth sphere without lift, the drive 103.5 m
    driver, golf = bouncelab.shot("golf-driver", **DRIVE), bouncelab.shot("golf", **DRIVE)
    assert driver["source"] == golf["source"]
    assert abs(driver["end"]["x"] / golf["end"]["x"] - 1.0) < 0.05
    mlb, baseball = bouncelab.shot("baseball-mlb", **DRIVE), bouncelab.shot("baseball", **DRIVE)
    assert mlb["source"] == baseball["source"]
    assert "Nathan" in mlb["source"]
