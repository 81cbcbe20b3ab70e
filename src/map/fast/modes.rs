//! The flow's modes and coefficients (`flow.rs`'s [`Flow`] is built from them): the cubic's
//! real root and pair at (λ, ζ) ([`Modes`], by `propagator::modes_of`), A, B, D from a state,
//! the pair part's antiderivative, and the quick cube root Cardano's formula takes.

use super::{Flow, JET};
use crate::solver::propagator::modes_of;

/// The cubic's modes at (λ, ζ): the real root r and the pair s² + 2σs + (σ² + ω²).
pub(super) struct Modes {
    pub(super) r: f64,
    pub(super) sigma: f64,
    pub(super) omega2: f64,
    /// (r + σ)² + ω² = p'(r).
    pub(super) gap: f64,
    /// σ² + ω².
    pub(super) p0: f64,
    /// 2ζλ, the cubic's constant term.
    pub(super) a0: f64,
}

impl Modes {
    /// `None` where the modes do not separate (the gap vanishes) or the pair does not decay.
    /// `cbrt` takes Cardano's cube root (`propagator::modes_of`).
    pub(super) fn new(lambda: f64, zeta: f64, cbrt: fn(f64) -> f64) -> Option<Modes> {
        let a0 = 2.0 * zeta * lambda;
        let (r, sigma, omega2, gap, p0) = modes_of([2.0 * zeta * (1.0 + lambda), 1.0, a0], cbrt);
        (gap > 0.0 && p0 > 0.0).then_some(Modes {
            r,
            sigma,
            omega2,
            gap,
            p0,
            a0,
        })
    }

    /// The flow z̄ = A e^{rτ} + e^{−στ}(B C + D S) from `[A, B, D]` and their rounding
    /// scales `[sa, sb, sd]`: the antiderivative's P, Q and the jet's rows.
    pub(super) fn flow(&self, [a, b, d]: [f64; 3], [sa, sb, sd]: [f64; 3]) -> Flow {
        let (r, sigma, omega2, p0) = (self.r, self.sigma, self.omega2, self.p0);
        let (p, q) = antiderivative(self, b, d);
        let sp = (sd + sigma.abs() * sb) / p0;
        let size = [sa, sb, sd, sp, sb + sigma.abs() * sp];
        let omega = if omega2 > 0.0 { omega2.sqrt() } else { 0.0 };
        // (e^{−στ}(c C + s S))' = e^{−στ}((s − σc) C + (−ω² c − σs) S), as u = (C, S) has
        // u' = (−ω² S, C)
        let mut jet = [[0.0; 3]; JET];
        let (mut ar, mut c, mut s) = (a, b, d);
        for row in &mut jet {
            *row = [ar, c, s];
            (ar, c, s) = (ar * r, s - sigma * c, -omega2 * c - sigma * s);
        }
        Flow {
            size,
            tight: false,
            gap: self.gap,
            p0,
            r,
            sigma,
            omega2,
            omega,
            a,
            d,
            p,
            q,
            jet,
        }
    }
}

/// A, B, D of the flow from the state x = (z̄, z̄', z̄'') at τ = 0, and their rounding scales.
/// A is the residue at r of the Laplace transform, N(r)/gap, with the numerator
/// N(s) = z̄ s² + (z̄' + a₂z̄) s + (z̄'' + a₂z̄' + a₁z̄). As a₂ = 2σ − r and a₁ = σ² + ω² − 2σr
/// (the roots' sums), N(r) = (σ² + ω²) z̄ + 2σ z̄' + z̄'': free of the r² terms that cancel
/// where the real mode is fast (their rounding, ε z̄ r², would cost D ε|r| z̄ and the
/// unloading's integral as much: it put the bound 2e4 times over 1e-13 at r = −2e5). B = z̄ − A
/// and D = z̄' − A r + σB match z̄ and z̄' at 0.
pub(super) fn state_coefficients(m: &Modes, x: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let (r, sigma) = (m.r, m.sigma);
    let a = (m.p0 * x[0] + 2.0 * sigma * x[1] + x[2]) / m.gap;
    let sa = (m.p0 * x[0].abs() + 2.0 * (sigma * x[1]).abs() + x[2].abs()) / m.gap;
    let b = x[0] - a;
    let d = x[1] - a * r + sigma * b;
    let sb = x[0].abs() + sa;
    (
        [a, b, d],
        [sa, sb, x[1].abs() + sa * r.abs() + sigma.abs() * sb],
    )
}

/// P and Q of the pair part's antiderivative: (e^{−στ}(P C + Q S))' = e^{−στ}((Q − σP) C −
/// (ω²P + σQ) S) = e^{−στ}(B C + D S).
pub(super) fn antiderivative(m: &Modes, b: f64, d: f64) -> (f64, f64) {
    let p = -(d + m.sigma * b) / m.p0;
    (p, b + m.sigma * p)
}

/// ∛x within an ulp (0.74 ε over 20 000 log-spread x, `quick_cbrt_is_cbrt`) where x is normal,
/// else `f64::cbrt`: the exponent divided by 3 in the bits (a guess within 3.2 %), two Halley
/// steps (2e-5, then 6e-15) and one Newton step. Hand-written because `f64::cbrt` (the
/// correctly rounded one of compiler_builtins) costs some 137 instructions a call where this
/// takes about 30, and Cardano's root is polished by Newton's steps on the cubic anyway.
pub(super) fn quick_cbrt(x: f64) -> f64 {
    /// (1023 − 1023/3)·2⁵² plus the mantissa's correction (Kahan's constant for doubles).
    const THIRD_BIAS: u64 = 0x2a9f_7893_782d_a1ce;
    if !x.is_normal() {
        return x.cbrt();
    }
    let a = x.abs();
    let mut y = f64::from_bits(a.to_bits() / 3 + THIRD_BIAS);
    for _ in 0..2 {
        let y3 = y * y * y;
        y *= (y3 + 2.0 * a) / (2.0 * y3 + a);
    }
    y -= (y * y * y - a) / (3.0 * y * y);
    y.copysign(x)
}

/// Σ|terms|.
pub(super) fn abs_sum(terms: [f64; 3]) -> f64 {
    terms.iter().map(|t| t.abs()).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, ulps: f64) -> bool {
        (a - b).abs() <= ulps * f64::EPSILON * b.abs().max(f64::MIN_POSITIVE)
    }

    /// `quick_cbrt` is `f64::cbrt` within an ulp over 2 000 log-spread x, either sign, and at
    /// 0, subnormals and infinities (where it is `f64::cbrt`).
    #[test]
    fn quick_cbrt_is_cbrt() {
        for i in -1000..=1000 {
            let x = 1.37f64.powi(i) * if i % 2 == 0 { 1.0 } else { -1.0 };
            assert!(close(quick_cbrt(x), x.cbrt(), 1.0), "∛{x}");
        }
        for x in [0.0, -0.0, 1e-310, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(quick_cbrt(x).to_bits(), x.cbrt().to_bits(), "∛{x}");
        }
    }
}
