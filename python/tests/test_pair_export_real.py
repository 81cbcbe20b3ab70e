"""A pair export runs in the real LAMMPS as two balls (issue 52 item 8, docs/peers.md §5 "The
case asked").

`peers --pair PRESET --v0 V --export lammps` writes the wall template for the pair's
relative motion (one particle of m_eff against the flat). Its Kelvin-Voigt line (`hooke`,
`damping velocity`: F = k δ + η δ̇, no mass in it) is also the pair's contact between two real
particles of masses m1 and m2, whose relative coordinate has the mass m_eff: pasted as
`pair_coeff`, two tennis balls closing at V must part with the pair's COR at V — `collide
--target-preset`'s, both balls deforming — to the exports' tolerance (0.002). An export made
at the preset's own speed (no --v0) and run at 30 m/s misses that COR by the change of the
pair's COR with speed (0.772 at 6.9 m/s against 0.690 at 30: a rebound some 2.5 m/s off),
which is why the export now states its closing speed and warns without --v0.

Skipped without the codes unless BOUNCELAB_REQUIRE_CODES=1 (test_exports_real.py).
"""

import json
import math
import subprocess

from cli_binary import binary

from test_exports_real import need


def run(*args):
    return subprocess.run([binary(), *args], check=True, capture_output=True, text=True)


def two_balls(export, mass, radius, closing):
    """The relative COR of two equal spheres closing head-on at `closing` m/s in LAMMPS, with
    the hooke model of `export` (the text of a pair export) as their pair contact, at its
    timestep."""
    lammps = need("lammps")
    lines = export.splitlines()
    timestep = next(l for l in lines if l.startswith("timestep "))
    words = next(l for l in lines if l.startswith("fix kv ")).split()
    k, eta = words[6], words[7]
    h = float(timestep.split()[1])
    gap = 2.3 * closing * h
    density = mass / (4 / 3 * math.pi * radius**3)
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    lmp.commands_string(
        f"""units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single 0 0 {-(radius + gap / 2)!r}
create_atoms 1 single 0 0 {radius + gap / 2!r}
set atom * diameter {2 * radius!r}
set atom * density {density!r}
velocity all set 0 0 0
set atom 1 vz {closing / 2!r}
set atom 2 vz {-closing / 2!r}
pair_style granular
pair_coeff * * hooke {k} {eta} tangential linear_nohistory 0.0 0.0 damping velocity
comm_modify vel yes
neighbor {radius!r} bin
fix integrate all nve/sphere
{timestep}
"""
    )
    try:
        touched = False
        for _ in range(1_000_000):
            lmp.command("run 1 pre no post no")
            x, v = lmp.extract_atom("x"), lmp.extract_atom("v")
            apart = x[1][2] - x[0][2]
            parting = v[1][2] - v[0][2]
            touched |= apart < 2 * radius
            if touched and apart > 2 * radius and parting > 0:
                return parting / closing
        raise AssertionError("the balls never parted")
    finally:
        lmp.close()


def export_at(closing):
    args = ["peers", "--preset", "tennis", "--pair", "tennis", "--export", "lammps"]
    if closing is not None:
        args += ["--v0", repr(closing)]
    return run(*args)


def test_a_pair_export_gives_the_pairs_cor_at_its_closing_speed():
    closing = 30.0
    ball = json.loads(run("run", "--preset", "tennis", "--format", "json").stdout)["ball"]
    pair = json.loads(run("collide", "--preset", "tennis", "--target-preset", "tennis",
                          "--v0", repr(closing), "--format", "json").stdout)["cor"]
    at = export_at(closing)
    assert "the pair's closing speed at v = 30 m/s" in at.stdout
    e = two_balls(at.stdout, ball["mass"], ball["radius"], closing)
    print(f"two tennis balls at {closing} m/s in LAMMPS: e {e:.5f}, the pair's {pair:.5f}")
    assert abs(e - pair) < 0.002, (e, pair)
    # made at the preset's speed, the export warns, and misses at 30 m/s
    old = export_at(None)
    assert "the pair export is calibrated at the closing speed" in old.stderr
    e_old = two_balls(old.stdout, ball["mass"], ball["radius"], closing)
    print(f"the export at the preset's speed: e {e_old:.5f}, "
          f"{(e_old - pair) * closing:+.2f} m/s off at {closing} m/s")
    assert abs(e_old - pair) * closing > 1.0
