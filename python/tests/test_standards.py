"""bouncelab.standards(): the list `bouncelab standards --format json` writes, which
batch's and drop's messages send the user to. Before, batch's error named
`bouncelab.standards()`, which did not exist (AttributeError)."""

import re
from pathlib import Path

import pytest

import bouncelab
from test_bouncelab import cli_error, cli_json, no_user_presets, same  # noqa: F401

LOT7 = Path(__file__).resolve().parents[2] / "tests" / "golden" / "batch-lot7.csv"


def test_the_same_list_as_the_command_line():
    same(bouncelab.standards(), cli_json("standards", "--format", "json"))


def test_every_drop_and_cor_standard_judges_a_drop():
    ball_tests = [s for s in bouncelab.standards() if s["test"]["kind"] in ("drop", "cor")]
    assert len(ball_tests) == 14  # with the WSF squash tests at 23 and 45 °C (issue 56)
    for s in ball_tests:
        v = bouncelab.drop(preset="tennis", standard=s["name"], bounces=1)["standard"]
        assert v["name"] == s["name"] and v["window"] == s["window"], s["name"]


def test_the_message_that_names_it_names_what_exists():
    with pytest.raises(ValueError) as e:
        bouncelab.batch(LOT7, preset="golf")
    call = re.search(r"bouncelab\.(\w+)\(\)", str(e.value))
    assert call, e.value
    assert [s["name"] for s in getattr(bouncelab, call.group(1))()][:2] == ["itf", "fifa-quality"]


def available_to_drop():
    """The names `drop --standard` takes, as its refusal of an unknown one lists them."""
    said = cli_error("drop", "--standard", "nope")
    return said[said.index("(available: ") + len("(available: "):-1].split(", ")


def drop_case(s):
    """The keyword arguments and flags that drop the standard's own ball (tennis where it
    names none) once: the pressure-loss test with a measured leak's half-life."""
    preset = (s["balls"] or ["tennis"])[0]
    kwargs, flags = {"preset": preset, "bounces": 1}, ["--preset", preset, "--bounces", "1"]
    if s["test"]["kind"] == "pressure-loss":
        kwargs["half_life"], flags = "300h", flags + ["--half-life", "300h"]
    return kwargs, flags


def test_drop_takes_every_standard_the_command_line_takes():
    # issue 53 item 3's neighbour: fifa-pressure-loss and itf-deformation were "unknown
    # standard" to the package while `drop --standard` judged them
    by_name = {s["name"]: s for s in bouncelab.standards()}
    names = available_to_drop()
    assert {"fifa-pressure-loss", "itf-deformation"} <= set(names), names
    kinds = set()
    for name in names:
        s = by_name[name]
        kinds.add(s["test"]["kind"])
        kwargs, flags = drop_case(s)
        expected = cli_json("drop", *flags, "--standard", name, "--format", "json")
        d = bouncelab.drop(standard=name, **kwargs)
        rows = expected.pop("bounces")
        same({k: v for k, v in d.items() if k != "bounces"}, expected, name)
        same({k: list(v) for k, v in d["bounces"].items()},
             {k: [r[k] for r in rows] for k in rows[0]}, name)
    assert kinds == {"drop", "cor", "static", "pressure-loss"}, kinds


def test_the_static_and_the_leak_verdicts_say_what_they_judged():
    d = bouncelab.drop(preset="tennis", standard="itf-deformation", bounces=1)
    v = d["standard"]
    assert v["name"] == "itf-deformation" and v["judged_at_height_m"] is None
    assert v["static"]["load_kg"] == 8.165 and v["verdict"] in ("pass", "fail")
    d = bouncelab.drop(preset="football", standard="fifa-pressure-loss", half_life="300h",
                       bounces=1)
    p = d["pressure_loss"]
    assert "standard" not in d and p["name"] == "fifa-pressure-loss"
    assert abs(p["lost"] - (1 - 2 ** (-72 / 300))) < 1e-12 and p["verdict"] == "pass"
    # the ball dropped is the one after the test's 72 h at 0.8 bar, 20 °C
    assert d["conditions"]["temperature_c"] == 20.0
    with pytest.raises(ValueError, match="half_life="):
        bouncelab.drop(preset="football", standard="fifa-pressure-loss")
    with pytest.raises(ValueError, match="give only half_life="):
        bouncelab.drop(preset="football", standard="fifa-pressure-loss", half_life="300h",
                       temperature=5.0)


def test_another_sports_ball_is_warned_and_keeps_its_own_conditions():
    # the newcomer trial of 2026-12-07: the tennis ball ran at FIBA's 8 psi, unwarned
    d = bouncelab.drop(preset="tennis", standard="fiba", bounces=1)
    said = [w for w in d["warnings"] if w.startswith("not the standard's ball: ")]
    assert said and said[0].startswith(
        "not the standard's ball: the fiba test drops basketball; this is tennis: "), said
    assert d["conditions"]["pressure_gauge_pa"] == 82737.09
    r = bouncelab.batch(LOT7, preset="tennis", standard="softball-47")
    assert "not the standard's ball: the softball-47 test fires softball; this is tennis: the " \
        "verdict judges another ball by this test" in r["warnings"]
    assert not [w for w in bouncelab.batch(LOT7, preset="tennis")["warnings"]
                if w.startswith("not the standard's ball")]
