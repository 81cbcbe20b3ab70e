//! Issue 54 item 4: a figure draws measured data reduced to what it can show. `fit
//! --force-time <10⁶ rows> --plot p.svg` wrote 492 MB of SVG, `figure --measured` 242 MB: one
//! path vertex per sample. Now a long measured line is drawn as the extremes of each pixel
//! column (src/figure/reduce.rs), its legend saying so, and the SVG stays small.

use crate::common;
use crate::common::embedded;
use bouncelab::solver::{SolveOptions, simulate};
use common::{argv, bl_at, parse_svg};

/// A superball's force trace of `n` samples, in `dir/trace.csv`.
fn dense_trace(dir: &std::path::Path, n: usize) {
    let p = embedded("superball");
    let r = simulate(&p.params(), p.law, &SolveOptions::default().with_samples(n)).unwrap();
    let mut trace = String::from("time_s,force_N\n");
    for (t, f) in r.history.t.iter().zip(&r.history.force) {
        trace.push_str(&format!("{t},{f}\n"));
    }
    std::fs::write(dir.join("trace.csv"), trace).unwrap();
}

fn svg_of(dir: &std::path::Path, args: &[&str], file: &str) -> String {
    let o = bl_at(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    std::fs::read_to_string(dir.join(file)).unwrap()
}

#[test]
fn a_dense_trace_is_drawn_as_its_pixel_columns_extremes() {
    let d = tempfile::tempdir().unwrap();
    dense_trace(d.path(), 100_000);
    let args = argv(
        "figure force-time --preset superball --measured trace.csv --out f.svg --csv-out f.csv",
    );
    let svg = svg_of(d.path(), &args, "f.svg");
    // 10⁵ vertices were ~2 MB of path alone; the columns' extremes a few thousand
    assert!(svg.len() < 600_000, "{} bytes", svg.len());
    let fig = parse_svg(&svg);
    let said = "trace.csv (min/max per pixel column of 100000 points)";
    assert!(fig.texts.iter().any(|t| t == said), "{:?}", fig.texts);
    // the CSV keeps every point
    let csv = std::fs::read_to_string(d.path().join("f.csv")).unwrap();
    let measured = csv.lines().filter(|l| l.contains("measured")).count();
    assert!(measured >= 100_000, "{measured} measured rows");
}

#[test]
fn a_trace_of_ordinary_length_is_drawn_as_it_is() {
    let d = tempfile::tempdir().unwrap();
    dense_trace(d.path(), 2_000);
    let args = argv("figure force-time --preset superball --measured trace.csv --out f.svg");
    let fig = parse_svg(&svg_of(d.path(), &args, "f.svg"));
    assert!(
        fig.texts.iter().any(|t| t == "trace.csv"),
        "{:?}",
        fig.texts
    );
    assert!(!fig.texts.iter().any(|t| t.contains("min/max")));
}

#[test]
fn a_fits_plot_of_a_dense_trace_stays_small() {
    let d = tempfile::tempdir().unwrap();
    dense_trace(d.path(), 100_000);
    let args = argv("fit --preset superball --force-time trace.csv --plot p.svg");
    let o = bl_at(d.path(), &args);
    assert!(o.code == 0 || o.code == 1, "{}", o.stderr);
    let svg = std::fs::read_to_string(d.path().join("p.svg")).unwrap();
    assert!(svg.len() < 1_500_000, "{} bytes", svg.len());
    assert!(svg.contains("min/max per pixel column"));
}
