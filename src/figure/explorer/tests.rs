//! Tests of the explorer's chart builders, without a terminal.

use super::*;
use crate::analysis::sweep::{cor_vs_zeta, log_space};
use crate::preset::Preset;
use crate::solver::{ImpactResponse, SolveOptions, simulate};

fn ball(p: &Preset) -> Ball {
    Ball::from_preset(p, p.parameters, p.law)
}

/// `p`'s impact under `law`, and its λ (the current λ of a ζ chart).
fn run_and_lambda(p: &Preset, law: ContactLaw) -> (ImpactResponse, f64) {
    let run = simulate(&p.params(), law, &SolveOptions::default()).unwrap();
    (run, p.params().normalized().lambda)
}

/// A scene of `b` with this run, the current λ's curve and reference curves, nothing else.
fn scene_with<'a>(
    b: Ball,
    run: Option<&'a ImpactResponse>,
    zeta: Option<ZetaSweep<'a>>,
    references: Vec<ZetaSweep<'a>>,
) -> Scene<'a> {
    Scene {
        ball: b.clone(),
        balls: vec![b],
        run,
        references,
        zeta,
        speed: None,
        speed_pending: None,
        speed_stopped: None,
        pinned: Vec::new(),
        measured: &[],
        models: None,
        models_pending: false,
        target: None,
    }
}

#[test]
fn a_scene_without_results_draws_frames_and_says_what_is_missing() {
    let p = &Preset::embedded()[0];
    let mut scene = scene_with(ball(p), None, None, Vec::new());
    scene.speed_pending = Some(20.0);
    let ft = figure(Chart::ForceTime, &scene);
    assert!(ft.series.is_empty());
    assert_eq!(ft.screen_title, "Force–time · F [N] vs t [ms]");
    assert_eq!(missing(Chart::ForceTime, &scene), Some("impact"));
    assert_eq!(missing(Chart::CorZeta, &scene), Some("COR-vs-ζ curve"));
    let speed = figure(Chart::CorSpeed, &scene);
    assert_eq!(
        speed.x.range,
        Some((0.0, 20.0)),
        "the axis spans the sweep out"
    );
    assert!(speed.screen_title.ends_with(" · updating…"));
    assert_eq!(missing(Chart::CorSpeed, &scene), Some("COR-vs-speed sweep"));
}

#[test]
fn zeta_charts_show_the_decades_and_mark_the_current_lambda() {
    let p = &Preset::embedded()[0];
    let (run, lambda) = run_and_lambda(p, p.law);
    let zetas = log_space(1e-3, 1e3, 121);
    let points = cor_vs_zeta(&[lambda], &zetas, ContactLaw::Linear).unwrap();
    let zeta = ZetaSweep {
        lambda,
        points: &points,
    };
    let scene = scene_with(ball(p), Some(&run), Some(zeta), Vec::new());
    let fig = figure(Chart::CorZeta, &scene);
    assert_eq!(fig.x.range, Some((0.01, 100.0)));
    let model = &fig.series[0];
    assert_eq!(model.points.len(), 81, "20 points a decade over 0.01 … 100");
    assert_eq!(model.look.tone, Tone::Current);
    assert!(model.look.key.as_deref().unwrap().ends_with(" now"));
    let kinds: Vec<Kind> = fig.series.iter().map(|s| s.kind).collect();
    assert_eq!(kinds, [Kind::Model, Kind::ThisRun, Kind::Measured]);
    let legend: Vec<String> = fig.legend().into_iter().map(|e| e.key).collect();
    assert_eq!(legend[1..], ["this run", "measured"]);
}

#[test]
fn no_color_cor_zeta_lines_each_have_their_own_glyph() {
    // the current λ and the three references λ = 0, 0.4, 1: the references were dashed,
    // dotted, dashed, so λ = 0 and λ = 1 shared "╍" without colour (issue 29, item 12)
    let p = &Preset::embedded()[0];
    let (run, lambda) = run_and_lambda(p, p.law);
    let zetas = log_space(1e-3, 1e3, 41);
    let sweep = |l: f64| cor_vs_zeta(&[l], &zetas, ContactLaw::Linear).unwrap();
    let (now, r0, r1, r2) = (sweep(lambda), sweep(0.0), sweep(0.4), sweep(1.0));
    let references: Vec<ZetaSweep> = [(0.0, &r0), (0.4, &r1), (1.0, &r2)]
        .into_iter()
        .map(|(lambda, points)| ZetaSweep {
            lambda,
            points: points.as_slice(),
        })
        .collect();
    let now = ZetaSweep {
        lambda,
        points: &now,
    };
    let scene = scene_with(ball(p), Some(&run), Some(now), references);
    let fig = figure(Chart::CorZeta, &scene);
    let lines: Vec<(String, crate::figure::Sample)> = fig
        .legend()
        .into_iter()
        .filter(|e| e.key.contains("λ") || e.key.contains("lambda"))
        .map(|e| (e.key, e.sample))
        .collect();
    assert_eq!(lines.len(), 4, "{lines:?}");
    for (i, a) in lines.iter().enumerate() {
        for b in &lines[i + 1..] {
            assert_ne!(a.1, b.1, "{} and {} share a glyph", a.0, b.0);
        }
    }
}

#[test]
fn a_run_off_the_linear_curves_is_drawn_hollow_and_says_so() {
    // the COR–ζ curves are the linear law's without flattening: a Hertz run's ◆ sat at its
    // own e, off every curve, as if on them (issue 29, item 11)
    let p = &Preset::embedded()[0];
    for (law, glyph) in [(ContactLaw::Linear, "◆"), (ContactLaw::Hertz, "◇")] {
        let (run, lambda) = run_and_lambda(p, law);
        let points = cor_vs_zeta(&[lambda], &log_space(1e-2, 1e2, 21), ContactLaw::Linear).unwrap();
        let mut b = ball(p);
        b.law = law;
        let zeta = ZetaSweep {
            lambda,
            points: &points,
        };
        let scene = scene_with(b, Some(&run), Some(zeta), Vec::new());
        let fig = figure(Chart::CorZeta, &scene);
        let marker = fig.series.iter().find(|s| s.id == "this run").unwrap();
        assert_eq!(marker.look.text.as_deref(), Some(glyph), "{law}");
        let off = marker.look.key.as_deref().unwrap().contains("off curves");
        assert_eq!(off, law != ContactLaw::Linear, "{law}");
    }
}

#[test]
fn the_open_hysteresis_loop_says_what_the_spring_keeps() {
    // the ball's α path ends open at F = 0: the recoil spring still holds energy (19.42 mJ
    // for the superball, the readout's "spring"); unexplained before (issue 29, item 11)
    let p = &Preset::embedded()[0];
    let options = SolveOptions {
        energy: true,
        ..SolveOptions::default().with_samples(200)
    };
    let run = simulate(&p.params(), p.law, &options).unwrap();
    let scene = scene_with(ball(p), Some(&run), None, Vec::new());
    let fig = figure(Chart::Hysteresis, &scene);
    let label = fig
        .series
        .iter()
        .find(|s| s.id == "model spring_energy_left")
        .expect("the open loop's label");
    let spring = run.energy.unwrap().spring;
    assert_eq!(
        label.look.text.as_deref(),
        Some(format!("●spring left {} mJ", crate::text::short(spring * 1e3, 4)).as_str())
    );
    assert_eq!(
        label.points,
        [(*run.history.displacement.last().unwrap(), 0.0)]
    );
    assert!(label.look.text.as_deref().unwrap().contains("19.42"));
}
