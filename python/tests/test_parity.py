"""Every command against the package, key for key (issue 52 items 2–3, issue 56 item 5): the
same inputs give the command line's JSON (BOUNCELAB_BIN) and the package's dict, every key
the command line writes — the `ball` object (`ball_record` for collide), the withheld
comparison, `conditions`, a preset's `calibration`, the `outside calibration:` warnings —
numbers to 1e-12, None where the JSON has null. Each case runs a ball the command line
changed (an override, a pressure, a temperature, a time since inflation) so that the keys
carry something to compare."""

import json

import numpy as np
import pytest
from test_bouncelab import cli_json, no_user_presets, same  # noqa: F401

import bouncelab

# the football: an inflated ball whose record states 20 °C and 0.8 bar (presets/football.toml)
AT_5_C = {"pressure": "0.75bar", "temperature": 5.0}
AT_5_C_FLAGS = ["--pressure", "0.75bar", "--temperature", "5"]


def columns_of(rows, keys):
    """The JSON's rows (a list of dicts) as the package's columns (a dict of arrays)."""
    return {k: [r[k] for r in rows] for k in keys}


CASES = {
    "run": (["run", "--preset", "football", *AT_5_C_FLAGS, "--v0", "12"],
            lambda: bouncelab.run("football", v0=12.0, **AT_5_C).to_dict()),
    "run with an override": (["run", "--preset", "golf", "--k-p", "2e6", "--v0", "40"],
                             lambda: bouncelab.run("golf", v0=40.0, k_p=2e6).to_dict()),
    "run after 72 h": (["run", "--preset", "football", "--after", "72h"],
                       lambda: bouncelab.run("football", after="72h").to_dict()),
    "run on a surface": (["run", "--preset", "tennis", "--surface", "clay"],
                         lambda: bouncelab.run("tennis", surface="clay").to_dict()),
    "oblique": (["oblique", "--preset", "football", "--angle", "30", "--friction", "0.5",
                 "--v0", "15", *AT_5_C_FLAGS],
                lambda: bouncelab.oblique("football", angle=30.0, friction=0.5, v0=15.0,
                                          **AT_5_C).to_dict()),
    "collide": (["collide", "--preset", "baseball", "--v0", "40", "--target-mass", "0.9",
                 "--mass", "0.15"],
                lambda: bouncelab.collide("baseball", v0=40.0, target_mass=0.9,
                                          mass=0.15).to_dict()),
    "collide ball on ball": (["collide", "--preset", "football", "--target-preset", "football",
                              "--target-speed", "5", *AT_5_C_FLAGS],
                             lambda: bouncelab.collide("football", target_preset="football",
                                                       target_speed=5.0, **AT_5_C).to_dict()),
    "court": (["court", "--preset", "tennis", "--surface", "clay", "--friction", "0.55"],
              lambda: bouncelab.court("tennis", surface="clay", friction=0.55)),
    "court calibrated": (["court", "--preset", "tennis", "--friction", "0.6",
                          "--surface-cor", "0.75", "--k-p", "6e4"],
                         lambda: bouncelab.court("tennis", friction=0.6, surface_cor=0.75,
                                                 k_p=6e4)),
    "static": (["static", "--preset", "tennis", "--load", "8.165"],
               lambda: bouncelab.static("tennis", load_kg=8.165)),
    "static elastic-plastic": (["static", "--preset", "baseball", "--load", "50", "--law",
                                "elastic-plastic", "--peak", "0.01"],
                               lambda: bouncelab.static("baseball", load_kg=50.0, peak=0.01,
                                                        law="elastic-plastic")),
    "mc": (["mc", "--preset", "football", "--vary", "k_p=5%", "--samples", "200",
            *AT_5_C_FLAGS],
           lambda: bouncelab.monte_carlo(preset="football", vary="k_p=5%", samples=200,
                                         **AT_5_C)),
    "fit": (["fit", "--preset", "baseball", "--cor", "0.5", "--v0", "30", "--mass", "0.15"],
            lambda: bouncelab.fit(0.5, preset="baseball", v0=30.0, mass=0.15)),
    "presets": (["presets"], lambda: bouncelab.presets()),
}


@pytest.mark.parametrize("case", CASES)
def test_the_package_answers_as_the_command_line(case):
    args, call = CASES[case]
    expected = cli_json(*args, "--format", "json")
    same(call(), expected)


