//! Parameters from materials and geometry (docs/model.md §3–§4).

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Effective modulus of a ball of modulus E, Poisson ratio ν against a rigid flat:
/// E* = E/(1−ν²) (Eq. 9 with E2 → ∞).
pub fn effective_modulus(e: f64, nu: f64) -> f64 {
    e / (1.0 - nu * nu)
}

/// Effective modulus of two bodies, 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2 (Eq. 9).
pub fn effective_modulus_pair(e1: f64, nu1: f64, e2: f64, nu2: f64) -> f64 {
    1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2)
}

/// Hertz stiffness K_h = (4/3) E* √R (Eq. 8; the printed (4/3)√(R E*) is a slip).
pub fn hertz_stiffness(e_star: f64, radius: f64) -> f64 {
    4.0 / 3.0 * e_star * radius.sqrt()
}

/// κ = I/(m R²) of a solid sphere, I = (2/5) m R² ([`shell_inertia_factor`] at q = 0): a
/// ball whose preset names none, and the solid spheres of the codes an export is for
/// (LAMMPS's `atom_style sphere`, LIGGGHTS's and Yade's spheres, Chrono's
/// `ChBodyEasySphere`, a MuJoCo sphere geom's inferred inertia; src/peers/case.rs).
pub const SOLID_INERTIA_FACTOR: f64 = 0.4;

/// κ = I/(m R²) of a spherical shell of uniform density between radii `inner` and `outer`:
/// (2/5)(1 − q⁵)/(1 − q³), q = inner/outer (docs/oblique.md §1). 0.4 for a solid ball
/// (q = 0), 2/3 in the thin-shell limit (q → 1, taken by its series there).
pub fn shell_inertia_factor(outer: f64, inner: f64) -> f64 {
    let q = inner / outer;
    if 1.0 - q < 1e-6 {
        // (1 − q⁵)/(1 − q³) = (5/3) q + O((1 − q)²) near q = 1
        return 0.4 * 5.0 / 3.0 * q;
    }
    0.4 * (1.0 - q.powi(5)) / (1.0 - q.powi(3))
}

/// Density of a solid sphere from its mass and radius, ρ = m / (4/3 π R³).
pub fn density(mass: f64, radius: f64) -> f64 {
    mass / (4.0 / 3.0 * PI * radius.powi(3))
}

/// Shear modulus G = E/(2(1+ν)).
pub fn shear_modulus(e: f64, nu: f64) -> f64 {
    e / (2.0 * (1.0 + nu))
}

/// Dashpot from Rayleigh-wave radiation (Eq. 5): c = 0.94 A √(ρG), A = 4πR².
pub fn rayleigh_damping(radius: f64, density: f64, e: f64, nu: f64) -> f64 {
    0.94 * 4.0 * PI * radius * radius * (density * shear_modulus(e, nu)).sqrt()
}

/// A long bar hit axially: c = A √(ρE).
pub fn bar_damping(area: f64, density: f64, e: f64) -> f64 {
    area * (density * e).sqrt()
}

/// A large thin plate hit transversely: c = 8 √(ρ h D), D the flexural rigidity.
pub fn plate_damping(density: f64, thickness: f64, rigidity: f64) -> f64 {
    8.0 * (density * thickness * rigidity).sqrt()
}

/// The threshold and slope of the linear (plastic or flattening) phase.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Flattening {
    /// z_p (m), Eq. 17.
    pub z_p: f64,
    /// K_p (N/m), Eqs. 15–16.
    pub k_p: f64,
    /// p0 (Pa), the mean contact pressure once fully plastic / flattened.
    pub p0: f64,
}

/// Metals: p0 = 2.2 S_y, z_p = π² p0² R / E*² (Eq. 17), K_p = 2π R p0 (Eq. 15).
pub fn metal_plastic(e_star: f64, radius: f64, yield_strength: f64) -> Flattening {
    let p0 = 2.2 * yield_strength;
    Flattening {
        z_p: PI * PI * p0 * p0 * radius / (e_star * e_star),
        k_p: 2.0 * PI * radius * p0,
        p0,
    }
}

/// Elastomers flatten: p0 = E z_p / R (Eq. 20), so with (16, 17) z_p = R (E*/(πE))² and
/// K_p = 2π E z_p.
pub fn elastomer_flattening(e_star: f64, e: f64, radius: f64) -> Flattening {
    let z_p = radius * (e_star / (PI * e)).powi(2);
    Flattening {
        z_p,
        k_p: 2.0 * PI * e * z_p,
        p0: e * z_p / radius,
    }
}

/// One shell of a layered ball, outermost first.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Layer {
    /// What the layer is (informational).
    #[serde(default)]
    pub name: Option<String>,
    /// Thickness t_i (m).
    pub thickness: f64,
    /// Young's modulus E_i (Pa).
    pub modulus: f64,
    /// Density ρ_i (kg/m³); needed only for surface layers.
    #[serde(default)]
    pub density: Option<f64>,
    /// Poisson ratio ν_i (informational: the contact uses the ball's overall ν).
    #[serde(default)]
    pub poisson: Option<f64>,
    /// Whether the layer counts in the surface rule of mixtures (Eq. 31).
    #[serde(default)]
    pub surface: bool,
}

