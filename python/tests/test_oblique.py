"""bouncelab.oblique: the same fields as ``bouncelab oblique --format json``, and its checks."""

import json
import math
import subprocess

import pytest
from cli_binary import binary, reach

import bouncelab


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    """Both the binary and the package read $XDG_CONFIG_HOME/bouncelab/presets: an empty one."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def as_json(value):
    """`value` as the JSON writes it: an infinite number (a rigid or fixed surface's K_s, M in
    the `surface` object) as null."""
    if isinstance(value, dict):
        return {k: as_json(v) for k, v in value.items()}
    if isinstance(value, float) and math.isinf(value):
        return None
    return value


def cli_json(*args):
    out = subprocess.run([binary(), *args, "--format", "json"], check=True, capture_output=True,
                         text=True)
    return json.loads(out.stdout)


@pytest.mark.parametrize("kwargs,args", [
    ({"v0": 25.0, "angle": 16.0, "spin": 300.0, "friction": 0.6},
     ["--v0", "25", "--angle", "16", "--spin", "300", "--friction", "0.6"]),
    # the tangential model given, and another law: the JSON says which ran
    ({"angle": 40.0, "friction": 0.3, "tangential_stiffness": 2e4, "inertia_factor": 0.5,
      "law": "hertz"},
     ["--angle", "40", "--friction", "0.3", "--tangential-stiffness", "2e4",
      "--inertia-factor", "0.5", "--law", "hertz"]),
])
def test_every_field_of_the_command_line(kwargs, args):
    # every key of the JSON, the ball and the tangential model it ran included (before, the
    # preset, origin, parameters, law, friction, K_t, κ and radius were missing: a K_t taken
    # from Mindlin's ratio was not to be seen)
    r = bouncelab.oblique("tennis", **kwargs)
    cli = cli_json("oblique", "--preset", "tennis", *args)
    # c_t is a key of the JSON only when the tangential spring had a dashpot
    assert r.tangential_damping is None
    assert set(cli) == {k for k in dir(r) if not k.startswith("_") and k != "to_dict"} - {
        "t", "normal_force", "friction_force", "slip_velocity", "spin", "tangential_damping"}
    for key, want in cli.items():
        assert as_json(getattr(r, key)) == want, key
    assert r.t is None
    assert as_json(r.to_dict()) == cli


def test_to_dict_with_a_history_is_the_json_with_its_arrays():
    r = bouncelab.oblique("tennis", angle=20.0, friction=0.5, history=True, samples=30)
    cli = cli_json("oblique", "--preset", "tennis", "--angle", "20", "--friction", "0.5",
                   "--history", "--samples", "30")
    d = r.to_dict()
    assert list(d) == list(cli)
    for key, want in cli.items():
        if isinstance(want, list) and key != "warnings":
            assert d[key] is getattr(r, key) and list(d[key]) == want, key
        else:
            assert as_json(d[key]) == want, key


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