def test_the_new_keys_say_what_ran():
    # the comparisons above would pass on two answers without them: they must be there
    r = bouncelab.run("football", v0=12.0, **AT_5_C)
    assert r.ball["name"] == "football" and r.ball["overrides"] == []
    assert r.conditions["temperature_c"] == 5.0
    assert r.conditions["pressure_gauge_pa"] < 75_000.0  # the gas law at 5 °C
    assert "its record at 20 °C, 80 kPa gauge" in r.comparison_withheld
    assert any(w.startswith("outside calibration:") for w in r.warnings)
    c = bouncelab.collide("baseball", v0=40.0, target_mass=0.9, mass=0.15)
    assert c.ball == "baseball" and c.ball_record["overrides"] == ["mass"]
    o = bouncelab.oblique("tennis", angle=30.0, friction=0.5)
    # a pressurised ball: its record's 12 psi gauge (presets/tennis.toml)
    assert o.ball["name"] == "tennis" and o.conditions["pressure_gauge_pa"] == 82_737.09
    s = bouncelab.oblique("superball", angle=30.0, friction=0.5)
    assert s.conditions["pressure_gauge_pa"] is None  # a solid ball


def test_fit_drops_and_a_cor_table_name_the_ball_as_the_command_line(tmp_path):
    table = tmp_path / "cor.csv"
    table.write_text("v0,cor\n1.0,0.85\n2.0,0.84\n4.0,0.83\n8.0,0.80\n")
    expected = cli_json("fit", "--preset", "superball", "--cor-table", str(table), "--format",
                        "json")
    f = bouncelab.fit_cor_table([1.0, 2.0, 4.0, 8.0], [0.85, 0.84, 0.83, 0.80])
    # the ball, the rigid plate the fit assumed and the conditions (issues 52, 53)
    for key in ("ball", "surface", "conditions"):
        same(f[key], expected[key], key)
    expected = cli_json("fit", "--preset", "tennis", "--free", "k_r", "--drop-height", "2.54",
                        "--rebound-height", "1.40", "--drop-height", "1.0", "--rebound-height",
                        "0.57", "--format", "json")
    f = bouncelab.fit_drops([2.54, 1.0], [1.40, 0.57], preset="tennis", free="k_r")
    same(f["ball"], expected["ball"])
    assert f["warnings"] == expected["warnings"]


def test_sweep_velocity_names_the_ball_as_the_command_line():
    expected = cli_json("sweep", "velocity", "--preset", "football", "--pressure", "0.75bar",
                        "--points", "3", "--from", "2", "--to", "8", "--format", "json")
    s = bouncelab.sweep_velocity("football", speeds=[2.0, 5.0, 8.0], pressure="0.75bar")
    named = ("ball", "surface", "conditions", "uncalibrated_outputs")
    same({k: s[k] for k in named}, {k: expected[k] for k in named})
    rows = columns_of(expected["rows"], ["v0", "cor", "warnings"])
    np.testing.assert_allclose(s["cor"], rows["cor"], rtol=1e-12)
    assert s["warnings"] == rows["warnings"]


def test_the_outputs_a_record_does_not_vouch_for_are_the_command_lines():
    # the tennis ball's record holds a rebound and a static deflection: its peak force and
    # contact time are the model's (docs/presets.md, "The calibration record")
    expected = cli_json("drop", "--preset", "tennis", "--standard", "itf", "--bounces", "2",
                        "--format", "json")
    d = bouncelab.drop("tennis", standard="itf", bounces=2)
    assert d["uncalibrated_outputs"] == expected["uncalibrated_outputs"] == [
        "max_force", "contact_time"]
    r = bouncelab.run("tennis")
    assert r.uncalibrated_outputs == r.to_dict()["uncalibrated_outputs"] == [
        "max_force", "contact_time", "max_indentation", "permanent_indentation"]
    assert bouncelab.run("baseball").uncalibrated_outputs == [
        "max_indentation", "permanent_indentation"]


def test_shot_states_its_conditions_as_the_command_line():
    expected = cli_json("shot", "--preset", "football", "--height", "1", "--speed", "20",
                        "--friction", "0.5", *AT_5_C_FLAGS, "--format", "json")
    s = bouncelab.shot("football", height=1.0, speed=20.0, friction=0.5, **AT_5_C)
    same(s["conditions"], expected["conditions"])
    assert s["ball"]["name"] == "football"
    np.testing.assert_allclose(s["bounces"]["v_out"], [b["v_out"] for b in expected["bounces"]],
                               rtol=1e-12)


def test_the_keys_survive_a_pickle():
    import pickle

    for r in (bouncelab.run("football", **AT_5_C),
              bouncelab.oblique("football", angle=30.0, friction=0.5, **AT_5_C),
              bouncelab.collide("golf", target_mass=0.2, k_p=2e6)):
        back = pickle.loads(pickle.dumps(r))
        assert back == r and back.to_dict().keys() == r.to_dict().keys()
        assert json.dumps(back.to_dict()["conditions"]) == json.dumps(r.to_dict()["conditions"])


def test_after_is_the_command_line_s_after():
    with pytest.raises(ValueError, match="after"):
        bouncelab.run("golf", after="72h")  # a solid ball: no leak
    with pytest.raises(ValueError, match="after"):
        bouncelab.run("football", after="72 parsecs")
