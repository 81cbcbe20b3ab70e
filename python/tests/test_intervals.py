"""Prediction intervals on a preset saved by `fit --save` (docs/fitting.md, "Prediction
intervals"): Python's `run` reports the same 95 % intervals as `bouncelab run --format json`,
and none on a plain preset."""

import json
import os
import subprocess
from pathlib import Path

import pytest

import bouncelab

ROOT = Path(__file__).resolve().parents[2]


def binary():
    path = os.environ.get("BOUNCELAB_BIN") or str(ROOT / "target" / "debug" / "bouncelab")
    if not Path(path).is_file():
        pytest.skip(f"no bouncelab binary at {path}")
    return path


def test_a_fitted_preset_carries_its_intervals(tmp_path, monkeypatch):
    home = tmp_path / "config"
    monkeypatch.setenv("XDG_CONFIG_HOME", str(home))
    monkeypatch.setenv("HOME", str(home))
    table = tmp_path / "cors.csv"
    noise = [0.004, -0.006, 0.002, 0.005, -0.003, -0.001, 0.006, -0.004]
    rows = ["v0,cor"]
    for v0, n in zip([1, 2, 3, 5, 8, 12, 18, 25], noise):
        rows.append(f"{v0},{bouncelab.run(preset='baseball', v0=v0).cor + n}")
    table.write_text("\n".join(rows) + "\n")
    env = dict(os.environ)
    fit = [binary(), "fit", "--preset", "baseball", "--cor-table", str(table), "--save", "bbfit"]
    subprocess.run(fit, check=True, capture_output=True, env=env)
    cli = json.loads(
        subprocess.run(
            [binary(), "run", "--preset", "bbfit", "--v0", "45", "--format", "json"],
            check=True,
            capture_output=True,
            env=env,
        ).stdout
    )
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
