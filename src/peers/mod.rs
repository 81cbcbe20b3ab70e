//! The field's normal contact models beside the Christoforou–Yigit one (docs/peers.md):
//! Kelvin–Voigt (with tension, and clipped at F ≥ 0), Tsuji's Hertz law with a δ^{1/4}
//! dashpot, and the Hunt–Crossley family, for a ball of mass m hitting a rigid flat at v0.
//! Each impact returns the crate's [`ImpactResponse`], so every chart can draw it; the exact
//! calibration ([`calibrate`]) and the published approximate rules ([`rules`]) turn a
//! requested COR into each model's damping. No I/O here.

pub mod calibrate;
pub mod case;
mod dop853;
pub mod export;
mod integrate;
mod laws;
pub mod rules;
pub mod steps;
pub mod tangential;

use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, Normalized, ParamError};
use crate::solver::{EventKind, History, ImpactResponse, Method, PhaseEvent};
use serde::Serialize;
use std::fmt;

/// A normal contact model of the field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PeerModel {
    /// F = k δ + η δ̇, tension allowed; the contact ends when δ returns to 0.
    KelvinVoigt,
    /// F = max(0, k δ + η δ̇); the ball leaves when the force reaches 0.
    KelvinVoigtNoTension,
    /// F = max(0, K_h δ^{3/2} + η δ^{1/4} δ̇) (Tsuji, Tanaka & Ishida 1992).
    Tsuji,
    /// F = K_h δ^{3/2} (1 + χ δ̇/v0) (Hunt & Crossley 1975), never negative (laws.rs).
    HuntCrossley,
}

impl PeerModel {
    /// The four models, in the order the output lists them.
    pub const ALL: [PeerModel; 4] = [
        PeerModel::KelvinVoigt,
        PeerModel::KelvinVoigtNoTension,
        PeerModel::Tsuji,
        PeerModel::HuntCrossley,
    ];

    /// Its name on the command line and in the output: `kelvin-voigt`,
    /// `kelvin-voigt-no-tension`, `tsuji`, `hunt-crossley`.
    pub fn name(self) -> &'static str {
        match self {
            PeerModel::KelvinVoigt => "kelvin-voigt",
            PeerModel::KelvinVoigtNoTension => "kelvin-voigt-no-tension",
            PeerModel::Tsuji => "tsuji",
            PeerModel::HuntCrossley => "hunt-crossley",
        }
    }

    /// Whether the stiffness is the Hertz K_h (N/m^1.5) rather than a linear k (N/m).
    pub fn is_hertzian(self) -> bool {
        matches!(self, PeerModel::Tsuji | PeerModel::HuntCrossley)
    }

    /// Units of the stiffness and of the damping as reported (SI).
    pub fn units(self) -> (&'static str, &'static str) {
        match self {
            PeerModel::KelvinVoigt | PeerModel::KelvinVoigtNoTension => ("N/m", "kg/s"),
            PeerModel::Tsuji => ("N/m^1.5", "kg/(s·m^0.25)"),
            PeerModel::HuntCrossley => ("N/m^1.5", "1 (χ)"),
        }
    }
}

impl fmt::Display for PeerModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The ball and the wall: mass, radius, impact speed and both stiffnesses, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeerBall {
    /// m (kg): the effective mass, the ball's own against a rigid flat.
    pub mass: f64,
    /// R (m), for the codes that take a radius (the exports).
    pub radius: f64,
    /// v0 (m/s).
    pub v0: f64,
    /// Linear stiffness k (N/m) of the Kelvin–Voigt models.
    pub k: f64,
    /// Hertz stiffness K_h (N/m^1.5) of Tsuji and the Hunt–Crossley family.
    pub k_h: f64,
}

impl PeerBall {
    /// From a preset's parameter set: k = K_p, the linear (flattening) stiffness the
    /// Christoforou–Yigit linear law loads with (Eqs. 15–16, 21), and K_h = the set's Hertz
    /// stiffness (materials: Eq. 8, K_h = (4/3) E* √R; adopted: Eq. 16, K_p/(1.5 √z_p)).
    pub fn from_params(p: &ImpactParams, radius: f64) -> PeerBall {
        PeerBall {
            mass: p.mass,
            radius,
            v0: p.v0,
            k: p.k_p,
            k_h: p.k_h,
        }
    }

    /// Every value positive, finite and in 1e-15 … 1e15, or an error naming the first that is
    /// not.
    pub fn validate(&self) -> Result<(), PeerError> {
        positive("mass", self.mass)?;
        positive("radius", self.radius)?;
        positive("v0", self.v0)?;
        positive("k", self.k)?;
        positive("k_h", self.k_h)
    }

