//! Two balls that both deform (docs/targets.md §8): ball 1 – its contact element – its
//! (c₁ ∥ K_r1) – ball 2's (c₂ ∥ K_r2) – ball 2's contact element – ball 2, every element
//! massless, so one force F runs through all. In ball 1's units over the reduced mass
//! (docs/model.md §5 with m* and the closing speed v_c: τ = ω t, ω = √(K_p1/m*)), with
//! r = ω₂/ω, ω₂ = √(K_p2/m*), ball 2's own normalized law f̄₂ and constants λ₂, ζ₂:
//!
//! ```text
//! ᾱ'' = −F̄,  ȳ₁' = 2ζ₁(F̄ − λ₁ȳ₁),  ȳ₂' = 2ζ₂(F̄/r − λ₂ r ȳ₂),  Z̄' = ᾱ' − ȳ₁' − ȳ₂',
//! ```
//!
//! Z̄ = z̄₁ + z̄₂ the two contacts' indentations together, and F̄ the force at which they add to
//! Z̄: g₁(F̄) + g₂(F̄) = Z̄, g₁ ball 1's indentation at F̄ and g₂(F̄) = ḡ₂(F̄/r)/r ball 2's, each
//! on its own branch (loading, or unloading from its own peak). Both contacts carry the same
//! force, so they turn, reload and let go together: loading until Z̄' falls through 0, then
//! unloading until Z̄ falls to z̄_f1 + z̄_f2 (separation) or rises past Z̄_m (reload). DOP853
//! (the `differential-equations` crate) at 1e-12 per phase, events on its dense output by
//! Brent and the state there by integrating to them, as the compliant target's run
//! (`numeric`). Identical balls make both halves equal at every step: the wall impact of one
//! ball at half the closing speed (`identical_balls_head_on_are_the_wall_impact`).

use super::series::{FirstEvent, MAX_PHASES, MAX_STEPS, RELOAD, Series, X, state_at, watch_run};
use crate::model::contact::{Contact, ContactLaw, Unloading};
use crate::model::params::{ImpactParams, Normalized};
use crate::solver::Unresolved;
use crate::solver::roots::brent;

/// The pair's answer in ball 1's reduced units: ᾱ' at separation (−e), the peak force, the
/// contact time (τ) and ball 1's own contact indentations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairOutcome {
    /// e, the pair's COR (0 without rebound).
    pub cor: f64,
    /// F̄_m.
    pub f_max: f64,
    /// τ_f, or the horizon after which "no rebound" was concluded.
    pub tau_end: f64,
    /// Whether the pair let go within the horizon.
    pub rebound: bool,
    /// Ball 1's peak indentation z̄_m1 (its contact's share of Z̄ at the turn).
    pub z_max: f64,
    /// Ball 1's permanent indentation z̄_f1 (Eq. 18, from its own peak).
    pub z_f: f64,
}

#[derive(Clone, Copy)]
enum Branch {
    Loading,
    Unloading(Unloading, Unloading),
}

struct Pair {
    n1: Normalized,
    n2: Normalized,
    c1: Contact,
    c2: Contact,
    /// r = ω₂/ω₁.
    r: f64,
    branch: Branch,
}

impl Pair {
    /// Both contacts' indentations (ball 1's units) at force F̄.
    fn indentations(&self, f: f64) -> (f64, f64) {
        let r = self.r;
        match &self.branch {
            Branch::Loading => (
                self.c1.loading_indentation(f),
                self.c2.loading_indentation(f / r) / r,
            ),
            Branch::Unloading(u1, u2) => (
                self.c1.unloading_indentation(f, u1),
                self.c2.unloading_indentation(f / r, u2) / r,
            ),
        }
    }

    /// The force at which the two indentations add to Z̄ (0 at or below the permanent ones).
    fn force(&self, z: f64) -> f64 {
        let h = |f: f64| {
            let (a, b) = self.indentations(f);
            a + b - z
        };
        let h0 = h(0.0);
        if h0 >= 0.0 {
            return 0.0;
        }
        let mut hi = 1.0;
        let mut hh = h(hi);
        while hh < 0.0 {
            hi *= 2.0;
            hh = h(hi);
        }
        brent(h, 0.0, hi, h0, hh, 1e-16 * hi)
    }
}

/// The state is (Z̄, ᾱ', ȳ₁, ȳ₂).
impl Series for Pair {
    /// (F̄, ȳ₁', ȳ₂', Z̄') at x.
    fn rates(&self, x: &X) -> (f64, f64, f64, f64) {
        let f = self.force(x[0]);
        let relax = |n: &Normalized, f: f64, y: f64| {
            if n.zeta > 0.0 {
                2.0 * n.zeta * (f - n.lambda * y)
            } else {
                0.0
            }
        };
        let y1 = relax(&self.n1, f, x[2]);
        // ball 2's pair in its own units (ȳ₂ r, F̄/r), its rate unchanged by the scaling
        let y2 = relax(&self.n2, f / self.r, self.r * x[3]);
        (f, y1, y2, x[1] - y1 - y2)
    }

    /// What ends the phase, as g crossing 0 upward: the turn (−Z̄'), separation, reload.
    fn watches(&self, x: &X) -> [f64; 2] {
        match &self.branch {
            Branch::Loading => [-self.rates(x).3, f64::NEG_INFINITY],
            Branch::Unloading(u1, u2) => {
                let (zm, zf) = (u1.z_m + u2.z_m / self.r, u1.z_f + u2.z_f / self.r);
                [zf - x[0], x[0] - zm * (1.0 + RELOAD)]
            }
        }
    }
}

