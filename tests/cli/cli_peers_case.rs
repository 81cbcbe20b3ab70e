//! `peers --export … --angle θ [--spin ω]` (issue 52 item 8, docs/peers.md §5 "The case
//! asked"): the export is calibrated at the normal speed v·sinθ (its `v0` and its target
//! COR are `run`'s there), states the code's κ against the ball's, and gives bouncelab's own
//! answer for the bounce at the code's κ — `oblique --inertia-factor 0.4`'s, to the digit.

use crate::common;

use common::*;
use serde_json::Value;

fn export(extra: &[&str]) -> Value {
    let mut args = argv("peers --preset tennis --target christoforou-yigit --export json");
    args.extend(extra);
    let o = bl(&args);
    assert_eq!(o.code, 0, "{}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

fn close(a: f64, b: f64, rel: f64) {
    assert!((a - b).abs() <= rel * b.abs().max(1e-12), "{a} against {b}");
}

#[test]
fn an_oblique_export_is_calibrated_at_the_normal_speed() {
    let v = export(&argv("--v0 30 --angle 16 --spin 50 --friction 0.6"));
    let vn = 30.0 * 16f64.to_radians().sin();
    close(f(&v, "v0"), vn, 1e-15);
    // the target: the Christoforou–Yigit COR at v·sinθ, not at v
    let run = bl(&argv_with(
        "run --preset tennis --v0 {} --format json",
        &[&vn.to_string()],
    ));
    let run: Value = serde_json::from_str(&run.stdout).unwrap();
    close(f(&v, "target_cor"), f(&run, "cor"), 1e-12);
    let at_v = bl(&argv("run --preset tennis --v0 30 --format json"));
    let at_v: Value = serde_json::from_str(&at_v.stdout).unwrap();
    assert!((f(&v, "target_cor") - f(&at_v, "cor")).abs() > 0.01, "{v}");
    let case = &v["case"];
    assert_eq!(f(case, "speed"), 30.0);
    assert_eq!(f(case, "angle_deg"), 16.0);
    assert_eq!(f(case, "spin"), 50.0);
    assert_eq!(f(case, "inertia_factor_code"), 0.4);
    assert_eq!(
        f(case, "inertia_factor_ball"),
        f(&v_ball(), "inertia_factor")
    );
    // bouncelab's own answer at the code's κ: `oblique`'s for the same bounce
    let ob = |kappa: Option<&str>| -> Value {
        let mut args = argv(
            "oblique --preset tennis --v0 30 --angle 16 --spin 50 --friction 0.6 --format json",
        );
        if let Some(k) = kappa {
            args.extend(["--inertia-factor", k]);
        }
        serde_json::from_str(&bl(&args).stdout).unwrap()
    };
    let (code, own) = (ob(Some("0.4")), ob(None));
    let a = &case["answer"];
    for key in ["vx_out", "vy_out", "spin_out", "cor_normal"] {
        close(f(a, key), f(&code, key), 1e-12);
    }
    close(f(a, "spin_out_ball_kappa"), f(&own, "spin_out"), 1e-12);
    close(f(a, "vx_out_ball_kappa"), f(&own, "vx_out"), 1e-12);
    assert!((f(a, "spin_out") - f(&own, "spin_out")).abs() > 10.0, "{a}");
}

fn v_ball() -> Value {
    json(&["run", "--preset", "tennis", "--format", "json"])["ball"].clone()
}

#[test]
fn every_snippet_states_the_case_and_the_codes_kappa() {
    for code in ["lammps", "liggghts", "chrono", "yade", "mujoco"] {
        let o = bl(&argv_with(
            "peers --preset tennis --export {} --v0 30 --angle 16",
            &[code],
        ));
        assert_eq!(o.code, 0, "{code}: {}", o.stderr);
        let s = &o.stdout;
        assert!(s.contains("the normal speed v·sinθ = 8.269"), "{code}: {s}");
        assert!(
            s.contains("κ = I/(m R²) = 0.4; this ball's κ = 0.6105"),
            "{code}: {s}"
        );
        assert!(
            s.contains("bouncelab for this bounce at κ = 0.4"),
            "{code}: {s}"
        );
    }
    // head-on, without --angle: at v, and said to hold there only
    let s = ok_calibrated(&["peers", "--preset", "tennis", "--export", "lammps"]);
    assert!(
        s.contains("head-on: the COR holds at this speed only"),
        "{s}"
    );
    assert!(s.contains("κ = I/(m R²) = 0.4"), "{s}");
}

#[test]
fn a_pair_export_says_its_closing_speed() {
    let o = bl(&argv(
        "peers --preset tennis --pair tennis --v0 30 --export json",
    ));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let v: Value = serde_json::from_str(&o.stdout).unwrap();
    let case = &v["case"];
    assert_eq!(case["pair"], "tennis");
    assert_eq!(f(case, "speed"), 30.0);
    // the pair's COR at its closing speed: `collide --target-preset`'s
    let c = bl(&argv(
        "collide --preset tennis --target-preset tennis --v0 30 --format json",
    ));
    let c: Value = serde_json::from_str(&c.stdout).unwrap();
    close(f(&v, "target_cor"), f(&c, "cor"), 1e-12);
    close(f(&case["answer"], "vy_out"), 30.0 * f(&c, "cor"), 1e-12);
    let o = bl(&argv(
        "peers --preset tennis --pair tennis --v0 30 --export lammps",
    ));
    assert!(
        o.stdout.contains("the pair's closing speed at v = 30 m/s"),
        "{}",
        o.stdout
    );
    assert!(
        !o.stderr.contains("the pair export is calibrated"),
        "{}",
        o.stderr
    );
    // without --v0 the pair export holds at the preset's speed, and says so on stderr
    let o = bl(&argv("peers --preset tennis --pair tennis --export lammps"));
    assert_eq!(o.code, 0, "{}", o.stderr);
    assert!(
        o.stderr
            .contains("the pair export is calibrated at the closing speed 6.906 m/s"),
        "{}",
        o.stderr
    );
}

#[test]
fn the_case_is_checked() {
    bad(
        &["peers", "--preset", "tennis", "--angle", "16"],
        &["--export"],
    );
    bad(
        &argv("peers --preset tennis --export lammps --angle 0"),
        &["invalid angle"],
    );
    bad(
        &argv("peers --preset tennis --export lammps --angle 91"),
        &["invalid angle"],
    );
    bad(
        &argv("peers --preset tennis --export lammps --spin 10"),
        &["--spin needs --angle"],
    );
}

/// The e_y a snippet states (`… (e_y = 0.760977)`), or the JSON case's.
fn stated_e_y(code: &str, out: &str) -> f64 {
    if code == "json" {
        let v: Value = serde_json::from_str(out).unwrap();
        return f(&v["case"]["answer"], "cor_normal");
    }
    let at = out
        .find("(e_y = ")
        .unwrap_or_else(|| panic!("{code}: {out}"))
        + 7;
    let n = &out[at..];
    n[..n.find(')').unwrap()].parse().unwrap()
}

/// Issue 52 item 8, a new user's trial: the same bounce (tennis at 30 m/s and 16°) had two
/// "bouncelab answers": e_y 0.770900 — the measured COR, taken at 6.906 m/s — without
/// `--friction`, `oblique`'s 0.760977 with it. The export is now calibrated to the model's COR
/// at the normal speed and states the model's answer, `oblique`'s e_y to the printed digits,
/// for every code, with and without `--friction`.
#[test]
fn the_stated_answer_is_obliques_with_and_without_friction() {
    let oblique = |mu: &str| {
        let v = json(&argv_with(
            "oblique --preset tennis --v0 30 --angle 16 --friction {} --inertia-factor 0.4 --format json",
            &[mu],
        ));
        f(&v, "cor_normal")
    };
    let e_y = oblique("0");
    assert!((e_y - oblique("0.6")).abs() < 1e-12, "{e_y}");
    for code in ["lammps", "liggghts", "chrono", "yade", "mujoco", "json"] {
        let frictions: &[&[&str]] = match code {
            "lammps" | "mujoco" | "json" => &[&[], &["--friction", "0.6"]],
            _ => &[&[]],
        };
        for friction in frictions {
            let mut args = argv_with(
                "peers --preset tennis --v0 30 --angle 16 --export {}",
                &[code],
            );
            args.extend(*friction);
            let o = bl(&args);
            assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
            let stated = stated_e_y(code, &o.stdout);
            // six significant digits printed: within half the last one
            assert!(
                (stated - e_y).abs() <= 5e-7,
                "{args:?}: e_y {stated}, oblique's {e_y}"
            );
            // calibrated to it: the code's bounce is bouncelab's, so no second COR is said
            assert!(!o.stdout.contains("is not bouncelab's e_y"), "{args:?}");
            assert!(!o.stderr.contains("measured at"), "{args:?}: {}", o.stderr);
        }
    }
    let v: Value = serde_json::from_str(&ok_calibrated(&argv(
        "peers --preset tennis --v0 30 --angle 16 --export json",
    )))
    .unwrap();
    assert!((f(&v, "target_cor") - e_y).abs() <= 5e-7, "{v}");
}

/// A target of the user's (`--cor`, `--target measured`) is calibrated to as asked, and the
/// snippet says both it and bouncelab's answer, which stays the model's.
#[test]
fn a_users_target_is_said_beside_the_models_answer() {
    for target in ["--cor 0.7", "--target measured"] {
        for code in ["yade", "lammps"] {
            let line = format!("peers --preset tennis --v0 30 --angle 16 {target} --export {code}");
            let o = bl(&argv(&line));
            assert_eq!(o.code, 0, "{line}: {}", o.stderr);
            let want = if target.contains("cor") {
                "0.7"
            } else {
                "0.7709"
            };
            assert!(
                o.stdout.contains(&format!("target COR {want}")),
                "{line}: {}",
                o.stdout
            );
            assert!(
                o.stdout.contains("is not bouncelab's e_y = 0.760977"),
                "{line}: {}",
                o.stdout
            );
            assert!(
                o.stdout.contains("(e_y = 0.760977)"),
                "{line}: {}",
                o.stdout
            );
        }
    }
}
