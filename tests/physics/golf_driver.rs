//! The golf ball at driver speeds (issue 52, docs/presets.md): fitted to the fall of COR with
//! impact speed quoted from Chou & Yang (1994), 0.85 at 20 m/s and 0.78 at 45 m/s.

use bouncelab::analysis::fit::{FitData, Param, fit};
use bouncelab::measured::CorPoint;
use bouncelab::preset::Preset;
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

/// The quoted points: (impact speed m/s, COR). Two figures each, so the quotes' own
/// resolution is ±0.005 — the scatter the preset must land within (none other is given).
const QUOTED: [(f64, f64); 2] = [(20.0, 0.85), (45.0, 0.78)];
const QUOTE_RESOLUTION: f64 = 0.005;

fn preset(name: &str) -> Preset {
    Preset::embedded_all()
        .into_iter()
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("no embedded preset {name}"))
}

fn cor_at(p: &ImpactParams, v0: f64) -> f64 {
    let at = ImpactParams { v0, ..*p };
    simulate(&at, ContactLaw::Linear, &SolveOptions::default())
        .unwrap()
        .cor
}

#[test]
fn golf_driver_gives_the_quoted_cor_at_both_speeds() {
    let p = preset("golf-driver");
    for (v0, cor) in QUOTED {
        let e = cor_at(&p.params(), v0);
        // The fit is exact (two data, two parameters); the stored values are rounded to seven
        // figures, which moves the COR by far less than 1e-4.
        assert!((e - cor).abs() < 1e-4, "{v0} m/s: e = {e} vs quoted {cor}");
        assert!((e - cor).abs() <= QUOTE_RESOLUTION);
    }
    // The COR falls with speed through the range, as quoted, and on past it.
    let e: Vec<f64> = [20.0, 30.0, 45.0, 60.0]
        .iter()
        .map(|&v| cor_at(&p.params(), v))
        .collect();
    assert!(e.windows(2).all(|w| w[1] < w[0]), "{e:?}");
}

#[test]
fn the_papers_golf_ball_misses_the_quoted_cor_at_both_speeds() {
    // Why the new ball: Cross's ball, fitted at 1.47 m/s, is far outside the quotes' ±0.005 —
    // 0.796 at 20 m/s and 0.673 at 45 m/s against 0.85 and 0.78: the gap the issue names.
    let golf = preset("golf").params();
    for (v0, cor) in QUOTED {
        let e = cor_at(&golf, v0);
        assert!(
            (e - cor).abs() > 0.05,
            "golf at {v0} m/s: {e} vs quoted {cor}"
        );
    }
}

#[test]
fn golf_driver_is_the_fit_of_the_paper_ball_to_the_quoted_points() {
    // How presets/golf-driver.toml was made: the paper's golf ball with the Rules of Golf's
    // limit mass, K_r and z_p fitted to the two quoted points.
    let golf = preset("golf").params();
    let driver = preset("golf-driver");
    let start = ImpactParams {
        mass: 0.04593,
        ..golf
    };
    let pts: Vec<CorPoint> = QUOTED.iter().map(|&(v, e)| CorPoint::new(v, e)).collect();
    let f = fit(
        &start,
        ContactLaw::Linear,
        FitData::Cor(&pts),
        &[Param::KR, Param::ZP],
    )
    .unwrap();
    let stored = driver.params();
    let k_r = f.fitted[0].value;
    let z_p = f.fitted[1].value;
    assert!(
        (k_r / stored.k_r - 1.0).abs() < 1e-5,
        "K_r {k_r} vs {}",
        stored.k_r
    );
    assert!(
        (z_p / stored.z_p - 1.0).abs() < 1e-5,
        "z_p {z_p} vs {}",
        stored.z_p
    );
    assert_eq!((stored.k_p, stored.damping), (golf.k_p, golf.damping));
    assert_eq!(driver.measured.mass, 0.04593);
    assert_eq!(driver.measured.radius, 0.021335);
}

#[test]
fn golf_driver_holds_from_20_to_45_m_s() {
    let cal = preset("golf-driver")
        .calibration
        .expect("a calibration record");
    assert_eq!((cal.speed_min, cal.speed_max), (20.0, 45.0));
    assert!(cal.data[0].source.starts_with("Chou & Yang (1994)"));
}

#[test]
fn a_rigid_club_face_at_110_mph_gives_about_the_published_cor() {
    // Not fitted: a check by a second source. A club head with no spring-like face and a
    // standard ball give COR "about 0.768 at a head speed of about 110 mph" (franklygolf.com,
    // docs/presets.md): a heavy, nearly rigid face, as the model's plate. "About": ±0.01.
    let e = cor_at(&preset("golf-driver").params(), 110.0 * 0.447_04);
    assert!((e - 0.768).abs() < 0.01, "e = {e}");
}
