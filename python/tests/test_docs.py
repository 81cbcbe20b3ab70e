"""The Python pages say what the package does: docs/library.md's table gives every public
function with its arguments and defaults as they are, and the examples in docs/ and in the
package's docstring run as written and print what their comments say."""

import doctest
import inspect
import re
import shutil
from pathlib import Path

import pytest

import bouncelab
from test_bouncelab import no_user_presets  # noqa: F401

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"


def python_blocks(page):
    """The ```python blocks of a docs page, in order."""
    return re.findall(r"```python\n(.*?)```", (DOCS / page).read_text(), re.S)


def table_rows():
    """{name: [(argument, default text or None), …]} from library.md's function table;
    `**ball` is the ball's keyword arguments (the stub's `BallArguments`), each None."""
    from test_stubs import stub_classes

    ball = [(k, "None") for k in stub_classes()["BallArguments"][1]]
    text = (DOCS / "library.md").read_text()
    rows = {}
    for name, args in re.findall(r"^\| `(\w+)\((.*?)\)` \|", text, re.M):
        parts = [a.strip() for a in args.split(",") if a.strip() not in ("", "*")]
        rows[name] = [p for a in parts
                      for p in (ball if a == "**ball" else
                                [tuple(a.split("=", 1)) if "=" in a else (a, None)])]
    return rows


FUNCTIONS = [n for n in bouncelab.__all__ if not inspect.isclass(getattr(bouncelab, n))]


@pytest.mark.parametrize("name", FUNCTIONS)
def test_the_table_gives_each_function_as_it_is(name):
    rows = table_rows()
    assert name in rows, f"{name} has no row in library.md's table"
    real = inspect.signature(getattr(bouncelab, name)).parameters
    assert [a for a, _ in rows[name]] == list(real), name
    for arg, default in rows[name]:
        want = real[arg].default
        if want is inspect.Parameter.empty:
            assert default is None, (name, arg, "is required")
        else:
            assert default == repr(want).replace("'", '"'), (name, arg, default, want)


def test_the_package_docstring_runs():
    finder = doctest.DocTestFinder(recurse=False)
    runner = doctest.DocTestRunner()
    tests = finder.find(bouncelab, "bouncelab")
    assert sum(len(t.examples) for t in tests) >= 2
    for t in tests:
        runner.run(t)
    assert runner.summarize(verbose=False).failed == 0


def test_library_md_examples_run_and_say_what_they_print():
    block, errors = python_blocks("library.md")
    # the block's data, which the page leaves to the reader: a golf ball's force trace and a
    # COR table of three speeds
    h = bouncelab.run(preset="golf", v0=3.0, history=True, samples=200)
    speeds = [1.0, 2.0, 4.0, 8.0]
    cors = [bouncelab.run(preset="golf", v0=v).cor for v in speeds]
    ns = {"t": h.t, "force": h.force, "v0": speeds, "cor": cors, "sd": [0.01] * 4}
    exec(block, ns)
    r = ns["r"]
    assert (round(r.cor, 4), round(r.max_force, 1), round(r.contact_time, 6)) == (
        0.8404, 437.4, 0.000905)
    verdict = bouncelab.drop(preset="tennis", standard="itf")["standard"]
    assert (verdict["verdict"], round(verdict["margin"], 4)) == ("pass", 0.06)
    what_if = bouncelab.drop(preset="tennis", standard="itf", k_r=4e4)["standard"]
    assert (what_if["verdict"], round(what_if["margin"], 4)) == ("pass", 0.0198)
    for call, message in re.findall(r">>> (.*)\nValueError: (.*)", errors):
        with pytest.raises(ValueError) as e:
            eval(call, {"bouncelab": bouncelab})
        assert str(e.value) == message


def test_batch_md_example_runs(tmp_path, monkeypatch):
    shutil.copy(ROOT / "tests" / "golden" / "batch-lot7.csv", tmp_path / "lot7.csv")
    monkeypatch.chdir(tmp_path)
    (block,) = python_blocks("batch.md")
    ns = {}
    exec(block, ns)
    assert ns["r"]["standard"]["name"] == "itf"


def test_scale_md_single_process_example_runs():
    block = python_blocks("scale.md")[0]
    ns = {}
    exec(block.replace("samples=10**6", "samples=10**4"), ns)
    assert ns["r"]["values"]["cor"].shape == (10**4,)