    /// The model's time, length and force units (laws.rs): T, L = v0 T, F = m v0 / T.
    pub fn scales(&self, model: PeerModel) -> (f64, f64, f64) {
        let t = if model.is_hertzian() {
            (self.mass * self.v0 * self.v0 / self.k_h).powf(0.4) / self.v0
        } else {
            (self.mass / self.k).sqrt()
        };
        (t, self.v0 * t, self.mass * self.v0 / t)
    }

    /// The model's stiffness: k or K_h.
    pub fn stiffness(&self, model: PeerModel) -> f64 {
        if model.is_hertzian() {
            self.k_h
        } else {
            self.k
        }
    }

    /// SI damping from the normalized one (laws.rs): η = 2ζ√(mk), η = α√(m K_h), χ = χ.
    pub fn damping_si(&self, model: PeerModel, d: f64) -> f64 {
        match model {
            PeerModel::KelvinVoigt | PeerModel::KelvinVoigtNoTension => {
                2.0 * d * (self.mass * self.k).sqrt()
            }
            PeerModel::Tsuji => d * (self.mass * self.k_h).sqrt(),
            PeerModel::HuntCrossley => d,
        }
    }

    /// The normalized damping from the SI one; inverse of [`PeerBall::damping_si`].
    pub fn damping_normalized(&self, model: PeerModel, damping: f64) -> f64 {
        damping / self.damping_si(model, 1.0)
    }
}

/// Why a peer impact or calibration has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PeerError {
    /// A value out of its domain, named: "invalid cor: 1.5 (…)".
    #[error("invalid {field}: {} ({reason})", crate::text::number(*.value))]
    Invalid {
        /// The value's name (`mass`, `radius`, `v0`, `k`, `k_h`, `cor`, …).
        field: &'static str,
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
    /// No damping ≥ 0 gives this COR: the model's COR spans (0, 1] (Kelvin–Voigt with tension
    /// [0, 1]).
    #[error(
        "invalid cor: {} is out of reach of {model} (its COR lies in (0, 1])",
        crate::text::number(*.target)
    )]
    OutOfReach {
        /// The model asked.
        model: PeerModel,
        /// The COR asked for.
        target: f64,
    },
    /// The exact calibration's damping, run as the ball's impact, misses the target by more
    /// than [`calibrate::COR_TOL`] (relative): a target below what the impact resolves.
    #[error(
        "invalid cor: {} is out of reach of {model}'s exact calibration: its impact gives COR \
         {} (a miss of {} %); targets from 1e-6 to 1 are verified for every preset",
        crate::text::number(*.target),
        crate::text::sig(*.got, 4),
        crate::text::sig(100.0 * (*.got - *.target).abs() / *.target, 2)
    )]
    Missed {
        /// The model asked.
        model: PeerModel,
        /// The COR asked for.
        target: f64,
        /// The COR its impact gives.
        got: f64,
    },
    /// The step budget ran out (not seen over the tested domain): not the input's fault.
    #[error("{model}: the impact did not end within {steps} steps")]
    Unresolved {
        /// The model run.
        model: PeerModel,
        /// The steps taken.
        steps: usize,
    },
}

impl From<ParamError> for PeerError {
    fn from(e: ParamError) -> Self {
        PeerError::Invalid {
            field: e.field.as_str(),
            value: e.value,
            reason: e.reason,
        }
    }
}

/// The physically meaningful range of every input, as the solver's (docs/model.md §4).
const ABSURD: f64 = 1e15;

/// A finite value in 1e-15 … 1e15, or an error naming `field`.
pub fn positive(field: &'static str, value: f64) -> Result<(), PeerError> {
    let reason = if value.is_nan() {
        "not a number"
    } else if value.is_infinite() {
        "must be finite"
    } else if value <= 0.0 {
        "must be positive"
    } else if !(1.0 / ABSURD..=ABSURD).contains(&value) {
        "out of the physically meaningful range 1e-15 … 1e15"
    } else {
        return Ok(());
    };
    Err(PeerError::Invalid {
        field,
        value,
        reason,
    })
}

/// A damping: finite and ≥ 0 (0 is the elastic limit), or an error naming `field`.
pub fn non_negative(field: &'static str, value: f64) -> Result<(), PeerError> {
    if value == 0.0 {
        Ok(())
    } else {
        positive(field, value)
    }
}

