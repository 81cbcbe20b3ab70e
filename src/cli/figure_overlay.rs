//! What `figure` adds to the paper's figures: measured data from files (`--measured`,
//! labelled by file name), further balls (`--preset` given more than once, each labelled by
//! its name), and the user's own measurements never credited to Cross (1999).

use super::figure::FigureName;
use super::measured_file as files;
use crate::figure::{BLACK, Figure, Kind, Marker, Series, Style};
use crate::measured::{Data, Flight, Trace, drop_to_cor};
use std::path::Path;

const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
];

/// The measured points of `data` for figure `name`, as (x, y) in SI, or why they do not fit
/// that figure. A trace is put on the model's clock: its contact start (where the force,
/// above the baseline, first exceeds 5 % of its peak, continued to zero) at t = 0, its
/// baseline subtracted. Against displacement, α(t) = v0 t − (1/m) ∫∫ F dt² from that start
/// (Eq. 1 integrated twice with the ball's m and v0; trapezoidal rule).
fn points(name: FigureName, data: &Data, mass: f64, v0: f64) -> Result<Vec<(f64, f64)>, String> {
    use FigureName::*;
    match (name, data) {
        (CorVelocity, Data::Cor(t)) => Ok(t.points.iter().map(|p| (p.v0, p.cor)).collect()),
        (CorVelocity, Data::Drop(d)) => Ok(d
            .drops
            .iter()
            .map(|&(h, r, _)| drop_to_cor(h, r, &Flight::vacuum()))
            .collect()),
        (ForceTime, Data::Trace(t)) => {
            let (start, base) = clock(t)?;
            Ok(t.time
                .iter()
                .zip(&t.force)
                .map(|(x, f)| (x - start, f - base))
                .collect())
        }
        (ForceDisplacement, Data::Trace(t)) => displacement(t, mass, v0),
        (CorZeta | ForceZeta, _) => Err(format!(
            "--measured does not apply to {} (the normalized ball)",
            name.name()
        )),
        (_, d) => Err(format!(
            "holds a {}, which {} does not draw",
            d.kind(),
            name.name()
        )),
    }
}

fn clock(t: &Trace) -> Result<(f64, f64), String> {
    let s = t.summary().map_err(|e| e.to_string())?;
    Ok((s.t_start, s.baseline))
}

fn displacement(t: &Trace, mass: f64, v0: f64) -> Result<Vec<(f64, f64)>, String> {
    let s = t.summary().map_err(|e| e.to_string())?;
    let (mut velocity, mut alpha) = (v0, 0.0);
    let mut out = Vec::new();
    let mut prev: Option<(f64, f64)> = None;
    for (&time, &f) in t.time.iter().zip(&t.force) {
        if time < s.t_start || time > s.t_end {
            continue;
        }
        let f = (f - s.baseline).max(0.0);
        let (t0, f0) = prev.unwrap_or((s.t_start, 0.0));
        let dt = time - t0;
        let v_new = velocity - 0.5 * (f + f0) / mass * dt;
        alpha += 0.5 * (velocity + v_new) * dt;
        velocity = v_new;
        prev = Some((time, f));
        out.push((alpha, f));
    }
    Ok(out)
}

/// Add each `--measured` file's points to `fig`, labelled by the file name.
pub fn add_measured(
    fig: &mut Figure,
    name: FigureName,
    files_given: &[std::path::PathBuf],
    mass: f64,
    v0: f64,
) -> anyhow::Result<()> {
    for (i, path) in files_given.iter().enumerate() {
        let data = files::any(path)?;
        let pts = points(name, &data, mass, v0)
            .map_err(|m| anyhow::anyhow!("--measured {}: {m}", path.display()))?;
        let label = files::label(path);
        let id = format!("measured {}", label.replace(',', "_"));
        fig.series.push(
            Series::new(
                &label,
                &id,
                Kind::Measured,
                Style::Markers(MARKERS[i % 4]),
                BLACK,
            )
            .with_points(pts),
        );
    }
    widen_to_data(fig);
    Ok(())
}

/// A fixed x range that hides some points is widened to show them.
fn widen_to_data(fig: &mut Figure) {
    let Some((lo, hi)) = fig.x.range else { return };
    let Some((dlo, dhi)) = fig.data_extent(true) else {
        return;
    };
    fig.x.range = Some((lo.min(dlo), hi.max(dhi)));
}

/// The series of `other` (another ball on the same figure) added to `fig`, each label prefixed
/// with the ball's name, in the `index`-th colour.
pub fn merge_ball(fig: &mut Figure, other: Figure, ball: &str, index: usize) {
    for mut s in other.series {
        if s.kind == Kind::Reference {
            continue;
        }
        s.label = format!("{ball}: {}", s.label);
        s.id = format!("{ball} {}", s.id);
        if s.kind == Kind::Model {
            s.color = index % crate::figure::PALETTE.len().min(6);
            s.style = [Style::Solid, Style::Dashed, Style::Dotted][index % 3];
        }
        fig.series.push(s);
    }
    fig.title = format!("{}, {ball}", fig.title);
}

/// A user preset's own measurements are its file's, not Cross (1999)'s.
pub fn relabel_user(fig: &mut Figure, origin: &str) {
    if origin == "embedded" || origin == "normalized" {
        return;
    }
    let name = files::label(Path::new(origin));
    for s in &mut fig.series {
        if s.label.contains("Cross 1999") {
            s.label = s.label.replace("Cross 1999", &name);
        }
    }
}
