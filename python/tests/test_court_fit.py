"""bouncelab.court(fit=FILE) is `bouncelab court --fit FILE` (issue 53 item 3): the measured
ITF court pace test bounces' mean μ_app and e, the court calibrated to them, and the CPR of
the means. Before, the package had no `fit` argument (TypeError)."""

import math

import pytest

import bouncelab
from test_bouncelab import cli_error, cli_json, no_user_presets, same  # noqa: F401

V_IN, ANGLE_IN = 30.0, 16.0


def bounce(mu, e):
    """(v_out, angle_out) of a ball at the ITF test leaving a court of μ_app `mu` and e `e`:
    v_y,out = e v_y,in, v_x,out = v_x,in − μ (v_y,in + v_y,out) (docs/oblique.md §6)."""
    a = math.radians(ANGLE_IN)
    vx, vy = V_IN * math.cos(a), V_IN * math.sin(a)
    vy_out = e * vy
    vx_out = vx - mu * (vy + vy_out)
    return math.hypot(vx_out, vy_out), math.degrees(math.atan2(vy_out, vx_out))


def write_bounces(path, pairs):
    rows = ["v_in,angle_in,v_out,angle_out"]
    for mu, e in pairs:
        v, angle = bounce(mu, e)
        rows.append(f"{V_IN},{ANGLE_IN},{v!r},{angle!r}")
    path.write_text("\n".join(rows) + "\n")
    return path


PAIRS = [(0.54, 0.71), (0.56, 0.69), (0.55, 0.70)]


def test_the_package_calibrates_as_the_command_line(tmp_path):
    f = write_bounces(tmp_path / "court.csv", PAIRS)
    expected = cli_json("court", "--preset", "tennis", "--fit", str(f), "--format", "json")
    d = bouncelab.court("tennis", fit=str(f))
    same(d, expected)
    # the keys the comparison rests on are there and say what was measured
    m = d["measured"]
    assert m["file"] == "court.csv" and m["bounces"] == 3
    assert abs(m["apparent_friction"] - 0.55) < 1e-12 and abs(m["cor_normal"] - 0.70) < 1e-12
    assert abs(m["cpr"] - (100 * (1 - 0.55) + 150 * (0.81 - 0.70))) < 1e-9
    assert d["friction"] == m["apparent_friction"]
    assert abs(d["calibration"]["cor"] - 0.70) < 1e-9
    assert d["surface"]["origin"].startswith(f"calibrated by court --fit {f} from ")


def test_a_pathlike_and_a_surface_with_its_stiffness(tmp_path):
    f = write_bounces(tmp_path / "clay.csv", PAIRS)
    expected = cli_json("court", "--preset", "tennis", "--fit", str(f), "--surface", "clay",
                        "--surface-stiffness", "2e5", "--format", "json")
    d = bouncelab.court("tennis", fit=f, surface={"name": "clay", "stiffness": 2e5})
    same(d, expected)
    assert d["calibration"]["stiffness"] == 2e5


def test_what_the_command_line_refuses_the_package_refuses(tmp_path):
    f = write_bounces(tmp_path / "court.csv", PAIRS)
    for kwargs in ({"friction": 0.5}, {"surface_cor": 0.7}):
        with pytest.raises(ValueError, match="fit measures"):
            bouncelab.court("tennis", fit=f, **kwargs)
    with pytest.raises(ValueError, match="damping"):
        bouncelab.court("tennis", fit=f, surface={"damping": 10.0})
    bad = tmp_path / "bad.csv"
    bad.write_text("v_in,angle_in,v_out,angle_out\n30,16,20,15\n30,95,20,15\n")
    said = cli_error("court", "--preset", "tennis", "--fit", str(bad))
    with pytest.raises(ValueError) as e:
        bouncelab.court("tennis", fit=bad)
    assert str(e.value) == said and f"{bad}:3:" in said, (str(e.value), said)
    # an e out of the court's reach is refused with the range, as on the command line
    f = write_bounces(tmp_path / "lively.csv", [(0.5, 0.95)])
    said = cli_error("court", "--preset", "tennis", "--fit", str(f))
    with pytest.raises(ValueError) as e:
        bouncelab.court("tennis", fit=f)
    assert str(e.value) == said


def test_the_default_ball_is_the_tests_ball():
    # `court` fired the superball when no ball was given; the ITF test's ball is the tennis
    # ball (issue 52's second trial), as `bouncelab court` without --preset fires
    expected = cli_json("court", "--surface", "clay", "--friction", "0.6", "--format", "json")
    assert expected["ball"]["name"] == "tennis"
    same(bouncelab.court(surface="clay", friction=0.6), expected)
