//! Tests of the explorer's chart builders, without a terminal.

use super::*;
use crate::analysis::sweep::{cor_vs_zeta, log_space};
use crate::preset::Preset;
use crate::solver::{SolveOptions, simulate};

fn ball(p: &Preset) -> Ball {
    Ball {
        name: p.name.clone(),
        source: p.parameters.name().into(),
        params: p.params(),
        law: p.law,
        measured: Some(p.measured.clone()),
    }
}

#[test]
fn a_scene_without_results_draws_frames_and_says_what_is_missing() {
    let p = &Preset::embedded()[0];
    let scene = Scene {
        ball: ball(p),
        balls: vec![ball(p)],
        run: None,
        references: Vec::new(),
        zeta: None,
        speed: None,
        speed_pending: Some(20.0),
        pinned: Vec::new(),
        measured: &[],
        models: None,
        models_pending: false,
        target: None,
    };
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
    let run = simulate(&p.params(), p.law, &SolveOptions::default()).unwrap();
    let lambda = p.params().normalized().lambda;
    let zetas = log_space(1e-3, 1e3, 121);
    let points = cor_vs_zeta(&[lambda], &zetas, ContactLaw::Linear).unwrap();
    let scene = Scene {
        ball: ball(p),
        balls: vec![ball(p)],
        run: Some(&run),
        references: Vec::new(),
        zeta: Some(ZetaSweep {
            lambda,
            points: &points,
        }),
        speed: None,
        speed_pending: None,
        pinned: Vec::new(),
        measured: &[],
        models: None,
        models_pending: false,
        target: None,
    };
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
