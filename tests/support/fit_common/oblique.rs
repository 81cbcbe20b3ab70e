//! The oblique fits' shared setting (tests/analysis/fit_oblique*.rs): the tennis ball's radius,
//! a spread of bounces that shows both μ and K_t, the bounces made from a known truth, and a
//! fit's start.

use super::Rng;
use bouncelab::Ball;
use bouncelab::analysis::fit::oblique::ObliqueStart;
use bouncelab::measured::ObliqueRow;
use bouncelab::model::contact::ContactLaw;
use bouncelab::oblique::{self, Oblique};

/// The tennis ball's radius, m.
pub const R: f64 = 0.0335;

/// Low angles that slide throughout (they show μ) and steep ones that grip (they show K_t):
/// (v0 m/s, angle °, spin rad/s).
pub fn mixed() -> Vec<(f64, f64, f64)> {
    let mut c = Vec::new();
    for (k, angle) in [8.0, 12.0, 16.0, 25.0, 35.0, 45.0, 55.0, 65.0, 75.0]
        .into_iter()
        .enumerate()
    {
        for spin in [-200.0, 0.0, 250.0] {
            c.push((15.0 + 2.0 * k as f64, angle, spin));
        }
    }
    c
}

/// A fit of μ, K_t and κ from the tennis ball on the linear law, K_t and κ started at `kt`
/// and `kappa`.
pub fn start(kt: f64, kappa: f64) -> ObliqueStart {
    let ball = Ball::from_preset("tennis").unwrap();
    ObliqueStart {
        params: ball.params,
        law: ContactLaw::Linear,
        radius: R,
        friction: None,
        tangential_stiffness: kt,
        inertia_factor: kappa,
        tangential_damping: None,
    }
}

/// Gaussian noise on a data set's readings: v_x,out, and v_y,out (m/s; `None`: exact), and ω_out
/// (rad/s; `None`: not measured). Drawn in that order, bounce by bounce.
#[derive(Clone, Copy)]
pub struct Noise {
    pub vx: f64,
    pub vy: Option<f64>,
    pub spin: Option<f64>,
}

impl Noise {
    /// Noise of `sd` on v_x,out only; no spins measured.
    pub fn vx(sd: f64) -> Noise {
        Noise {
            vx: sd,
            vy: None,
            spin: None,
        }
    }
}

/// The tennis ball's bounces at `cases` (v0 m/s, angle °, spin rad/s) under μ, K_t, κ and the
/// tangential dashpot `ct` (kg/s; `None`: none), on the linear law, with `noise`.
pub fn bounces(
    cases: &[(f64, f64, f64)],
    (mu, kt, kappa): (f64, f64, f64),
    ct: Option<f64>,
    noise: Noise,
    rng: &mut Rng,
) -> Vec<ObliqueRow> {
    let p = Ball::from_preset("tennis").unwrap().params;
    cases
        .iter()
        .enumerate()
        .map(|(i, &(v0, angle, spin))| {
            let mut o = Oblique::new(angle, spin, mu, kt, kappa, R).unwrap();
            if let Some(ct) = ct {
                o = o.with_tangential_damping(ct).unwrap();
            }
            let r = oblique::solve_law(&p, ContactLaw::Linear, v0, &o, 0).unwrap();
            let vx_out = r.vx_out + noise.vx * rng.normal();
            let vy_out = match noise.vy {
                Some(s) => r.vy_out + s * rng.normal(),
                None => r.vy_out,
            };
            ObliqueRow {
                v0,
                angle_deg: angle,
                spin_in: spin,
                vx_out,
                vy_out,
                spin_out: noise.spin.map(|s| r.spin_out + s * rng.normal()),
                line: i + 2,
            }
        })
        .collect()
}
