//! Each exported snippet, read back as the code would read it: the numbers are parsed from
//! the text, turned into the force law with the code's own formulas (written out here from
//! the codes' sources, not taken from src/peers/), and the COR is recomputed
//! (src/peers/export.rs; docs/peers.md §5).

use bouncelab::peers::export::{Code, ExportSet, snippet};
use bouncelab::peers::{PeerBall, PeerModel, cor};
use std::f64::consts::PI;

fn ball() -> PeerBall {
    // the golf ball's adopted set (docs/model.md §7)
    PeerBall {
        mass: 0.0456,
        radius: 0.02075,
        v0: 1.47,
        k: 5.6e5,
        k_h: 5.6e5 / (1.5 * 3.0e-3f64.sqrt()),
    }
}

/// The numbers after `key` on the first line containing `line_has` (and not `not`).
fn numbers_after(text: &str, line_has: &str, not: &str, key: &str, n: usize) -> Vec<f64> {
    let line = text
        .lines()
        .find(|l| {
            l.contains(line_has) && (not.is_empty() || !l.contains(not)) && !l.starts_with('#')
        })
        .unwrap_or_else(|| panic!("no line with {line_has:?} in\n{text}"));
    let rest = &line[line
        .find(key)
        .unwrap_or_else(|| panic!("{key:?} in {line}"))
        + key.len()..];
    rest.split(|c: char| c.is_whitespace() || c == ',' || c == ')' || c == '"' || c == '(')
        .filter(|s| !s.is_empty())
        .take(n)
        .map(|s| s.parse().unwrap_or_else(|_| panic!("{s:?} in {line}")))
        .collect()
}

/// β = |ln e| / √(ln² e + π²), as LAMMPS, LIGGGHTS and Chrono compute it.
fn beta(e: f64) -> f64 {
    let l = e.ln();
    -l / (l * l + PI * PI).sqrt()
}

fn close(e: f64, target: f64, what: &str) {
    assert!(
        (e - target).abs() < 1e-9,
        "{what}: COR {e} for target {target}"
    );
}

#[test]
fn lammps_snippet_gives_the_target() {
    let b = ball();
    for target in [0.3, 0.84] {
        let s = ExportSet::new(&b, target, "golf").unwrap();
        let t = snippet(Code::Lammps, &s);
        // hooke k_n damp, damping velocity: F = k_n δ + damp δ̇
        let kv = numbers_after(&t, "granular hooke", "limit_damping", "hooke", 2);
        assert_eq!(kv[0], b.k);
        let zeta = kv[1] / (2.0 * (b.mass * kv[0]).sqrt());
        close(cor(PeerModel::KelvinVoigt, zeta).unwrap(), target, "hooke");
        let clip = numbers_after(&t, "limit_damping zplane", "hertz", "hooke", 2);
        let zeta = clip[1] / (2.0 * (b.mass * clip[0]).sqrt());
        close(
            cor(PeerModel::KelvinVoigtNoTension, zeta).unwrap(),
            target,
            "hooke clipped",
        );
        // hertz k_n e: F = k_n √(R δ) δ; coeff_restitution: η = √(3/2)·2√(5/6) β √(m k_n a)
        let h = numbers_after(&t, "granular hertz", "", "hertz", 2);
        let k_h = h[0] * b.radius.sqrt();
        assert!((k_h - b.k_h).abs() < 1e-9 * b.k_h);
        let damp = 1.224_744_871_391_589 * 1.825_741_858_350_553_8 * beta(h[1]);
        close(cor(PeerModel::Tsuji, damp).unwrap(), target, "hertz");
    }
}

#[test]
fn liggghts_and_chrono_snippets_give_the_target() {
    let b = ball();
    let s = ExportSet::new(&b, 0.84, "golf").unwrap();
    for code in [Code::Liggghts, Code::Chrono] {
        let t = snippet(code, &s);
        let (y, nu) = if code == Code::Liggghts {
            (
                numbers_after(&t, "youngsModulus", "", "peratomtype", 1)[0],
                numbers_after(&t, "poissonsRatio", "", "peratomtype", 1)[0],
            )
        } else {
            (
                numbers_after(&t, "SetYoungModulus", "", "(", 1)[0],
                numbers_after(&t, "SetPoissonRatio", "", "(", 1)[0],
            )
        };
        // two equal materials: Y* = 1/((1−ν²)/Y + (1−ν²)/Y); k_n = (4/3) Y* √(R δ)
        let y_star = y / (2.0 * (1.0 - nu * nu));
        let k_h = 4.0 / 3.0 * y_star * b.radius.sqrt();
        assert!((k_h - b.k_h).abs() < 1e-9 * b.k_h, "{code:?}");
        // γ_n = 2√(5/6) β √(S_n m), S_n = 2 Y* √(R δ): η = γ_n / δ^{1/4}
        let e_in = if code == Code::Liggghts {
            numbers_after(&t, "coefficientRestitution", "", "peratomtypepair 2", 1)[0]
        } else {
            let line = t
                .lines()
                .find(|l| l.contains("// mat->SetRestitution"))
                .unwrap();
            line.split(['(', ')']).nth(1).unwrap().parse().unwrap()
        };
        let eta = 2.0
            * (5.0f64 / 6.0).sqrt()
            * beta(e_in)
            * (2.0 * y_star * b.radius.sqrt() * b.mass).sqrt();
        let alpha = eta / (b.mass * k_h).sqrt();
        close(cor(PeerModel::Tsuji, alpha).unwrap(), 0.84, "hertz");
    }
    // Chrono's Flores: γ_n = 8(1 − c_r) k_n δ / (5 c_r v), so χ = 8(1 − c_r)/(5 c_r)
    let t = snippet(Code::Chrono, &s);
    let line = t
        .lines()
        .find(|l| l.starts_with("mat->SetRestitution"))
        .unwrap();
    let cr: f64 = line.split(['(', ')']).nth(1).unwrap().parse().unwrap();
    let chi = 8.0 * (1.0 - cr) / (5.0 * cr);
    close(cor(PeerModel::HuntCrossley, chi).unwrap(), 0.84, "flores");
}

