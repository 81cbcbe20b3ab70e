//! What `figure` adds to the paper's figures: measured data from files (`--measured`,
//! labelled by file name), and the user's own measurements never credited to Cross (1999).

use super::FigureName;
use crate::cli::measured_file as files;
use crate::figure::{BLACK, Figure, Kind, Marker, Series, Style};
use crate::measured::{Data, overlay};
use std::path::Path;

const MARKERS: [Marker; 4] = [
    Marker::Circle,
    Marker::Square,
    Marker::Triangle,
    Marker::Diamond,
];

/// The measured points of `data` for figure `name`, as (x, y) in SI, or why they do not fit
/// that figure ([`crate::measured::overlay`]).
fn points(name: FigureName, data: &Data, mass: f64, v0: f64) -> Result<Vec<(f64, f64)>, String> {
    use FigureName::*;
    let err = |e: crate::measured::MeasuredError| e.to_string();
    match (name, data) {
        (CorVelocity, Data::Cor(_) | Data::Drop(_)) => {
            Ok(overlay::cor_points(data).unwrap_or_default())
        }
        (ForceTime, Data::Trace(t)) => overlay::aligned(t).map_err(err),
        (ForceDisplacement, Data::Trace(t)) => overlay::displacement(t, mass, v0).map_err(err),
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

/// Add each `--measured` file's points (its data as read) to `fig`, labelled by the file name.
pub fn add_measured(
    fig: &mut Figure,
    name: FigureName,
    measured: &[(&Path, Data)],
    mass: f64,
    v0: f64,
) -> anyhow::Result<()> {
    for (i, (path, data)) in measured.iter().enumerate() {
        let pts = points(name, data, mass, v0)
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

/// A user preset's own measurements are its file's, not Cross (1999)'s.
pub fn relabel_user(fig: &mut Figure, origin: &str) {
    if origin == "embedded" || origin == "normalized" {
        return;
    }
    let name = files::label(Path::new(origin));
    for s in &mut fig.series {
        // `Ball::measured_label` of a user's ball: plain "measured", here named by its file
        if s.label.ends_with("measured") {
            s.label = format!("{} ({name})", s.label);
        }
    }
}
