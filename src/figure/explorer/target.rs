//! A moving or compliant target in the force–displacement chart (docs/explorer.md): the
//! ball's curve is then its displacement relative to the target, α = x_b − x_t (the chain's
//! compression, whose loop encloses the energy the pair lost), and beside it what a bat or
//! racket engineer reads of the target — how far the impact pushed the target off its free
//! path, u_t, and how far its surface gave, s.

use super::{Figure, Kind, Look, Scene, Series, Style, Tone};

/// The target's side of the current run, sampled at the run's history times (m).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TargetMotion {
    /// The target's displacement from its free path u_t = (m*/M)(v_c t − α); empty for M = ∞.
    pub displacement: Vec<f64>,
    /// The surface's deflection s; empty for a rigid surface.
    pub deflection: Vec<f64>,
}

/// The key of the ball's curve against a target: relative to it.
pub const RELATIVE_KEY: &str = "α ball−target";

/// Add the target's curves to the force–displacement figure of the current run, and say in
/// the subtitle what α is.
pub fn add(fig: &mut Figure, scene: &Scene) {
    let (Some(run), Some(motion)) = (scene.run, scene.target) else {
        return;
    };
    let force = &run.history.force;
    if let Some(s) = fig.series.iter_mut().find(|s| s.id == "model displacement") {
        s.look.key = Some(RELATIVE_KEY.into());
    }
    fig.subtitle
        .push_str("; α: the ball's displacement relative to the target");
    let curve = |label: &str, id: &str, key: &str, xs: &[f64], color, tone| {
        let pts = xs.iter().copied().zip(force.iter().copied()).collect();
        Series::new(label, id, Kind::Model, Style::Dotted, color)
            .with_points(pts)
            .with_look(Look::new(tone, Some(key), None))
    };
    if !motion.displacement.is_empty() {
        fig.insert_before_measured(curve(
            "target pushed off its path u_t",
            "target displacement",
            "target u_t",
            &motion.displacement,
            5,
            Tone::Reference(0),
        ));
    }
    if !motion.deflection.is_empty() {
        fig.insert_before_measured(curve(
            "target surface deflection s",
            "target deflection",
            "surface s",
            &motion.deflection,
            6,
            Tone::Reference(2),
        ));
    }
}
