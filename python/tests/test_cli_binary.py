"""The comparisons with the command line skip, saying why, where there is no binary to compare
with, and fail where BOUNCELAB_BIN names none (python/tests/cli_binary.py). Before,
test_oblique.py and test_fit_oblique.py ran `bouncelab` from PATH without BOUNCELAB_BIN and
failed with FileNotFoundError where it was not installed."""

import os
import subprocess
import sys
from pathlib import Path


HERE = Path(__file__).resolve().parent
COMPARING = ["test_oblique.py", "test_fit_oblique.py"]


def pytest_run(tmp_path, **env):
    """pytest on COMPARING in a child, with no binary at $CARGO_TARGET_DIR and none on PATH."""
    child = {k: v for k, v in os.environ.items() if k != "BOUNCELAB_BIN"}
    child.update(CARGO_TARGET_DIR=str(tmp_path), PATH=str(Path(sys.executable).parent), **env)
    args = [sys.executable, "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider"]
    p = subprocess.run([*args, *(str(HERE / f) for f in COMPARING)], cwd=tmp_path, env=child,
                       capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def test_without_a_binary_the_comparisons_skip_and_say_why(tmp_path):
    code, out = pytest_run(tmp_path)
    assert code == 0, out
    assert "failed" not in out and " skipped" in out, out
    assert f"no bouncelab binary at {tmp_path / 'debug' / 'bouncelab'}" in out, out


def test_a_bouncelab_bin_that_is_not_a_file_fails(tmp_path):
    missing = tmp_path / "no-such-bouncelab"
    code, out = pytest_run(tmp_path, BOUNCELAB_BIN=str(missing))
    assert code == 1, out
    assert f"BOUNCELAB_BIN={missing} is not a file" in out, out