/// Modulus for contact of a layered ball, springs in series (Eq. 30): 1/E = (1/R) Σ t_i/E_i.
pub fn layered_contact_modulus(radius: f64, layers: &[Layer]) -> f64 {
    radius / layers.iter().map(|l| l.thickness / l.modulus).sum::<f64>()
}

/// Modulus and density along the surface, rule of mixtures over the surface layers (Eq. 31):
/// E = Σ t_i E_i / Σ t_i, likewise ρ. `None` if no layer is marked as surface.
pub fn layered_surface(layers: &[Layer]) -> Option<(f64, f64)> {
    let surf: Vec<&Layer> = layers.iter().filter(|l| l.surface).collect();
    let t: f64 = surf.iter().map(|l| l.thickness).sum();
    if surf.is_empty() || t <= 0.0 {
        return None;
    }
    let e = surf.iter().map(|l| l.thickness * l.modulus).sum::<f64>() / t;
    let rho = surf
        .iter()
        .map(|l| l.thickness * l.density.unwrap_or(0.0))
        .sum::<f64>()
        / t;
    Some((e, rho))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, rel: f64) -> bool {
        (a - b).abs() <= rel * b.abs()
    }

    /// docs/model.md §7: from the formulas the superball has z_p = 3.88 mm, K_p = 5.37e4 N/m,
    /// c = 140.3 kg/s, ρ = 892 kg/m³.
    #[test]
    fn superball_from_formulas() {
        let (m, r, e, nu) = (0.0374, 0.02155, 2.2e6, 0.5);
        let rho = density(m, r);
        assert!(close(rho, 892.0, 2e-3), "ρ = {rho}");
        let f = elastomer_flattening(effective_modulus(e, nu), e, r);
        assert!(close(f.z_p, 3.88e-3, 2e-3), "z_p = {}", f.z_p);
        assert!(close(f.k_p, 5.37e4, 2e-3), "K_p = {}", f.k_p);
        assert!(close(rayleigh_damping(r, rho, e, nu), 140.3, 2e-3));
        // Eq. 16 holds for the derived set: K_p = 1.5 K_h √z_p
        let k_h = hertz_stiffness(effective_modulus(e, nu), r);
        assert!(close(f.k_p, 1.5 * k_h * f.z_p.sqrt(), 1e-12));
    }

    /// The golf ball's layers give 30 MPa for contact (Eq. 30) and 144.6 MPa, 1100 kg/m³ along
    /// the surface (Eq. 31).
    #[test]
    fn golf_ball_layers() {
        let l = |t: f64, e: f64, rho: f64, surface| Layer {
            name: None,
            thickness: t,
            modulus: e,
            density: Some(rho),
            poisson: None,
            surface,
        };
        let layers = [
            l(2.0e-3, 400e6, 950.0, true),
            l(5.4e-3, 50e6, 1155.0, true),
            l(1.3e-3, 116e9, 4510.0, false),
            l(12.05e-3, 20.8e6, 0.0, false),
        ];
        assert!(close(
            layered_contact_modulus(20.75e-3, &layers),
            30e6,
            2e-3
        ));
        let (e, rho) = layered_surface(&layers).unwrap();
        assert!(close(e, 144.6e6, 1e-3), "E = {e}");
        assert!(close(rho, 1100.0, 1e-3), "ρ = {rho}");
    }

    /// Baseball: K_p ≈ 1.27e6 N/m and c ≈ 347 kg/s from the stated inputs.
    #[test]
    fn baseball_from_formulas() {
        let (m, r) = (0.1436, 0.03525);
        let f = elastomer_flattening(effective_modulus(40e6, 0.4), 40e6, r);
        assert!(close(f.k_p, 1.27e6, 3e-3), "K_p = {}", f.k_p);
        assert!(close(f.z_p, 5.06e-3, 3e-3));
        let c = rayleigh_damping(r, density(m, r), 2e6, 0.4);
        assert!(close(c, 347.0, 3e-3), "c = {c}");
    }

    #[test]
    fn shells_run_from_solid_to_thin() {
        assert_eq!(shell_inertia_factor(1.0, 0.0), 0.4);
        assert!(close(
            shell_inertia_factor(1.0, 1.0 - 1e-9),
            2.0 / 3.0,
            1e-8
        ));
        assert!(close(shell_inertia_factor(1.0, 0.999), 2.0 / 3.0, 1.1e-3));
        // the presets' hollow balls (their comments): tennis and table tennis
        assert!(close(shell_inertia_factor(33.5, 30.5), 0.6105, 1e-3));
        assert!(close(shell_inertia_factor(20.0, 19.6), 0.6535, 1e-3));
    }

    #[test]
    fn metal_plastic_eq_15_17() {
        // steel ball: E = 200 GPa, ν = 0.3, S_y = 1 GPa, R = 10 mm
        let es = effective_modulus(200e9, 0.3);
        let f = metal_plastic(es, 0.01, 1e9);
        assert!(close(f.k_p, 2.0 * PI * 0.01 * 2.2e9, 1e-15));
        // Eq. 16 is consistent with (15, 17): K_p = 1.5 K_h √z_p
        assert!(close(
            f.k_p,
            1.5 * hertz_stiffness(es, 0.01) * f.z_p.sqrt(),
            1e-12
        ));
        assert!(close(
            effective_modulus_pair(200e9, 0.3, f64::INFINITY, 0.3),
            es,
            1e-15
        ));
    }
}
