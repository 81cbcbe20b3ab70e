//! Whether a run stays inside the model's validity: indentation and ball displacement below
//! the radius (docs/model.md).

use crate::solver::ImpactResponse;

/// Where a run leaves the model's validity: the contact model is a small-deformation model,
/// so a peak indentation z_m or a peak ball displacement α_max beyond the radius R is outside
/// it. From the run's own numbers (z_m from the solver, α_max the largest sampled α). On a
/// compliant target α also holds the surface's give s (`deflection`, sampled with α): the
/// ball's own displacement is α − s (docs/targets.md §2: α = z + y + s).
pub fn validity(run: &ImpactResponse, deflection: Option<&[f64]>, radius: f64) -> Option<String> {
    let z_m = run.max_indentation;
    let give = |i: usize| deflection.and_then(|d| d.get(i)).copied().unwrap_or(0.0);
    let alpha = run
        .history
        .displacement
        .iter()
        .enumerate()
        .map(|(i, a)| a - give(i))
        .fold(f64::NAN, f64::max);
    // a number and its unit joined by a no-break space: the readout's line breaking
    // (`format::fit_lines`) never parts them, and the parenthesis is a field of its own (two
    // spaces before it) (tests/tui/tui_render.rs, `the_validity_note_keeps_its_numbers_with_their_units`)
    // four significant digits, the readout's one format (issue 51 item 4; it wrote three,
    // trimmed: "α_max 35 mm")
    let mm = |x: f64| format!("{}\u{a0}mm", crate::tui::format::value(x * 1e3));
    let mut over = Vec::new();
    if z_m > radius {
        over.push(format!("z_m {}", mm(z_m)));
    }
    if alpha > radius {
        over.push(format!("α_max {}", mm(alpha)));
    }
    let worst = z_m.max(alpha);
    (!over.is_empty()).then(|| {
        format!(
            "outside the model: {} > R {}  (by {}, ×{})",
            over.join(", "),
            mm(radius),
            mm(worst - radius),
            crate::tui::format::value(worst / radius)
        )
    })
}
