"""bouncelab.collide against `bouncelab collide --format json` (issue 33): the same fields by
the same names, to 1e-12, and the same one-line errors."""

import json
import math

import pytest
from cli_binary import cli

import bouncelab
from test_bouncelab import same

KEYS = [
    "cor",
    "apparent_cor",
    "ball_speed_out",
    "target_speed_out",
    "max_force",
    "contact_time",
    "reduced_mass",
    "closing_speed",
    "max_indentation",
    "permanent_indentation",
    "max_target_deflection",
]


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def close(a, b):
    return abs(a - b) <= 1e-12 * max(abs(b), 1e-300)


CASES = [
    (dict(preset="baseball", v0=40.0, target_mass=0.8, target_speed=30.0),
     ["--preset", "baseball", "--v0", "40", "--target-mass", "0.8", "--target-speed", "30"]),
    (dict(preset="superball", target_mass=0.3, target_stiffness=2e4, target_damping=3.0),
     ["--target-mass", "0.3", "--target-stiffness", "2e4", "--target-damping", "3"]),
    (dict(preset="golf", law="elastic-plastic", v0=20.0, target_mass=0.2, target_stiffness=1e6),
     ["--preset", "golf", "--law", "elastic-plastic", "--v0", "20", "--target-mass", "0.2",
      "--target-stiffness", "1e6"]),
    (dict(preset="golf", target_preset="golf", target_speed=1.47),
     ["--preset", "golf", "--target-preset", "golf", "--target-speed", "1.47"]),
]


@pytest.mark.parametrize("kwargs,args", CASES)
def test_collide_is_the_command_lines(kwargs, args):
    code, out, err = cli("collide", *args, "--format", "json")
    assert code == 0, err
    want = json.loads(out)
    got = bouncelab.collide(**kwargs)
    for key in KEYS:
        assert close(getattr(got, key), want[key]), (key, getattr(got, key), want[key])
    for key in ["method", "rebound", "ball", "law", "effective_mass", "effective_radius"]:
        assert getattr(got, key) == want[key], key
    assert got.target_mass == want["target"]["mass"]
    # the whole document, warnings and the target's object included (inf for its nulls)
    same(got.to_dict(), want)


def test_the_wall_is_run():
    r = bouncelab.run(preset="golf", v0=3.0)
    c = bouncelab.collide(preset="golf", v0=3.0, target_mass=math.inf)
    assert close(c.cor, r.cor) and close(c.max_force, r.max_force)
    assert c.target_speed_out == 0.0 and c.apparent_cor == c.cor


def test_bad_targets_raise_the_command_lines_line():
    for kwargs, args in [
        (dict(target_mass=0.0), ["--target-mass", "0"]),
        (dict(target_mass=1.0, target_stiffness=-1.0), ["--target-mass", "1", "--target-stiffness", "-1"]),
        (dict(target_mass=1.0, target_speed=-10.0), ["--target-mass", "1", "--target-speed", "-10"]),
    ]:
        code, out, err = cli("collide", *args)
        assert code == 2 and out == ""
        with pytest.raises(ValueError) as e:
            bouncelab.collide(**kwargs)
        assert "bouncelab: error: " + str(e.value) + "\n" == err
    with pytest.raises(ValueError):
        bouncelab.collide()
