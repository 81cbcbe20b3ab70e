"""The catalog is kept between calls (issue 30 item 5: `run(preset=…)` without re-reading
every preset), yet a user preset added, edited or removed is seen at the next call, as the
command line sees it."""

from pathlib import Path

import pytest

import bouncelab

ROOT = Path(__file__).resolve().parents[2]
SUPERBALL = (ROOT / "presets" / "superball.toml").read_text()


def test_a_preset_added_edited_and_removed_is_seen(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path))
    folder = tmp_path / "bouncelab" / "presets"
    folder.mkdir(parents=True)
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")
    path = folder / "mine.toml"
    path.write_text(SUPERBALL.replace('name = "superball"', 'name = "mine"'))
    first = bouncelab.run(preset="mine")
    assert first == bouncelab.run(preset="mine")  # from the cache: the same answer
    assert first.k_r == bouncelab.run(preset="superball").k_r
    path.write_text(
        SUPERBALL.replace('name = "superball"', 'name = "mine"').replace("k_r = 7.08e4", "k_r = 9e4")
    )
    assert bouncelab.run(preset="mine").k_r == 9e4
    path.unlink()
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")
