//! The figure library as the explorer would call it: builders on solver output, the SVG as a
//! `String`, the CSV to any `io::Write`, the report as a pure function.

use bouncelab::analysis::sweep::{cor_vs_zeta, log_space};
use bouncelab::figure::{Kind, csv, paper, report, svg};
use bouncelab::preset::{ParamSource, Preset};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

fn balls() -> Vec<paper::Ball> {
    Preset::embedded()
        .iter()
        .map(|p| paper::Ball::from_preset(p, ParamSource::Adopted, ContactLaw::Linear))
        .collect()
}

#[test]
fn flattening_speed_scales_with_the_peak_indentation() {
    // loading is linear under the linear law, so z_m ∝ v0 and the speed is explicit
    let b = &balls()[0];
    let r = simulate(&b.params, b.law, &SolveOptions::default()).unwrap();
    for ratio in [1.0, 3.0] {
        let v = paper::speed_for_indentation(&b.params, b.law, ratio)
            .unwrap()
            .unwrap();
        let expected = b.params.v0 * ratio * b.params.z_p / r.max_indentation;
        assert!((v / expected - 1.0).abs() < 2e-4, "{v} vs {expected}");
    }
    let none = ImpactParams::from_normalized(1.0, 0.1, f64::INFINITY);
    assert_eq!(
        paper::speed_for_indentation(&none, ContactLaw::Linear, 1.0).unwrap(),
        None
    );
}

#[test]
fn zeta_figures_place_the_measurements_at_each_balls_zeta() {
    let rows = cor_vs_zeta(&[0.0, 1.0], &log_space(0.01, 100.0, 21), ContactLaw::Linear).unwrap();
    let bs = balls();
    let cor = paper::cor_zeta(&rows, &bs, ContactLaw::Linear);
    assert_eq!(cor.series.len(), 2 + 3);
    assert!(cor.x.log && cor.x.range == Some((0.01, 100.0)));
    let model: Vec<_> = cor
        .series
        .iter()
        .filter(|s| s.kind == Kind::Model)
        .collect();
    assert_eq!(model.len(), 2);
    assert!(model.iter().all(|s| s.points.len() == 21));
    let force = paper::force_zeta(&rows, &bs, ContactLaw::Linear);
    for (b, (c, f)) in bs
        .iter()
        .zip(cor.series[2..].iter().zip(&force.series[2..]))
    {
        let zeta = b.params.normalized().zeta;
        let m = b.measured.as_ref().unwrap();
        assert_eq!(c.points, vec![(zeta, m.cor.unwrap())]);
        // F̄ = F/(m v0 ω0), ω0 = √(K_p/m)
        let scale = b.params.mass * m.v0 * (b.params.k_p / b.params.mass).sqrt();
        assert_eq!(f.points, vec![(zeta, m.max_force.unwrap() / scale)]);
        assert_eq!(c.annotations, vec![b.name.clone()]);
    }
}

#[test]
fn the_svg_is_a_string_with_decades_evenly_spaced() {
    let rows = cor_vs_zeta(&[0.4], &log_space(0.01, 100.0, 41), ContactLaw::Linear).unwrap();
    let fig = paper::cor_zeta(&rows, &balls(), ContactLaw::Linear);
    let text = svg::render(&fig).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let x_of = |label: &str| -> f64 {
        doc.descendants()
            .find(|n| n.has_tag_name("text") && n.text().map(str::trim) == Some(label))
            .and_then(|n| n.attribute("x"))
            .unwrap_or_else(|| panic!("tick {label}"))
            .parse()
            .unwrap()
    };
    let xs: Vec<f64> = ["0.01", "0.1", "1", "10", "100"]
        .iter()
        .map(|l| x_of(l))
        .collect();
    let step = xs[1] - xs[0];
    assert!(step > 0.0);
    for w in xs.windows(2) {
        assert!(
            (w[1] - w[0] - step).abs() <= 1.0,
            "decades evenly spaced: {xs:?}"
        );
    }
    // the same figure renders to the same text: no hidden state, no timestamps
    assert_eq!(svg::render(&fig).unwrap(), text);
}

#[test]
fn history_figures_show_flattening_when_it_happens() {
    let b = &balls()[0];
    let v = paper::speed_for_indentation(&b.params, b.law, 2.0)
        .unwrap()
        .unwrap();
    let fast = paper::Ball {
        params: ImpactParams { v0: v, ..b.params },
        ..b.clone()
    };
    let r = simulate(
        &fast.params,
        fast.law,
        &SolveOptions::default().with_samples(200),
    )
    .unwrap();
    let fig = paper::force_displacement(&fast, &r);
    let zf = fig
        .series
        .iter()
        .find(|s| s.id == "model permanent_indentation")
        .unwrap();
    // Eq. 18 at z_m = 2 z_p: z_f = z_p (2 − √3)
    let expected = b.params.z_p * (2.0 - 3f64.sqrt());
    assert!((zf.points[0].0 - expected).abs() < 1e-6, "{:?}", zf.points);
    assert!(
        fig.series.iter().all(|s| s.kind != Kind::Measured),
        "not the measured speed"
    );
    let time = paper::force_time(&fast, &r);
    assert_eq!(time.series.len(), 1);
    // the CSV goes to any writer, SI units: indentation in m
    let mut out = Vec::new();
    csv::write(&fig, &mut out).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.starts_with("series,kind,displacement,force\n"));
    assert!(text.contains(&format!(
        "model permanent_indentation,model,{},0",
        zf.points[0].0
    )));
}

#[test]
fn the_report_compares_every_ball_both_ways() {
    let cmp: Vec<_> = Preset::embedded()
        .iter()
        .map(|p| report::compare(p, ContactLaw::Linear).unwrap())
        .collect();
    let figs = vec![report::FigureRef {
        file: "cor-zeta.svg".into(),
        caption: "Fig. 2".into(),
        ball: None,
    }];
    let md = report::markdown(&cmp, &figs);
    assert_eq!(md, report::markdown(&cmp, &figs), "pure");
    for ball in ["superball", "golf", "baseball"] {
        assert!(md.contains(&format!("\n## {ball}\n")), "{ball}");
        assert!(
            md.contains(&format!("\n| {ball} | ")),
            "summary row for {ball}"
        );
    }
    for needle in [
        "| COR e | 0.75 | 0.7506 | +0.1 % |",
        "| dashpot c (kg/s), Eq. 5 | 140 | 140.3 | +0.2 % |",
        "| contact stiffness K_p (N/m), Eq. 16 | 1.05e6 | 1.272e6 | **+21.2 %** |",
        "![Fig. 2](cor-zeta.svg)",
    ] {
        assert!(md.contains(needle), "{needle} not in\n{md}");
    }
    // the COR was fitted: refitting K_r to it lands on the adopted K_r
    let fit = cmp[0].fit_adopted.unwrap();
    assert!((fit.k_r / cmp[0].adopted.k_r - 1.0).abs() < 0.01);
}
