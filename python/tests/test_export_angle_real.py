"""`peers --export lammps --angle θ --spin ω` runs in the real LAMMPS (issue 52 item 8,
docs/peers.md §5 "The case asked").

The export is asked for the bounce itself — speed v, angle θ, spin ω — not for its normal
speed: it calibrates the normal contact at v·sinθ, and states bouncelab's own answer for the
bounce at LAMMPS's κ (a solid sphere, 0.4). Pasted as it is into an input with one sphere
arriving at that angle and spin (test_oblique_exports_real.py's), a bounce that slides
throughout must give that answer: the normal rebound to the COR's tolerance (0.002), the
change of v_x and ω to 1e-3 of itself (μ times the normal impulse, whatever F_n's shape).

Skipped without the codes unless BOUNCELAB_REQUIRE_CODES=1 (test_exports_real.py).
"""

import json
import math

from test_oblique_exports_real import bouncelab, lammps_oblique
from test_exports_real import header


def test_the_angle_export_gives_its_own_answer_in_lammps():
    v, angle, spin, mu = 20.0, 10.0, -200.0, 0.2
    args = ["peers", "--preset", "tennis", "--target", "christoforou-yigit", "--v0", repr(v),
            "--angle", repr(angle), "--spin", repr(spin), "--friction", repr(mu)]
    case = json.loads(bouncelab(*args, "--export", "json"))["case"]
    snippet = bouncelab(*args, "--export", "lammps")
    theta = math.radians(angle)
    vx, vy = v * math.cos(theta), v * math.sin(theta)
    assert abs(case["normal_speed"] - vy) < 1e-12 * vy
    assert "v·sinθ" in snippet and "κ = I/(m R²) = 0.4" in snippet
    lines = snippet.splitlines()
    timestep = next(l for l in lines if l.startswith("timestep "))
    fix = next(l for l in lines if l.startswith("fix kvclipt "))
    # the comment says v·sinθ to six figures for a reader; the JSON case holds it whole
    mass, radius, v0 = header(snippet)
    assert abs(v0 - vy) < 5e-6 * vy, (v0, vy)
    vx_out, w_out, vz_out = lammps_oblique(timestep, fix, mass, radius, vx, vy, spin)
    a = case["answer"]
    assert a["inertia_factor"] == 0.4
    assert abs(vz_out / vy - a["cor_normal"]) < 0.002, (vz_out / vy, a["cor_normal"])
    dvx, dw = a["vx_out"] - vx, a["spin_out"] - spin
    print(f"bouncelab at κ 0.4: Δv_x {dvx:.5f}, Δω {dw:.3f}; "
          f"LAMMPS: Δv_x {vx_out - vx:.5f}, Δω {w_out - spin:.3f}")
    assert abs((vx_out - vx) - dvx) < 1e-3 * abs(dvx), (vx_out, a["vx_out"])
    assert abs((w_out - spin) - dw) < 1e-3 * abs(dw), (w_out, a["spin_out"])
