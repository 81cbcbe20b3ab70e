"""The Python bindings against the command line.

Two references: the transcripts stored by the Rust test tests/cli/cli_golden.rs (tests/golden/*.txt,
what `bouncelab ARGS` printed, byte for byte), and the `bouncelab` binary itself, run on the
same arguments (cli_binary.py: BOUNCELAB_BIN, default $CARGO_TARGET_DIR/debug/bouncelab). Values
must agree to 1e-12, messages word for word.
"""

import csv
import json
import math
import shlex
import threading
import time
from pathlib import Path

import numpy as np
import pytest
import cli_binary
from cli_binary import cli

import bouncelab

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "golden"
PRESETS = ROOT / "presets"


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    """Both the binary and the bindings read $XDG_CONFIG_HOME/bouncelab/presets: an empty one."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    return tmp_path / "config" / "bouncelab" / "presets"


def cli_json(*args):
    """The command line's JSON."""
    code, out, err = cli(*args)
    assert code == 0, err
    return json.loads(out)


def cli_error(*args):
    code, out, err = cli(*args)
    assert code != 0 and out == "", (code, out)
    prefix = "bouncelab: error: "
    assert err.startswith(prefix) and err.endswith("\n") and err.count("\n") == 1, err
    return err[len(prefix) : -1]


def golden(name):
    """(argv after `bouncelab`, exit code, stdout, stderr) of a stored transcript."""
    text = (GOLDEN / f"{name}.txt").read_text()
    head, rest = text.split("\n== exit ", 1)
    code, rest = rest.split("\n== stdout\n", 1)
    stdout, _, stderr = rest.partition("== stderr\n")
    argv = shlex.split(head.removeprefix("$ bouncelab "))
    return argv, int(code), stdout, stderr


def same(a, b, path="value"):
    """Equal structures, numbers to 1e-12 relative; the JSON's null is the bindings' inf for
    infinite z_p or c, and their NaN or None for an absent contact time; between two answers
    of the bindings, inf equals inf and NaN NaN."""
    if isinstance(b, dict):
        assert isinstance(a, dict), path
        assert set(a) == set(b), (path, set(a) ^ set(b))
        for k in b:
            same(a[k], b[k], f"{path}.{k}")
    elif isinstance(b, list):
        a = list(a)
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(b, bool) or isinstance(b, str):
        assert a == b, (path, a, b)
    elif b is None:
        assert a is None or math.isinf(a) or math.isnan(a), (path, a)
    else:
        a = float(a)
        if not math.isfinite(b):
            # two answers of the bindings compared: inf is inf, NaN is NaN (JSON has neither)
            assert a == b or (math.isnan(a) and math.isnan(b)), (path, a, b)
            return
        assert abs(a - b) <= 1e-12 * max(abs(b), 1e-300), (path, a, b)


def test_the_package_carries_the_command_lines_ball_and_conditions():
    # issue 52 item 3, issue 56 item 5: the answer names the ball it ran and its conditions
    d = bouncelab.run(preset="golf", k_p=2e6).to_dict()
    assert d["ball"]["name"] == "golf" and d["ball"]["overrides"] == ["k_p"]
    assert d["comparison_withheld"].startswith("the measurement is the preset's ball's")
    assert set(d["conditions"]) == {"temperature_c", "pressure_gauge_pa", "atmosphere_pa"}
    assert all("calibration" in p for p in bouncelab.presets())
    models = {p["name"]: p["aerodynamics"] for p in bouncelab.presets()}
    assert models["golf-driver"] == "golf" and models["superball"] is None


# ---- values against the stored transcripts ----------------------------------------------


def test_run_json_golf_matches_the_stored_transcript():
    argv, code, out, _ = golden("run-json-golf")
    assert argv == ["run", "--preset", "golf", "--format", "json"] and code == 0
    same(bouncelab.run(preset="golf").to_dict(), json.loads(out))


def test_run_history_matches_the_stored_transcript():
    argv, code, out, _ = golden("run-json-history-ep")
    assert argv == ["run", "--law", "elastic-plastic", "--v0", "6", "--format", "json",
                    "--history", "--samples", "25"]
    expected = json.loads(out)
    r = bouncelab.run(law="elastic-plastic", v0=6.0, history=True, samples=25)
    same(r.to_dict(), expected)
    for key in ("t", "force", "indentation", "displacement"):
        a = getattr(r, key)
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (25,)
        np.testing.assert_allclose(a, expected[key], rtol=1e-12, atol=0)


