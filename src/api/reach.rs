//! The ball past its radius: its peak indentation z_m, or its centre's peak displacement
//! α_max = max (z + y) toward the wall, read exactly where α' = 0 (the explorer's validity
//! note, `tui::physical::validity`, checks the same two). tests/cli/answer_reach.rs.

use super::BallError;
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

impl Reach {
    /// The warning of this reach past a ball of `radius` (m), as `run` gives it: the peak
    /// indentation's ([`indentation_warning`]), else the centre's ([`displacement_warning`]),
    /// one warning for both (a z_m past R is an α_max past R too).
    pub fn warning(self, radius: f64) -> Option<String> {
        Some(match self {
            Reach::Indentation(z_m) => indentation_warning(z_m, radius)?,
            Reach::Displacement(alpha) => displacement_warning(alpha, radius)?,
            Reach::Unchecked(e) => {
                format!("the ball's peak displacement could not be checked against its radius: {e}")
            }
        })
    }
}

/// Whether an impact of `params` reaches past the ball's `radius` (m), and how: its peak
/// indentation `z_m`, else the peak displacement of its centre; `duration` the time it was
/// followed (s). α = z + y ≥ z (the recoil element only compresses: c y' + K_r y = F ≥ 0 from
/// y = 0), so a z_m past R is an α_max past R too; and α_max ≤ min(v0 · duration,
/// z_m + m v0/c) (`centre_bounds`), which spares the second run whenever that is within R.
/// `None` within, or with no radius known (NaN). [`Reach::warning`] words it as `run` warns of
/// it; a figure's note (`figure::history`) its own way. tests/cli/answer_warnings.rs.
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
