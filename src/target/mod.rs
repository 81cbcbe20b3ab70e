//! Two-body impacts: the ball against a target of mass M moving toward it at v_t, rigid or with
//! a surface of its own (stiffness K_s in parallel with damping c_s) — a bat, a racket, a club
//! face, another ball, a floor that gives (docs/targets.md).
//!
//! The chain, in series: ball m – contact element – (c ∥ K_r) – (K_s ∥ c_s) – target M. Every
//! element between the two masses is massless, so the same force F acts on both:
//! m x_b'' = −F and M x_t'' = +F. Their separation α = x_b − x_t therefore obeys
//! m* α'' = −F with the reduced mass m* = mM/(m + M), starting at the closing speed
//! v_c = v_ball + v_t (docs/targets.md §2). With a rigid target this is today's impact of a ball
//! of mass m* at v_c, run by today's solvers ([`crate::simulate`]); a compliant target adds its
//! surface's deflection s as a state of its own (`linear` solves it exactly for the linear law
//! without flattening, `numeric` integrates it for every law). The outgoing speeds follow from
//! the impulse J = m*(1 + e) v_c, which conserves momentum by construction.
//!
//! ```
//! use bouncelab::{Ball, target::Target};
//! let ball = Ball::from_preset("baseball")?.with_v0(40.0)?;
//! let bat = Target { mass: 0.8, speed: 30.0, ..Target::wall() };
//! let r = ball.collide(&bat)?;
//! // batted-ball speed from the apparent COR (docs/targets.md §3)
//! let c = &r.collision;
//! let bbs = c.apparent_cor * 40.0 + (1.0 + c.apparent_cor) * 30.0;
//! assert!((c.ball_speed_out - bbs).abs() < 1e-9);
//! # Ok::<(), bouncelab::BallError>(())
//! ```

pub mod bat;
mod history;
mod linear;
mod numeric;
pub mod pair;
mod series;
pub mod surface;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_history;
#[cfg(test)]
mod tests_stiff;
#[cfg(test)]
mod tests_surface;

use crate::model::contact::ContactLaw;
use crate::model::params::{Field, ImpactParams, ParamError, check_range};
use crate::solver::{Method, SolveError, SolveOptions, Unresolved, simulate};
use serde::Serialize;

pub use history::{TargetHistory, displacement_off_path, history};

/// What the ball hits. `Target::wall()` is today's rigid, immovable wall.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Target {
    /// Mass M (kg); `f64::INFINITY` for an immovable target.
    pub mass: f64,
    /// Speed v_t along the line of impact, positive toward the ball (m/s).
    pub speed: f64,
    /// Stiffness K_s of the target's surface (N/m); `f64::INFINITY` for a rigid one.
    pub stiffness: f64,
    /// Damping c_s in parallel with K_s (kg/s); 0 for none. No part in a rigid target.
    pub damping: f64,
}

impl Target {
    /// The rigid, immovable wall: M = ∞, v_t = 0, K_s = ∞.
    pub const fn wall() -> Target {
        Target {
            mass: f64::INFINITY,
            speed: 0.0,
            stiffness: f64::INFINITY,
            damping: 0.0,
        }
    }

    /// Whether the surface is rigid (K_s = ∞).
    pub fn is_rigid(&self) -> bool {
        self.stiffness == f64::INFINITY
    }

    /// Check every field (the first bad one is named): M > 0 (∞ allowed), v_t finite,
    /// K_s > 0 (∞ allowed), c_s ≥ 0 and finite.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_range(Field::TargetMass, self.mass, false, true)?;
        if !self.speed.is_finite() || self.speed.abs() > 1e15 {
            return Err(ParamError {
                field: Field::TargetSpeed,
                value: self.speed,
                reason: "must be finite, within ±1e15 m/s",
            });
        }
        check_range(Field::TargetStiffness, self.stiffness, false, true)?;
        check_range(Field::TargetDamping, self.damping, true, false)
    }
}

