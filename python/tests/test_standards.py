"""bouncelab.standards(): the list `bouncelab standards --format json` writes, which
batch's and drop's messages send the user to. Before, batch's error named
`bouncelab.standards()`, which did not exist (AttributeError)."""

import re
from pathlib import Path

import pytest

import bouncelab
from test_bouncelab import cli_json, no_user_presets, same  # noqa: F401

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
