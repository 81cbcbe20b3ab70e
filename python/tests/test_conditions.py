"""The conditions a ball runs at (issue 56, docs/cli.md "Conditions"): `run` and `drop` take
`pressure=` (Pa, or a string with its unit), `temperature=` and `inflated_at=` (°C) as the
command line's `--pressure`, `--temperature`, `--inflated-at`, and answer as it does."""

import pytest

import bouncelab
from test_bouncelab import cli_json, no_user_presets, same  # noqa: F401


def test_run_takes_the_pressure_and_temperature_as_the_command_line():
    r = bouncelab.run(preset="football", pressure="0.6bar", temperature=5.0)
    want = cli_json(
        "run", "--preset", "football", "--pressure", "0.6bar", "--temperature", "5",
        "--format", "json",
    )
    same(r.to_dict(), want)
    # a number is pascals, and the nominal moves nothing
    assert bouncelab.run(preset="football", pressure=60000.0, temperature=5.0).cor == r.cor
    assert bouncelab.run(preset="football", pressure=80000.0).cor == bouncelab.run(
        preset="football"
    ).cor


def test_a_basketball_passes_fiba_at_8_psi_and_fails_at_4():
    for psi, verdict in [("8psi", "pass"), ("4psi", "fail")]:
        d = bouncelab.drop(preset="basketball", standard="fiba", pressure=psi)
        want = cli_json(
            "drop", "--preset", "basketball", "--standard", "fiba", "--pressure", psi,
            "--format", "json",
        )
        same(d["standard"], want["standard"])
        assert d["standard"]["verdict"] == verdict


def test_a_solid_ball_refuses_a_pressure_naming_it():
    with pytest.raises(ValueError, match="invalid pressure.*superball is not inflated"):
        bouncelab.run(preset="superball", pressure="1bar")
    with pytest.raises(ValueError, match="invalid pressure"):
        bouncelab.run(preset="football", pressure="0.8 bars")