/// The head-on impact of ball `p1` with ball `p2` (their `v0` ignored) at closing speed
/// `closing` (m/s), both on `law`. A pair that does not let go within the horizon (a hundred
/// times the slowest of its periods and relaxations) is no rebound (`rebound` false, e 0); an
/// error says which budget (steps, phases) ran out.
pub fn solve(
    p1: &ImpactParams,
    p2: &ImpactParams,
    law: ContactLaw,
    closing: f64,
) -> Result<PairOutcome, Unresolved> {
    let m_star = p1.mass * p2.mass / (p1.mass + p2.mass);
    let b1 = ImpactParams {
        mass: m_star,
        v0: closing,
        ..*p1
    };
    let b2 = ImpactParams {
        mass: m_star,
        v0: closing,
        ..*p2
    };
    let (n1, n2) = (b1.normalized(), b2.normalized());
    let contact = |n: &Normalized| Contact {
        law,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let mut pair = Pair {
        n1,
        n2,
        c1: contact(&n1),
        c2: contact(&n2),
        r: b2.omega0() / b1.omega0(),
        branch: Branch::Loading,
    };
    let soft = |n: &Normalized| if n.lambda > 0.0 { 1.0 / n.lambda } else { 0.0 };
    let t_max = 100.0 * std::f64::consts::PI * (2.0 + soft(&n1) + soft(&n2) + 1.0 / pair.r);
    let (mut t, mut x) = (0.0, [0.0, 1.0, 0.0, 0.0]);
    let mut f_max: f64 = 0.0;
    let (mut z_max, mut z_f): (f64, f64) = (0.0, 0.0);
    for _ in 0..MAX_PHASES {
        let (done, hit) = watch_run(&pair, (t, x), t_max, &mut FirstEvent(&pair));
        if !done {
            return Err(Unresolved::Steps);
        }
        let Some((tc, which, tp, xp)) = hit else {
            // followed to the horizon without letting go: no rebound
            return Ok(PairOutcome {
                cor: 0.0,
                f_max,
                tau_end: t_max,
                rebound: false,
                z_max,
                z_f,
            });
        };
        let Some(end) = state_at(&pair, (tp, xp), tc) else {
            return Err(Unresolved::Steps);
        };
        (t, x) = (tc, end);
        match (pair.branch, which) {
            (Branch::Loading, _) => {
                let f = pair.force(x[0]);
                f_max = f_max.max(f);
                let (z1, z2) = pair.indentations(f);
                let u1 = pair.c1.unload_from(z1);
                let u2 = pair.c2.unload_from(z2 * pair.r);
                (z_max, z_f) = (z_max.max(u1.z_m), u1.z_f);
                pair.branch = Branch::Unloading(u1, u2);
            }
            (Branch::Unloading(..), 0) => {
                // the force gone with the two still closing (ᾱ' ≥ 0: sunk into each other,
                // λ = 0 and ζ ≥ 1) is no rebound, as the wall impact says
                return Ok(PairOutcome {
                    cor: (-x[1]).clamp(0.0, 1.0),
                    f_max,
                    tau_end: t,
                    rebound: x[1] < 0.0,
                    z_max,
                    z_f,
                });
            }
            (Branch::Unloading(..), _) => pair.branch = Branch::Loading,
        }
    }
    Err(Unresolved::Phases)
}

/// Ball `p1` (its `v0` ignored) at `ball_speed` toward ball `p2` coming at `other_speed`,
/// head-on, both chains in series (docs/targets.md §8), as a [`super::Collision`] in SI: the
/// pair's e, F_m, t_f, ball 1's z_m and z_f, and both speeds out from the impulse
/// J = m*(1 + e) v_c (docs/targets.md §3). The partner has no surface apart from its own
/// chain: `max_target_deflection` is 0. Method: numeric (DOP853).
pub fn collide(
    p1: &ImpactParams,
    p2: &ImpactParams,
    law: ContactLaw,
    ball_speed: f64,
    other_speed: f64,
) -> Result<super::Collision, crate::solver::SolveError> {
    use crate::model::params::Field;
    let partner = super::Target {
        mass: p2.mass,
        speed: other_speed,
        ..super::Target::wall()
    };
    partner.validate()?;
    if !ball_speed.is_finite() {
        return Err(super::bad(Field::V0, ball_speed, "must be finite").into());
    }
    let closing = ball_speed + other_speed;
    if closing.is_nan() || closing <= 0.0 {
        return Err(super::bad(
            Field::TargetSpeed,
            other_speed,
            "the ball and the target never meet: v0 + target_speed must be positive",
        )
        .into());
    }
    let m_star = p1.mass * p2.mass / (p1.mass + p2.mass);
    let reduced = ImpactParams {
        mass: m_star,
        v0: closing,
        ..*p1
    };
    reduced.validate()?;
    ImpactParams {
        mass: m_star,
        v0: closing,
        ..*p2
    }
    .validate()?;
    let o = solve(p1, p2, law, closing).map_err(|reason| {
        let n = reduced.normalized();
        crate::solver::SolveError::Unresolved {
            steps: if reason == Unresolved::Steps {
                MAX_STEPS
            } else {
                0
            },
            reason,
            lambda: n.lambda,
            zeta: n.zeta,
        }
    })?;
    let outcome = super::Outcome {
        rebound: o.rebound,
        tau_end: o.tau_end,
        velocity_end: -o.cor,
        f_max: o.f_max,
        z_max: o.z_max,
        z_f: o.z_f,
        s_max: 0.0,
        method: crate::solver::Method::Numeric,
    };
    let relative = outcome.to_si(&reduced);
    Ok(relative.into_collision(p1.mass, &partner, ball_speed, m_star))
}
