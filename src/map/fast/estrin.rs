//! The short steps' series of `Flow::shift` (flow.rs) — eˣ and (cos x, sin(x)/x) for
//! |x| ≤ 1/16, each to x¹⁰ — summed by Estrin's scheme: pairs of terms side by side, then
//! pairs of pairs, some four products deep where Horner's rule chains ten multiply–adds. The
//! same terms (1/k! from `series::INV_FACTORIAL`), other roundings: within 2 ulp of the
//! Horner sums (`estrin_is_horner_to_two_ulp`). Hand-written: eleven terms of a fixed series,
//! which no crate sums for a latency-bound scalar chain (the flattening's refinements,
//! `search::refine`, wait on one shift a root).

use crate::solver::series::INV_FACTORIAL as C;

/// eˣ for |x| ≤ 1/16: Σ xᵏ/k!, k ≤ 10, as (c₀ + c₁x) + x²(c₂ + c₃x) + x⁴(…) + x⁸(…).
#[inline(always)]
pub(super) fn exp_small(x: f64) -> f64 {
    let (x2, x4) = (x * x, (x * x) * (x * x));
    let low = (C[0] + x * C[1]) + x2 * (C[2] + x * C[3]);
    let mid = (C[4] + x * C[5]) + x2 * (C[6] + x * C[7]);
    let high = (C[8] + x * C[9]) + x2 * C[10];
    low + x4 * (mid + x4 * high)
}

/// (cos x, sin(x)/x) for |x| ≤ 1/16, each to x¹⁰, in y = x² the same way.
#[inline(always)]
pub(super) fn cos_sinc(x: f64) -> (f64, f64) {
    let (y, y2) = (x * x, (x * x) * (x * x));
    let cos = (C[0] - y * C[2]) + y2 * ((C[4] - y * C[6]) + y2 * (C[8] - y * C[10]));
    let sinc = (C[1] - y * C[3]) + y2 * ((C[5] - y * C[7]) + y2 * (C[9] - y * C[11]));
    (cos, sinc)
}

#[cfg(test)]
mod tests {
    use crate::solver::series::{cos_sinc_to, exp_to};

    fn close(a: f64, b: f64, ulps: f64) -> bool {
        (a - b).abs() <= ulps * f64::EPSILON * b.abs()
    }

    /// Estrin's sums are the Horner sums of `solver::series` (`Flow::shift`'s) within 2 ulp
    /// over |x| ≤ 1/16, and libm's exp, cos and sin(x)/x within 2 ulp too.
    #[test]
    fn estrin_is_horner_to_two_ulp() {
        for i in -1000..=1000 {
            let x = f64::from(i) / 16_000.0;
            let (cos, sinc) = super::cos_sinc(x);
            let (hcos, hsinc) = cos_sinc_to::<5>(x);
            assert!(close(super::exp_small(x), exp_to::<10>(x), 2.0), "exp({x})");
            assert!(
                close(cos, hcos, 2.0) && close(sinc, hsinc, 2.0),
                "cos_sinc({x})"
            );
            assert!(close(super::exp_small(x), x.exp(), 2.0), "exp({x}) vs libm");
            let libm_sinc = if x == 0.0 { 1.0 } else { x.sin() / x };
            assert!(
                close(cos, x.cos(), 2.0) && close(sinc, libm_sinc, 2.0),
                "{x} vs libm"
            );
        }
    }
}
