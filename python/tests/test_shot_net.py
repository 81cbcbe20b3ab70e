"""bouncelab.shot(net=...) and bouncelab.shots(net=...) (issue 57): the command line's
``shot --net DISTANCE[,HEIGHT]``, number for number; and ``shots`` naming its surface as
``shot`` does."""

import json
import subprocess

import numpy as np
import pytest

import bouncelab
from cli_binary import binary


LAUNCH = dict(height=2.8, speed=50.0, spin=200.0, friction=0.6)


def cli_shot(*flags):
    out = subprocess.run(
        [binary(), "shot", "--preset", "tennis", "--height", "2.8", "--speed", "50",
         "--spin", "200", "--friction", "0.6", "--format", "json", *flags],
        capture_output=True, text=True, check=True,
    )
    return json.loads(out.stdout)


def test_the_net_is_the_command_lines():
    for elevation, net, flag in [(-6.0, 11.89, "11.89"), (-5.0, (11.89, 1.2), "11.89,1.2"),
                                 (-5.0, 11.89, "11.89"), (-5.0, 40.0, "40")]:
        r = bouncelab.shot("tennis", samples=0, elevation=elevation, net=net, **LAUNCH)
        cli = cli_shot("--elevation", str(elevation), "--net", flag)
        assert r["net"] == cli["net"], (elevation, net)
    # the docs' serves: 6° down meets the net, 5° down clears it
    assert not bouncelab.shot("tennis", elevation=-6.0, net=11.89, **LAUNCH)["net"]["cleared"]
    assert bouncelab.shot("tennis", elevation=-5.0, net=11.89, **LAUNCH)["net"]["cleared"]
    # no net, no key
    assert "net" not in bouncelab.shot("tennis", elevation=-5.0, **LAUNCH)


def test_shots_gives_the_net_element_by_element():
    elevations = np.array([-6.0, -5.5, -5.0])
    many = bouncelab.shots("tennis", elevation=elevations, net=11.89, **LAUNCH)
    assert many["net_cleared"].dtype == bool
    for k, e in enumerate(elevations):
        one = bouncelab.shot("tennis", samples=0, elevation=e, net=11.89, **LAUNCH)["net"]
        assert many["net_clearance"][k] == one["clearance"]
        assert many["net_cleared"][k] == one["cleared"]
    assert list(many["net_cleared"]) == [False, True, True]
    assert "net_cleared" not in bouncelab.shots("tennis", elevation=elevations, **LAUNCH)


def test_shots_names_its_surface_as_shot_does():
    """The defect: ``shots(surface=...)`` ran on the surface but its answer did not name it
    (``shot``'s and the command line's do). Fails on the old code (no ``surface`` key)."""
    for surface in [None, {"stiffness": 3e5, "damping": 12.0}]:
        many = bouncelab.shots("tennis", elevation=np.array([-5.0, -4.0]), surface=surface,
                               **LAUNCH)
        one = bouncelab.shot("tennis", samples=0, elevation=-5.0, surface=surface, **LAUNCH)
        assert many["surface"] == one["surface"]
    assert many["surface"]["stiffness"] == 3e5


def test_a_bad_net_is_named():
    with pytest.raises(ValueError, match="invalid net"):
        bouncelab.shot("tennis", elevation=-5.0, net=0.0, **LAUNCH)
    with pytest.raises(ValueError, match="invalid net"):
        bouncelab.shot("tennis", elevation=-5.0, net="far", **LAUNCH)
    with pytest.raises(ValueError, match="invalid net"):
        bouncelab.shots("tennis", elevation=np.array([-5.0]), net=(11.89, -1.0), **LAUNCH)
