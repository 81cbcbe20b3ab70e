"""Prediction intervals on a preset saved by `fit --save` (docs/fitting.md, "Prediction
intervals"): Python's `run` reports the same 95 % intervals as `bouncelab run --format json`,
and none on a plain preset."""

import json
import subprocess

import pytest
from cli_binary import binary

import bouncelab


def cli_json(env, *args):
    out = subprocess.run([binary(), *args, "--format", "json"], check=True, capture_output=True, env=env)
    return json.loads(out.stdout)


def test_a_fitted_preset_carries_its_intervals(fitted_baseball):
    env = fitted_baseball
    cli = cli_json(env, "run", "--preset", "bbfit", "--v0", "45")
    r = bouncelab.run(preset="bbfit", v0=45)
    for key in ["cor_ci95", "max_force_ci95", "contact_time_ci95"]:
        lo, hi = getattr(r, key)
        assert lo < hi
        assert lo == pytest.approx(cli[key][0], rel=1e-12)
        assert hi == pytest.approx(cli[key][1], rel=1e-12)
        assert r.to_dict()[key] == tuple(cli[key])
    assert r.cor_ci95[0] < r.cor < r.cor_ci95[1]
    plain = bouncelab.run(preset="baseball")
    assert plain.cor_ci95 is None and "cor_ci95" not in plain.to_dict()


def test_sweep_and_drop_carry_them_too(fitted_baseball):
    env = fitted_baseball
    rows = cli_json(env, "sweep", "velocity", "--preset", "bbfit", "--points", "4")["rows"]
    sweep = bouncelab.sweep_velocity(preset="bbfit", speeds=[r["v0"] for r in rows])
    bounces = cli_json(env, "drop", "--preset", "bbfit", "--bounces", "3")["bounces"]
    drop = bouncelab.drop(preset="bbfit", bounces=3)["bounces"]
    for table, cli, keys in [
        (sweep, rows, ["cor", "max_force", "contact_time"]),
        (drop, bounces, ["cor", "max_force", "contact_time", "rebound_height"]),
    ]:
        for key in keys:
            for i, row in enumerate(cli):
                lo, hi = row[f"{key}_ci95"]
                assert table[f"{key}_ci95_lo"][i] == pytest.approx(lo, rel=1e-12)
                assert table[f"{key}_ci95_hi"][i] == pytest.approx(hi, rel=1e-12)
                assert lo <= row[key] <= hi
    assert "cor_ci95_lo" not in bouncelab.sweep_velocity(preset="baseball", speeds=[1.0])
    assert "cor_ci95_lo" not in bouncelab.drop(preset="baseball", bounces=1)["bounces"]


def test_drop_warns_when_its_air_is_not_the_fits(tmp_path, fitted_baseball):
    # a ball fitted to drops in vacuum (fit's default) and dropped through air (drop's
    # default) misses its own readings: Python's drop says so, as the command line's
    env = fitted_baseball
    drops = tmp_path / "drops.csv"
    drops.write_text("drop_height_m,rebound_height_m\n2.54,1.44\n2.54,1.46\n2.54,1.48\n2.54,1.47\n")
    fit = [binary(), "fit", "--preset", "tennis", "--drop-test", str(drops), "--free", "k_r",
           "--save", "tvac"]
    subprocess.run(fit, check=True, capture_output=True, env=env)
    cli = cli_json(env, "drop", "--preset", "tvac")
    py = bouncelab.drop(preset="tvac")
    air = [w for w in py["warnings"] if "fitted to drops taken in vacuum" in w]
    assert len(air) == 1 and "--no-drag drops it as the fit did" in air[0]
    assert py["warnings"] == cli["warnings"]
    assert not [w for w in bouncelab.drop(preset="tvac", drag=False)["warnings"] if "fitted to drops" in w]
