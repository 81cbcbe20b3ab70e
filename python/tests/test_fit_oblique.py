"""bouncelab.fit_oblique: μ and K_t (and κ with spins) from oblique bounces, the same document
as ``bouncelab fit --oblique FILE --format json``, and bad input refused naming the cell."""

import json
import math
import subprocess

import numpy as np
import pytest
from cli_binary import as_package, binary

import bouncelab


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path, monkeypatch):
    """Both the binary and the package read $XDG_CONFIG_HOME/bouncelab/presets: an empty one."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))

# the fit starts from the tennis preset's Mindlin K_t (K_p = 49427 N/m, ν = 0.5: 2/3 K_p =
# 32951 N/m) and the rows' largest apparent friction; the truth is away from both
MU, KT = 0.45, 1.3e4


def bounces(cases=None, mu=MU, kt=KT, spins=False, seed=1, sd=0.0):
    """Synthetic bounces of the tennis ball at (v0, angle, spin) `cases`, by default low angles
    that slide throughout (they show μ) and steep ones that grip (they show K_t)."""
    if cases is None:
        cases = [(15.0 + 2.0 * k, angle, spin)
                 for k, angle in enumerate([8.0, 12.0, 16.0, 25.0, 35.0, 45.0, 55.0, 65.0, 75.0])
                 for spin in [-200.0, 0.0, 250.0]]
    rng = np.random.default_rng(seed)
    cols = {k: [] for k in ["v0", "angle_deg", "spin_in", "vx_out", "vy_out", "spin_out"]}
    for v0, angle, spin in cases:
        r = bouncelab.oblique("tennis", v0=v0, angle=angle, spin=spin, friction=mu,
                              tangential_stiffness=kt)
        cols["v0"].append(v0)
        cols["angle_deg"].append(angle)
        cols["spin_in"].append(spin)
        cols["vx_out"].append(r.vx_out + sd * rng.standard_normal())
        cols["vy_out"].append(r.vy_out)
        cols["spin_out"].append(r.spin_out + 10 * sd * rng.standard_normal())
    if not spins:
        del cols["spin_out"]
    return cols


def write_csv(path, cols):
    names = list(cols)
    lines = [",".join(names)]
    for i in range(len(cols["v0"])):
        lines.append(",".join(repr(cols[n][i]) for n in names))
    path.write_text("\n".join(lines) + "\n")


def test_recovers_mu_and_k_t_from_arrays():
    f = bouncelab.fit_oblique(preset="tennis", **bounces())
    assert f["identified"] and f["converged"], f
    assert f["free"] == ["friction", "tangential_stiffness"]
    assert math.isclose(f["friction"], MU, rel_tol=1e-5), f["friction"]
    assert math.isclose(f["tangential_stiffness"], KT, rel_tol=1e-4), f["tangential_stiffness"]
    assert f["fitted"]["friction"]["value"] == f["friction"]
    assert f["file"] is None and f["rms_spin"] is None


def test_recovers_mu_k_t_and_kappa_with_spins():
    f = bouncelab.fit_oblique(preset="tennis", **bounces(spins=True))
    assert f["free"] == ["friction", "tangential_stiffness", "inertia_factor"]
    assert f["identified"], f
    for name, truth in [("friction", MU), ("tangential_stiffness", KT), ("inertia_factor", 0.6105)]:
        assert math.isclose(f[name], truth, rel_tol=1e-4), (name, f[name], truth)
    assert f["rms_spin"] is not None


def test_noisy_bounces_are_recovered_to_a_percent():
    # 0.03 m/s of noise on v_x,out (the interval's coverage is tests/analysis/fit_oblique.rs's)
    f = bouncelab.fit_oblique(preset="tennis", **bounces(sd=0.03, seed=7))
    assert f["identified"], f
    for name, truth in [("friction", MU), ("tangential_stiffness", KT)]:
        assert math.isclose(f[name], truth, rel_tol=0.01), (name, f[name], truth)


def test_the_same_document_as_the_command_line(tmp_path):
    path = tmp_path / "bounces.csv"
    write_csv(path, bounces())
    f = bouncelab.fit_oblique(path, preset="tennis")
    out = subprocess.run([binary(), "fit", "--preset", "tennis", "--oblique", str(path), "--format", "json"],
                         check=True, capture_output=True, text=True)
    assert f == as_package(json.loads(out.stdout))
    # the arrays give the same fit: only `file` differs
    g = bouncelab.fit_oblique(preset="tennis", **bounces())
    assert {**g, "file": str(path)} == f


def test_an_unfittable_set_is_refused():
    # low angles with backspin slide throughout: K_t leaves no trace in the outgoing motion
    # (as bounces_that_only_slide_cannot_pin_k_t, tests/analysis/fit_oblique.rs)
    sliding = bounces([(25.0, a, -300.0) for a in [5.0, 7.0, 9.0, 11.0, 13.0, 15.0]], mu=0.2,
                      kt=16475.0, sd=0.02, seed=5)
    f = bouncelab.fit_oblique(preset="tennis", **sliding)
    assert not f["identified"]
    assert "tangential_stiffness" in f["not_pinned"]
    assert "friction" not in f["not_pinned"]
    cols = bounces()
    # one row cannot pin two parameters
    one = {k: v[:1] for k, v in cols.items()}
    with pytest.raises(ValueError, match="1 data point, fewer than the 2 parameters"):
        bouncelab.fit_oblique(preset="tennis", **one)


def test_bad_input_names_the_cell(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("v0,angle_deg,spin_in,vx_out,vy_out\n20,30,0,15,5\n20,95,0,15,5\n")
    with pytest.raises(ValueError, match=r"bad\.csv:3:4: angle_deg 95 must lie in \(0, 90\]"):
        bouncelab.fit_oblique(path, preset="tennis")
    cols = bounces()
    cols["angle_deg"][2] = 0.0
    with pytest.raises(ValueError, match=r"oblique row 2, angle_deg: angle_deg 0"):
        bouncelab.fit_oblique(preset="tennis", **cols)
    with pytest.raises(ValueError, match="vy_out is missing"):
        bouncelab.fit_oblique(preset="tennis", v0=[20.0], angle_deg=[30.0], spin_in=[0.0], vx_out=[15.0])
    with pytest.raises(ValueError, match="not both"):
        bouncelab.fit_oblique(path, preset="tennis", v0=[20.0])
    with pytest.raises(ValueError, match="differ in length"):
        bouncelab.fit_oblique(preset="tennis", **{**cols, "vx_out": cols["vx_out"][:3]})
