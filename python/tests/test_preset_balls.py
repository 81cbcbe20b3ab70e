"""A preset's ball is built once while the catalog holds (python/src/catalog_cache.rs,
`PresetBalls`): the kept ball gives the bits a ball built anew gives, and it goes with the
catalog when the user's presets folder changes — under every parameter set and law it was
kept for, and for every call that takes a preset's ball."""

import math
import struct

import pytest
from user_presets import mine

import bouncelab


def bits(impact):
    """Every number of an impact's dict as its IEEE bits (NaN equal to NaN), the rest as is."""
    out = {}
    for k, v in impact.to_dict().items():
        if isinstance(v, float):
            out[k] = struct.pack("<d", v)
        elif isinstance(v, dict):
            out[k] = {kk: struct.pack("<d", vv) if isinstance(vv, float) else vv for kk, vv in v.items()}
        else:
            out[k] = v
    return out


@pytest.mark.parametrize("preset", ["golf", "tennis", "superball"])
@pytest.mark.parametrize("law", [None, "linear", "hertz"])
@pytest.mark.parametrize("params", [None, "materials"])
def test_the_kept_ball_is_a_ball_built_anew(preset, law, params):
    first = bouncelab.run(preset=preset, law=law, params=params)
    again = bouncelab.run(preset=preset, law=law, params=params)
    # a speed given builds the ball anew (Ball::from_entry with v0): the same speed, the same bits
    anew = bouncelab.run(preset=preset, law=law, params=params, v0=first.v0)
    assert bits(first) == bits(again) == bits(anew)
    assert repr(first) == repr(again) == repr(anew)


def test_lambda_and_zeta_leave_the_kept_ball_as_it_was():
    before = bits(bouncelab.run(preset="golf"))
    moved = bouncelab.run(preset="golf", lambda_=0.5, zeta=0.2)
    assert math.isclose(moved.lambda_, 0.5, rel_tol=1e-12) and math.isclose(moved.zeta, 0.2, rel_tol=1e-12)
    assert bits(bouncelab.run(preset="golf")) == before


def test_a_preset_edited_drops_every_ball_kept_from_it(presets_folder):
    path = presets_folder / "mine.toml"
    path.write_text(mine("7.08e4"))
    laws = [None, "linear", "hertz", "elastic-plastic"]
    for law in laws:  # each kept
        assert bouncelab.run(preset="mine", law=law).k_r == 7.08e4
    assert bouncelab.run(preset="mine", params="adopted").k_r == 7.08e4
    speeds = bouncelab.sweep_velocity(preset="mine", speeds=[1.0])
    path.write_text(mine("9.5e4"))
    for law in laws:
        assert bouncelab.run(preset="mine", law=law).k_r == 9.5e4
    assert bouncelab.run(preset="mine", params="adopted").k_r == 9.5e4
    # the other calls that take a preset's ball take it from the same place
    assert bouncelab.sweep_velocity(preset="mine", speeds=[1.0])["cor"][0] != speeds["cor"][0]
    path.unlink()
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")


def test_a_bad_law_or_set_is_the_same_error_kept_or_not():
    bouncelab.run(preset="golf")  # the golf ball kept
    for _ in range(2):
        with pytest.raises(ValueError) as law:
            bouncelab.run(preset="golf", law="cubic")
        with pytest.raises(ValueError) as params:
            bouncelab.run(preset="golf", params="guessed")
        # an unknown preset is named before its law or set is read, as the command line does
        with pytest.raises(ValueError, match="unknown preset 'nothing'"):
            bouncelab.run(preset="nothing", law="cubic")
    assert "cubic" in str(law.value) and "guessed" in str(params.value)