def test_fit_matches_the_stored_transcript():
    argv, code, out, _ = golden("fit-json-baseball")
    assert argv == ["fit", "--preset", "baseball", "--cor", "0.5", "--v0", "2", "--format", "json"]
    same(bouncelab.fit(0.5, preset="baseball", v0=2.0), json.loads(out))


def test_sweep_zeta_matches_the_stored_csv():
    argv, code, out, _ = golden("sweep-zeta-csv")
    assert argv == ["sweep", "zeta", "--points", "9"]
    lines = out.splitlines()
    columns = lines[0].split(",")
    rows = [[float(x) if x else math.nan for x in line.split(",")] for line in lines[1:]]
    zetas = np.logspace(-2, 2, 9)
    d = bouncelab.sweep_zeta([0.0, 0.4, 1.0], zetas)
    assert list(d) == columns
    for j, c in enumerate(columns):
        assert d[c].shape == (27,)
        np.testing.assert_allclose(d[c], [r[j] for r in rows], rtol=1e-12, atol=0)


def test_sweep_velocity_matches_the_stored_json():
    argv, code, out, _ = golden("sweep-velocity-json-golf")
    assert argv == ["sweep", "velocity", "--preset", "golf", "--points", "4", "--format", "json"]
    rows = json.loads(out)["rows"]
    speeds = [r["v0"] for r in rows]
    d = bouncelab.sweep_velocity("golf", speeds)
    assert list(d) == [
        "v0",
        "cor",
        "max_force",
        "contact_time",
        "permanent_indentation",
        "max_indentation",
        "warnings",
        "uncalibrated_outputs",
        "ball",
        "conditions",
        "surface",
    ]
    doc = json.loads(out)
    # the outputs golf's record does not vouch for: the JSON's, once for the whole sweep
    assert d["uncalibrated_outputs"] == doc["uncalibrated_outputs"] == [
        "max_indentation", "permanent_indentation"]
    named = ("uncalibrated_outputs", "ball", "conditions", "surface")
    same({k: d[k] for k in named}, {k: doc[k] for k in named})
    columns = [k for k in d if k not in named]
    same({k: list(d[k]) for k in columns}, {k: [r[k] for r in rows] for k in columns})


def test_presets_match_the_stored_json():
    _, _, out, _ = golden("presets-json")
    same(bouncelab.presets(), json.loads(out))


@pytest.mark.parametrize("name", ["bad-lambda", "bad-preset", "bad-fit-reach"])
def test_errors_match_the_stored_messages(name):
    argv, code, _, err = golden(name)
    assert code == 2
    message = err.removeprefix("bouncelab: error: ").rstrip("\n")
    calls = {
        "bad-lambda": lambda: bouncelab.run(lambda_=math.nan),
        "bad-preset": lambda: bouncelab.run(preset="no-such-ball"),
        "bad-fit-reach": lambda: bouncelab.fit(0.01),
    }
    with pytest.raises(ValueError) as e:
        calls[name]()
    assert str(e.value) == message


# ---- values and messages against the binary ---------------------------------------------

RUNS = [
    ({}, []),
    ({"preset": "golf", "v0": 3.0}, ["--preset", "golf", "--v0", "3"]),
    ({"preset": "baseball", "law": "hertz"}, ["--preset", "baseball", "--law", "hertz"]),
    ({"law": "elastic-plastic", "v0": 9.0}, ["--law", "elastic-plastic", "--v0", "9"]),
    ({"lambda_": 0.0, "zeta": 2.0}, ["--lambda", "0", "--zeta", "2"]),  # no rebound
    ({"preset": "golf", "params": "materials"}, ["--preset", "golf", "--params", "materials"]),
    ({"lambda_": 0.3, "zeta": 0.0}, ["--lambda", "0.3", "--zeta", "0"]),  # c = inf
]


@pytest.mark.parametrize("kwargs,args", RUNS)
def test_run_equals_the_cli_json(kwargs, args):
    expected = cli_json("run", *args, "--format", "json")
    same(bouncelab.run(**kwargs).to_dict(), expected)


