//! This run's labelled results (screen and SVG): on the force–time chart the peak force and
//! the contact time, on the hysteresis chart the energy the open loop leaves in the spring,
//! each a marker with its value.

use crate::figure::{Kind, Look, Marker, Series, Style, Tone};
use crate::solver::ImpactResponse;
use crate::text::short;

/// This run's peak force and contact time, labelled with their values on the force–time
/// chart (terminal and SVG): a ● at (t at the peak, F_m) and a ▲ at (t_f, 0). The peak's
/// time is the sampled history's at its largest force; F_m the solver's.
pub fn result_labels(run: &ImpactResponse) -> Vec<Series> {
    let h = &run.history;
    let mut out = Vec::new();
    let peak = h
        .force
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .and_then(|(i, _)| h.t.get(i));
    if let Some(&t) = peak {
        // rounded as the readout rounds it: 13270 beside the readout's 13270, not 13268
        let text = format!("F_m {} N", short(crate::text::rounded(run.max_force, 4), 4));
        out.push(label_series(
            &format!("peak force F_m ({text})"),
            "model max_force",
            Marker::Circle,
            (t, run.max_force),
            &text,
        ));
    }
    if let Some(t_f) = run.contact_time {
        let text = format!("t_f {} ms", short(t_f * 1e3, 4));
        out.push(label_series(
            &format!("contact time t_f ({text})"),
            "model contact_time",
            Marker::Triangle,
            (t_f, 0.0),
            &text,
        ));
    }
    out
}

/// Where the ball's α path ends open on the hysteresis chart, the energy still in the recoil
/// spring when the ball leaves (the loop does not close: "spring left 19.42 mJ" for the
/// superball); nothing when it holds less than 0.1 % of the impact's energy.
pub fn open_loop_label(run: &ImpactResponse) -> Option<Series> {
    let e = run.energy.as_ref()?;
    (e.spring > 1e-3 * e.initial_kinetic).then_some(())?;
    let alpha = *run.history.displacement.last()?;
    let text = format!("spring left {} mJ", short(e.spring * 1e3, 4));
    Some(label_series(
        &format!("energy in the recoil spring at separation ({text})"),
        "model spring_energy_left",
        Marker::Circle,
        (alpha, 0.0),
        &text,
    ))
}

fn label_series(label: &str, id: &str, m: Marker, at: (f64, f64), text: &str) -> Series {
    let glyph = if m == Marker::Circle { "●" } else { "▲" };
    let mut s = Series::new(label, id, Kind::Model, Style::Markers(m), 0)
        .with_points(vec![at])
        .with_look(Look::new(
            Tone::Current,
            None,
            Some(&format!("{glyph}{text}")),
        ));
    s.annotations = vec![text.into()];
    s
}
