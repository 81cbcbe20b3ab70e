//! `bouncelab batch`'s text report (src/cli/batch.rs): a row a ball with its verdict, then
//! the batch's statistics with Cpk.

use super::measured_file as files;
use super::output::{self, given, human};
use crate::api::{Ball, BatchReport, batch_quantity, unfitted_by_reason};
use crate::drop::standards;
use crate::measured::Air;
use std::io::Write;
use std::path::Path;

/// A number or a dash.
fn cell(x: Option<f64>, digits: usize) -> String {
    x.filter(|v| v.is_finite())
        .map_or_else(|| "–".to_string(), |v| human(v, digits))
}

pub(super) fn text(
    out: &mut dyn Write,
    ball: &Ball,
    file: &Path,
    air: Option<Air>,
    r: &BatchReport<'_>,
) -> std::io::Result<()> {
    let standard = standards::find(r.standard.name).map_err(std::io::Error::other)?;
    heading(out, ball, file, air, r, standard)?;
    let (quantity, _) = batch_quantity(standard);
    let drop = quantity == "rebound_height";
    balls_table(out, r, drop)?;
    statistics(out, r, quantity, drop)?;
    notes(out, r)
}

/// The ball, the file, how the balls were fitted and the standard they are judged against.
fn heading(
    out: &mut dyn Write,
    ball: &Ball,
    file: &Path,
    air: Option<Air>,
    r: &BatchReport<'_>,
    standard: &standards::Standard,
) -> std::io::Result<()> {
    let s = &r.summary;
    writeln!(out, "{}, {} law", ball.label(), r.law)?;
    // each ball is fitted and judged on the standard's rigid slab, as the JSON's surface says
    writeln!(out, "{}", output::surface_line(&output::Met::RigidPlate))?;
    if let Some(line) = ball.conditions_line() {
        writeln!(out, "{line}")?;
    }
    // the air plays a part only in drop tests, fitted or judged
    let drops = matches!(standard.test, standards::Test::Drop { .. })
        || r.balls.iter().any(|b| b.data == "drop test");
    writeln!(
        out,
        "{} from {}, fitted one by one ({}){}; judged against {}: {}, window {}",
        crate::text::counted(s.balls, "ball"),
        files::label(file),
        fitted_words(r),
        match (drops, air.is_some()) {
            (false, _) => "",
            (true, true) => ", with air drag",
            (true, false) => ", in vacuum",
        },
        r.standard.name,
        r.standard.title,
        super::standards::window_cell(standard)
    )?;
    writeln!(out)
}

/// What the balls were fitted on: `k_r, z_p` when every ball was fitted on the same, else
/// each set with its count of balls, then the balls whose fit gave nothing (`k_r, z_p: 3
/// balls; 2 without a fit`: their reasons are the summary's).
fn fitted_words(r: &BatchReport<'_>) -> String {
    let mut groups: Vec<(String, usize)> = Vec::new();
    for b in r.balls.iter().filter(|b| !b.free.is_empty()) {
        let set = b.free.join(", ");
        match groups.iter_mut().find(|(g, _)| *g == set) {
            Some((_, n)) => *n += 1,
            None => groups.push((set, 1)),
        }
    }
    let without = r.balls.iter().filter(|b| b.free.is_empty()).count();
    if let ([(set, _)], 0) = (groups.as_slice(), without) {
        return set.clone();
    }
    let mut words: Vec<String> = groups
        .iter()
        .map(|(set, n)| format!("{set}: {}", crate::text::counted(*n, "ball")))
        .collect();
    if without > 0 {
        words.push(format!("{without} without a fit"));
    }
    words.join("; ")
}

