//! The oblique fits' shared setting (tests/analysis/fit_oblique.rs, tests/analysis/fit_oblique_coverage.rs): the
//! tennis ball's radius, a spread of bounces that shows both μ and K_t, and a fit's start.

use bouncelab::Ball;
use bouncelab::analysis::fit::oblique::ObliqueStart;
use bouncelab::model::contact::ContactLaw;

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
