//! The three contact laws F = f(z) (Eqs. 7–22), written in normalized units
//! (F̄ = F/(m v0 ω0), z̄ = z ω0/v0, docs/model.md §5) where the linear stiffness K_p is 1.

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// x^{3/2} as x √x: the force law sits in the integrator's innermost loop, and powf costs
/// several times a square root.
fn pow15(x: f64) -> f64 {
    x * x.sqrt()
}

/// x^{5/2} as x² √x.
fn pow25(x: f64) -> f64 {
    x * x * x.sqrt()
}

/// Which contact law relates force to indentation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactLaw {
    /// Linearized bilinear law (Eqs. 21–22): loading F = K_p z, linear unloading to z_f.
    Linear,
    /// Elastic–fully plastic (Eqs. 10–19): Hertz to z_p, then slope K_p; 3/2-power unloading.
    ElasticPlastic,
    /// Hertz alone (Eqs. 7–9): F = K_h z^{3/2}, elastic.
    Hertz,
}

impl ContactLaw {
    /// The three laws, in the order the explorer cycles through them.
    pub const ALL: [ContactLaw; 3] = [
        ContactLaw::Linear,
        ContactLaw::ElasticPlastic,
        ContactLaw::Hertz,
    ];

    /// Its name in presets, on the command line (`--law`) and in the JSON: `linear`,
    /// `elastic-plastic`, `hertz` (the inverse of `str::parse`).
    pub fn name(self) -> &'static str {
        match self {
            ContactLaw::Linear => "linear",
            ContactLaw::ElasticPlastic => "elastic-plastic",
            ContactLaw::Hertz => "hertz",
        }
    }

    /// The next law in `ALL`, wrapping (the explorer's `c` key).
    pub fn next(self) -> ContactLaw {
        let i = ContactLaw::ALL.iter().position(|&l| l == self).unwrap_or(0);
        ContactLaw::ALL[(i + 1) % ContactLaw::ALL.len()]
    }
}

impl fmt::Display for ContactLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for ContactLaw {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ContactLaw::ALL
            .into_iter()
            .find(|l| l.name() == s)
            .ok_or_else(|| {
                format!("unknown contact law '{s}' (expected linear, elastic-plastic or hertz)")
            })
    }
}

/// The unloading branch entered at the peak indentation z_m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unloading {
    /// Peak indentation z̄_m.
    pub z_m: f64,
    /// Force at the peak F̄_m.
    pub f_m: f64,
    /// Permanent indentation z̄_f (Eq. 18).
    pub z_f: f64,
}

/// A contact law with its normalized constants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// The law.
    pub law: ContactLaw,
    /// z̄_p, the flattening / plastic threshold (∞: none).
    pub zp_bar: f64,
    /// κ = K_h √(v0/ω0) / K_p: F̄ = κ z̄^{3/2} on the Hertz branch.
    pub kappa: f64,
}

impl Contact {
    /// Force on the loading branch (Eqs. 10–11, 21, 7).
    pub fn loading_force(&self, z: f64) -> f64 {
        if z <= 0.0 {
            return 0.0;
        }
        match self.law {
            ContactLaw::Linear => z,
            ContactLaw::Hertz => self.kappa * pow15(z),
            ContactLaw::ElasticPlastic if z <= self.zp_bar => self.kappa * pow15(z),
            ContactLaw::ElasticPlastic => (z - self.zp_bar) + self.kappa * pow15(self.zp_bar),
        }
    }

    /// dF/dz on the loading branch (of `loading_force`), from below at the elastic–plastic
    /// kink z_p (the side `loading_force` takes there).
    pub fn loading_stiffness(&self, z: f64) -> f64 {
        if z <= 0.0 {
            return 0.0;
        }
        match self.law {
            ContactLaw::Linear => 1.0,
            ContactLaw::ElasticPlastic if z > self.zp_bar => 1.0,
            ContactLaw::Hertz | ContactLaw::ElasticPlastic => 1.5 * self.kappa * z.sqrt(),
        }
    }

    /// Permanent indentation after unloading from z_m: z_f = z_m − z_r, with
    /// z_r = z_p (2 z_m/z_p − 1)^{1/2} above z_p and z_r = z_m below (Eqs. 18, 19).
    /// Hertz alone is elastic: z_f = 0.
    pub fn permanent_indentation(&self, z_m: f64) -> f64 {
        if self.law == ContactLaw::Hertz || z_m <= self.zp_bar {
            return 0.0;
        }
        let z_r = self.zp_bar * (2.0 * z_m / self.zp_bar - 1.0).sqrt();
        (z_m - z_r).max(0.0)
    }

