"""A user preset for the catalog tests (not a test file: the tests import it): the superball's
preset file renamed `mine`, with its own K_r."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUPERBALL = (ROOT / "presets" / "superball.toml").read_text()


def mine(k_r="7.08e4"):
    """The text of preset `mine`: the superball with K_r = `k_r` (N/m, as typed)."""
    return SUPERBALL.replace('name = "superball"', 'name = "mine"').replace("k_r = 7.08e4", f"k_r = {k_r}")
