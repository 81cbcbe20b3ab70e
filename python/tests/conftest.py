"""Fixtures shared by the test files: a user presets folder in a config home of the test's own,
and a preset fitted by the binary and saved there."""

import os
import subprocess

import pytest
from cli_binary import binary

import bouncelab


@pytest.fixture
def presets_folder(tmp_path, monkeypatch):
    """The user's presets folder, made empty in a config home (XDG_CONFIG_HOME) of the test's
    own, so that no preset of the machine's user is seen."""
    home = tmp_path / "config"
    monkeypatch.setenv("XDG_CONFIG_HOME", str(home))
    folder = home / "bouncelab" / "presets"
    folder.mkdir(parents=True)
    return folder


@pytest.fixture
def fitted_baseball(tmp_path, monkeypatch):
    """A preset `bbfit` fitted by `bouncelab fit --save` to eight noisy baseball CORs, saved in
    a config home (XDG_CONFIG_HOME and HOME) of the test's own; the environment for the CLI."""
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
    return env
