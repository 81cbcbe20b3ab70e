//! A dimensional map's cells against the ball's radius (src/api/reach.rs for one impact):
//! each cell's peak indentation from its peak force, and its centre read once, by the bounds
//! where they decide and exactly where they do not. tests/cli/answer_reach.rs (the open cells
//! read by the Taylor steps) and tests/cli/answer_reach_map.rs (the counts).

use super::BallError;
use super::reach::{centre_bounds, peak_displacement};
use crate::map::{Cell, Map};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::Method;
use crate::text::sig;

/// The peak indentation z_m (m) of a dimensional map's cell from its peak force F_m (N),
/// through the loading branch the map's cells share (λ and ζ move K_r and c, never m, K_p,
/// K_h, z_p or v0; `Contact::loading_indentation`), in the normalized scales F̄ = F/(K_p
/// v0/ω0), z = z̄ v0/ω0 (docs/model.md §5).
pub(super) fn cell_indentation(spec: &crate::map::MapSpec) -> impl Fn(f64) -> f64 + Sync {
    let p = &spec.base;
    let n = p.normalized();
    let contact = crate::model::contact::Contact {
        law: spec.law,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let length = p.v0 / p.omega0();
    let k_p = p.k_p;
    move |f| contact.loading_indentation(f / (k_p * length)) * length
}

/// A map cell's centre against the radius: whether it passes R, whether by α alone (its
/// z_m within R), or why it could not be read (its impact run again did not answer).
#[derive(Default)]
struct Tally {
    /// Cells whose centre passes R (those whose indentation passes too: α ≥ z).
    past: usize,
    /// Of those, the cells whose indentation stays within R.
    alone: usize,
    /// Cells the bounds left open whose run again failed: neither within nor past.
    unchecked: usize,
    /// The first of their errors, to name a cell.
    error: Option<String>,
    /// Cells the bounds left open, read exactly (`MapReach::solved`).
    solved: usize,
    /// Of those, the cells the Taylor steps could not read, run again by the adaptive solver
    /// (`MapReach::slow`).
    slow: usize,
}

impl Tally {
    fn add(mut self, other: Tally) -> Tally {
        self.past += other.past;
        self.alone += other.alone;
        self.unchecked += other.unchecked;
        self.solved += other.solved;
        self.slow += other.slow;
        self.error = self.error.or(other.error);
        self
    }
}

/// The cells of a dimensional `map` whose ball's centre passes `radius` (m) while their peak
/// indentation does not ([`super::map_indentation_warning`] names those): a cell past by its
/// lower bound is counted, one within by its upper bound left (`centre_bounds`), and every other
/// read exactly ([`peak_displacement`], the cell's impact again with its flow, on all cores).
/// One warning, when some cell passes by its centre alone, naming how many cells the centre
/// passes in (those whose indentation passes too: α ≥ z) and how many of them by it alone;
/// a cell whose run again fails is neither: the warning counts it as not checked (and is
/// given for it alone), so no cell passes silently. `None` otherwise, for a normalized map,
/// or with no radius known (NaN). tests/cli/answer_reach_map.rs.
pub fn map_displacement_warning(map: &Map, radius: f64) -> Option<String> {
    map_reach(map, radius)?.warning()
}

/// A dimensional map's cells read once against the ball's radius ([`map_reach`]): both the
/// warning ([`map_displacement_warning`]) and the picture's note ([`map_radius_note`]) come
/// from it, so a caller that gives both solves the undecided cells once.
pub struct MapReach {
    tally: Tally,
    radius: f64,
    total: usize,
}

impl MapReach {
    /// [`map_displacement_warning`]'s text.
    pub fn warning(&self) -> Option<String> {
        map_reach_text(&self.tally, self.radius, self.total)
    }

    /// [`map_radius_note`]'s text.
    pub fn note(&self) -> Option<String> {
        map_note_text(&self.tally, self.radius, self.total)
    }

    /// How many cells the bounds left open and were read exactly ([`MapReach::slow`] of
    /// them by the adaptive solver, the rest by the Taylor steps; tests/cli/answer_reach.rs).
    pub fn solved(&self) -> usize {
        self.tally.solved
    }

    /// How many cells were run again by the adaptive solver, some 0.35 ms each: those whose
    /// centre the Taylor steps could not read (`solver::taylor::peak_displacement`: a stiff
    /// phase, the linear law); the others are decided by the bounds or read by the Taylor
    /// steps (issue 54 item 10).
    pub fn slow(&self) -> usize {
        self.tally.slow
    }
}

/// Every cell of `map` read against `radius` (m), once; `None` for a normalized map or with
/// no radius known (NaN).
pub fn map_reach(map: &Map, radius: f64) -> Option<MapReach> {
    Some(MapReach {
        tally: map_tally(map, radius)?,
        radius,
        total: map.cells().len(),
    })
}

/// The note a map's picture carries of its cells past `radius` (m), the figure's short form
/// of [`super::map_indentation_warning`] and [`map_displacement_warning`] together (one
/// tally, the same cells): `z_m > radius 21.55 mm in 8 of 9 cells` (or `centre's α_max`, or
/// both, by which passes), and the cells not checked. `None` when every cell is within, for
/// a normalized map, or with no radius known. tests/figures/figure_map_radius.rs.
pub fn map_radius_note(map: &Map, radius: f64) -> Option<String> {
    map_reach(map, radius)?.note()
}

/// The map's note from its `tally` over `total` cells (`map_radius_note`).
fn map_note_text(t: &Tally, radius: f64, total: usize) -> Option<String> {
    let r = sig(radius * 1e3, 4);
    let what = match (t.alone, t.past) {
        (_, 0) => None,
        (0, _) => Some("z_m"),
        (a, p) if a == p => Some("centre's α_max"),
        _ => Some("z_m or centre's α_max"),
    };
    let past = what.map(|w| format!("{w} > radius {r} mm in {} of {total} cells", t.past));
    let unchecked = (t.unchecked > 0).then(|| {
        format!(
            "α_max not checked against radius {r} mm in {} of {total} cells",
            t.unchecked
        )
    });
    match (past, unchecked) {
        (Some(p), Some(u)) => Some(format!("{p}; {u}")),
        (p, u) => p.or(u),
    }
}

/// Every cell of a dimensional `map` read against `radius` (`map_displacement_warning`).
fn map_tally(map: &Map, radius: f64) -> Option<Tally> {
    use rayon::prelude::*;
    let spec = &map.spec;
    if spec.normalized || !radius.is_finite() {
        return None;
    }
    let z_m = cell_indentation(spec);
    let method = match spec.law {
        ContactLaw::Linear => Method::Exact,
        _ => Method::Numeric,
    };
    let zetas = map.zetas.len();
    let at = |k: usize| spec.params_at(map.lambdas[k / zetas], map.zetas[k % zetas]);
    let read = |(k, c): (usize, Cell)| -> Tally {
        let z = z_m(c.max_force);
        if !z.is_finite() || z > radius {
            // α ≥ z: a z_m past R passes too
            let past = usize::from(z.is_finite());
            return Tally {
                past,
                ..Tally::default()
            };
        }
        read_centre(&at(k), spec.law, method, c, z, radius)
    };
    let cells: Vec<(usize, Cell)> = map
        .cells()
        .iter()
        .enumerate()
        .filter_map(|(k, c)| c.map(|c| (k, c)))
        .collect();
    let tally = cells
        .into_par_iter()
        .map(read)
        .reduce(Tally::default, Tally::add);
    Some(tally)
}

/// A map cell of `params` under `law`, whose summary is `c` and peak indentation `z` (m,
/// within `radius`), read by its centre: past by the lower bound, within by the upper one
/// (`centre_bounds`), else its impact run again by `method` ([`peak_displacement`]).
fn read_centre(
    params: &ImpactParams,
    law: ContactLaw,
    method: Method,
    c: Cell,
    z: f64,
    radius: f64,
) -> Tally {
    let t_f = c.contact_time.unwrap_or(f64::INFINITY);
    let (lo, hi) = centre_bounds(params, z, c.max_force, t_f, c.cor);
    let alone = if lo > radius {
        true
    } else if hi <= radius {
        false
    } else {
        let (alpha, slow) = cell_peak(params, law, method);
        match alpha {
            Ok(a) => {
                let n = usize::from(a > radius);
                return Tally {
                    past: n,
                    alone: n,
                    solved: 1,
                    slow: usize::from(slow),
                    ..Tally::default()
                };
            }
            Err(e) => {
                return Tally {
                    unchecked: 1,
                    error: Some(e.to_string()),
                    solved: 1,
                    slow: usize::from(slow),
                    ..Tally::default()
                };
            }
        }
    };
    let n = usize::from(alone);
    Tally {
        past: n,
        alone: n,
        ..Tally::default()
    }
}

/// α_max (m) of a map cell the bounds left open, and whether the adaptive solver read it: the
/// Taylor steps' read where the centre turns (`solver::taylor::peak_displacement`, a few µs,
/// the same value to 1e-9 and so the same cells: tests/cli/answer_reach.rs,
/// `the_map_reads_open_cells_by_the_taylor_steps_as_the_solver_does`), else
/// [`peak_displacement`] (some 0.35 ms).
fn cell_peak(
    params: &ImpactParams,
    law: ContactLaw,
    method: Method,
) -> (Result<f64, BallError>, bool) {
    let length = params.v0 / params.omega0();
    match crate::solver::taylor::peak_displacement(&params.normalized(), law) {
        Some(alpha) if alpha.is_finite() => (Ok(alpha * length), false),
        _ => (peak_displacement(params, law, method), true),
    }
}

/// The map's centre warning from its `tally` over `total` cells (`map_displacement_warning`).
fn map_reach_text(tally: &Tally, radius: f64, total: usize) -> Option<String> {
    let r = sig(radius * 1e3, 4);
    let unchecked = (tally.unchecked > 0).then(|| {
        format!(
            "in {} of {} cells the peak displacement of the ball's centre could not be checked \
             against the ball's radius {r} mm (the cell's impact run again gave no answer: {})",
            tally.unchecked,
            total,
            tally.error.as_deref().unwrap_or("")
        )
    });
    let past = (tally.alone > 0).then(|| {
        format!(
            "peak displacement of the ball's centre exceeds the ball's radius {r} mm in {} of {} \
             cells, {} of them with the peak indentation within it: outside the model's range \
             there (the model assumes a deformation small against the ball)",
            tally.past, total, tally.alone
        )
    });
    match (past, unchecked) {
        (Some(p), Some(u)) => Some(format!("{p}; {u}")),
        (p, u) => p.or(u),
    }
}
