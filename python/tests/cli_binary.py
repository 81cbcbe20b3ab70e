"""The `bouncelab` binary the tests compare the package with (not a test file: the tests import
it). BOUNCELAB_BIN names it; without it, $CARGO_TARGET_DIR/debug/bouncelab (CARGO_TARGET_DIR
defaulting to target/ at the repository's root; .ci/run builds it before pytest runs). No
binary there skips the comparison, saying why; a BOUNCELAB_BIN that is not a file fails, since
whoever set it meant the comparison to run (python/tests/test_cli_binary.py)."""

import math
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def binary():
    """The binary's path, or the calling test skipped (failed if BOUNCELAB_BIN is wrong)."""
    target = ROOT / os.environ.get("CARGO_TARGET_DIR", "target")  # an absolute one replaces ROOT
    path = os.environ.get("BOUNCELAB_BIN") or str(target / "debug" / "bouncelab")
    if not Path(path).is_file():
        if os.environ.get("BOUNCELAB_BIN"):
            pytest.fail(f"BOUNCELAB_BIN={path} is not a file")
        pytest.skip(f"no bouncelab binary at {path} (cargo build, or set BOUNCELAB_BIN)")
    return path


def cli(*args):
    """(exit code, stdout, stderr) of the binary run on `args`."""
    p = subprocess.run([binary(), *args], capture_output=True, text=True, env=os.environ)
    return p.returncode, p.stdout, p.stderr


def reach(warnings):
    """An answer's warnings but the calibration's (`outside calibration: …`, which every speed
    but the preset's own adds; tests/cli/calibration.rs checks them)."""
    return [w for w in warnings if not w.startswith("outside calibration:")]


def as_package(document):
    """The command line's JSON `document` as the package's dict holds it: its `surface`'s
    infinite K_s and M, null in JSON (which has no infinity), are inf (docs/python.md)."""
    surface = document["surface"]
    for key in ("stiffness", "mass"):
        if surface[key] is None:
            surface[key] = math.inf
    return document