def test_no_rebound_is_said():
    r = bouncelab.run(lambda_=0.0, zeta=2.0)
    assert (r.cor, r.rebound, r.contact_time, r.contact_time_normalized) == (0.0, False, None, None)


def test_run_normalized_equals_the_cli_json():
    expected = cli_json(
        "run", "--normalized", "--lambda", "0.4", "--zeta", "0.61", "--zp-bar", "0.5",
        "--format", "json", "--history", "--samples", "50",
    )
    r = bouncelab.run_normalized(lambda_=0.4, zeta=0.61, zp_bar=0.5, history=True, samples=50)
    same(r.to_dict(), expected)
    assert r.preset is None and r.origin == "normalized" and r.z_p == expected["z_p"]


def test_run_params_is_the_preset_it_copies():
    sb = bouncelab.run()
    r = bouncelab.run_params(m=sb.mass, k_p=sb.k_p, c=sb.c, k_r=sb.k_r, z_p=sb.z_p, v0=sb.v0)
    assert (r.preset, r.origin, r.parameters) == (None, "parameters", "given")
    for k in ("cor", "max_force", "contact_time", "max_indentation", "k_h", "lambda_", "zeta"):
        assert getattr(r, k) == getattr(sb, k), k
    # no flattening by default: z_p = inf
    assert bouncelab.run_params(m=1, k_p=1, c=1, k_r=1, v0=1).z_p == math.inf


def test_fit_equals_the_cli_json():
    expected = cli_json("fit", "--preset", "golf", "--cor", "0.9", "--law", "hertz",
                        "--format", "json")
    same(bouncelab.fit(0.9, preset="golf", law="hertz"), expected)


def test_fit_warns_of_a_fitted_ball_past_its_radius_as_the_cli():
    # the superball fitted to e = 0.6 at 45 m/s presses 33 mm into a 21.55 mm ball: the CLI
    # warns (qa11); the package's dict once lacked the key
    expected = cli_json("fit", "--preset", "superball", "--cor", "0.6", "--v0", "45",
                        "--format", "json")
    got = bouncelab.fit(0.6, preset="superball", v0=45)
    assert got["warnings"] and got["warnings"] == expected["warnings"]
    same(got, expected)


def test_sweep_velocity_defaults_are_the_clis():
    code, out, err = cli("sweep", "velocity", "--preset", "baseball")
    assert code == 0, err
    table = list(csv.reader(out.splitlines()))
    # the CSV's numbers, then its warnings column: the calibration's alone (the baseball stays
    # within its radius; every speed but its record's 1.25 m/s is outside its calibration),
    # then the ball, the surface and the conditions it ran (docs/cli.md)
    w = table[0].index("warnings")
    assert table[0][w + 1 :] == [
        "preset", "origin", "parameters", "law",
        "surface", "surface_stiffness", "surface_damping", "surface_mass",
        "temperature_c", "pressure_gauge_pa", "atmosphere_pa",
    ]
    assert all(cli_binary.reach(r[w].split("; ") if r[w] else []) == [] for r in table[1:])
    assert {tuple(r[w + 1 : w + 6]) for r in table[1:]} == {
        ("baseball", "embedded", "adopted", "linear", "steel-plate")
    }
    columns = table[0][:w]
    rows = [r[:w] for r in table[1:]]
    expected = np.array([[float(x) if x else math.nan for x in r] for r in rows])
    d = bouncelab.sweep_velocity("baseball")
    # the CSV's numeric columns, then the JSON's max_indentation, warnings,
    # uncalibrated_outputs, ball, conditions, surface
    assert list(d) == columns + ["max_indentation", "warnings", "uncalibrated_outputs", "ball",
                                 "conditions", "surface"]
    assert [cli_binary.reach(w) for w in d["warnings"]] == [[] for _ in rows]
    got = np.column_stack([d[c] for c in columns])
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=0)