#[test]
fn yade_and_mujoco_snippets_give_the_target() {
    let b = ball();
    let s = ExportSet::new(&b, 0.49, "golf").unwrap();
    // YADE: both materials kn, cn; the contact takes 1/(1/a + 1/b) of each
    let t = snippet(Code::Yade, &s);
    let kn = numbers_after(&t, "ViscElMat(", "", "kn=", 1)[0] / 2.0;
    let cn = numbers_after(&t, "ViscElMat(", "", "cn=", 1)[0] / 2.0;
    assert_eq!(kn, b.k);
    let zeta = cn / (2.0 * (b.mass * kn).sqrt());
    close(
        cor(PeerModel::KelvinVoigtNoTension, zeta).unwrap(),
        0.49,
        "yade",
    );
    // MuJoCo direct solref at d = dmin = dmax: a = −damping v − stiffness r, per unit mass
    let t = snippet(Code::Mujoco, &s);
    let sol = numbers_after(&t, "<geom", "", "solref=\"", 2);
    let imp = numbers_after(&t, "<geom", "", "solimp=\"", 2);
    assert_eq!(imp[0], imp[1]);
    let (stiffness, damping) = (-sol[0], -sol[1]);
    let mass = numbers_after(&t, "<geom", "", "mass=\"", 1)[0];
    assert!((stiffness * mass - b.k).abs() < 1e-9 * b.k);
    let zeta = damping / (2.0 * stiffness.sqrt());
    close(
        cor(PeerModel::KelvinVoigtNoTension, zeta).unwrap(),
        0.49,
        "mujoco",
    );
    // well-formed XML (comments without "--" inside) once put in a document
    let doc = format!("<mujoco><worldbody>{t}</worldbody></mujoco>");
    roxmltree::Document::parse(&doc).unwrap_or_else(|e| panic!("{e}: {t}"));
}

/// A COR so low that the log-decrement rule of a Hertz code cannot reach the exact damping:
/// the snippet says so instead of writing a wrong number.
#[test]
fn unreachable_rule_inputs_are_said() {
    let s = ExportSet::new(&ball(), 0.05, "golf").unwrap();
    let t = snippet(Code::Liggghts, &s);
    assert!(t.contains("not representable"), "{t}");
    assert!(!t.contains("coefficientRestitution peratomtypepair"), "{t}");
}

/// The MuJoCo comment's contact time is the clipped Kelvin–Voigt one, 2 arccos ζ / ω_d
/// (docs/peers.md §3), not the undamped half-period π/ω, and the advised step is that time
/// over a whole number of steps; the geom carries `priority="1"` so the plane's solimp and
/// condim are not mixed in (python/tests/test_exports_real.py runs it in MuJoCo).
#[test]
fn mujoco_step_comes_from_the_clipped_contact_time() {
    let b = ball();
    for target in [0.3, 0.84] {
        let s = ExportSet::new(&b, target, "golf").unwrap();
        let t = snippet(Code::Mujoco, &s);
        let sol = numbers_after(&t, "<geom", "", "solref=\"", 2);
        let (omega, zeta) = ((-sol[0]).sqrt(), -sol[1] / (2.0 * (-sol[0]).sqrt()));
        let t_c = 2.0 * zeta.acos() / (omega * (1.0 - zeta * zeta).sqrt());
        let said = numbers_after(&t, "The contact lasts", "", "lasts", 1)[0];
        assert!((said - t_c).abs() < 1e-9 * t_c, "{said} vs {t_c}");
        let h = numbers_after(&t, "<option", "", "timestep=\"", 1)[0];
        let n = t_c / h;
        assert!((n - n.round()).abs() < 1e-6 && n >= 20.0, "t_c/h = {n}");
        assert!(t.contains("priority=\"1\" condim=\"1\""), "{t}");
    }
}

/// LAMMPS gets a `timestep` line (before the fixes it holds for).
#[test]
fn lammps_snippet_advises_a_timestep() {
    let s = ExportSet::new(&ball(), 0.5, "golf").unwrap();
    let t = snippet(Code::Lammps, &s);
    let h = numbers_after(&t, "timestep", "", "timestep", 1)[0];
    let t_c = PI * (ball().mass / ball().k).sqrt();
    assert!(h > 0.0 && h < t_c / 20.0, "{h}");
    assert_eq!(Some(h), s.lammps_timestep);
}
