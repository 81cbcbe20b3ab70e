//! `bouncelab mc`'s text report (src/cli/mc.rs): the spreads asked for, a table of the
//! statistics and quantiles of the COR, peak force and contact time, and their 95 % intervals.

use super::output::{self, given, human, table};
use crate::analysis::mc::{McSpec, McStats, PROBS, Stats};
use crate::api::Ball;
use std::io::Write;

/// One statistic of a quantity (a row of the text table).
type StatOf = fn(&Stats) -> f64;

pub(super) fn text(
    out: &mut dyn Write,
    ball: &Ball,
    spec: &McSpec,
    no_rebound: usize,
    st: &McStats,
) -> std::io::Result<()> {
    writeln!(out, "{}", ball.label())?;
    // the samples bounce on the rigid plate, as the JSON `surface` says
    output::ball_lines(out, ball, output::Met::RigidPlate)?;
    let vary: Vec<String> = spec
        .vary
        .iter()
        .map(|v| format!("{} {}", v.what.name(), given(100.0 * v.spread, 6)))
        .collect();
    writeln!(
        out,
        "{} sample{}, seed {}, {} spreads (%): {}; {} law, v0 = {} m/s",
        spec.samples,
        if spec.samples == 1 { "" } else { "s" },
        spec.seed,
        spec.dist.name(),
        vary.join(", "),
        ball.law.name(),
        given(ball.params.v0, 6)
    )?;
    if let Some(c) = &spec.correlation {
        let pairs: Vec<String> = c
            .pairs
            .iter()
            .map(|(x, y, rho)| format!("{}:{} {}", x.name(), y.name(), given(*rho, 6)))
            .collect();
        writeln!(out, "correlated: {}", pairs.join(", "))?;
    }
    writeln!(out)?;
    let cols = columns(st);
    let mut rows = vec![header()];
    let stat_rows: [(&str, StatOf); 4] = [
        ("mean", |s| s.mean),
        ("sd", |s| s.sd),
        ("min", |s| s.min),
        ("max", |s| s.max),
    ];
    for (name, f) in stat_rows {
        rows.push(row(name.to_string(), &cols, |s, k| cell(f(s), k)));
    }
    rows.extend(quantile_rows(&cols, |s, i, k| cell(s.q.values()[i], k)));
    table(out, "  ", &rows)?;
    intervals(out, st)?;
    output::warning_lines(out, &ball.mc_warnings(spec, st))?;
    if no_rebound > 0 {
        writeln!(
            out,
            "\n{no_rebound} samples did not rebound (e = 0): left out of t_f"
        )?;
    }
    Ok(())
}

/// The text tables' columns: the three quantities' statistics, each with the scale it is
/// printed in (t_f in ms).
fn columns(st: &McStats) -> [(&Stats, f64); 3] {
    [
        (&st.cor, 1.0),
        (&st.max_force, 1.0),
        (&st.contact_time, 1e3),
    ]
}

/// The text tables' first row.
fn header() -> Vec<String> {
    ["", "COR", "F_m N", "t_f ms"].map(String::from).to_vec()
}

/// A row of the text tables: `label`, then each column's `value` (of its statistics and the
/// scale it is printed in).
fn row(
    label: String,
    cols: &[(&Stats, f64)],
    value: impl Fn(&Stats, f64) -> String,
) -> Vec<String> {
    std::iter::once(label)
        .chain(cols.iter().map(|(s, k)| value(s, *k)))
        .collect()
}

/// A row a quantile of [`PROBS`] ("2.5 %", …): each column's `value` of the i-th quantile.
fn quantile_rows(
    cols: &[(&Stats, f64)],
    value: impl Fn(&Stats, usize, f64) -> String,
) -> Vec<Vec<String>> {
    let label = |p: f64| format!("{} %", given(p, 3));
    let rows = PROBS.iter().enumerate();
    rows.map(|(i, p)| row(label(*p), cols, |s, k| value(s, i, k)))
        .collect()
}

/// A value of the text tables, scaled, to five digits; "–" where there is none.
fn cell(x: f64, scale: f64) -> String {
    if x.is_nan() {
        "–".to_string()
    } else {
        human(x * scale, 5)
    }
}

/// The 95 % intervals of the mean and the quantiles (analysis::mc_interval): how far each
/// estimate above may be from the run's infinite-sample value; "–" on a side the samples are
/// too few for, and a warning naming those quantiles.
fn intervals(out: &mut dyn Write, st: &McStats) -> std::io::Result<()> {
    let cols = columns(st);
    let span = |ci: [f64; 2], k: f64| format!("{} … {}", cell(ci[0], k), cell(ci[1], k));
    writeln!(
        out,
        "\n95 % intervals of these estimates (sampling error; docs/scale.md):"
    )?;
    let mut rows = vec![header()];
    rows.push(row("mean".to_string(), &cols, |s, k| span(s.mean_ci, k)));
    rows.extend(quantile_rows(&cols, |s, i, k| span(s.q_ci.values()[i], k)));
    table(out, "  ", &rows)?;
    Ok(())
}
