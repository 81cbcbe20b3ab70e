//! The ball squeezed slowly between two rigid plates (docs/model.md §11): the model's own static
//! chain, the deflection the ITF's forward and return deformation tests read.
//!
//! Statically the dashpot carries no force, so each plate's contact is the contact element in
//! series with the recoil spring K_r: under a steady load F one contact deflects
//! δ = z(F) + F/K_r, with z(F) the indentation at which the contact law's loading branch carries
//! F (Eqs. 7, 10–11, 21). Both plates carry the full load F (the ball is in equilibrium between
//! them), so the diameter shortens by 2δ. The return reading (compress to a peak, come back to
//! F) follows the law's unloading branch from the peak (Eqs. 12, 18–19, 22); the recoil spring
//! is elastic and returns along its own line.
//!
//! Pure: no I/O.

use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::ImpactParams;
use crate::solver::roots::brent;
use serde::Serialize;

/// The ITF return deformation test's peak: the ball is compressed until its diameter has
/// shortened by 1.00 in (2.54 cm), then unloaded back to the load (C. Lindsey, "Tennis Ball
/// Performance Testing", Tennis Warehouse University, 2021; docs/presets.md).
pub const ITF_RETURN_PEAK: f64 = 0.0254;

/// One contact's share of a static deflection, m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ContactDeflection {
    /// z: the contact element's indentation at the plate.
    pub indentation: f64,
    /// F/K_r: the recoil spring's compression behind it.
    pub recoil: f64,
}

impl ContactDeflection {
    /// δ = z + F/K_r, one plate's approach to the ball's centre.
    pub fn total(&self) -> f64 {
        self.indentation + self.recoil
    }

    /// 2δ: the shortening of the diameter between the two plates.
    pub fn diameter(&self) -> f64 {
        2.0 * self.total()
    }
}

/// The static answer: forward deflection under F, return deflection at F after a peak.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticDeflection {
    /// The load F on each contact, N.
    pub force: f64,
    /// Forward: loading from the undeformed ball to F (`Err`: why the model gives none).
    pub forward: Result<ContactDeflection, String>,
    /// The diameter shortening the ball is first taken to for the return reading, m.
    pub peak: f64,
    /// The force at that peak, N (`None` where there is no return reading).
    pub peak_force: Option<f64>,
    /// Return: back down to F from the peak (`Err`: why the model gives none).
    pub return_: Result<ContactDeflection, String>,
}

/// A contact law in SI units: F = K_p · f(z) with f the normalized law taken with z̄ = z (m),
/// z̄_p = z_p and κ = K_h/K_p (so K_p f(z) is K_p z, K_h z^{3/2}, or Eq. 11 in newtons).
fn si_contact(p: &ImpactParams, law: ContactLaw) -> Contact {
    Contact {
        law,
        zp_bar: p.z_p,
        kappa: p.k_h / p.k_p,
    }
}

/// Forward and return deflection of the ball between two plates under `force` (N), the return
/// read after compressing the diameter by `peak` (m). A ball without a recoil spring
/// (K_r = 0) creeps into its dashpot under any steady load: no static answer.
pub fn static_deflection(
    p: &ImpactParams,
    law: ContactLaw,
    force: f64,
    peak: f64,
) -> StaticDeflection {
    let none = |why: &str| StaticDeflection {
        force,
        forward: Err(why.to_string()),
        peak,
        peak_force: None,
        return_: Err(why.to_string()),
    };
    if p.k_r <= 0.0 {
        return none(
            "K_r = 0: with no recoil spring the ball creeps into its dashpot under any steady \
             load (docs/model.md §11)",
        );
    }
    let c = si_contact(p, law);
    let at = |f: f64| ContactDeflection {
        indentation: c.loading_indentation(f / p.k_p),
        recoil: f / p.k_r,
    };
    let forward = at(force);
    let mut answer = StaticDeflection {
        force,
        forward: Ok(forward),
        peak,
        peak_force: None,
        return_: Err(String::new()),
    };
    if law == ContactLaw::Hertz {
        answer.return_ = Err(
            "the hertz law is elastic: it unloads along its loading curve, \
                              with no hysteresis and so no separate return deflection"
                .into(),
        );
        return answer;
    }
    let f_m = peak_force(p, &c, peak / 2.0);
    if f_m < force {
        let short = crate::text::short;
        answer.return_ = Err(format!(
            "the peak {} m is reached below the load ({} N < {} N): the ball is never \
             unloaded to the load",
            short(peak, 6),
            short(f_m, 4),
            short(force, 4)
        ));
        return answer;
    }
    answer.peak_force = Some(f_m);
    let u = c.unload_from(c.loading_indentation(f_m / p.k_p));
    answer.return_ = Ok(ContactDeflection {
        indentation: c.unloading_indentation(force / p.k_p, &u),
        recoil: force / p.k_r,
    });
    answer
}