/// The normalized impact of `model` with normalized damping `d` (laws.rs).
fn run(model: PeerModel, d: f64, want: integrate::Want, s: &mut Vec<[f64; 3]>) -> integrate::Run {
    match model {
        PeerModel::KelvinVoigt => integrate::run(&laws::KelvinVoigt { zeta: d }, want, s),
        PeerModel::KelvinVoigtNoTension => {
            integrate::run(&laws::KelvinVoigtNoTension { zeta: d }, want, s)
        }
        PeerModel::Tsuji => integrate::run(&laws::Tsuji { alpha: d }, want, s),
        PeerModel::HuntCrossley => integrate::run(&laws::HuntCrossley { chi: d }, want, s),
    }
}

/// The COR of `model` at normalized damping `d` ≥ 0; it depends on nothing else (laws.rs).
pub fn cor(model: PeerModel, d: f64) -> Result<f64, PeerError> {
    non_negative("damping", d)?;
    let r = run(model, d, integrate::Want::Cor, &mut Vec::new());
    if r.unresolved {
        return Err(PeerError::Unresolved {
            model,
            steps: r.steps,
        });
    }
    Ok(if r.rebound {
        (-r.end[1]).clamp(0.0, 1.0)
    } else {
        0.0
    })
}

/// One impact of `ball` under `model` with SI damping (η, or χ for Hunt–Crossley), with
/// `samples` evenly spaced history points over the contact (0: summary only).
pub fn impact(
    model: PeerModel,
    ball: &PeerBall,
    damping: f64,
    samples: usize,
) -> Result<ImpactResponse, PeerError> {
    ball.validate()?;
    non_negative("damping", damping)?;
    let d = ball.damping_normalized(model, damping);
    let mut pts = Vec::new();
    let r = run(model, d, integrate::Want::Peaks, &mut pts);
    if r.unresolved {
        return Err(PeerError::Unresolved {
            model,
            steps: r.steps,
        });
    }
    if samples > 1 {
        // second pass landing on the sample times; the last point is the end of contact
        let every = r.tau / (samples - 1) as f64;
        run(model, d, integrate::Want::History(every), &mut pts);
        pts.truncate(samples - 1);
        pts.push([r.tau, r.f_end, r.end[0]]);
    }
    Ok(response(model, ball, &r, &pts))
}

fn response(
    model: PeerModel,
    ball: &PeerBall,
    r: &integrate::Run,
    pts: &[[f64; 3]],
) -> ImpactResponse {
    let (t, l, f) = ball.scales(model);
    let history = History {
        t: pts.iter().map(|p| p[0] * t).collect(),
        force: pts.iter().map(|p| p[1] * f).collect(),
        indentation: pts.iter().map(|p| p[2] * l).collect(),
        // the ball's displacement toward the wall is the indentation (rigid flat, no element)
        displacement: pts.iter().map(|p| p[2] * l).collect(),
    };
    let mut events = vec![PhaseEvent {
        t: r.tau_unload * t,
        kind: EventKind::Unload,
        z: r.x_max * l,
    }];
    if r.rebound {
        events.push(PhaseEvent {
            t: r.tau * t,
            kind: EventKind::Separation,
            z: r.end[0].max(0.0) * l,
        });
    }
    ImpactResponse {
        law: if model.is_hertzian() {
            ContactLaw::Hertz
        } else {
            ContactLaw::Linear
        },
        method: Method::Numeric,
        cor: if r.rebound {
            (-r.end[1]).clamp(0.0, 1.0)
        } else {
            0.0
        },
        rebound: r.rebound,
        max_force: r.f_max * f,
        contact_time: r.rebound.then_some(r.tau * t),
        duration: r.tau * t,
        max_indentation: r.x_max * l,
        // what is left of δ when the force lets go (Tsuji, clipped Kelvin–Voigt): the ball
        // leaves before δ is back to 0; it recovers in free flight, nothing is permanent
        permanent_indentation: if r.rebound {
            r.end[0].max(0.0) * l
        } else {
            0.0
        },
        element_displacement: 0.0,
        max_force_normalized: r.f_max,
        element_displacement_normalized: 0.0,
        contact_time_normalized: r.rebound.then_some(r.tau),
        // the Christoforou–Yigit groups do not apply: no recoil element (λ = 0), no dashpot in
        // series (ζ = ∞), no flattening; κ = 1 is F̄ = x^{3/2} in the peers' Hertz scaling
        normalized: Normalized {
            lambda: 0.0,
            zeta: f64::INFINITY,
            zp_bar: f64::INFINITY,
            kappa: if model.is_hertzian() { 1.0 } else { 0.0 },
        },
        events,
        energy: None,
        history,
        steps: r.steps,
        stiff: false,
    }
}
