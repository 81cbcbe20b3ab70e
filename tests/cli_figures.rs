//! `bouncelab figure` and `bouncelab reproduce` through the binary: well-formed SVG with the
//! expected series, CSV with the documented columns, files never overwritten silently.

mod common;

use common::*;
use std::fs;
use std::path::Path;

/// Run in a fresh temp folder; (folder, outcome). Paths in `args` are relative to it.
fn bl_at(dir: &Path, args: &[&str]) -> Out {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_bouncelab"))
        .args(args)
        .current_dir(dir)
        .env("XDG_CONFIG_HOME", dir)
        .env("HOME", dir)
        .stdin(std::process::Stdio::null())
        .output()
        .expect("the binary runs");
    Out {
        code: o.status.code().expect("exited"),
        stdout: String::from_utf8(o.stdout).unwrap(),
        stderr: String::from_utf8(o.stderr).unwrap(),
    }
}

fn ok_at(dir: &Path, args: &[&str]) -> String {
    let o = bl_at(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    assert!(o.stderr.is_empty(), "{args:?}: {}", o.stderr);
    o.stdout
}

/// What a figure holds, read from its SVG as an XML document.
struct Svg {
    /// Every `<text>` content, trimmed.
    texts: Vec<String>,
    /// Series named in `<desc>`.
    series: Vec<String>,
    polylines: usize,
}

fn parse_svg(text: &str) -> Svg {
    let doc = roxmltree::Document::parse(text).unwrap_or_else(|e| panic!("not XML: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some("800"));
    assert_eq!(root.attribute("height"), Some("560"));
    assert!(root.attribute("viewBox").is_some());
    let title = root.children().find(|n| n.has_tag_name("title"));
    assert!(
        title.and_then(|t| t.text()).is_some_and(|t| !t.is_empty()),
        "a <title>"
    );
    let desc = root
        .children()
        .find(|n| n.has_tag_name("desc"))
        .and_then(|d| d.text());
    let series = desc
        .and_then(|d| d.split("Series: ").nth(1))
        .map(|s| {
            s.trim_end_matches('.')
                .split("; ")
                .map(String::from)
                .collect()
        })
        .unwrap_or_default();
    let texts = root
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(|t| t.trim().to_string()))
        .collect();
    let polylines = root
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .count();
    Svg {
        texts,
        series,
        polylines,
    }
}

/// The figure `args` draws, with the legend holding exactly `legend` (plus the axis labels).
fn figure(args: &[&str], legend: &[&str]) -> Svg {
    let dir = tempfile::tempdir().unwrap();
    let mut all = vec!["figure"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", "f.svg"]);
    assert_eq!(ok_at(dir.path(), &all), "f.svg\n");
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
        &[
            "cor-velocity",
            "--preset",
            "golf",
            "--from",
            "1",
            "--to",
            "5",
        ],
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
        all.extend_from_slice(&["--out", &svg, "--data", &csv]);
        assert_eq!(ok_at(d, &all), format!("{svg}\n{csv}\n"));
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

#[test]
fn existing_files_are_refused_unless_forced() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("old.svg"), "keep").unwrap();
    let o = bl_at(d, &["figure", "cor-zeta", "--out", "old.svg"]);
    assert_bad(&o, &["old.svg exists", "--force"]);
    assert_eq!(fs::read_to_string(d.join("old.svg")).unwrap(), "keep");
    // an existing --data file stops the command before the SVG is written
    fs::write(d.join("old.csv"), "keep").unwrap();
    let o = bl_at(
        d,
        &[
            "figure",
            "force-time",
            "--out",
            "new.svg",
            "--data",
            "old.csv",
        ],
    );
    assert_bad(&o, &["old.csv exists"]);
    assert!(!d.join("new.svg").exists());
    ok_at(
        d,
        &[
            "figure",
            "force-time",
            "--out",
            "old.svg",
            "--data",
            "old.csv",
            "--force",
        ],
    );
    assert!(
        fs::read_to_string(d.join("old.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    assert!(
        fs::read_to_string(d.join("old.csv"))
            .unwrap()
            .starts_with("series,kind,t,force")
    );
}

#[test]
fn bad_figure_commands_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: [(&[&str], &[&str]); 8] = [
        (
            &["figure", "fig9", "--out", "a.svg"],
            &[
                "fig9",
                "cor-zeta, force-zeta, cor-velocity, force-time, force-displacement",
            ],
        ),
        (&["figure", "cor-zeta"], &["--out"]),
        (
            &["figure", "cor-velocity", "--out", "a.svg", "--lambda", "1"],
            &["--lambda does not apply to cor-velocity"],
        ),
        (
            &["figure", "cor-zeta", "--out", "a.svg", "--v0", "3"],
            &["--v0 does not apply to cor-zeta"],
        ),
        (
            &["figure", "force-time", "--out", "a.svg", "--v0", "0"],
            &["invalid v0"],
        ),
        (
            &["figure", "cor-zeta", "--out", "a.svg", "--lambda", "-1"],
            &["invalid lambda"],
        ),
        (
            &["figure", "force-time", "--out", "nowhere/a.svg"],
            &["no such directory nowhere"],
        ),
        (
            &[
                "figure",
                "force-time",
                "--out",
                "a.svg",
                "--data",
                "./a.svg",
            ],
            &["given twice"],
        ),
    ];
    for (args, needles) in cases {
        assert_bad(&bl_at(d, args), needles);
    }
    assert!(
        fs::read_dir(d)
            .unwrap()
            .all(|e| e.unwrap().file_name() != "a.svg")
    );
}

#[test]
fn reproduce_writes_every_figure_and_the_report_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let listed = ok_at(d, &["reproduce", "--out", "new/paper"]);
    let files: Vec<&str> = listed.lines().collect();
    assert_eq!(files.len(), 2 * (2 + 3 * 4) + 1, "{listed}");
    for f in &files {
        let text = fs::read_to_string(d.join(f)).unwrap();
        if f.ends_with(".svg") {
            parse_svg(&text);
        } else if f.ends_with(".csv") {
            assert!(text.starts_with("series,kind,"), "{f}");
        }
    }
    let report = fs::read_to_string(d.join("new/paper/report.md")).unwrap();
    for ball in ["superball", "golf", "baseball"] {
        assert!(report.contains(&format!("## {ball}\n")), "{ball}");
        assert!(
            report.contains(&format!("](cor-velocity-{ball}.svg)")),
            "{ball}"
        );
    }
    // the baseball's contact time is the model's clearest miss, and is marked
    assert!(report.contains("**-28.3 %**"), "{report}");
    // a second run refuses, and touches nothing; --force replaces and leaves other files alone
    fs::write(d.join("new/paper/notes.txt"), "mine").unwrap();
    fs::write(d.join("new/paper/report.md"), "edited").unwrap();
    assert_bad(
        &bl_at(d, &["reproduce", "--out", "new/paper"]),
        &["exists", "--force"],
    );
    assert_eq!(
        fs::read_to_string(d.join("new/paper/report.md")).unwrap(),
        "edited"
    );
    ok_at(d, &["reproduce", "--out", "new/paper", "--force"]);
    assert_eq!(
        fs::read_to_string(d.join("new/paper/report.md")).unwrap(),
        report
    );
    assert_eq!(
        fs::read_to_string(d.join("new/paper/notes.txt")).unwrap(),
        "mine"
    );
    fs::write(d.join("file"), "").unwrap();
    assert_bad(
        &bl_at(d, &["reproduce", "--out", "file"]),
        &["not a directory"],
    );
    assert_bad(
        &bl_at(d, &["--preset", "golf", "reproduce"]),
        &["do not apply"],
    );
}