    /// The unloading branch that starts at z_m.
    pub fn unload_from(&self, z_m: f64) -> Unloading {
        Unloading {
            z_m,
            f_m: self.loading_force(z_m),
            z_f: self.permanent_indentation(z_m),
        }
    }

    /// Force on an unloading branch: linear for the bilinear law (Eq. 22), 3/2 power otherwise
    /// (Eq. 12). Zero at and below z_f: contact is lost. Past z_m the branch goes on by the
    /// same formula: a reload switches to the loading law there (docs/model.md §3), but the
    /// adaptive solver switches a hair past z_m (see `solver::numeric::RELOAD_SLACK`), and the
    /// branch must stay smooth up to the switch, for a stiff integrator's Newton iteration
    /// stalls on a kink in the force.
    pub fn unloading_force(&self, z: f64, u: &Unloading) -> f64 {
        // An unloading branch entered at z_m ≤ z_f (the adaptive solver, in a stiff extreme,
        // can place the unload event at z ≤ 0, where F = 0) carries no force; the 3/2 power of
        // the negative ratio would be NaN and poison the whole run (tests/physics/fuzz_regressions.rs,
        // `solver_inputs_regressions`; `unloading_from_no_indentation_has_no_force`).
        if z <= u.z_f || u.z_m <= u.z_f {
            return 0.0;
        }
        let ratio = (z - u.z_f) / (u.z_m - u.z_f);
        match self.law {
            ContactLaw::Linear => u.f_m * ratio,
            _ => u.f_m * pow15(ratio),
        }
    }

    /// dF/dz on an unloading branch (of `unloading_force`): what sets how fast a dashpot in
    /// series relaxes the contact.
    pub fn unloading_stiffness(&self, z: f64, u: &Unloading) -> f64 {
        if z <= u.z_f || u.z_m <= u.z_f {
            return 0.0;
        }
        let span = u.z_m - u.z_f;
        match self.law {
            ContactLaw::Linear => u.f_m / span,
            _ => 1.5 * u.f_m / span * ((z - u.z_f) / span).sqrt(),
        }
    }

    /// The indentation at which the loading branch carries force `f` ≥ 0: the inverse of
    /// `loading_force` (Eqs. 10–11, 21, 7).
    pub fn loading_indentation(&self, f: f64) -> f64 {
        let f = f.max(0.0);
        let hertz = |f: f64| (f / self.kappa).powf(2.0 / 3.0);
        match self.law {
            ContactLaw::Linear => f,
            ContactLaw::Hertz => hertz(f),
            ContactLaw::ElasticPlastic => {
                let f_p = self.kappa * pow15(self.zp_bar);
                if f <= f_p {
                    hertz(f)
                } else {
                    self.zp_bar + (f - f_p)
                }
            }
        }
    }

    /// The indentation at which the ball, on unloading branch `u`, carries force `f` ≥ 0: the
    /// inverse of `unloading_force` up to F̄_m (Eqs. 12, 22), and of the loading branch above
    /// it (where a reload continues).
    pub fn unloading_indentation(&self, f: f64, u: &Unloading) -> f64 {
        let f = f.max(0.0);
        if f >= u.f_m || u.z_m <= u.z_f {
            return self.loading_indentation(f).max(u.z_m);
        }
        let ratio = f / u.f_m;
        let span = u.z_m - u.z_f;
        match self.law {
            ContactLaw::Linear => u.z_f + span * ratio,
            _ => u.z_f + span * ratio.powf(2.0 / 3.0),
        }
    }

    /// ∫ F dz along the loading branch from 0 to z (an antiderivative, for the energy audit).
    pub fn loading_work(&self, z: f64) -> f64 {
        let z = z.max(0.0);
        let hertz = |z: f64| 0.4 * self.kappa * pow25(z);
        match self.law {
            ContactLaw::Linear => 0.5 * z * z,
            ContactLaw::Hertz => hertz(z),
            ContactLaw::ElasticPlastic if z <= self.zp_bar => hertz(z),
            ContactLaw::ElasticPlastic => {
                let d = z - self.zp_bar;
                hertz(self.zp_bar) + 0.5 * d * d + self.kappa * pow15(self.zp_bar) * d
            }
        }
    }

