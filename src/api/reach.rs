//! The ball past its radius: its peak indentation z_m, or its centre's peak displacement
//! α_max = max (z + y) toward the wall, read exactly where α' = 0 (the explorer's validity
//! note, `tui::physical::validity`, checks the same two). tests/cli/answer_reach.rs.

use super::BallError;
use crate::map::{Cell, Map};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{Method, SolveOptions, simulate, simulate_flow};
use crate::text::sig;

/// A peak indentation `z_m` beyond the ball's `radius` (both m): the contact would reach past
/// the ball's centre, far outside the small-deformation contact the laws describe
/// (docs/model.md §3). `None` within, or with no radius known (NaN).
pub fn indentation_warning(z_m: f64, radius: f64) -> Option<String> {
    (radius.is_finite() && z_m > radius).then(|| {
        format!(
            "peak indentation {} mm exceeds the ball's radius {} mm: outside the model's range \
             (the contact laws assume a deformation small against the ball)",
            sig(z_m * 1e3, 4),
            sig(radius * 1e3, 4)
        )
    })
}

/// A peak displacement `alpha_max` of the ball's centre toward the wall beyond the ball's
/// `radius` (both m): the centre would pass where the undeformed surface met the wall, far
/// outside the small deformation the model describes (the explorer's validity note checks the
/// same, `tui::physical::validity`). `None` within, or with no radius known (NaN).
pub fn displacement_warning(alpha_max: f64, radius: f64) -> Option<String> {
    (radius.is_finite() && alpha_max > radius).then(|| {
        format!(
            "peak displacement of the ball's centre α_max {} mm exceeds the ball's radius {} mm: \
             outside the model's range (the model assumes a deformation small against the ball)",
            sig(alpha_max * 1e3, 4),
            sig(radius * 1e3, 4)
        )
    })
}

/// The peak displacement α_max = max (z + y) (m) of the ball's centre toward the wall in the
/// impact of `params` under `law` by `method`: the same run again with its flow kept, read
/// where α' = 0 (`solver::Flow::peak_displacement`). A run the adaptive solver finished in a
/// closed-form creep keeps no flow: then the largest of 4 001 samples of α, a value from below.
pub fn peak_displacement(
    params: &ImpactParams,
    law: ContactLaw,
    method: Method,
) -> Result<f64, BallError> {
    let opts = SolveOptions::default().with_method(method);
    let length = params.v0 / params.omega0();
    Ok(match simulate_flow(params, law, &opts)? {
        (_, Some(flow)) => flow.peak_displacement() * length,
        (_, None) => {
            let r = simulate(params, law, &opts.with_samples(4001))?;
            r.history.displacement.iter().fold(0.0, |a, &b| a.max(b))
        }
    })
}

/// The warning of an impact of `params` reaching past the ball's `radius` (m): its peak
/// indentation `z_m` ([`indentation_warning`]), else the peak displacement of its centre
/// ([`displacement_warning`]); `duration` the time it was followed (s). α = z + y ≥ z (the
/// recoil element only compresses: c y' + K_r y = F ≥ 0 from y = 0), so a z_m past R is
/// an α_max past R too, and one warning says it; and α_max ≤ min(v0 · duration, z_m + m v0/c)
/// (`centre_bounds`), which spares the second run whenever that is within R.
/// tests/cli/answer_warnings.rs.
pub fn reach_warning(
    params: &ImpactParams,
    law: ContactLaw,
    method: Method,
    z_m: f64,
    duration: f64,
    radius: f64,
) -> Option<String> {
    Some(match reach(params, law, method, z_m, duration, radius)? {
        Reach::Indentation(z_m) => indentation_warning(z_m, radius)?,
        Reach::Displacement(alpha) => displacement_warning(alpha, radius)?,
        Reach::Unchecked(e) => {
            format!("the ball's peak displacement could not be checked against its radius: {e}")
        }
    })
}

/// How an impact reaches past the ball's radius ([`reach`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Reach {
    /// Its peak indentation z_m (m) passes the radius (and so does its centre: α ≥ z).
    Indentation(f64),
    /// Its centre's peak displacement α_max (m) passes the radius, z_m within it.
    Displacement(f64),
    /// z_m is within the radius, and the run again for α_max gave no answer.
    Unchecked(BallError),
}