/// The answer to one two-body impact, SI units (docs/targets.md §3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Collision {
    /// COR of the pair, e: separation speed over closing speed (0 without rebound).
    pub cor: f64,
    /// Apparent COR e_A = (e − m/M)/(1 + m/M): the ball's rebound speed over its incoming
    /// speed off the target at rest (= e for M = ∞).
    pub apparent_cor: f64,
    /// The ball's speed after the impact, positive away from the target (m/s).
    pub ball_speed_out: f64,
    /// The target's speed after the impact, positive toward the ball as [`Target::speed`]
    /// counts (m/s): negative when it is knocked back.
    pub target_speed_out: f64,
    /// Peak force F_m (N).
    pub max_force: f64,
    /// Contact time t_f (s); `None` without rebound.
    pub contact_time: Option<f64>,
    /// Reduced mass m* = mM/(m + M) (kg; m for M = ∞).
    pub reduced_mass: f64,
    /// Closing speed v_c = v_ball + v_t (m/s).
    pub closing_speed: f64,
    /// Whether the ball left the target.
    pub rebound: bool,
    /// Peak indentation of the ball's contact z_m (m).
    pub max_indentation: f64,
    /// Permanent indentation z_f (m), Eq. 18.
    pub permanent_indentation: f64,
    /// Peak deflection of the target's surface s_m (m); 0 for a rigid target.
    pub max_target_deflection: f64,
    /// The solver that ran it: today's (rigid), or the exact or integrated compliant one.
    pub method: Method,
}

/// One impact of the ball (`params`, its `v0` ignored) at `ball_speed` (m/s, toward the
/// target) against `target`, on `law`. `method` forces a solver (`None`: the exact one where
/// it applies); a rigid target runs today's solvers through [`simulate`].
pub fn collide(
    params: &ImpactParams,
    law: ContactLaw,
    target: &Target,
    ball_speed: f64,
    method: Option<Method>,
) -> Result<Collision, SolveError> {
    target.validate()?;
    if !ball_speed.is_finite() {
        return Err(bad(Field::V0, ball_speed, "must be finite").into());
    }
    let closing = ball_speed + target.speed;
    if closing.is_nan() || closing <= 0.0 {
        return Err(bad(
            Field::TargetSpeed,
            target.speed,
            "the ball and the target never meet: v0 + target_speed must be positive",
        )
        .into());
    }
    let m = params.mass;
    // m* = m/(1 + m/M): exactly m for M = ∞
    let reduced = ImpactParams {
        mass: m / (1.0 + m / target.mass),
        v0: closing,
        ..*params
    };
    reduced.validate()?;
    let relative = if target.is_rigid() {
        let opts = SolveOptions {
            method,
            ..SolveOptions::default()
        };
        Relative::from(&simulate(&reduced, law, &opts)?)
    } else {
        compliant(&reduced, law, target, method)?
    };
    Ok(relative.into_collision(m, target, ball_speed, reduced.mass))
}

fn bad(field: Field, value: f64, reason: &'static str) -> ParamError {
    ParamError {
        field,
        value,
        reason,
    }
}

/// The relative motion's answer, SI, from whichever solver ran it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Relative {
    pub cor: f64,
    pub rebound: bool,
    pub max_force: f64,
    pub contact_time: f64,
    pub max_indentation: f64,
    pub permanent_indentation: f64,
    pub max_deflection: f64,
    pub method: Method,
    /// Time followed (s): t_f, or the horizon after which "no rebound" was concluded.
    pub duration: f64,
}

impl From<&crate::solver::ImpactResponse> for Relative {
    fn from(r: &crate::solver::ImpactResponse) -> Relative {
        Relative {
            cor: r.cor,
            rebound: r.rebound,
            max_force: r.max_force,
            contact_time: r.contact_time.unwrap_or(f64::NAN),
            max_indentation: r.max_indentation,
            permanent_indentation: r.permanent_indentation,
            max_deflection: 0.0,
            method: r.method,
            duration: r.duration,
        }
    }
}

