//! The flow's modes and coefficients (`flow.rs`'s [`Flow`] is built from them): the cubic's
//! real root and pair at (λ, ζ) and A, B, D from a state (`solver::modes`, the core the
//! oblique impact's phases share), the pair part's antiderivative, and the quick cube root
//! Cardano's formula takes.

use super::{Flow, JET};
pub(super) use crate::solver::modes::Modes;

/// The flow's modes at (λ, ζ) (the loading's: slope 1), `None` where the modes do not
/// separate (the gap vanishes) or the pair does not decay. `cbrt` takes Cardano's cube root.
pub(super) fn modes(lambda: f64, zeta: f64, cbrt: fn(f64) -> f64) -> Option<Modes> {
    let m = Modes::of_phase(lambda, zeta, 1.0, cbrt);
    (m.gap > 0.0 && m.p0 > 0.0).then_some(m)
}

/// The flow z̄ = A e^{rτ} + e^{−στ}(B C + D S) of the modes `m` from `[A, B, D]` and their
/// rounding scales `[sa, sb, sd]`: the antiderivative's P, Q and the jet's rows.
pub(super) fn flow(m: &Modes, [a, b, d]: [f64; 3], [sa, sb, sd]: [f64; 3]) -> Flow {
    let (r, sigma, omega2, p0) = (m.r, m.sigma, m.omega2, m.p0);
    let (p, q) = antiderivative(m, b, d);
    let sp = (sd + sigma.abs() * sb) / p0;
    let size = [sa, sb, sd, sp, sb + sigma.abs() * sp];
    let omega = if omega2 > 0.0 { omega2.sqrt() } else { 0.0 };
    Flow {
        size,
        tight: false,
        gap: m.gap,
        p0,
        r,
        sigma,
        omega2,
        omega,
        a,
        d,
        p,
        q,
        jet: m.rows::<JET>([a, b, d]),
    }
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
    use super::super::tests::close;
    use super::*;

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
