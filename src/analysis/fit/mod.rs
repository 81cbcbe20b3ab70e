//! Fitting the model to measurements (docs/model.md §4, docs/fitting.md).
//!
//! - [`fit_k_r`]: K_r (λ) from one COR at fixed ζ, a bracketed root find (the original fit).
//! - [`fit`]: several parameters at once from a force–time trace or a COR-against-speed table
//!   (drop tests become such a table): bounded Levenberg–Marquardt ([`lm`]) in the logarithms
//!   of the parameters (so they stay positive and the steps are relative), started from
//!   estimates read off the data and restarted from a few others, with standard errors, 95 %
//!   intervals and correlations from the Jacobian and the residual variance ([`stats`]).

mod bins;
mod checks;
mod cor;
pub mod cor_temperature;
mod edge;
pub mod joint;
pub mod lm;
mod multi;
pub mod oblique;
pub mod pressure_loss;
pub mod profile;
mod result;
mod sensitivity;
mod single;
pub mod stats;
mod trace;
pub mod verdict;

pub use multi::{fit, fit_watched};
pub use result::{Estimate, FitData, MultiFit, MultiFitError};
pub use single::{Fit, FitError, fit_k_r};

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;

/// A parameter a fit can move; the rest of the ball stays as given.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Param {
    /// K_p (N/m).
    KP,
    /// c (kg/s).
    C,
    /// K_r (N/m).
    KR,
    /// z_p (m).
    ZP,
    /// K_h (N/m^1.5); moves K_p with it, K_p = 1.5 K_h √z_p (Eq. 16), as the adopted set ties
    /// them.
    KH,
    /// The impact speed v0 (m/s): a force–time trace carries it in its impulse,
    /// I = m v0 (1 + e), so it can be fitted from a trace alone (not from a COR table, whose
    /// rows give their speeds).
    V0,
}

impl Param {
    /// Every parameter a fit can free, in the order the output lists them.
    pub const ALL: [Param; 6] = [
        Param::KP,
        Param::C,
        Param::KR,
        Param::ZP,
        Param::KH,
        Param::V0,
    ];

    /// The name `--free` takes and the JSON writes: `k_p`, `c`, `k_r`, `z_p`, `k_h`, `v0`.
    pub fn name(self) -> &'static str {
        match self {
            Param::KP => "k_p",
            Param::C => "c",
            Param::KR => "k_r",
            Param::ZP => "z_p",
            Param::KH => "k_h",
            Param::V0 => "v0",
        }
    }

    /// Its SI unit, as the text output writes it.
    pub fn unit(self) -> &'static str {
        match self {
            Param::KP | Param::KR => "N/m",
            Param::C => "kg/s",
            Param::ZP => "m",
            Param::KH => "N/m^1.5",
            Param::V0 => "m/s",
        }
    }

    /// The parameter of that [`name`](Param::name) (surrounding blanks ignored).
    pub fn parse(s: &str) -> Option<Param> {
        Param::ALL.into_iter().find(|p| p.name() == s.trim())
    }

    /// The value in `b`.
    pub fn get(self, b: &ImpactParams) -> f64 {
        match self {
            Param::KP => b.k_p,
            Param::C => b.damping,
            Param::KR => b.k_r,
            Param::ZP => b.z_p,
            Param::KH => ImpactParams::k_h_matching(b.k_p, b.z_p),
            Param::V0 => b.v0,
        }
    }

    /// The defaults of the issue: a trace pins the three springs and the dashpot (K_h in
    /// place of K_p for the Hertz law, where K_p only sets units); a COR table of three
    /// points or more pins K_r and z_p (flattening makes e fall with speed), leaving a degree
    /// of freedom for the uncertainty; fewer pin K_r alone.
    pub fn defaults(trace: bool, points: usize, law: ContactLaw) -> Vec<Param> {
        match (trace, law) {
            (true, ContactLaw::Hertz) => vec![Param::KH, Param::C, Param::KR],
            (true, _) => vec![Param::KP, Param::C, Param::KR],
            (false, _) if points >= 3 => vec![Param::KR, Param::ZP],
            (false, _) => vec![Param::KR],
        }
    }
}

/// A name that is no fittable parameter (a `--free` entry, a `free=` item).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("invalid free parameter '{0}' (choose from k_p, c, k_r, z_p, k_h, v0)")]
pub struct UnknownParam(pub String);

/// The parameters named (`k_p`, `c`, `k_r`, `z_p`, `k_h`, `v0`; blanks around a name ignored), in
/// the order given; an error naming the first unknown one.
pub fn parse_free<S: AsRef<str>>(names: &[S]) -> Result<Vec<Param>, UnknownParam> {
    names
        .iter()
        .map(|n| Param::parse(n.as_ref()).ok_or_else(|| UnknownParam(n.as_ref().trim().into())))
        .collect()
}

/// `base` with the free parameters set to `values` (z_p before K_h, which reads it).
pub fn apply(base: &ImpactParams, free: &[Param], values: &[f64]) -> ImpactParams {
    let mut b = *base;
    let mut order: Vec<(Param, f64)> = free.iter().copied().zip(values.iter().copied()).collect();
    order.sort_by_key(|(p, _)| *p);
    for (p, v) in order {
        match p {
            Param::KP => b.k_p = v,
            Param::C => b.damping = v,
            Param::KR => b.k_r = v,
            Param::ZP => b.z_p = v,
            Param::KH => b.k_p = 1.5 * v * b.z_p.sqrt(),
            Param::V0 => b.v0 = v,
        }
    }
    // K_h follows K_p and z_p when either moves (and is kept as given when neither does, or
    // when there is no flattening threshold to tie it to)
    let tied = free
        .iter()
        .any(|p| matches!(p, Param::KP | Param::ZP | Param::KH));
    if tied && b.z_p.is_finite() {
        b.k_h = ImpactParams::k_h_matching(b.k_p, b.z_p);
    }
    b
}

/// The forward-difference step in a log-parameter (ln p) of the models that run an impact per
/// evaluation, the COR table's and the force trace's (`Residuals::step`): 1e-5 under the
/// linear law, 1e-4 under the others, the two values the fit was written with (a25b884).
pub(super) fn log_step(law: ContactLaw) -> f64 {
    if law == ContactLaw::Linear {
        1e-5
    } else {
        1e-4
    }
}