impl Relative {
    /// The two bodies' speeds from the impulse J = m*(1 + e) v_c (docs/targets.md §3): the
    /// ball's velocity toward the target drops by J/m, the target's away from the ball rises
    /// by J/M, so m·Δu_b + M·Δu_t = 0 and their difference turns from v_c to −e v_c.
    fn into_collision(self, m: f64, target: &Target, ball_speed: f64, m_star: f64) -> Collision {
        let closing = ball_speed + target.speed;
        let impulse = m_star * (1.0 + self.cor) * closing;
        let ratio = m / target.mass;
        Collision {
            cor: self.cor,
            apparent_cor: (self.cor - ratio) / (1.0 + ratio),
            ball_speed_out: impulse / m - ball_speed,
            target_speed_out: target.speed - impulse / target.mass,
            max_force: self.max_force,
            contact_time: self.rebound.then_some(self.contact_time),
            reduced_mass: m_star,
            closing_speed: closing,
            rebound: self.rebound,
            max_indentation: self.max_indentation,
            permanent_indentation: self.permanent_indentation,
            max_target_deflection: self.max_deflection,
            method: self.method,
        }
    }
}

/// The normalized numbers of a compliant target against the reduced ball (docs/targets.md
/// §2): λ_s = K_s/K_p and ζ_s = √(m* K_p)/(2 c_s) (∞ for c_s = 0: a spring alone).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Surface {
    pub lambda_s: f64,
    pub zeta_s: f64,
}

/// A compliant target: the exact solution where the law is linear and the contact does not
/// flatten, else (or when asked for) the integrated one.
fn compliant(
    reduced: &ImpactParams,
    law: ContactLaw,
    target: &Target,
    method: Option<Method>,
) -> Result<Relative, SolveError> {
    compliant_sampled(reduced, law, target, method, &mut history::Samples::none())
}

impl Surface {
    /// The target's surface against the reduced ball `reduced` (docs/targets.md §2).
    pub(crate) fn of(reduced: &ImpactParams, target: &Target) -> Surface {
        Surface {
            lambda_s: target.stiffness / reduced.k_p,
            zeta_s: (reduced.mass * reduced.k_p).sqrt() / (2.0 * target.damping),
        }
    }
}

/// [`compliant`], with the integrated run's history at `samples`' times.
fn compliant_sampled(
    reduced: &ImpactParams,
    law: ContactLaw,
    target: &Target,
    method: Option<Method>,
    samples: &mut history::Samples,
) -> Result<Relative, SolveError> {
    let n = reduced.normalized();
    let surface = Surface::of(reduced, target);
    let unresolved = |reason: Unresolved, steps| SolveError::Unresolved {
        reason,
        steps,
        lambda: n.lambda,
        zeta: n.zeta,
    };
    let exact = match (method, law) {
        (Some(Method::Numeric), _) | (_, ContactLaw::ElasticPlastic | ContactLaw::Hertz) => None,
        (_, ContactLaw::Linear) => Some(linear::solve(&n, &surface)),
    };
    let out = match exact {
        // the exact flow holds while the contact does not flatten (z̄_m ≤ z̄_p)
        Some(Ok(o)) if o.z_max <= n.zp_bar => o,
        Some(Err((reason, steps))) if method == Some(Method::Exact) => {
            return Err(unresolved(reason, steps));
        }
        _ if method == Some(Method::Exact) => {
            return Err(bad(
                Field::Method,
                f64::NAN,
                "the exact compliant solver runs the linear law without flattening only",
            )
            .into());
        }
        _ => integrated(&n, law, &surface, samples).map_err(|(r, s)| unresolved(r, s))?,
    };
    if out.method == Method::Exact {
        samples.fill(|times| linear::sample(&n, &surface, times));
    }
    Ok(out.to_si(reduced))
}

/// Above this relaxation rate of the surface's dashpot, 2ζ_s λ_s (normalized: K_s/(c_s ω0)),
/// the spring-alone limit is tried first: DOP853 needs about that many steps per unit time.
const STIFF_RATE: f64 = 1e4;
/// The largest estimated change of e the surface's dashpot may make for the spring-alone
/// limit to stand for it: a tenth of what the two compliant solvers are held to agree to
/// (1e-9, `the_exact_and_the_integrated_compliant_solvers_agree`).
const NEGLIGIBLE: f64 = 1e-10;
/// The margin on the half-sine estimate of ∫ F̄'² dτ (a Hertz pulse's is within 1.5 of it).
const PULSE_MARGIN: f64 = 3.0;

