"""The conditions a ball runs at (issue 56, docs/cli.md "Conditions"): `run` and `drop` take
`pressure=` (Pa, or a string with its unit), `temperature=` and `inflated_at=` (°C) as the
command line's `--pressure`, `--temperature`, `--inflated-at`, and answer as it does."""

import pytest

import bouncelab
from test_bouncelab import cli_error, cli_json, no_user_presets, same  # noqa: F401


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


def test_the_conditions_hold_where_the_command_line_holds_them():
    # no time since inflation is the record's conditions: the comparison made, no warning
    r = bouncelab.run(preset="football", after="0h")
    assert r.comparison_withheld is None
    same(r.to_dict(), bouncelab.run(preset="football").to_dict())
    # beyond its shift's span, past the COR's minimum, the squash ball is refused; inside
    # the refusal's bound but outside the span, warned
    with pytest.raises(ValueError, match="invalid temperature: -50 .*COR's minimum"):
        bouncelab.run(preset="squash", temperature=-50.0)
    cold = bouncelab.run(preset="squash", temperature=23.0)
    assert any("outside the temperature shift's fitted span" in w for w in cold.warnings)
    # a refusal names the flag that caused it, as the command line's
    with pytest.raises(ValueError, match="invalid after: .*leaked flat"):
        bouncelab.run(preset="football", after="1e30d")
    with pytest.raises(ValueError, match="invalid inflated-at: 30 .*give --temperature too"):
        bouncelab.run(preset="tennis", inflated_at=30.0)
    with pytest.raises(ValueError, match="invalid temperature: 45 .*--damping"):
        bouncelab.run(preset="squash", temperature=45.0, damping=10.0)


def test_zeta_beside_a_temperature_that_shifts_c_is_refused_as_the_command_line():
    # the command line refuses `--temperature 30 --zeta 0.2` on the squash ball (ζ sets c,
    # which the temperature shifts); `run` ran it on the ζ's c, the shift dropped
    message = cli_error("run", "--preset", "squash", "--temperature", "30", "--zeta", "0.2")
    assert message.startswith("invalid temperature: 30 (--zeta sets c too"), message
    with pytest.raises(ValueError) as e:
        bouncelab.run(preset="squash", temperature=30.0, zeta=0.2)
    assert str(e.value) == message
    # each alone runs, and ζ beside a temperature on a ball without a shift too
    assert bouncelab.run(preset="squash", zeta=0.2).zeta == pytest.approx(0.2, rel=1e-12)
    bouncelab.run(preset="squash", temperature=30.0)
    bouncelab.run(preset="football", temperature=5.0, zeta=0.2)
