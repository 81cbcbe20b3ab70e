//! The peers' force laws in normalized form (docs/peers.md §2). Each model has one
//! dimensionless damping parameter `d`, and its COR depends on `d` alone:
//!
//! - Kelvin–Voigt, τ = t √(k/m), x = δ/(v0 √(m/k)):  F̄ = x + 2ζ x',  ζ = η / (2√(m k));
//! - Tsuji, x = δ/δ*, δ* = (m v0²/K_h)^{2/5}, τ = t v0/δ*:
//!   F̄ = x^{3/2} + α x^{1/4} x',  α = η / √(m K_h) (Tsuji et al. 1992);
//! - Hunt–Crossley family, same scaling: F̄ = x^{3/2} (1 + χ x').
//!
//! Substituting the scalings into m δ'' = −F(δ, δ') leaves x'' = −F̄(x, x') with x(0) = 0,
//! x'(0) = 1 and no other parameter: that is why none of these COR depend on v0, m, k or K_h at
//! fixed d (tests/physics/peers.rs checks it on the SI equations, integrated independently).

use super::integrate::Law;

/// Linear spring–dashpot with tension: the contact ends when x returns to 0.
pub struct KelvinVoigt {
    pub zeta: f64,
}

/// Linear spring–dashpot clipped at F ≥ 0: the ball leaves when the force reaches 0.
pub struct KelvinVoigtNoTension {
    pub zeta: f64,
}

/// Hertz spring with a δ^{1/4} dashpot, clipped at F ≥ 0.
pub struct Tsuji {
    pub alpha: f64,
}

/// Hertz spring with Hunt–Crossley damping. The clip F ≥ 0 never acts: u = 1 + χ x' obeys
/// u' = −χ x^{3/2} u, so u > 0 throughout and the contact ends at x = 0.
pub struct HuntCrossley {
    pub chi: f64,
}

/// x^{3/2} and x^{1/2} of a non-negative indentation (0 outside contact).
fn hertz(x: f64) -> (f64, f64) {
    if x > 0.0 {
        let r = x.sqrt();
        (x * r, r)
    } else {
        (0.0, 0.0)
    }
}

impl Law for KelvinVoigt {
    fn force(&self, x: f64, v: f64) -> f64 {
        x + 2.0 * self.zeta * v
    }
    fn end(&self, x: f64, _v: f64) -> f64 {
        x
    }
    fn end_rate(&self, _x: f64, v: f64, _a: f64) -> f64 {
        v
    }
    fn force_rate(&self, _x: f64, v: f64, a: f64) -> f64 {
        v + 2.0 * self.zeta * a
    }
    /// Overdamped (ζ ≥ 1): x = (e^{r₁τ} − e^{r₂τ})/(r₁ − r₂), r₁,₂ = −ζ ± √(ζ² − 1), is
    /// positive for every τ > 0, so the ball creeps back towards x = 0 without ever reaching
    /// it: no rebound (e = 0, docs/model.md §2's convention), decided at the turning point rather
    /// than after an integration whose stiff rate 2ζ would need ~ζ² steps.
    fn stays_after_turning(&self) -> bool {
        self.zeta >= 1.0
    }
}

impl Law for KelvinVoigtNoTension {
    fn force(&self, x: f64, v: f64) -> f64 {
        (x + 2.0 * self.zeta * v).max(0.0)
    }
    fn drive(&self, x: f64, v: f64) -> f64 {
        x + 2.0 * self.zeta * v
    }
    fn end(&self, x: f64, v: f64) -> f64 {
        x + 2.0 * self.zeta * v
    }
    fn end_rate(&self, _x: f64, v: f64, a: f64) -> f64 {
        v + 2.0 * self.zeta * a
    }
    fn force_rate(&self, x: f64, v: f64, a: f64) -> f64 {
        self.end_rate(x, v, a)
    }
}

impl Law for Tsuji {
    fn force(&self, x: f64, v: f64) -> f64 {
        self.drive(x, v).max(0.0)
    }
    fn drive(&self, x: f64, v: f64) -> f64 {
        let (x15, r) = hertz(x);
        x15 + self.alpha * r.sqrt() * v
    }
    /// F̄ / x^{1/4} = x^{5/4} + α x': crosses zero transversally even when α = 0, where F̄
    /// itself would touch zero with a vanishing slope.
    fn end(&self, x: f64, v: f64) -> f64 {
        if x <= 0.0 {
            return x.min(-f64::MIN_POSITIVE);
        }
        x * x.sqrt().sqrt() + self.alpha * v
    }
    fn end_rate(&self, x: f64, v: f64, a: f64) -> f64 {
        1.25 * x.max(0.0).sqrt().sqrt() * v + self.alpha * a
    }
    fn force_rate(&self, x: f64, v: f64, a: f64) -> f64 {
        if x <= 0.0 {
            return if v > 0.0 { f64::INFINITY } else { 0.0 };
        }
        let (_, r) = hertz(x);
        let q = r.sqrt();
        1.5 * r * v + self.alpha * (0.25 * v * v / (q * q * q) + q * a)
    }
    /// x^{1/4} = w for x = w⁴.
    fn smoothing_power(&self) -> Option<i32> {
        Some(4)
    }
}

impl Law for HuntCrossley {
    fn force(&self, x: f64, v: f64) -> f64 {
        (hertz(x).0 * (1.0 + self.chi * v)).max(0.0)
    }
    fn end(&self, x: f64, _v: f64) -> f64 {
        x
    }
    fn end_rate(&self, _x: f64, v: f64, _a: f64) -> f64 {
        v
    }
    fn force_rate(&self, x: f64, v: f64, a: f64) -> f64 {
        let (x15, r) = hertz(x);
        1.5 * r * v * (1.0 + self.chi * v) + x15 * self.chi * a
    }
    /// x^{3/2} = w³ for x = w².
    fn smoothing_power(&self) -> Option<i32> {
        Some(2)
    }
    fn ends_at_zero(&self) -> bool {
        true
    }
}
