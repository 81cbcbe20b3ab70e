//! One arrival under several frictions, the normal impact solved once: the explorer's (angle,
//! μ) map (src/tui/views/oblique/) asks 50 frictions at each of 90 angles, and the normal
//! motion depends on the angle alone (docs/oblique.md §1: it is driven by v_y = v sin θ).

use super::{NormalAt, Oblique, ObliqueError, ObliqueResponse};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;

/// [`super::solve_law`] of `oblique` under `law` with each friction of `frictions` in turn (no history),
/// sharing the normal impact ([`NormalAt`]): each answer equals `solve`'s to the last bit
/// (`frictions_equal_solve` below). The outer error is the arrival's (the angle, the normal
/// impact); each inner one that friction's.
pub fn solve_frictions(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
    frictions: &[f64],
) -> Result<Vec<Result<ObliqueResponse, ObliqueError>>, ObliqueError> {
    oblique.validate()?;
    let normal = NormalAt::new(params, law, v, oblique.angle_deg)?;
    let one = |mu: f64| {
        let o = Oblique {
            friction: mu,
            ..*oblique
        };
        normal.solve(&o, 0)
    };
    Ok(frictions.iter().map(|&mu| one(mu)).collect())
}

#[cfg(test)]
mod tests {
    use super::solve_frictions;
    use crate::model::contact::ContactLaw;
    use crate::oblique::{Oblique, mindlin_ratio, solve_law};

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
        let laws = [ContactLaw::Linear, ContactLaw::Hertz];
        for (law, (angle, spin)) in laws
            .into_iter()
            .flat_map(|l| [(16.0, 300.0), (40.0, -200.0), (85.0, 0.0)].map(|a| (l, a)))
        {
            let o = Oblique::new(angle, spin, 0.5, k_t, kappa, ball.measured.radius).unwrap();
            let all = solve_frictions(&p, law, 25.0, &o, &mus).unwrap();
            for (mu, got) in mus.iter().zip(all) {
                let one = Oblique { friction: *mu, ..o };
                let alone = solve_law(&p, law, 25.0, &one, 0).unwrap();
                assert_eq!(
                    got.unwrap(),
                    alone,
                    "{law:?} angle {angle}, spin {spin}, μ {mu}"
                );
            }
        }
        // a friction out of its range is that friction's error, the others answer
        let o = Oblique::new(30.0, 0.0, 0.5, k_t, kappa, 0.0335).unwrap();
        let all = solve_frictions(&p, ContactLaw::Linear, 25.0, &o, &[-1.0, 0.4]).unwrap();
        assert!(all[0].is_err() && all[1].is_ok());
    }
}
