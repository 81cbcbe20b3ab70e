//! The model's chain at rest under a load (docs/model.md §1–§3): the contact element and, in
//! series behind it, the recoil spring K_r (the dashpot carries nothing at rest, Eq. 2 with
//! y' = 0: K_r y = F). One contact pressed by a force F deflects
//!
//! ```text
//! δ(F) = z(F) + F/K_r,
//! ```
//!
//! z(F) the loading branch's indentation at F (Eqs. 21, 7, 10–11 inverted): F/K_p for the
//! linear law, (F/K_h)^{2/3} for Hertz, and for the elastic–plastic law Hertz up to
//! F_p = K_h z_p^{3/2}, then z_p + (F − F_p)/K_p. A ball squeezed between two plates under a
//! load of mass M carries F = M g at each of its two contacts, so its diameter shortens by
//! 2 δ(M g): for the linear law d = 2F (1/K_p + 1/K_r). The tennis preset once held K_p = K_r =
//! 24 713 N/m (2F/d, the recoil spring forgotten) and so shortened by 12.96 mm under the ITF's
//! 8.165 kg, outside its 5.59–7.37 mm window; refitted through this chain it gives 6.48 mm. Here to be shared by `bouncelab static` (issue 52 item 6) and the
//! joint fit's static deflections (item 5), so both use one formula.

use super::contact::ContactLaw;
use super::params::ImpactParams;

/// Standard gravity, m/s² (CGPM 1901, exact), with which a load in kg becomes a force.
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// The indentation of the loading branch carrying force `f` ≥ 0 (m), in SI.
pub fn loading_indentation(p: &ImpactParams, law: ContactLaw, f: f64) -> f64 {
    let f = f.max(0.0);
    let hertz = |f: f64| (f / p.k_h).powf(2.0 / 3.0);
    match law {
        ContactLaw::Linear => f / p.k_p,
        ContactLaw::Hertz => hertz(f),
        ContactLaw::ElasticPlastic => {
            let f_p = p.k_h * p.z_p.powf(1.5);
            if f <= f_p {
                hertz(f)
            } else {
                p.z_p + (f - f_p) / p.k_p
            }
        }
    }
}

/// One contact's static deflection under force `f` (N): indentation plus the recoil spring's
/// compression, δ = z(F) + F/K_r (m).
pub fn contact_deflection(p: &ImpactParams, law: ContactLaw, f: f64) -> f64 {
    loading_indentation(p, law, f) + f.max(0.0) / p.k_r
}

/// The shortening of the ball's diameter between two plates under a load of `load_kg`
/// (each contact carries F = load·g): 2 δ(F) (m).
pub fn plates_deflection(p: &ImpactParams, law: ContactLaw, load_kg: f64) -> f64 {
    2.0 * contact_deflection(p, law, load_kg * STANDARD_GRAVITY)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(k_p: f64, k_r: f64, z_p: f64) -> ImpactParams {
        ImpactParams {
            mass: 0.0577,
            k_p,
            damping: 210.0,
            k_r,
            z_p,
            k_h: k_p / (1.5 * z_p.sqrt()),
            v0: 3.0,
        }
    }

    /// The tennis preset's numbers of issue 52: 2 F (1/K_p + 1/K_r) with F = 8.165 kg · g.
    #[test]
    fn linear_chain_under_the_itf_load() {
        let p = ball(24_713.0, 24_713.0, 0.0060342);
        let d = plates_deflection(&p, ContactLaw::Linear, 8.165);
        let f = 8.165 * 9.806_65;
        assert!((d - 2.0 * f * (2.0 / 24_713.0)).abs() < 1e-15, "{d}");
        assert!((d * 1e3 - 12.96).abs() < 0.005, "{d}");
    }

    /// Each branch inverts its force law (docs/model.md Eqs. 7, 10, 11): the force at the
    /// indentation found is the force asked; the elastic–plastic branches meet at z_p.
    #[test]
    fn the_indentation_inverts_each_law() {
        let p = ball(5.45e4, 7.08e4, 0.004);
        for f in [0.5, 10.0, 200.0, 5000.0] {
            let z = loading_indentation(&p, ContactLaw::Hertz, f);
            assert!((p.k_h * z.powf(1.5) / f - 1.0).abs() < 1e-12);
            let z = loading_indentation(&p, ContactLaw::ElasticPlastic, f);
            let back = if z <= p.z_p {
                p.k_h * z.powf(1.5)
            } else {
                p.k_p * (z - p.z_p) + p.k_h * p.z_p.powf(1.5)
            };
            assert!((back / f - 1.0).abs() < 1e-12, "{f}: {z}");
        }
        let f_p = p.k_h * p.z_p.powf(1.5);
        let below = loading_indentation(&p, ContactLaw::ElasticPlastic, f_p * (1.0 - 1e-12));
        let above = loading_indentation(&p, ContactLaw::ElasticPlastic, f_p * (1.0 + 1e-12));
        assert!((below - p.z_p).abs() < 1e-12 && (above - p.z_p).abs() < 1e-12);
        // the recoil spring in series adds F/K_r; no load, no deflection
        let d = contact_deflection(&p, ContactLaw::Hertz, 100.0);
        let z = loading_indentation(&p, ContactLaw::Hertz, 100.0);
        assert!((d - z - 100.0 / 7.08e4).abs() < 1e-15);
        assert_eq!(plates_deflection(&p, ContactLaw::Linear, 0.0), 0.0);
    }
}
