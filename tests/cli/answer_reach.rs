//! The ball's centre past its radius is warned of at the command line as in the explorer
//! (`tui::physical::validity`): the superball at λ 0.001, ζ 10 keeps its contact at 0.13 mm
//! while its centre sinks 35 mm against a radius of 21.55 mm, and only the explorer said so.
//! The warning reads α_max where α' = 0 (`api::peak_displacement`), exact, not sampled.

use crate::common;
use bouncelab::model::contact::ContactLaw;
use bouncelab::solver::{Method, SolveOptions, simulate};
use bouncelab::{Ball, api};
use common::*;

const SOFT: [&str; 6] = ["--preset", "superball", "--lambda", "0.001", "--zeta", "10"];
/// The same ball by its K_r and c, for the commands without `--lambda` and `--zeta`.
const SOFT_SUPERBALL: [&str; 6] = [
    "--preset",
    "superball",
    "--k-r",
    "54.5",
    "--damping",
    "2.2573767961950884",
];
const ALPHA: &str = "peak displacement of the ball's centre α_max 34.97 mm exceeds the ball's \
                     radius 21.55 mm";

fn args<'a>(head: &[&'a str], tail: &[&'a str]) -> Vec<&'a str> {
    head.iter()
        .chain(SOFT.iter())
        .chain(tail)
        .copied()
        .collect()
}

fn soft() -> Ball {
    Ball::from_preset("superball")
        .unwrap()
        .with_lambda_zeta(Some(0.001), Some(10.0))
        .unwrap()
}

/// The answer's warnings but the calibration's (`outside calibration: …`, which an override or
/// another speed adds beside them and tests/cli/calibration.rs checks): this file's are the reach's.
fn reach(v: &serde_json::Value) -> Vec<serde_json::Value> {
    let all = v["warnings"].as_array().expect("a warnings array");
    // the record's range, and `bat`'s ball that is not the standard's: not the reach
    let calibration = |w: &&serde_json::Value| {
        w.as_str().is_some_and(|s| {
            s.starts_with("outside calibration:") || s.starts_with("not the standard's ball:")
        })
    };
    all.iter().filter(|w| !calibration(w)).cloned().collect()
}

#[test]
fn run_warns_when_the_centre_passes_the_radius_in_every_format() {
    let v = json(&args(&["run"], &["--format", "json"]));
    let w = reach(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].as_str().unwrap().starts_with(ALPHA), "{w:?}");
    assert!(
        f(&v, "max_indentation") < 0.001,
        "the contact alone stays small"
    );
    let text = ok(&args(&["run"], &[]));
    assert!(text.contains(&format!("warning: {ALPHA}")), "{text}");
    let csv = ok(&args(&["run"], &["--format", "csv"]));
    assert!(csv.lines().nth(1).unwrap().contains(ALPHA), "{csv}");
    // beside a history, on stderr (exit 0)
    let o = bl(&args(&["run"], &["--history", "--format", "csv"]));
    assert_eq!(o.code, 0);
    assert!(o.stderr.contains(&format!("bouncelab: warning: {ALPHA}")));
}

/// The threshold is α_max itself: a radius a hair above it is silent, a hair below warns.
#[test]
fn the_warning_turns_at_the_exact_peak() {
    let b = soft();
    let r = b.impact().unwrap();
    let alpha = api::peak_displacement(&b.params, r.law, r.method).unwrap();
    assert!((alpha * 1e3 - 34.97).abs() < 0.005, "{alpha}");
    let w =
        |radius: f64| api::reach(&b.params, r.law, r.method, 1e-4, 1.0, radius)?.warning(radius);
    assert!(w(alpha * (1.0 + 1e-9)).is_none());
    assert!(w(alpha * (1.0 - 1e-9)).is_some());
    for (radius, warned) in [("0.0349", true), ("0.0351", false)] {
        let v = json(&args(&["run"], &["--radius", radius, "--format", "json"]));
        assert_eq!(reach(&v).len(), warned as usize, "{v}");
    }
}

/// α_max off the exact flow against the adaptive solver's, and both against a dense history
/// (which can only fall short of the peak, by at most F_m h²/(8 m) between samples).
#[test]
fn the_peak_displacement_is_the_histories_peak() {
    let b = soft();
    let p = &b.params;
    let exact = api::peak_displacement(p, ContactLaw::Linear, Method::Exact).unwrap();
    let numeric = api::peak_displacement(p, ContactLaw::Linear, Method::Numeric).unwrap();
    assert!(
        ((exact - numeric) / exact).abs() < 1e-8,
        "{exact} {numeric}"
    );
    for (law, peak) in [
        (ContactLaw::Linear, exact),
        (
            ContactLaw::Hertz,
            api::peak_displacement(p, ContactLaw::Hertz, Method::Numeric).unwrap(),
        ),
    ] {
        let r = simulate(p, law, &SolveOptions::default().with_samples(20_001)).unwrap();
        let sampled = r.history.displacement.iter().fold(0.0f64, |a, &x| a.max(x));
        let h = r.duration / 20_000.0;
        let gap = r.max_force * h * h / (8.0 * p.mass);
        assert!(
            sampled <= peak * (1.0 + 1e-12),
            "{law:?}: {sampled} > {peak}"
        );
        assert!(
            peak - sampled <= gap + 1e-12 * peak,
            "{law:?}: {peak} {sampled}"
        );
    }
}

