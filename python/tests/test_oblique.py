"""bouncelab.oblique: the same fields as ``bouncelab oblique --format json``, and its checks."""

import json
import math
import subprocess

import pytest
from cli_binary import binary

import bouncelab


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    """Both the binary and the package read $XDG_CONFIG_HOME/bouncelab/presets: an empty one."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def cli_json(*args):
    out = subprocess.run([binary(), *args, "--format", "json"], check=True, capture_output=True,
                         text=True)
    return json.loads(out.stdout)


def test_same_fields_as_the_command_line():
    r = bouncelab.oblique("tennis", v0=25.0, angle=16.0, spin=300.0, friction=0.6)
    cli = cli_json("oblique", "--preset", "tennis", "--v0", "25", "--angle", "16", "--spin", "300", "--friction", "0.6")
    for key in ["v_in", "angle_in_deg", "spin_in", "vx_in", "vy_in", "v_out", "angle_out_deg", "spin_out",
                "vx_out", "vy_out", "cor_normal", "cor_tangential", "apparent_friction", "slid_throughout",
                "grip_time", "contact_time", "max_normal_force", "max_friction_force"]:
        assert getattr(r, key) == cli[key], key
    assert r.energy == cli["energy"]
    assert r.t is None


def test_history_and_limits():
    r = bouncelab.oblique("tennis", angle=20.0, friction=0.0, spin=100.0, history=True, samples=50)
    assert len(r.t) == 50 and len(r.friction_force) == 50
    # no friction: the tangential motion is unchanged
    assert r.vx_out == r.vx_in and r.spin_out == 100.0
    assert r.energy["residual"] < 1e-12
    assert math.isclose(r.vy_out / r.vy_in, r.cor_normal, rel_tol=1e-12)


def test_bad_input_names_the_field():
    with pytest.raises(ValueError, match="invalid angle: 0"):
        bouncelab.oblique("tennis", angle=0.0, friction=0.5)
    with pytest.raises(ValueError, match="invalid inertia_factor"):
        bouncelab.oblique("tennis", angle=30.0, friction=0.5, inertia_factor=1.5)