/// A row a ball: its COR (and rebound, judged on a drop), verdict, margin and what went wrong.
fn balls_table(out: &mut dyn Write, r: &BatchReport<'_>, drop: bool) -> std::io::Result<()> {
    let mut head = vec!["id", "points", "COR"];
    if drop {
        head.push("rebound m");
    }
    head.extend(["verdict", "margin", ""]);
    let mut rows = vec![head.into_iter().map(String::from).collect::<Vec<_>>()];
    for b in r.balls {
        let mut row = vec![b.id.clone(), b.points.to_string(), cell(b.cor, 5)];
        if drop {
            row.push(cell(b.measured, 5));
        }
        row.push(b.verdict.unwrap_or("no verdict").to_string());
        row.push(b.margin.map_or("–".into(), |m| format!("{m:+.4}")));
        row.push(match (&b.error, &b.fit_error) {
            (Some(e), _) => e.clone(),
            (None, Some(e)) => format!("on its readings; no fit: {e}"),
            (None, None) => String::new(),
        });
        rows.push(row);
    }
    output::table(out, "  ", &rows)
}

/// The judged quantity's statistics over the batch, the failures and Cpk.
fn statistics(
    out: &mut dyn Write,
    r: &BatchReport<'_>,
    quantity: &str,
    drop: bool,
) -> std::io::Result<()> {
    let s = &r.summary;
    let st = &s.stats;
    let unit = if drop { " m" } else { "" };
    let v = |x: f64| {
        if x.is_finite() {
            format!("{}{unit}", human(x, 5))
        } else {
            "–".to_string()
        }
    };
    // an estimate's 95 % interval beside it, where there is one (analysis::batch_stats)
    let within = |ci: [f64; 2], f: &dyn Fn(f64) -> String, note: &str| {
        if ci.iter().all(|x| x.is_finite()) {
            format!(" (95 % {} … {}{note})", f(ci[0]), f(ci[1]))
        } else {
            String::new()
        }
    };
    let c = |x: f64| given(x, 3);
    // the Student interval cut to [0, 1] (a COR) or [0, ∞) (a height): say so beside it
    let clipped = match (st.mean_ci_clipped, drop) {
        (false, _) => "",
        (true, false) => "; Student's t clipped to 0 … 1, where a COR lies",
        (true, true) => "; Student's t clipped at 0 m, where a rebound lies",
    };
    writeln!(out)?;
    writeln!(
        out,
        "{}: n {}, mean {}{}, sd {}, min {}, max {}",
        quantity.replace('_', " "),
        st.n,
        v(st.mean),
        within(st.mean_ci, &v, clipped),
        v(st.sd),
        v(st.min),
        v(st.max)
    )?;
    writeln!(
        out,
        "failures {} of {}, Cpk {}{}; {} of {} fits answered",
        st.failures,
        st.n,
        if st.cpk.is_finite() {
            c(st.cpk)
        } else {
            "–".into()
        },
        within(st.cpk_ci, &c, ""),
        s.identified,
        s.balls
    )?;
    Ok(())
}

/// How many balls went without a fit, with an unsure verdict or with warnings; the warnings.
fn notes(out: &mut dyn Write, r: &BatchReport<'_>) -> std::io::Result<()> {
    let s = &r.summary;
    if s.unfitted > 0 {
        // each ball's reason, grouped: too few points is not the model failing them
        let why = match unfitted_by_reason(r.balls).as_slice() {
            [(kind, _)] => kind.words().to_string(),
            groups => groups
                .iter()
                .map(|(kind, n)| format!("{n}: {}", kind.words()))
                .collect::<Vec<_>>()
                .join("; "),
        };
        writeln!(
            out,
            "judged on their readings without a fit: {} ({why}; their rows say why)",
            s.unfitted
        )?;
    }
    if s.unsure > 0 {
        writeln!(
            out,
            "verdicts not sure at 95 %: {} (a bound of the window within the ball's own interval)",
            s.unsure
        )?;
    }
    let warned = r.balls.iter().filter(|b| !b.warnings.is_empty()).count();
    if warned > 0 {
        writeln!(
            out,
            "balls whose fit warns: {warned} (--format json or --csv-out gives the warnings)"
        )?;
    }
    output::warning_lines(out, &r.warnings)?;
    Ok(())
}
