//! What the solvers return in normalized units (docs/model.md §5), and its conversion to the
//! SI response.

use super::{EnergyBudget, EventKind, History, ImpactResponse, Method, PhaseEvent, Unresolved};
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, Normalized};

/// What a solver returns, in normalized units (docs/model.md §5).
#[derive(Debug, Clone, Default)]
pub(crate) struct Outcome {
    pub rebound: bool,
    /// τ at separation, or at the horizon.
    pub tau_end: f64,
    /// ᾱ' at τ_end.
    pub velocity_end: f64,
    /// ȳ at τ_end.
    pub y_end: f64,
    pub f_max: f64,
    pub z_max: f64,
    pub z_f: f64,
    pub events: Vec<Event>,
    /// Net contact work ∮ F̄ dz̄.
    pub contact_work: f64,
    /// ∫ ȳ'²/(2ζ) dτ, when asked for.
    pub dashpot: Option<f64>,
    /// Solver steps taken (exact: propagator steps; adaptive: accepted and rejected steps).
    pub steps: usize,
    /// A stiff integrator carried some of the run.
    pub stiff: bool,
    /// Why the run could not be brought to an end (a step or phase budget ran out, the
    /// integrator gave up): the outcome is then not an answer.
    pub unresolved: Option<Unresolved>,
    /// The history at evenly spaced τ.
    pub samples: Vec<Sample>,
}

impl Outcome {
    /// Record a phase event at τ, z̄.
    pub fn event(&mut self, tau: f64, kind: EventKind, z: f64) {
        self.events.push(Event { tau, kind, z });
    }
}

/// A phase event in normalized units (see `PhaseEvent`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Event {
    pub tau: f64,
    pub kind: EventKind,
    /// z̄ at the event.
    pub z: f64,
}

/// One sample of the history in normalized units (see `History`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Sample {
    pub tau: f64,
    /// F̄
    pub force: f64,
    /// z̄
    pub z: f64,
    /// ᾱ = z̄ + ȳ
    pub alpha: f64,
}

/// The SI response of a run of `p` from its normalized outcome `o`.
pub(crate) fn to_si(
    p: &ImpactParams,
    n: Normalized,
    law: ContactLaw,
    method: Method,
    o: Outcome,
) -> ImpactResponse {
    let w0 = p.omega0();
    let (t, z, f) = (1.0 / w0, p.v0 / w0, p.mass * p.v0 * w0);
    let energy_unit = p.mass * p.v0 * p.v0;
    // e ∈ [0, 1] physically (the dashpot only dissipates); rounding or the stiff integrator's
    // tolerance can put the computed value a hair outside. Projecting onto the admissible
    // interval can only move it closer to the true value.
    let cor = if o.rebound {
        (-o.velocity_end).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let energy = o.dashpot.map(|d| EnergyBudget {
        initial_kinetic: 0.5 * energy_unit,
        final_kinetic: 0.5 * energy_unit * o.velocity_end * o.velocity_end,
        dashpot: d * energy_unit,
        contact: o.contact_work * energy_unit,
        spring: 0.5 * n.lambda * o.y_end * o.y_end * energy_unit,
    });
    let history = history(&o.samples, t, f, z);
    ImpactResponse {
        law,
        method,
        cor,
        rebound: o.rebound,
        max_force: o.f_max * f,
        contact_time: o.rebound.then_some(o.tau_end * t),
        duration: o.tau_end * t,
        max_indentation: o.z_max * z,
        permanent_indentation: o.z_f * z,
        element_displacement: o.y_end * z,
        max_force_normalized: o.f_max,
        element_displacement_normalized: o.y_end,
        contact_time_normalized: o.rebound.then_some(o.tau_end),
        normalized: n,
        // by value: the same layout, so the allocation is reused in place
        events: o
            .events
            .into_iter()
            .map(|e| PhaseEvent {
                t: e.tau * t,
                kind: e.kind,
                z: e.z * z,
            })
            .collect(),
        energy,
        history,
        steps: o.steps,
        stiff: o.stiff,
    }
}

/// The sampled history in SI units: time unit `t`, force unit `f`, length unit `z`.
fn history(samples: &[Sample], t: f64, f: f64, z: f64) -> History {
    let mut history = History {
        t: Vec::with_capacity(samples.len()),
        force: Vec::with_capacity(samples.len()),
        indentation: Vec::with_capacity(samples.len()),
        displacement: Vec::with_capacity(samples.len()),
    };
    for s in samples {
        history.t.push(s.tau * t);
        history.force.push(s.force * f);
        history.indentation.push(s.z * z);
        history.displacement.push(s.alpha * z);
    }
    history
}
