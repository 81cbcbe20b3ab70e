//! `bouncelab figure` through the binary: well-formed SVG with the expected series, and CSV
//! with the documented columns and SI values.

use crate::common;

use common::*;
use std::fs;

/// The figure `args` draws, with the legend holding exactly `legend` (plus the axis labels).
fn figure(args: &[&str], legend: &[&str]) -> Svg {
    let dir = tempfile::tempdir().unwrap();
    let mut all = vec!["figure"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", "f.svg"]);
    assert_eq!(ok_at_calibrated(dir.path(), &all), "f.svg\n");
    let svg = parse_svg(&fs::read_to_string(dir.path().join("f.svg")).unwrap());
    assert_eq!(svg.series.len(), legend.len(), "series {:?}", svg.series);
    for l in legend {
        assert_eq!(
            svg.texts.iter().filter(|t| t == l).count(),
            1,
            "legend {l:?} in {:?}",
            svg.texts
        );
    }
    assert!(svg.polylines >= 1, "a curve is drawn");
    svg
}

#[test]
fn cor_zeta_has_three_curves_three_balls_and_decade_ticks() {
    let legend = [
        "model, λ = 0",
        "model, λ = 0.4",
        "model, λ = 1",
        "superball (λ = 1.3)",
        "golf (λ = 1)",
        "baseball (λ = 0.4)",
    ];
    let svg = figure(&["cor-zeta"], &legend);
    for tick in ["0.01", "0.1", "1", "10", "100", "0.0", "0.2", "1.0"] {
        assert!(svg.texts.iter().any(|t| t == tick), "tick {tick}");
    }
    for label in ["damping factor ζ (–)", "coefficient of restitution e (–)"] {
        assert!(svg.texts.iter().any(|t| t == label), "axis label {label}");
    }
    // the three balls' points are labelled on the chart
    for ball in ["superball", "golf", "baseball"] {
        assert!(svg.texts.iter().any(|t| t == ball), "{ball}");
    }
    let svg = figure(
        &["cor-zeta", "--lambda", "0.2,5"],
        &[
            "model, λ = 0.2",
            "model, λ = 5",
            "superball (λ = 1.3)",
            "golf (λ = 1)",
            "baseball (λ = 0.4)",
        ],
    );
    assert_eq!(svg.series.len(), 5);
}

#[test]
fn force_zeta_has_the_same_series() {
    let svg = figure(
        &["force-zeta", "--params", "materials"],
        &[
            "model, λ = 0",
            "model, λ = 0.4",
            "model, λ = 1",
            "superball (λ = 1.3)",
            "golf (λ = 1)",
            "baseball (λ = 0.33)",
        ],
    );
    assert!(
        svg.texts
            .iter()
            .any(|t| t.starts_with("normalized peak force"))
    );
}

#[test]
fn cor_velocity_shows_the_flattening_onset_and_the_measured_point() {
    let svg = figure(
        &["cor-velocity"],
        &[
            "model",
            "flattening starts, z_m = z_p (5.8 m/s)",
            "measured (Cross 1999)",
        ],
    );
    assert!(svg.texts.iter().any(|t| t == "impact speed v0 (m/s)"));
    figure(
        &argv("cor-velocity --preset golf --from 1 --to 5"),
        &["model", "measured (Cross 1999)"],
    );
}

#[test]
fn force_time_and_displacement_at_the_measured_speed_and_beyond() {
    let svg = figure(
        &["force-time", "--preset", "baseball"],
        &[
            "model",
            "measured peak force (289 N)",
            "measured contact time (2.2 ms)",
        ],
    );
    assert!(svg.texts.iter().any(|t| t == "time t (ms)"));
    // at another speed the measurements do not apply
    figure(&["force-time", "--v0", "5"], &["model"]);
    figure(
        &["force-displacement"],
        &[
            "contact indentation z",
            "ball displacement α",
            "measured peak force (121.8 N)",
        ],
    );
    // past flattening: the threshold and the permanent indentation (8 − 4√3 mm at z_m = 2 z_p)
    let svg = figure(
        &["force-displacement", "--v0", "11.59"],
        &[
            "contact indentation z",
            "ball displacement α",
            "flattening threshold z_p (4 mm)",
            "permanent indentation z_f (1.07 mm)",
        ],
    );
    assert!(svg.texts.iter().any(|t| t == "contact force F (N)"));
}

/// CSV rows as (series, kind, x, y).
fn csv_rows(text: &str, header: &str) -> Vec<(String, String, f64, f64)> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(header));
    lines
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            assert_eq!(f.len(), 4, "{l}");
            assert!(["model", "measured", "reference"].contains(&f[1]), "{l}");
            (
                f[0].to_string(),
                f[1].to_string(),
                f[2].parse().unwrap(),
                f[3].parse().unwrap(),
            )
        })
        .collect()
}

#[test]
fn data_files_hold_the_plotted_series_in_si() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: [(&[&str], &str, usize); 5] = [
        (
            &["cor-zeta", "--points", "50"],
            "series,kind,zeta,cor",
            3 * 50 + 3,
        ),
        (
            &["force-zeta", "--points", "50"],
            "series,kind,zeta,max_force_normalized",
            3 * 50 + 3,
        ),
        (
            &["cor-velocity", "--points", "30"],
            "series,kind,v0,cor",
            30 + 2 + 1,
        ),
        (
            &["force-time", "--points", "40"],
            "series,kind,t,force",
            40 + 2 + 2,
        ),
        (
            &["force-displacement", "--points", "40"],
            "series,kind,displacement,force",
            2 * 40 + 2,
        ),
    ];
    for (i, (args, header, n)) in cases.iter().enumerate() {
        let (svg, csv) = (format!("f{i}.svg"), format!("f{i}.csv"));
        let mut all = vec!["figure"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", &svg, "--csv-out", &csv]);
        assert_eq!(ok_at_calibrated(d, &all), format!("{svg}\n{csv}\n"));
        let rows = csv_rows(&fs::read_to_string(d.join(&csv)).unwrap(), header);
        assert_eq!(rows.len(), *n, "{args:?}");
    }
    // SI: the superball's contact lasts 2.74 ms, written in seconds
    let rows = csv_rows(
        &fs::read_to_string(d.join("f3.csv")).unwrap(),
        "series,kind,t,force",
    );
    let model: Vec<_> = rows.iter().filter(|r| r.0 == "model").collect();
    let t_end = model.last().unwrap().2;
    assert!((t_end - 2.7425e-3).abs() < 1e-6, "{t_end}");
    assert!(
        rows.iter()
            .any(|r| r.0 == "measured contact_time" && r.2 == 3e-3)
    );
    // the measured COR of the superball sits at its adopted ζ
    let rows = csv_rows(
        &fs::read_to_string(d.join("f0.csv")).unwrap(),
        "series,kind,zeta,cor",
    );
    let sb = rows.iter().find(|r| r.0 == "measured superball").unwrap();
    assert_eq!(sb.1, "measured");
    assert!((sb.2 - 0.16124).abs() < 1e-4 && sb.3 == 0.75, "{sb:?}");
}
