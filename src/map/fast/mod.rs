//! A fast summary of one linear-law impact without flattening: COR, F̄_m and τ_f, no history,
//! in closed form (issue 21, "Speed").
//!
//! Without flattening (or while z̄_m ≤ z̄_p) the force is F̄ = z̄ on loading and unloading
//! alike, so one linear flow holds from first touch to separation (docs/model.md §5):
//! z̄''' + 2ζ(1+λ) z̄'' + z̄' + 2ζλ z̄ = 0, z̄(0) = 0, z̄'(0) = 1, z̄''(0) = −2ζ. With r the real
//! root of its cubic that stands apart and s² + 2σs + (σ² + ω²) the quadratic factor of the
//! other two,
//!
//! ```text
//! z̄(τ) = A e^{rτ} + e^{−στ} (−A C(τ) + D S(τ)),   C = cos ωτ,  S = sin(ωτ)/ω,
//! A = 2(σ − ζ)/((r + σ)² + ω²),  D = 1 − (r + σ) A,
//! ```
//!
//! with cosh and sinh(ντ)/ν where ω² = −ν² < 0. What keeps it exact where the complex pair
//! turns real (ω² → 0): the pair is never split into its two roots (which a double root would
//! leave with only half the digits), only σ and ω² enter, and C and S are smooth in ω² (the
//! exact solver's roots keep the pair so too: `propagator::cubic`).
//!
//! τ_m is the first zero of z̄' (F̄_m = z̄(τ_m)), τ_f the first zero of z̄ after it. Where the
//! pair oscillates, the pair's own zeros (a phase each) start Householder's fourth-order
//! steps, and both events are refined side by side in one or two evaluations of the flow
//! each; elsewhere a bracket search with the same steps finds them (`search`). Values at the
//! roots come from the last evaluation's jet by Taylor's series, without another one.
//! e = ∫₀^τ_f z̄ dτ − 1 (ᾱ'' = −F̄, ᾱ'(0) = 1), in closed form too. Cases it does not settle
//! quickly — no rebound (λ = 0, ζ ≥ 1), slow creeps, flattening — and those whose rounding
//! bound (`Flow::rounding`) cannot keep 1e-13 return `None`: the caller runs the exact
//! solver. The real root comes from Cardano's formula, polished (`propagator::modes_of`), where the
//! other two are a complex pair.

mod estrin;
mod flatten;
mod flow;
pub mod lanes;
mod search;

pub use flatten::flattening;
use flow::Flow;
use search::events;

/// One impact's summary, normalized.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// The COR e (Eq. 6).
    pub cor: f64,
    /// F̄_m = z̄_m.
    pub max_force: f64,
    /// τ_f.
    pub contact_time: f64,
}

/// The relative precision a summary must keep, by the bound of [`Flow::rounding`], to be
/// returned: the exact solver (`bouncelab run`) keeps 1e-12 and the map promises its values
/// to 1e-12; a summary that cannot is left to it.
const KEEP: f64 = 1e-13;

/// COR, F̄_m and τ_f of the normalized linear-law impact at (λ, ζ) without flattening (valid
/// with flattening at z̄_p while F̄_m ≤ z̄_p: the caller checks); `None` where the exact solver
/// must answer.
pub fn summary(lambda: f64, zeta: f64) -> Option<Summary> {
    if !(lambda.is_finite() && zeta.is_finite() && lambda >= 0.0 && zeta >= 0.0) {
        return None;
    }
    if zeta == 0.0 {
        // the contact spring alone: e = 1, F̄_m = 1, τ_f = π
        return Some(Summary {
            cor: 1.0,
            max_force: 1.0,
            contact_time: std::f64::consts::PI,
        });
    }
    let flow = Flow::new(lambda, zeta)?;
    let (peak, end) = events(&flow, zeta)?;
    let z_m = peak.derivative(0);
    let h = end.t - end.point.t;
    let integral = flow.integral(&end.point);
    let j = &end.jet;
    let cor = search::taylor(&[integral, j[0], j[1], j[2], j[3]], h) - 1.0;
    // z̄' = 0 at τ_m and z̄ = 0 at τ_f: F̄_m and e are stationary in their τ, only the sums'
    // rounding enters; τ_f moves by z̄'s rounding over the slope it crosses 0 with
    let (dz_m, _) = flow.rounding(&peak.point);
    let (dz_f, dint) = flow.rounding(&end.point);
    let slope = end.derivative(1).abs();
    let tau_f = end.t;
    let precise = dz_m <= KEEP * z_m && dint <= KEEP * cor.abs() && dz_f <= KEEP * slope * tau_f;
    precise.then_some(Summary {
        cor,
        max_force: z_m,
        contact_time: tau_f,
    })
}
