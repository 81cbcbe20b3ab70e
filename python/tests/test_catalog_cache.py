"""The catalog is kept between calls (issue 30 item 5: `run(preset=…)` without re-reading
every preset), yet a user preset added, edited or removed is seen at the next call, as the
command line sees it."""

import os
import sys
import warnings

import pytest
from cli_binary import cli
from user_presets import mine

import bouncelab


def test_a_preset_added_edited_and_removed_is_seen(presets_folder):
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")
    path = presets_folder / "mine.toml"
    path.write_text(mine())
    first = bouncelab.run(preset="mine")
    assert first == bouncelab.run(preset="mine")  # from the cache: the same answer
    assert first.k_r == bouncelab.run(preset="superball").k_r
    path.write_text(mine("9e4"))
    assert bouncelab.run(preset="mine").k_r == 9e4
    path.unlink()
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")


def test_a_folder_made_after_the_first_call_is_seen(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    with pytest.raises(ValueError, match="unknown preset 'mine'"):
        bouncelab.run(preset="mine")
    bouncelab.run(preset="golf")  # from the cache, the folder still missing
    folder = tmp_path / "config" / "bouncelab" / "presets"
    folder.mkdir(parents=True)
    (folder / "mine.toml").write_text(mine())
    assert bouncelab.run(preset="mine").k_r == 7.08e4


@pytest.fixture
def mine_read(presets_folder):
    """The user's preset ``mine`` (K_r 7.08e4) in the presets folder, read once (the cache
    holds it now): its file."""
    path = presets_folder / "mine.toml"
    path.write_text(mine("7.08e4"))
    assert bouncelab.run(preset="mine").k_r == 7.08e4
    return path


linux_only = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="the inotify watch is Linux's"
)


@linux_only
def test_an_edit_that_keeps_size_and_time_is_seen(mine_read):
    # the stamp (name, size, modification time) cannot tell this edit; the watch does
    path = mine_read
    before = path.stat()
    path.write_text(mine("9.08e4"))
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))
    assert path.stat().st_size == before.st_size
    assert bouncelab.run(preset="mine").k_r == 9.08e4


def test_a_linked_preset_edited_at_its_target_is_seen(tmp_path, presets_folder):
    # a link's target lies in a folder nobody watches: the stamp is taken at each call
    target = tmp_path / "elsewhere.toml"
    target.write_text(mine("7.08e4"))
    (presets_folder / "mine.toml").symlink_to(target)
    assert bouncelab.run(preset="mine").k_r == 7.08e4
    target.write_text(mine("1.5e5"))
    assert bouncelab.run(preset="mine").k_r == 1.5e5


@linux_only
def test_a_forked_child_does_not_take_its_parents_news(mine_read):
    # parent and child share an inotify instance after a fork: a child reading it would take
    # the event the parent needs
    path = mine_read
    pid = os.fork()
    if pid == 0:  # the child: edit, then read
        code = 1
        try:
            path.write_text(mine("9e4"))
            code = 0 if bouncelab.run(preset="mine").k_r == 9e4 else 2
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert bouncelab.run(preset="mine").k_r == 9e4


def test_a_bad_preset_file_is_warned_of_as_the_command_line_warns(presets_folder):
    # the command line warns of each file of the presets folder it skips, one line on stderr,
    # and runs; the package skipped them silently. Asked for by name, the file's error ends
    # the call (exit 2 there), the other bad file warned of first
    (presets_folder / "broken.toml").write_text('name = "x"\n[measured\n')
    (presets_folder / "bad.toml").write_text('name = "bad"\nmass = [\n')
    (presets_folder / "mine.toml").write_text(mine())
    prefix = "bouncelab: warning: "
    code, _, err = cli("run", "--preset", "mine")
    assert code == 0 and err.startswith(prefix), err
    said = [line[len(prefix):] for line in err.splitlines()]
    assert len(said) == 2 and "bad.toml:" in said[0] and "broken.toml:2:" in said[1], said

    def warned(call):
        """The UserWarnings `call` gives, and the ValueError it raises (None if none)."""
        error = None
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            try:
                call()
            except ValueError as e:
                error = str(e)
        return [str(x.message) for x in w if x.category is UserWarning], error

    assert warned(lambda: bouncelab.run(preset="mine")) == (said, None)
    assert warned(lambda: bouncelab.run(preset="mine", k_p=6e4)) == (said, None)
    assert warned(bouncelab.presets) == (said, None)
    code, _, err = cli("run", "--preset", "broken")
    lines = err.splitlines()
    assert code == 2 and len(lines) == 2 and lines[0] == prefix + said[0], err
    error = lines[1].removeprefix("bouncelab: error: ")
    assert warned(lambda: bouncelab.run(preset="broken")) == (said[:1], error)
    assert warned(lambda: bouncelab.run(preset="broken", k_p=6e4)) == (said[:1], error)