#[test]
fn sweep_rows_and_oblique_warn_of_the_centre_at_their_own_speed() {
    let csv = ok(&args(
        &["sweep", "velocity"],
        &["--from", "0.312", "--to", "3.12", "--points", "2"],
    ));
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert!(!rows[0].contains(ALPHA), "3.5 mm at 0.312 m/s: {csv}");
    assert!(rows[1].contains(ALPHA), "{csv}");
    // the normal impact at v sin θ = 3.12 sin 45° m/s: α_max 34.97 sin 45° = 24.73 mm
    let oblique = ["--angle", "45", "--friction", "0.5", "--format", "json"];
    let v = json(&[&["oblique"][..], &SOFT_SUPERBALL, &oblique].concat());
    let w = reach(&v);
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].as_str().unwrap().contains("α_max 24.73 mm"), "{w:?}");
}

/// `collide` and `bat` warned of the indentation only. On a rigid target the ball's
/// compression is the reduced-mass impact's α_max, exactly; on a stiff compliant surface it
/// tends to it (read off the sampled run, from below).
#[test]
fn collide_and_bat_warn_of_the_ball_s_own_compression() {
    let soft = SOFT_SUPERBALL;
    let collide = |extra: &[&str]| {
        let mut a = vec!["collide"];
        a.extend(soft);
        a.extend(["--target-mass", "1", "--format", "json"]);
        a.extend(extra);
        json(&a)
    };
    let b = soft_ball();
    let m = b.params.mass;
    let reduced = bouncelab::ImpactParams {
        mass: m / (1.0 + m / 1.0),
        ..b.params
    };
    let alpha = api::peak_displacement(&reduced, ContactLaw::Linear, Method::Exact).unwrap();
    let shown = format!("α_max {} mm exceeds", bouncelab::text::sig(alpha * 1e3, 4));
    for extra in [&[][..], &["--target-stiffness", "1e9"]] {
        let v = collide(extra);
        let w = reach(&v);
        assert_eq!(w.len(), 1, "{extra:?}: {w:?}");
        assert!(w[0].as_str().unwrap().contains(&shown), "{shown}: {w:?}");
    }
    let mut a = vec!["bat"];
    a.extend(soft);
    a.extend(["--bat-mass", "0.8", "--format", "json"]);
    let v = json(&a);
    let w = reach(&v);
    assert_eq!(w.len(), 2, "{w:?}");
    assert!(
        w[0].as_str()
            .unwrap()
            .starts_with("game: peak displacement")
    );
    assert!(
        w[1].as_str()
            .unwrap()
            .starts_with("BBCOR test: peak displacement")
    );
}

/// The superball with K_r 54.5 N/m and c as ζ = 10 (λ 0.001): `soft()` by its parameters.
fn soft_ball() -> Ball {
    let b = soft();
    assert!((b.params.k_r - 54.5).abs() < 1e-9);
    assert!((b.params.damping - 2.2573767961950884).abs() < 1e-12);
    b
}

/// The map of ball `base` under `law` as the command line computes it (the fast paths on:
/// the Hertz table, the Taylor steps, the closed forms), over λ and ζ each log-spaced
/// `(from, to, points)`; with its spec.
fn command_line_map(
    base: bouncelab::ImpactParams,
    law: ContactLaw,
    lambda: (f64, f64, usize),
    zeta: (f64, f64, usize),
) -> (bouncelab::map::MapSpec, bouncelab::map::Map) {
    use bouncelab::map::{Axis, MapSpec, Param, Scale, compute};
    let axis =
        |p: Param, (from, to, n): (f64, f64, usize)| Axis::new(p, from, to, n, Scale::Log).unwrap();
    let spec = MapSpec::dimensional(
        base,
        law,
        axis(Param::Lambda, lambda),
        axis(Param::Zeta, zeta),
    )
    .unwrap()
    .with_fast(true)
    .with_fast_laws(true);
    (spec.clone(), compute(spec))
}

