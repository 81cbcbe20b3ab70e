//! `bouncelab static` through the binary (docs/model.md §11, docs/cli.md "static"): the
//! linear law's closed form d = 2F(1/K_p + 1/K_r) from the JSON's own ball, the Hertz law's
//! forward in closed form and its return `null` with the reason, a ball with no recoil spring,
//! and bad input (exit 2, one line).

use crate::common;

use common::*;

const G: f64 = 9.80665;

fn close(a: f64, b: f64, rel: f64) {
    assert!((a - b).abs() <= rel * b.abs(), "{a} against {b}");
}

#[test]
fn linear_forward_is_the_two_springs_in_series_at_both_plates() {
    for preset in ["tennis", "superball", "baseball", "softball"] {
        let v = json(&argv_with(
            "static --preset {} --load 8.165 --format json",
            &[preset],
        ));
        let b = &v["ball"];
        let (k_p, k_r) = (f(b, "k_p"), f(b, "k_r"));
        let force = 8.165 * G;
        close(f(&v, "force_n"), force, 1e-15);
        let d = f(&v["forward"], "deflection_m");
        close(d, 2.0 * force * (1.0 / k_p + 1.0 / k_r), 1e-14);
        close(f(&v["forward"], "recoil_m"), force / k_r, 1e-14);
        assert!(v["forward"]["reason"].is_null());
        // the linear law has hysteresis past z_p: a return reading, never below the forward
        let r = f(&v["return"], "deflection_m");
        assert!(r >= d * (1.0 - 1e-15), "{preset}: {r} < {d}");
        assert_eq!(f(&v["return"], "peak_m"), 0.0254);
    }
}

#[test]
fn hertz_has_no_return_and_says_why() {
    let v = json(&argv(
        "static --preset superball --law hertz --load 2 --format json",
    ));
    let b = &v["ball"];
    let force = 2.0 * G;
    // z = (F/K_h)^{2/3} (Eq. 7 inverted), in series with F/K_r
    let z = (force / f(b, "k_h")).powf(2.0 / 3.0);
    close(
        f(&v["forward"], "deflection_m"),
        2.0 * (z + force / f(b, "k_r")),
        1e-13,
    );
    assert!(v["return"]["deflection_m"].is_null());
    let why = v["return"]["reason"].as_str().unwrap();
    assert!(why.contains("elastic"), "{why}");
    // a law the record was not fitted with is named in a warning
    let w = v["warnings"][0].as_str().unwrap();
    assert!(w.starts_with("outside calibration:"), "{w}");
}

#[test]
fn no_recoil_spring_gives_no_static_answer() {
    // a user preset with K_r = 0 (the command line's --k-r refuses 0 on a preset)
    let (_dir, path) = file_with(renamed("maxwell", "0.0").as_bytes());
    let v = json(&argv_with(
        "static --config {} --load 1 --format json",
        &[&path],
    ));
    assert!(v["forward"]["deflection_m"].is_null());
    assert!(v["return"]["deflection_m"].is_null());
    assert!(v["forward"]["reason"].as_str().unwrap().contains("K_r = 0"));
    let text = ok(&["static", "--config", &path, "--load", "1"]);
    assert!(text.contains("forward deflection  none: K_r = 0"), "{text}");
}

#[test]
fn an_override_is_listed_and_warned() {
    let v = json(&argv(
        "static --preset tennis --k-p 5e4 --load 1 --format json",
    ));
    assert_eq!(v["ball"]["overrides"][0], "k_p");
    let w = v["warnings"][0].as_str().unwrap();
    assert!(
        w.starts_with("outside calibration: k_p changed the ball"),
        "{w}"
    );
    let text = ok(&argv("static --preset tennis --k-p 5e4 --load 1"));
    assert!(
        text.contains("overrides: k_p; kept from the preset"),
        "{text}"
    );
}

#[test]
fn a_ball_with_no_static_test_in_its_record_is_warned() {
    let text = ok(&["static", "--preset", "superball", "--load", "1"]);
    assert!(
        text.contains("warning: outside calibration: the ball's record holds no static test"),
        "{text}"
    );
}

#[test]
fn bad_input_is_one_line_and_exit_2() {
    bad_each(&[
        ("static --preset tennis --load -1", &["invalid load"]),
        ("static --preset tennis --load 0", &["invalid load"]),
    ]);
    bad(
        &argv("static --preset tennis --load 1 --peak 0.07"),
        &["invalid peak", "diameter"],
    );
    bad(&["static", "--preset", "tennis"], &["--load"]);
}
