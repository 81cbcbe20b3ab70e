"""bouncelab.shot(surface=..., after_bounce=...) (issue 57 item 1, issue 53 item 1): the
command line's ``shot --surface NAME`` / explicit surface flags and ``--after-bounce D``,
number for number against its JSON."""

import json
import math
import subprocess

import pytest

import bouncelab
from cli_binary import binary


LAUNCH = dict(height=2.8, speed=50.0, elevation=-6.0, spin=200.0)
LAUNCH_FLAGS = ["--height", "2.8", "--speed", "50", "--elevation", "-6", "--spin", "200"]


def cli_shot(*flags):
    out = subprocess.run(
        [binary(), "shot", "--preset", "tennis", *LAUNCH_FLAGS, "--format", "json", *flags],
        capture_output=True, text=True, check=True,
    )
    return json.loads(out.stdout)


def same_shot(r, cli):
    for key in ["x", "t", "v_out", "angle_out", "spin_out", "cor_normal"]:
        assert list(r["bounces"][key]) == [b[key] for b in cli["bounces"]], key
    for key in ["t", "x", "y", "vx", "vy", "spin", "reason"]:
        assert r["end"][key] == cli["end"][key], key
    assert list(r["trajectory"]["x"]) == [p["x"] for p in cli.get("trajectory", [])]


def same_surface(ours, cli):
    for key, value in cli.items():
        if value is None and key in ("stiffness", "mass"):
            assert math.isinf(ours[key]), key
        else:
            assert ours[key] == value, key


def test_a_shot_on_a_surface_is_the_command_lines():
    r = bouncelab.shot("tennis", samples=3, friction=0.55,
                       surface={"stiffness": 3e5, "damping": 12.0}, **LAUNCH)
    cli = cli_shot("--surface-stiffness", "3e5", "--surface-damping", "12", "--friction",
                   "0.55", "--samples", "3")
    same_shot(r, cli)
    same_surface(r["surface"], cli["surface"])
    assert r["surface"]["stiffness"] == 3e5
    # the surface gives: not the rigid plate's bounce
    rigid = bouncelab.shot("tennis", samples=0, friction=0.55, **LAUNCH)
    assert abs(rigid["bounces"]["cor_normal"][0] - r["bounces"]["cor_normal"][0]) > 1e-3
    assert rigid["surface"]["name"] == "steel-plate"


def test_a_named_user_surface_gives_its_friction(tmp_path, monkeypatch):
    folder = tmp_path / "bouncelab" / "surfaces"
    folder.mkdir(parents=True)
    (folder / "court.toml").write_text(
        'name = "court"\ndescription = "a test court"\n[normal]\nstiffness = 3e5\n'
        'damping = 12.0\n[tangential]\nfriction = 0.55\n[[sources]]\nquantity = "stiffness"\n'
        'source = "a test"\n[[sources]]\nquantity = "damping"\nsource = "a test"\n'
        '[[sources]]\nquantity = "friction"\nsource = "a test"\n'
    )
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    monkeypatch.setenv("HOME", str(tmp_path))
    r = bouncelab.shot("tennis", samples=0, surface="court", **LAUNCH)
    cli = cli_shot("--surface", "court")
    same_shot(r, cli)
    same_surface(r["surface"], cli["surface"])
    assert r["surface"]["name"] == "court" and r["surface"]["friction"] == 0.55


def test_after_bounce_is_the_command_lines():
    for bounces in (1, 2):
        r = bouncelab.shot("tennis", samples=3, friction=0.6, bounces=bounces,
                           after_bounce=1.0, **LAUNCH)
        cli = cli_shot("--friction", "0.6", "--bounces", str(bounces), "--after-bounce", "1",
                       "--samples", "3")
        same_shot(r, cli)
        assert r["end"]["reason"] == "distance"
        assert r["end"]["x"] == r["bounces"]["x"][bounces - 1] + 1.0


def test_bad_surface_and_after_bounce_are_named():
    with pytest.raises(ValueError, match="unknown surface 'nope'"):
        bouncelab.shot("tennis", surface="nope", friction=0.6, **LAUNCH)
    with pytest.raises(ValueError, match="gives no μ"):
        bouncelab.shot("tennis", **LAUNCH)
    with pytest.raises(ValueError, match="invalid after_bounce: the shot makes no bounce"):
        bouncelab.shot("tennis", friction=0.6, bounces=0, after_bounce=1.0, **LAUNCH)
    with pytest.raises(ValueError, match="invalid after_bounce: 0"):
        bouncelab.shot("tennis", friction=0.6, after_bounce=0.0, **LAUNCH)
    with pytest.raises(ValueError, match="after_bounce does not go with distance"):
        bouncelab.shot("tennis", friction=0.6, after_bounce=1.0, distance=20.0, **LAUNCH)
