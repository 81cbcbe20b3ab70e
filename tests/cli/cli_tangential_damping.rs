//! `--tangential-damping` through the binary (docs/cli.md, docs/oblique.md §1, §9, §10): the
//! JSON keys it adds only when given, agreement with the library, the energy's dashpot term,
//! `court`, the LAMMPS export's x_gamma_t = c_t/η, `fit --oblique` fitting c_t, bad input.

use crate::common;
use bouncelab::Ball;
use bouncelab::api::ObliqueSpec;
use common::{argv, argv_with, bad, bl, f, file_with, json, ok};

const OBLIQUE: [&str; 11] = [
    "oblique",
    "--preset",
    "tennis",
    "--v0",
    "25",
    "--angle",
    "45",
    "--friction",
    "0.6",
    "--format",
    "json",
];

#[test]
fn oblique_json_names_the_dashpot_and_its_loss_only_when_given() {
    let plain = json(&OBLIQUE);
    assert!(plain.get("tangential_damping").is_none());
    assert!(plain["energy"].get("tangential_damping").is_none());
    let mut args = OBLIQUE.to_vec();
    args.extend(["--tangential-damping", "19"]);
    let v = json(&args);
    assert_eq!(f(&v, "tangential_damping"), 19.0);
    let loss = f(&v["energy"], "tangential_damping");
    assert!(loss > 0.0, "{loss}");
    assert!(f(&v["energy"], "residual") < 1e-12);
    // the library's answer, to the last bit
    let ball = Ball::from_preset("tennis").unwrap();
    let spec = ObliqueSpec {
        v: Some(25.0),
        angle_deg: 45.0,
        spin: 0.0,
        friction: 0.6,
        tangential_stiffness: None,
        inertia_factor: None,
    };
    let r = ball.oblique_damped(&spec, Some(19.0), 0).unwrap();
    // read from the text: serde_json's default parser may land one unit in the last place
    // off (9.210541943043001 read as 9.210541943043 with the tennis ball of issue 52); the
    // shortest round-trip text of an f64 is its own, so equal text is the same bits
    let text = bl(&args).stdout;
    for (key, x) in [("vx_out", r.vx_out), ("spin_out", r.spin_out)] {
        let want = format!("\"{key}\":{}", serde_json::to_string(&x).unwrap());
        assert!(text.contains(&want), "{want} not in {text}");
    }
    let ex = f(&v, "cor_tangential");
    // 0.264 with the tennis ball of issue 52 (within 0.1–0.2 before its K_p was read through
    // the static chain)
    assert!((0.2..0.3).contains(&ex), "{ex}");
    assert!(f(&plain, "cor_tangential") > 0.5);
}

#[test]
fn zero_damping_answers_as_none() {
    let plain = json(&OBLIQUE);
    let mut args = OBLIQUE.to_vec();
    args.extend(["--tangential-damping", "0"]);
    let v = json(&args);
    for key in ["vx_out", "spin_out", "cor_tangential", "grip_time"] {
        assert_eq!(f(&v, key), f(&plain, key), "{key}");
    }
}

#[test]
fn bad_damping_is_one_line_exit_2() {
    let mut args = OBLIQUE.to_vec();
    args.extend(["--tangential-damping", "-1"]);
    bad(&args, &["invalid tangential_damping: -1"]);
    bad(
        &argv("court --preset tennis --friction 0.6 --tangential-damping -2"),
        &["invalid tangential_damping: -2"],
    );
}

#[test]
fn court_takes_the_dashpot() {
    let args = argv("court --preset tennis --friction 0.2 --format json");
    let plain = json(&args);
    let mut with = args.to_vec();
    with.extend(["--tangential-damping", "19"]);
    let v = json(&with);
    assert_eq!(f(&v, "tangential_damping"), 19.0);
    assert!(plain.get("tangential_damping").is_none());
    // μ = 0.2 at 16° slides throughout: the dashpot does not move a bounce that never sticks
    assert!((f(&v, "cpr") - f(&plain, "cpr")).abs() < 1e-9);
}

#[test]
fn the_lammps_export_carries_x_gamma_t() {
    let args =
        argv("peers --preset tennis --export lammps --friction 0.6 --tangential-stiffness 15000");
    let plain = ok(&args);
    let mut with = args.to_vec();
    with.extend(["--tangential-damping", "19"]);
    let text = ok(&with);
    let eta: f64 = plain
        .lines()
        .find(|l| l.starts_with("fix kvclip "))
        .and_then(|l| l.split_whitespace().nth(7))
        .and_then(|w| w.parse().ok())
        .expect("the clipped Kelvin-Voigt line's eta");
    let fix = text
        .lines()
        .find(|l| l.starts_with("fix kvclipt"))
        .expect("the tangential fix");
    let words: Vec<&str> = fix.split_whitespace().collect();
    let at = words.iter().position(|w| *w == "linear_history").unwrap();
    assert_eq!(words[at + 1], "15000");
    let x: f64 = words[at + 2].parse().unwrap();
    assert!((x * eta - 19.0).abs() < 1e-12 * 19.0, "{x} × {eta}");
    assert_eq!(words[at + 3], "0.6");
    let j = json(&argv(
        "peers --preset tennis --export json --friction 0.6 --tangential-damping 19",
    ));
    assert_eq!(f(&j["tangential"], "tangential_damping"), 19.0);
}

#[test]
fn fit_oblique_fits_c_t_from_a_start() {
    // bounces of c_t = 12 kg/s, μ = 0.45 without noise beyond the printing's: recovered
    let mut csv = String::from("v0,angle_deg,spin_in,vx_out,vy_out\n");
    for angle in ["8", "12", "16", "25", "35", "45", "55", "65", "75"] {
        for spin in ["-200", "0", "250"] {
            let v = json(&argv_with(
                "oblique --preset tennis --v0 20 --angle {} --spin {} --friction 0.45 \
                 --tangential-damping 12 --format json",
                &[angle, spin],
            ));
            let (vx, vy) = (f(&v, "vx_out"), f(&v, "vy_out"));
            csv.push_str(&format!("20,{angle},{spin},{vx:.6},{vy}\n"));
        }
    }
    let (_dir, path) = file_with(csv.as_bytes());
    let v = json(&argv_with(
        "fit --preset tennis --oblique {} --tangential-damping 4 --format json",
        &[&path],
    ));
    let c = f(&v, "tangential_damping");
    assert!((c - 12.0).abs() < 1e-3 * 12.0, "{c}");
    assert!((f(&v, "friction") - 0.45).abs() < 1e-4);
    let free: Vec<&str> = v["free"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap())
        .collect();
    assert_eq!(
        free,
        ["friction", "tangential_stiffness", "tangential_damping"]
    );
    let e = &v["fitted"]["tangential_damping"];
    assert_eq!(f(e, "value"), c);
    assert!(e["ci95"].is_array());
    bad(
        &argv("fit --preset tennis --cor 0.7 --tangential-damping 4"),
        &["--oblique"],
    );
}
