//! A stiff, lightly damped surface on the nonlinear laws (docs/targets.md §4): the spring-alone
//! limit stands for it where the dashpot's estimated work is negligible, and that estimate is
//! checked against the damped surface integrated where the integrator can still follow it.

use super::*;
use crate::api::Ball;

fn tennis() -> crate::model::params::Normalized {
    Ball::from_preset("tennis").unwrap().params.normalized()
}

/// A surface of stiffness λ_s whose dashpot relaxes at the normalized rate 2ζ_s λ_s.
fn surface(lambda_s: f64, rate: f64) -> Surface {
    Surface {
        lambda_s,
        zeta_s: rate / (2.0 * lambda_s),
    }
}

fn cor(o: &Outcome) -> f64 {
    -o.velocity_end
}

/// The dashpot's work as `integrated` estimates it, as a change of e.
fn estimate(spring: &Outcome, s: &Surface) -> f64 {
    let pulse = std::f64::consts::PI.powi(2) * spring.f_max.powi(2) / (2.0 * spring.tau_end);
    PULSE_MARGIN * pulse / (2.0 * s.zeta_s * s.lambda_s * s.lambda_s) / cor(spring)
}

/// Where the damped surface can still be integrated (rate 3·10⁴, ~10⁵ steps) its e departs
/// from the spring alone's by less than the estimate, and by more than a tenth of it: the
/// estimate bounds the dashpot's effect without being vacuous — on both nonlinear laws.
#[test]
fn the_dashpots_estimated_work_bounds_its_effect() {
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let n = tennis();
        for lambda_s in [30.0, 300.0, 3000.0] {
            let s = surface(lambda_s, 3e4);
            let damped = numeric::solve(&n, law, &s).unwrap();
            let spring = Surface {
                zeta_s: f64::INFINITY,
                ..s
            };
            let spring = numeric::solve(&n, law, &spring).unwrap();
            let effect = cor(&spring) - cor(&damped);
            let est = estimate(&spring, &s);
            let what = format!("{law} λ_s {lambda_s}: effect {effect:e}, estimate {est:e}");
            assert!(
                effect > 0.0 && effect <= est && effect >= 0.1 * est,
                "{what}"
            );
        }
    }
}

/// The case — K_s = 10⁵ K_p with a few kg/s, which ran the integrator out of steps
/// (exit 1) — answers on both nonlinear laws; the ball's dashpot locked (c = ∞, ζ = 0) it
/// loses no energy but the surface dashpot's negligible share: e = 1 to 1e-10.
#[test]
fn a_stiff_lightly_damped_surface_answers_and_keeps_the_energy() {
    let p = Ball::from_preset("tennis").unwrap().params;
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let target = Target {
            stiffness: 1e5 * p.k_p,
            damping: 3.0,
            ..Target::wall()
        };
        let locked = ImpactParams {
            damping: f64::INFINITY,
            z_p: if law == ContactLaw::Hertz { p.z_p } else { 1e3 },
            ..p
        };
        let c = collide(&locked, law, &target, p.v0, None).unwrap();
        assert!((c.cor - 1.0).abs() <= 1e-10, "{law}: {}", c.cor);
        let c = collide(&p, law, &target, p.v0, None).unwrap();
        let rigid = collide(&p, law, &Target::wall(), p.v0, None).unwrap();
        // between the rigid wall's and a softer surface's (K_s = 10³ K_p, the same dashpot)
        let soft = Target {
            stiffness: 1e3 * p.k_p,
            ..target
        };
        let soft = collide(&p, law, &soft, p.v0, None).unwrap();
        let (gap, wider) = ((c.cor - rigid.cor).abs(), (soft.cor - rigid.cor).abs());
        assert!(gap * 30.0 <= wider, "{law}: {gap:e} {wider:e}");
    }
}