def test_a_user_preset_is_seen_as_the_cli_sees_it(no_user_presets):
    no_user_presets.mkdir(parents=True)
    text = (PRESETS / "superball.toml").read_text().replace('name = "superball"', 'name = "mine"')
    assert 'name = "mine"' in text
    (no_user_presets / "mine.toml").write_text(text.replace("k_r = 70800", "k_r = 50000"))
    names = [p["name"] for p in bouncelab.presets()]
    assert names[-1] == "mine"
    same(bouncelab.presets(), cli_json("presets", "--format", "json"))
    same(bouncelab.run(preset="mine").to_dict(),
         cli_json("run", "--preset", "mine", "--format", "json"))


@pytest.mark.parametrize(
    "kwargs,args",
    [
        ({"preset": "tennis", "height": 2.54, "bounces": 3}, ["--preset", "tennis", "--height", "2.54", "--bounces", "3"]),
        ({"drag": False, "min_rebound": 0.05}, ["--no-drag", "--min-rebound", "0.05"]),
        ({"preset": "golf", "drag_coefficient": 0.25, "air_density": 1.0, "law": "hertz"},
         ["--preset", "golf", "--drag-coefficient", "0.25", "--air-density", "1", "--law", "hertz"]),
        # a standard: its verdict under "standard", the drop from its own height when none is
        # given, judged on its own drop when one is (docs/drop.md, "Standards")
        ({"preset": "tennis", "standard": "itf", "bounces": 2}, ["--preset", "tennis", "--standard", "itf", "--bounces", "2"]),
        ({"preset": "tennis", "standard": "itf", "height": 1.0, "bounces": 1},
         ["--preset", "tennis", "--standard", "itf", "--height", "1", "--bounces", "1"]),
        ({"preset": "basketball", "standard": "fiba", "bounces": 1}, ["--preset", "basketball", "--standard", "fiba", "--bounces", "1"]),
        ({"preset": "softball", "standard": "softball-47", "bounces": 1},
         ["--preset", "softball", "--standard", "softball-47", "--bounces", "1"]),
        ({"preset": "table-tennis", "standard": "ittf", "drag": False, "bounces": 1},
         ["--preset", "table-tennis", "--standard", "ittf", "--no-drag", "--bounces", "1"]),
    ],
)
def test_drop_equals_the_cli_json(kwargs, args):
    expected = cli_json("drop", *args, "--format", "json")
    d = bouncelab.drop(**kwargs)
    rows = expected.pop("bounces")
    same({k: v for k, v in d.items() if k != "bounces"}, expected)
    assert len(rows) >= 1 and all(a.shape == (len(rows),) for a in d["bounces"].values())
    same({k: list(v) for k, v in d["bounces"].items()}, {k: [r[k] for r in rows] for k in rows[0]})


ERRORS = [
    (lambda: bouncelab.run(v0=-1.0), ["run", "--v0", "-1"]),
    (lambda: bouncelab.run(v0=math.inf), ["run", "--v0", "inf"]),
    (lambda: bouncelab.run(lambda_=2e6), ["run", "--lambda", "2e6"]),
    (lambda: bouncelab.run(zeta=1e-14), ["run", "--zeta", "1e-14"]),
    (lambda: bouncelab.run(preset="golf", history=True, samples=1),
     ["run", "--preset", "golf", "--history", "--samples", "1"]),
    (lambda: bouncelab.run_normalized(zp_bar=0.0), ["run", "--normalized", "--zp-bar", "0"]),
    (lambda: bouncelab.fit(1.5), ["fit", "--cor", "1.5"]),
    (lambda: bouncelab.fit(0.5, preset="golf", v0=0.0), ["fit", "--preset", "golf", "--cor", "0.5", "--v0", "0"]),
    (lambda: bouncelab.sweep_velocity("cricket"), ["sweep", "velocity", "--preset", "cricket"]),
    (lambda: bouncelab.drop(bounces=0), ["drop", "--bounces", "0"]),
    (lambda: bouncelab.drop(height=-1.0), ["drop", "--height", "-1"]),
    (lambda: bouncelab.drop(drag_coefficient=-1.0), ["drop", "--drag-coefficient", "-1"]),
    (lambda: bouncelab.drop(standard="nope"), ["drop", "--standard", "nope"]),
    (lambda: bouncelab.drop(standard="ncaa-bbcor"), ["drop", "--standard", "ncaa-bbcor"]),
]


@pytest.mark.parametrize("call,args", ERRORS)
def test_errors_are_the_clis(call, args):
    message = cli_error(*args)
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value) == message


