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