/// Every bound of `api::centre_bounds` holds the adaptive solver's α_max (read where α' = 0,
/// `api::peak_displacement`) in every cell of a λ × ζ grid, 10⁻³ … 10³ × 10⁻² … 10², under
/// each law, from the cells as the command line's map computes them (the Hertz table, the
/// Taylor steps, the closed forms), within the solver's own error: its rtol 1e-10, loosened to
/// 1e-6 where it ran stiff (docs/numerics.md; a stiff cell, λ 178, ζ 100, is 1.2e-7 past the
/// upper bound, exact there to its inputs: y relaxes to F_m/K_r at the peak).
#[test]
fn the_centre_bounds_hold_the_solver_s_peak_on_a_grid() {
    let cases = [
        ("tennis", ContactLaw::Hertz),
        ("tennis", ContactLaw::ElasticPlastic),
        ("superball", ContactLaw::Linear),
        ("superball", ContactLaw::ElasticPlastic),
        ("golf", ContactLaw::Hertz),
    ];
    for (preset, law) in cases {
        let base = Ball::from_preset(preset).unwrap().params;
        let (spec, map) = command_line_map(base, law, (1e-3, 1e3, 9), (1e-2, 1e2, 9));
        let method = match law {
            ContactLaw::Linear => Method::Exact,
            _ => Method::Numeric,
        };
        let zetas = map.zetas.len();
        let mut checked = 0;
        for (k, cell) in map.cells().iter().enumerate() {
            let Some(c) = cell else { continue };
            let p = spec.params_at(map.lambdas[k / zetas], map.zetas[k % zetas]);
            let z_m = simulate(&p, law, &SolveOptions::default())
                .unwrap()
                .max_indentation;
            let alpha = api::peak_displacement(&p, law, method).unwrap();
            let t_f = c.contact_time.unwrap_or(f64::INFINITY);
            let (lo, hi) = api::centre_bounds(&p, z_m, c.max_force, t_f, c.cor);
            let tol = 1e-6 * alpha;
            assert!(
                lo <= alpha + tol && alpha <= hi + tol,
                "{preset} {law:?} cell {k}: {lo} ≤ {alpha} ≤ {hi} fails"
            );
            checked += 1;
        }
        assert!(checked > 70, "{preset} {law:?}: {checked} cells");
    }
}

/// Issue 54 item 10: a preset's map under Hertz or elastic–plastic ran every cell its bounds
/// left open again by the adaptive solver (some 0.35 ms each: tennis under Hertz, 200 × 120,
/// 0.04 → 0.92 s CPU). The Taylor steps now read those cells' α_max where the centre turns
/// (`solver::taylor::peak_displacement`): the same value as the adaptive solver's to 1e-8 in
/// every cell, the same cells counted past the radius at the ball's own radius and at radii
/// among the cells' own α_max, and no open cell left to the adaptive solver (`slow`, on the
/// old code every open cell).
#[test]
fn the_map_reads_open_cells_by_the_taylor_steps_as_the_solver_does() {
    let cases = [
        ("tennis", ContactLaw::Hertz),
        ("tennis", ContactLaw::ElasticPlastic),
        ("superball", ContactLaw::ElasticPlastic),
        ("golf", ContactLaw::Hertz),
    ];
    for (preset, law) in cases {
        let ball = Ball::from_preset(preset).unwrap();
        let (spec, map) = command_line_map(ball.params, law, (0.01, 100.0, 14), (0.01, 100.0, 10));
        let exact: Vec<(f64, f64, bool)> = map
            .lambdas
            .iter()
            .flat_map(|&l| map.zetas.iter().map(move |&z| (l, z)))
            .map(|(l, z)| {
                let p = spec.params_at(l, z);
                let z_m = simulate(&p, law, &SolveOptions::default())
                    .unwrap()
                    .max_indentation;
                let alpha = api::peak_displacement(&p, law, Method::Numeric).unwrap();
                let length = p.v0 / p.omega0();
                let taylor = bouncelab::solver::taylor::peak_displacement(&p.normalized(), law);
                if let Some(a) = taylor {
                    let a = a * length;
                    assert!(
                        (a - alpha).abs() <= 1e-8 * alpha,
                        "{preset} {law:?} λ {l} ζ {z}: Taylor α_max {a} against {alpha}"
                    );
                }
                (z_m, alpha, taylor.is_some())
            })
            .collect();
        let mut alphas: Vec<f64> = exact.iter().map(|e| e.1).collect();
        alphas.sort_by(f64::total_cmp);
        // cells the Taylor steps leave (a phase stiffer than they take on): the most the
        // adaptive solver may be asked for
        let stiff = exact.iter().filter(|e| !e.2).count();
        let (mut open, mut slow) = (0, 0);
        // radii between two cells' α_max (at a cell's own the two reads may differ by 1e-10)
        let between = |k: usize| 0.5 * (alphas[k] + alphas[k + 1]);
        for radius in [ball.radius(), between(40), between(70), between(100)] {
            let reach = api::map_reach(&map, radius).unwrap();
            let past = exact.iter().filter(|(_, a, _)| *a > radius).count();
            let alone = exact
                .iter()
                .filter(|(z, a, _)| *z <= radius && *a > radius)
                .count();
            let w = reach.warning();
            assert_eq!(w.is_some(), alone > 0, "{preset} {law:?} R {radius}: {w:?}");
            if let Some(w) = w {
                let counts = format!("in {past} of 140 cells, {alone} of them with");
                assert!(w.contains(&counts), "{preset} {law:?} R {radius}: {w}");
            }
            assert!(
                reach.slow() <= stiff,
                "{preset} {law:?} R {radius}: {} cells left to the solver, {stiff} stiff",
                reach.slow()
            );
            open += reach.solved();
            slow += reach.slow();
        }
        // on the old code every open cell ran the adaptive solver (slow = open)
        assert!(
            open > 0 && slow * 4 < open,
            "{preset} {law:?}: {slow} of {open} open cells by the adaptive solver"
        );
    }
}
