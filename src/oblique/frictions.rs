//! One arrival under several frictions, the normal impact solved once: the explorer's (angle,
//! μ) map (src/tui/views/oblique/) asks 50 frictions at each of 90 angles, and the normal
//! motion depends on the angle alone (docs/oblique.md §1: it is driven by v_y = v sin θ).

use super::{Oblique, ObliqueError, ObliqueResponse, Scaled, energy, prepare, tangential};
use crate::model::params::ImpactParams;

/// [`super::solve`] of `oblique` with each friction of `frictions` in turn (no history),
/// sharing the normal impact and its flow: each answer equals `solve`'s to the last bit
/// (`frictions_equal_solve` below). The outer error is the arrival's (the
/// angle, the normal impact); each inner one that friction's.
pub fn solve_frictions(
    params: &ImpactParams,
    v: f64,
    oblique: &Oblique,
    frictions: &[f64],
) -> Result<Vec<Result<ObliqueResponse, ObliqueError>>, ObliqueError> {
    let p = prepare(params, v, oblique)?;
    // the slip velocity at first touch, in v_y, written as `solve` writes it
    let (vx_n, w_n) = (p.vx / p.vy, oblique.radius * oblique.spin / p.vy);
    let one = |mu: f64| {
        let o = Oblique {
            friction: mu,
            ..*oblique
        };
        o.validate()?;
        let s = Scaled::new(mu, p.scaled.kt, p.scaled.kappa);
        let run = tangential::run(&p.path, &s, vx_n - w_n)?;
        let answer = energy::Answer {
            params: &p.normal_params,
            oblique: &o,
            scaled: &s,
            vx: p.vx,
            vy: p.vy,
            v,
        };
        Ok(answer.response(&p.path, run, p.normal.clone(), 0))
    };
    Ok(frictions.iter().map(|&mu| one(mu)).collect())
}

#[cfg(test)]
mod tests {
    use super::solve_frictions;
    use crate::oblique::{Oblique, mindlin_ratio, solve};

    #[test]
    fn frictions_equal_solve() {
        let ball = crate::preset::Preset::embedded_all()
            .into_iter()
            .find(|p| p.name == "tennis")
            .expect("tennis is embedded");
        let p = ball.params();
        let k_t = mindlin_ratio(0.5) * p.k_p;
        let kappa = ball.measured.inertia_factor.expect("tennis names κ");
        let mus = [0.0, 0.05, 0.3, 0.6, 2.0];
        for (angle, spin) in [(16.0, 300.0), (40.0, -200.0), (85.0, 0.0)] {
            let o = Oblique::new(angle, spin, 0.5, k_t, kappa, ball.measured.radius).unwrap();
            let all = solve_frictions(&p, 25.0, &o, &mus).unwrap();
            for (mu, got) in mus.iter().zip(all) {
                let alone = solve(&p, 25.0, &Oblique { friction: *mu, ..o }, 0).unwrap();
                assert_eq!(got.unwrap(), alone, "angle {angle}, spin {spin}, μ {mu}");
            }
        }
        // a friction out of its range is that friction's error, the others answer
        let o = Oblique::new(30.0, 0.0, 0.5, k_t, kappa, 0.0335).unwrap();
        let all = solve_frictions(&p, 25.0, &o, &[-1.0, 0.4]).unwrap();
        assert!(all[0].is_err() && all[1].is_ok());
    }
}
