"""bouncelab.batch against the command line's `bouncelab batch --format json` (BOUNCELAB_BIN):
the same dict key by key, the same refusals (as ValueError / OSError), picklable."""

import json
import pickle
from pathlib import Path

import pytest
from cli_binary import as_package, cli

import bouncelab


def answer(out):
    """The command line's JSON, every key (its `conditions` included), as the package holds it."""
    return as_package(json.loads(out))


ROOT = Path(__file__).resolve().parents[2]
LOT7 = ROOT / "tests" / "golden" / "batch-lot7.csv"


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))


def test_lot7_is_the_command_line_s_json():
    code, out, err = cli("batch", str(LOT7), "--preset", "tennis", "--format", "json")
    # T06 cannot be fitted, but was dropped from the ITF's height: it FAILs on its reading
    # and says why its fit failed (docs/batch.md); every ball has a verdict, exit 0
    assert code == 0, err
    r = bouncelab.batch(LOT7, preset="tennis")
    assert r == answer(out)
    assert r["summary"]["no_answer"] == 0 and r["summary"]["failures"] == 2
    t06 = [b for b in r["balls"] if b["id"] == "T06"][0]
    assert t06["verdict"] == "FAIL" and t06["verdict_from"] == "measurement"
    assert t06["error"] is None and "out of reach" in t06["fit_error"]
    assert pickle.loads(pickle.dumps(r)) == r


def test_options_as_the_command_line_s(tmp_path):
    code, out, err = cli(
        "batch", str(LOT7), "--preset", "tennis", "--standard", "itf", "--free", "k_r,c",
        "--drag-coefficient", "0.55", "--format", "json",
    )
    assert code in (0, 1), err
    r = bouncelab.batch(
        str(LOT7), preset="tennis", standard="itf", free="k_r,c", drag_coefficient=0.55
    )
    assert r == answer(out)
    assert bouncelab.batch(LOT7, preset="tennis", free=["k_r", "c"], drag_coefficient=0.55) == r


def test_a_cor_table_batch(tmp_path):
    f = tmp_path / "golf.csv"
    f.write_text("id,v0,cor\nG1,40,0.80\nG1,30,0.82\nG2,40,0.78\nG2,30,0.81\n")
    code, out, err = cli(
        "batch", str(f), "--preset", "golf", "--standard", "mlb", "--format", "json"
    )
    assert code in (0, 1), err
    assert bouncelab.batch(f, preset="golf", standard="mlb") == answer(out)


@pytest.mark.parametrize(
    "text, standard, where",
    [
        ("id,v0,cor\nA,1,0.5\nB,1,0.6\nA,2,0.4\n", "itf", ":4:1:"),
        ("v0,cor\n1,0.5\n", "itf", ":1:1:"),
        ("id,v0,cor\nA,1,x\n", "itf", ":2:5:"),
        ("id,drop_height_m,rebound_height_m\nA,2.54,1.4\n", "no-such-standard", None),
    ],
)
def test_refusals_are_the_command_line_s(tmp_path, text, standard, where):
    f = tmp_path / "bad.csv"
    f.write_text(text)
    code, _, err = cli("batch", str(f), "--preset", "tennis", "--standard", standard)
    assert code == 2
    with pytest.raises(ValueError) as e:
        bouncelab.batch(f, preset="tennis", standard=standard)
    assert str(e.value) in err
    if where:
        assert f"{f}{where}" in str(e.value)


def test_a_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="no such file"):
        bouncelab.batch(tmp_path / "none.csv", preset="tennis")
    with pytest.raises(ValueError, match="free|k_x"):
        bouncelab.batch(LOT7, preset="tennis", free="k_x")


def test_a_file_it_cannot_read_is_refused_in_the_readers_words(tmp_path):
    # the batch file, a trace it names, court's and fit_oblique's files: one reader, the
    # library's (measured::bounded), each refusal worded as before it was shared
    latin = tmp_path / "latin.csv"
    latin.write_bytes(b"id,time_s,force_N\nA,0.5 \xe9t\xe9,1\n")
    big = tmp_path / "big.csv"
    with open(big, "wb") as f:
        f.truncate((64 << 20) + 1)  # sparse: its size is read, not its bytes
    cases = [
        (tmp_path, OSError, f"{tmp_path}: is not a regular file"),
        (Path("/dev/null"), OSError, "/dev/null: is not a regular file"),
        (latin, ValueError, f"{latin}:2:7: not UTF-8 text"),
        (big, ValueError, f"{big}: is {(64 << 20) + 1} bytes; a data file is at most "
                          f"{64 << 20} bytes"),
    ]
    for path, kind, message in cases:
        with pytest.raises(kind) as e:
            bouncelab.batch(path, preset="tennis")
        assert str(e.value) == message, path
        with pytest.raises(kind) as e:
            bouncelab.fit_oblique(path, preset="tennis")
        assert str(e.value) == message, path