/// Whether an impact reaches past the ball's `radius` (m), and how: [`reach_warning`]'s
/// test, for a caller that words it its own way (a figure's note, `figure::history`).
/// `None` within, or with no radius known (NaN).
pub fn reach(
    params: &ImpactParams,
    law: ContactLaw,
    method: Method,
    z_m: f64,
    duration: f64,
    radius: f64,
) -> Option<Reach> {
    if !radius.is_finite() {
        return None;
    }
    if z_m > radius {
        return Some(Reach::Indentation(z_m));
    }
    // α_max ≤ min(v0 t_f, z_m + m v0/c) (`centre_bounds`): within R, no second run
    let momentum = params.mass * params.v0;
    if (params.v0 * duration).min(z_m + momentum / params.damping) <= radius {
        return None;
    }
    match peak_displacement(params, law, method) {
        Ok(alpha) => (alpha > radius).then_some(Reach::Displacement(alpha)),
        Err(e) => Some(Reach::Unchecked(e)),
    }
}

/// Bounds on α_max (m) of an impact of `p` that peaked at `z_m` with peak force `f_m` (N),
/// lasted `t_f` (s; ∞ without rebound) and left at `cor`, every one exact for any law
/// (tests/cli/answer_reach.rs: `the_centre_bounds_hold_the_solver_s_peak_on_a_grid`).
///
/// The recoil element (c y' + K_r y = F, y(0) = 0, docs/model.md §2) gives, with τ = c/K_r,
/// y(t) = ∫₀ᵗ e^{−(t − s)/τ} F(s) ds / c. With 0 ≤ F ≤ F_m and a given impulse Q = ∫₀ᵗ F,
/// that integral is largest with the impulse at the end (F = F_m on [t − Q/F_m, t]) and
/// smallest with it at the start (F = F_m on [0, Q/F_m]):
///
/// ```text
/// (Q/c) e^{x − t/τ} φ(x)  ≤  y(t)  ≤  (Q/c) φ(x),   x = Q/(F_m τ),  φ(x) = (1 − e^{−x})/x
/// ```
///
/// (→ Q/c as K_r → 0; the lower one needs x ≤ t/τ, true as Q ≤ F_m t).
/// - Above: at the peak t*, α' = 0, so Q = m v0; α_max = z(t*) + y(t*) ≤ z_m + (m v0/c) φ(x)
///   (below both of the older min(m v0/c, F_m/K_r)), and α ≤ v0 t* (α'' ≤ 0) with the
///   rebound's impulse e m v0 after t* taking at least e m v0/F_m: t* ≤ t_f − e m v0/F_m.
/// - Below: α is largest at t*, so α_max ≥ α(t_f) = z_f + y(t_f) ≥ y(t_f), the impulse to
///   t_f being (1 + e) m v0; without rebound only K_r = 0 says anything: y(t*) = m v0/c.
pub fn centre_bounds(p: &ImpactParams, z_m: f64, f_m: f64, t_f: f64, cor: f64) -> (f64, f64) {
    let momentum = p.mass * p.v0;
    let rate = p.k_r / p.damping; // 1/τ
    let phi = |x: f64| if x > 0.0 { -(-x).exp_m1() / x } else { 1.0 };
    let within = |q: f64| (q / p.damping) * phi(q * rate / f_m);
    let rebound = t_f.is_finite() && cor.is_finite();
    let peak_time = if rebound {
        t_f - cor.max(0.0) * momentum / f_m
    } else {
        t_f
    };
    let hi = (p.v0 * peak_time).min(z_m + within(momentum));
    let lo = if rebound {
        let q = (1.0 + cor.max(0.0)) * momentum;
        let x = q * rate / f_m;
        within(q) * (x - t_f * rate).min(0.0).exp()
    } else if p.k_r == 0.0 {
        momentum / p.damping
    } else {
        0.0
    };
    (lo, hi)
}

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
/// or with no radius known (NaN). tests/cli/answer_reach.rs.
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
    /// phase, the linear law). Every undecided cell was, before (issue 54 item 10: a preset's
    /// Hertz map 4–23 × slower than BENCHMARKS.md recorded).
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