/// The integrated run. A stiff, lightly damped surface — its dashpot relaxing in
/// 1/(2ζ_s λ_s), far faster than the contact — holds the explicit integrator to its stability
/// limit (K_s = 10⁵ K_p with a few kg/s needs some 10⁷ steps). Such a dashpot barely moves
/// against its spring: s ≈ F/K_s, and what it takes is the work c_s ∫ s'² dt ≈
/// (1/(2ζ_s λ_s²)) ∫ F̄'² dτ (normalized; ∫ F̄'² dτ ≈ π² F̄_m²/(2τ_f) for a pulse of height F̄_m
/// and length τ_f, taken `PULSE_MARGIN` times over). Where that changes e by less than `NEGLIGIBLE`
/// (Δe ≈ W̄/e, from e² = 1 − 2W̄ − …), the spring alone (c_s = 0, held exactly by the
/// equations) is the answer; else the damped surface is integrated (docs/targets.md §4).
fn integrated(
    n: &crate::model::params::Normalized,
    law: ContactLaw,
    s: &Surface,
    samples: &mut history::Samples,
) -> Result<Outcome, (Unresolved, usize)> {
    let rate = 2.0 * s.zeta_s * s.lambda_s;
    if s.zeta_s.is_finite() && rate > STIFF_RATE {
        let spring = Surface {
            zeta_s: f64::INFINITY,
            ..*s
        };
        let o = numeric::solve_sampled(n, law, &spring, samples)?;
        let pulse = std::f64::consts::PI.powi(2) * o.f_max * o.f_max / (2.0 * o.tau_end);
        let work = PULSE_MARGIN * pulse / (rate * s.lambda_s);
        let e = (-o.velocity_end).max(1e-3);
        if o.rebound && work / e <= NEGLIGIBLE {
            return Ok(o);
        }
        samples.restart();
    }
    numeric::solve_sampled(n, law, s, samples)
}

/// A compliant run's answer in the reduced ball's normalized units (docs/model.md §5 with m*
/// and v_c).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Outcome {
    pub rebound: bool,
    pub tau_end: f64,
    /// ᾱ' at separation: −e.
    pub velocity_end: f64,
    pub f_max: f64,
    pub z_max: f64,
    pub z_f: f64,
    pub s_max: f64,
    pub method: Method,
}

impl Outcome {
    fn to_si(self, p: &ImpactParams) -> Relative {
        let w0 = p.omega0();
        let (length, force) = (p.v0 / w0, p.mass * p.v0 * w0);
        Relative {
            cor: if self.rebound {
                (-self.velocity_end).clamp(0.0, 1.0)
            } else {
                0.0
            },
            rebound: self.rebound,
            max_force: self.f_max * force,
            contact_time: self.tau_end / w0,
            max_indentation: self.z_max * length,
            permanent_indentation: self.z_f * length,
            max_deflection: self.s_max * length,
            method: self.method,
            duration: self.tau_end / w0,
        }
    }
}

/// How long a ball that may never leave is followed (normalized time): a hundred times the
/// slowest of the series' periods π √(1 + 1/λ + 1/λ_s), the ball's creep 2ζ, its recoil
/// spring's relaxation 1/(2ζλ) and the target's 1/(2ζ_s λ_s).
pub(crate) fn horizon(n: &crate::model::params::Normalized, s: &Surface) -> f64 {
    let relax = |zeta: f64, lambda: f64| {
        if zeta > 0.0 && zeta.is_finite() && lambda > 0.0 {
            1.0 / (2.0 * zeta * lambda)
        } else {
            0.0
        }
    };
    let soft = if n.lambda > 0.0 { 1.0 / n.lambda } else { 0.0 };
    let period = std::f64::consts::PI * (1.0 + soft + 1.0 / s.lambda_s).sqrt();
    let hertz = 2.95 * (1.25 / n.kappa).powf(0.4);
    let creep = 2.0 * n.zeta + relax(n.zeta, n.lambda) + relax(s.zeta_s, s.lambda_s);
    (100.0 * (period + hertz + creep)).min(1e12)
}