def test_broken_user_preset_is_named_with_line_and_column(no_user_presets):
    # skipped by the catalog the command line shares (both warn of it and list the others),
    # and the error, file:line:column, of a call asking for it by its file name
    no_user_presets.mkdir(parents=True)
    (no_user_presets / "bad.toml").write_text('name = "bad"\nmass = [\n')
    message = cli_error("run", "--preset", "bad")
    assert ":2:" in message or ":3:" in message, message
    with pytest.raises(ValueError) as e:
        bouncelab.run(preset="bad")
    assert str(e.value) == message
    with pytest.warns(UserWarning, match="bad.toml:2:"):
        assert "superball" in [p["name"] for p in bouncelab.presets()]


def test_errors_of_the_bindings_own_arguments():
    with pytest.raises(ValueError, match=r"unknown contact law 'plastic' \(expected linear"):
        bouncelab.run(law="plastic")
    with pytest.raises(ValueError, match=r"unknown parameter set 'fitted'"):
        bouncelab.run(params="fitted")
    with pytest.raises(ValueError, match=r"^invalid lambda: no value given$"):
        bouncelab.sweep_zeta([], [1.0])
    with pytest.raises(ValueError, match=r"^invalid mass: -1 \(must not be negative\)$"):
        bouncelab.run_params(m=-1, k_p=1, c=1, k_r=1, v0=1)
    with pytest.raises(
        ValueError, match=r"^zetas\[1\]: invalid zeta: -1 \(must not be negative\)$"
    ):
        bouncelab.sweep_zeta([1.0], [0.5, -1.0])
    with pytest.raises(TypeError):
        bouncelab.run_params(1, 1, 1, 1, 1)  # keyword-only
    assert issubclass(bouncelab.NoAnswerError, ValueError)


# ---- shapes, inputs, the GIL -------------------------------------------------------------


def test_shapes_and_inputs():
    r = bouncelab.run()
    assert (r.t, r.force, r.indentation, r.displacement) == (None, None, None, None)
    assert set(r.energy) == {"initial_kinetic", "final_kinetic", "dashpot", "contact", "spring",
                             "relative_residual"}
    assert r.energy["relative_residual"] < 1e-12
    h = bouncelab.run(history=True)
    assert h.t.shape == h.force.shape == (400,)
    assert h.force[0] == 0.0 and abs(h.t[-1] - h.contact_time) < 1e-15
    assert h.t is not None and h.t.flags["C_CONTIGUOUS"]
    # lists, tuples, numpy arrays (float or int) and scalars are all accepted
    a = bouncelab.sweep_zeta(np.array([1.0]), np.logspace(-1, 1, 5))
    b = bouncelab.sweep_zeta((1,), [0.1, 10**-0.5, 1, 10**0.5, 10])
    c = bouncelab.sweep_zeta(1.0, np.array([1]))
    assert all(v.shape == (5,) for v in a.values())
    np.testing.assert_allclose(a["cor"], b["cor"], rtol=1e-12)
    assert c["cor"][0] == a["cor"][2]
    assert bouncelab.sweep_zeta([0.0, 1.0], [0.5, 2.0])["lambda"].tolist() == [0, 0, 1, 1]
    # no rebound: NaN in the arrays (an empty CSV field)
    assert math.isnan(bouncelab.sweep_zeta([0.0], [2.0])["contact_time_normalized"][0])
    # the repr shows every digit: the COR as repr(float) writes it (0.750567725333737…, the
    # last digit the closed form's, docs/python.md: within 1e-12 of the exact solver's …372)
    assert f"cor={r.cor!r}," in repr(r) and abs(r.cor - 0.7505677253337372) <= 1e-12


def test_the_gil_is_released_during_a_sweep():
    """Another Python thread keeps running while a long sweep runs."""
    zetas = np.logspace(-2, 2, 20000)
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    time.sleep(0.01)
    start = time.perf_counter()
    bouncelab.sweep_zeta([0.4, 1.0], zetas)
    end = time.perf_counter()
    stop.set()
    t.join()
    during = [x for x in ticks if start < x < end]
    # with the GIL held the thread could not tick at all while the sweep ran
    assert end - start > 0.02, "sweep too short to tell"
    assert len(during) >= 3, (len(during), end - start)