/// The force F_m at which one contact's chain deflects `delta`: z(F_m) + F_m/K_r = δ. The linear
/// law in closed form, F_m = δ/(1/K_p + 1/K_r); the others by Brent on the monotone chain.
fn peak_force(p: &ImpactParams, c: &Contact, delta: f64) -> f64 {
    if c.law == ContactLaw::Linear {
        return delta / (1.0 / p.k_p + 1.0 / p.k_r);
    }
    let chain = |f: f64| c.loading_indentation(f / p.k_p) + f / p.k_r - delta;
    // the chain is at least as soft as the recoil spring alone: F_m ≤ K_r δ
    let hi = p.k_r * delta;
    brent(
        chain,
        0.0,
        hi,
        chain(0.0),
        chain(hi),
        1e-14 * hi.max(1e-300),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(k_p: f64, k_r: f64, z_p: f64) -> ImpactParams {
        ImpactParams {
            mass: 0.05,
            k_p,
            damping: 100.0,
            k_r,
            z_p,
            k_h: k_p / (1.5 * z_p.sqrt()),
            v0: 1.0,
        }
    }

    fn close(a: f64, b: f64, rel: f64) {
        assert!((a - b).abs() <= rel * b.abs(), "{a} against {b}");
    }

    #[test]
    fn linear_forward_is_two_springs_in_series_at_each_plate() {
        // d = 2F(1/K_p + 1/K_r)
        let p = ball(49_000.0, 30_000.0, 6e-3);
        let s = static_deflection(&p, ContactLaw::Linear, 80.0, 0.0254);
        let d = s.forward.clone().unwrap().diameter();
        close(d, 2.0 * 80.0 * (1.0 / 49_000.0 + 1.0 / 30_000.0), 1e-14);
    }

    #[test]
    fn linear_return_follows_the_unloading_line_from_the_peak() {
        let (k_p, k_r, z_p, f) = (49_000.0, 30_000.0, 2e-3, 80.0);
        let p = ball(k_p, k_r, z_p);
        let peak = 0.0254;
        let s = static_deflection(&p, ContactLaw::Linear, f, peak);
        // by hand: F_m from the series chain, z_m = F_m/K_p, Eqs. 18-19, Eq. 22 inverted
        let f_m = (peak / 2.0) / (1.0 / k_p + 1.0 / k_r);
        let z_m = f_m / k_p;
        let z_r = z_p * (2.0 * z_m / z_p - 1.0).sqrt();
        let z = (z_m - z_r) + z_r * f / f_m;
        close(s.peak_force.unwrap(), f_m, 1e-14);
        close(
            s.return_.clone().unwrap().diameter(),
            2.0 * (z + f / k_r),
            1e-13,
        );
        // hysteresis: the return reads more than the forward
        assert!(s.return_.clone().unwrap().diameter() > s.forward.clone().unwrap().diameter());
    }

    #[test]
    fn below_flattening_the_return_is_the_forward() {
        let p = ball(49_000.0, 30_000.0, 1.0);
        let s = static_deflection(&p, ContactLaw::Linear, 80.0, 0.0254);
        close(
            s.return_.clone().unwrap().diameter(),
            s.forward.clone().unwrap().diameter(),
            1e-14,
        );
    }

    #[test]
    fn hertz_forward_in_closed_form_and_no_return() {
        // z = (F/K_h)^{2/3} (Eq. 7 inverted)
        let p = ball(49_000.0, 30_000.0, 6e-3);
        let s = static_deflection(&p, ContactLaw::Hertz, 80.0, 0.0254);
        let z = (80.0 / p.k_h).powf(2.0 / 3.0);
        close(
            s.forward.clone().unwrap().diameter(),
            2.0 * (z + 80.0 / 30_000.0),
            1e-13,
        );
        assert!(s.return_.clone().unwrap_err().contains("elastic"));
    }

    #[test]
    fn elastic_plastic_forward_on_both_branches_and_its_return() {
        let p = ball(49_000.0, 30_000.0, 1e-3);
        let f_p = p.k_h * 1e-3_f64.powf(1.5);
        // below yield: Hertz; above: z = z_p + (F − F_p)/K_p (Eqs. 10, 11)
        let lo = static_deflection(&p, ContactLaw::ElasticPlastic, 0.5 * f_p, 0.0254);
        close(
            lo.forward.clone().unwrap().indentation,
            (0.5 * f_p / p.k_h).powf(2.0 / 3.0),
            1e-13,
        );
        let hi = static_deflection(&p, ContactLaw::ElasticPlastic, 80.0, 0.0254);
        close(
            hi.forward.clone().unwrap().indentation,
            1e-3 + (80.0 - f_p) / 49_000.0,
            1e-13,
        );
        // the peak's chain closes, and the 3/2-power unloading (Eq. 12) inverted by hand
        let f_m = hi.peak_force.unwrap();
        let z_m = 1e-3 + (f_m - f_p) / 49_000.0;
        close(z_m + f_m / 30_000.0, 0.0254 / 2.0, 1e-12);
        let z_r = 1e-3 * (2.0 * z_m / 1e-3 - 1.0).sqrt();
        let z = (z_m - z_r) + z_r * (80.0 / f_m).powf(2.0 / 3.0);
        close(hi.return_.clone().unwrap().indentation, z, 1e-10);
    }

    #[test]
    fn no_recoil_spring_no_static_answer_and_a_low_peak_no_return() {
        let p = ball(49_000.0, 0.0, 6e-3);
        let s = static_deflection(&p, ContactLaw::Linear, 80.0, 0.0254);
        assert!(s.forward.clone().unwrap_err().contains("K_r = 0"));
        let p = ball(49_000.0, 30_000.0, 6e-3);
        let s = static_deflection(&p, ContactLaw::Linear, 80.0, 1e-3);
        assert!(s.forward.is_ok());
        assert!(s.return_.clone().unwrap_err().contains("below the load"));
    }
}