    /// ∫ F dz along an unloading branch from z_f to z.
    pub fn unloading_work(&self, z: f64, u: &Unloading) -> f64 {
        let span = u.z_m - u.z_f;
        // no force on a degenerate branch (see `unloading_force`), so no work
        if span <= 0.0 {
            return 0.0;
        }
        let d = (z - u.z_f).max(0.0);
        match self.law {
            ContactLaw::Linear => 0.5 * u.f_m * d * d / span,
            _ => 0.4 * u.f_m * pow25(d) / pow15(span),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ep(zp: f64) -> Contact {
        Contact {
            law: ContactLaw::ElasticPlastic,
            zp_bar: zp,
            kappa: 1.0 / (1.5 * zp.sqrt()),
        }
    }

    #[test]
    fn elastic_plastic_is_c1_at_zp() {
        // Eq. 16 makes the Hertz branch meet the linear one with matching slope.
        let c = ep(0.3);
        let h = 1e-7;
        let below = (c.loading_force(0.3) - c.loading_force(0.3 - h)) / h;
        let above = (c.loading_force(0.3 + h) - c.loading_force(0.3)) / h;
        assert!((below - 1.0).abs() < 1e-5 && (above - 1.0).abs() < 1e-5);
    }

    #[test]
    fn permanent_indentation_eq_18_19() {
        let c = ep(1.0);
        assert_eq!(c.permanent_indentation(0.5), 0.0);
        // z_m = 5 z_p: z_r = z_p √9 = 3 z_p, z_f = 2 z_p
        assert!((c.permanent_indentation(5.0) - 2.0).abs() < 1e-15);
    }

    #[test]
    fn work_matches_force() {
        for law in ContactLaw::ALL {
            let c = Contact { law, ..ep(0.4) };
            let u = c.unload_from(1.7);
            for z in [0.1, 0.39, 0.41, 1.2] {
                let h = 1e-6;
                let dl = (c.loading_work(z + h) - c.loading_work(z - h)) / (2.0 * h);
                assert!(
                    (dl - c.loading_force(z)).abs() < 1e-6,
                    "{law} loading at {z}"
                );
                if z > u.z_f + h {
                    let du =
                        (c.unloading_work(z + h, &u) - c.unloading_work(z - h, &u)) / (2.0 * h);
                    assert!(
                        (du - c.unloading_force(z, &u)).abs() < 1e-6,
                        "{law} unloading at {z}"
                    );
                }
            }
            // the unloading branch meets the loading one at the peak
            assert!((c.unloading_force(1.7, &u) - c.loading_force(1.7)).abs() < 1e-14);
        }
    }

    #[test]
    fn indentation_inverts_force() {
        for law in ContactLaw::ALL {
            let c = Contact { law, ..ep(0.4) };
            let u = c.unload_from(1.7);
            for z in [0.0, 0.1, 0.39, 0.4, 0.41, 1.2, 1.7, 2.5] {
                let back = c.loading_indentation(c.loading_force(z));
                assert!((back - z).abs() < 1e-12, "{law} loading at {z}: {back}");
                if z >= u.z_f {
                    let f = if z <= u.z_m {
                        c.unloading_force(z, &u)
                    } else {
                        c.loading_force(z)
                    };
                    let back = c.unloading_indentation(f, &u);
                    assert!((back - z).abs() < 1e-12, "{law} unloading at {z}: {back}");
                }
            }
        }
    }

    #[test]
    fn unloading_from_no_indentation_has_no_force() {
        for law in ContactLaw::ALL {
            let c = Contact { law, ..ep(0.4) };
            let u = c.unload_from(-0.04);
            for z in [-0.05, -0.01, 0.0, 0.3] {
                assert_eq!(c.unloading_force(z, &u), 0.0, "{law} at {z}");
                assert_eq!(c.unloading_work(z, &u), 0.0, "{law} at {z}");
            }
        }
    }

    #[test]
    fn law_names_round_trip() {
        for law in ContactLaw::ALL {
            assert_eq!(law.name().parse::<ContactLaw>().unwrap(), law);
        }
        assert!("plastic".parse::<ContactLaw>().is_err());
        assert_eq!(ContactLaw::Hertz.next(), ContactLaw::Linear);
    }
}
