//! The flattening's unloading over any [`Lane`] (issue 30 item 2; `lanes/flatten.rs` is its
//! caller): the loading's cubic at (λ/k, ζ√k) as a `Flow4` from the turn's state (u0, 0, u2)
//! (`solver::modes::Modes::coefficients`' A, B, D with z̄' = 0), ∫₀^s u, and the rounding bounds of a
//! flow from a state (the scalar `tight` flow's: `Flow::rounding`, `Flow::responses`), lane by
//! lane, as `flatten::flattening` forms them.

use super::super::super::lane::Lane;
use super::super::super::math::{Estrin, pair};
use super::super::{Flow4, Point4, lone_real_root};
use crate::solver::series::INV_FACTORIAL;
/// The unloading's flow: a `Flow4` from a state, and what its bounds need beyond it.
pub(super) struct Unload<L: Lane> {
    pub(super) flow: Flow4<L, Estrin>,
    /// B's rounding scale (the loading's B = −A shares A's; a state's does not).
    sb: L,
    /// (r + σ)² + ω² and σ² + ω², for the responses.
    gap: L,
    p0: L,
}

/// e^x − 1 for |x| < 1/2 (the scalar `tight` flow's `exp_m1` range): x Σ xᵏ/(k + 1)!, k ≤ 16
/// (the first term left out is below 2e-21 of the sum), summed by Estrin's scheme — pairs of
/// terms by one multiply-add each, then pairs of pairs with x², x⁴, x⁸ and x¹⁶ — six
/// operations deep where Horner's rule chained sixteen products and sums: this sum waits on
/// the unloading's last point and the COR waits on it (a lone cell's chain, `flattening_one`).
/// What libm's `exp_m1` gives the scalar unloading there, to a few ulp
/// (`exp_m1_half_is_libms_to_four_ulp`). By hand, as `estrin.rs`: seventeen terms of a fixed
/// series over a [`Lane`], which no crate sums.
#[inline(always)]
fn exp_m1_half<L: Lane>(x: L) -> L {
    // 1/(k + 1)! is INV_FACTORIAL[k + 1]; `pair` a function, not a closure (math.rs says why)
    let (x2, f) = (x * x, &INV_FACTORIAL[1..]);
    let x4 = x2 * x2;
    let quad0 = x2.mul_add(pair(x, f, 2), pair(x, f, 0));
    let quad4 = x2.mul_add(pair(x, f, 6), pair(x, f, 4));
    let quad8 = x2.mul_add(pair(x, f, 10), pair(x, f, 8));
    let quad12 = x2.mul_add(pair(x, f, 14), pair(x, f, 12));
    let (low, high) = (x4.mul_add(quad4, quad0), x4.mul_add(quad12, quad8));
    let x8 = x4 * x4;
    let sum = (x8 * x8).mul_add(L::splat(f[16]), x8.mul_add(high, low));
    x * sum
}

impl<L: Lane> Unload<L> {
    /// The flow at (λ, ζ) from the state (u0, 0, u2) at s = 0 (`Flow::from_state`), and the
    /// lanes whose modes separate and whose pair oscillates and decays.
    #[inline(always)]
    pub(super) fn from_state(lambda: L, zeta: L, u0: L, u2: L) -> (Unload<L>, L) {
        let v = L::splat;
        let two_zeta = v(2.0) * zeta;
        let (a2, a0) = (two_zeta * (v(1.0) + lambda), two_zeta * lambda);
        // three real roots: the pair does not oscillate, the lane goes back to the scalar path
        let (r, p1, p0, mut ok, three) = lone_real_root::<L, Estrin>(a2, a0);
        ok &= !three;
        let sigma = v(0.5) * p1;
        let omega2 = p0 - sigma * sigma;
        let gap = (r + sigma) * (r + sigma) + omega2;
        ok &= gap.gt(v(0.0)) & p0.gt(v(0.0)) & omega2.gt(v(0.0));
        // `solver::modes::Modes::coefficients` with z̄' = 0: A = N(r)/gap, B = z̄ − A, D = −A r + σB
        let a = (p0 * u0 + u2) / gap;
        let sa = (p0 * u0.abs() + u2.abs()) / gap;
        let b = u0 - a;
        let d = -a * r + sigma * b;
        let sb = u0.abs() + sa;
        let sd = sa * r.abs() + sigma.abs() * sb;
        let (p, q) = antiderivative(sigma, p0, b, d);
        let sp = (sd + sigma.abs() * sb) / p0;
        let mut jet = [[v(0.0); 3]; 6];
        let (mut ar, mut c, mut s) = (a, b, d);
        for row in &mut jet {
            *row = [ar, c, s];
            (ar, c, s) = (ar * r, s - sigma * c, -omega2 * c - sigma * s);
        }
        let flow = Flow4 {
            size: [sa, sd, sp, sb + sigma.abs() * sp],
            r,
            sigma,
            omega2,
            omega: omega2.sqrt(),
            inv_omega: v(1.0) / omega2.sqrt(),
            a,
            d,
            p,
            q,
            jet,
            hyper: three & !three,
            sums: std::marker::PhantomData,
        };
        (Unload { flow, sb, gap, p0 }, ok)
    }

    /// (e^{rs} − 1)/r's numerator, `exp_m1` below |rs| = 1/2 (`Flow::real_growth`, tight).
    #[inline(always)]
    fn grown(&self, pt: &Point4<L>) -> L {
        let rt = self.flow.r * pt.t;
        rt.abs()
            .lt(L::splat(0.5))
            .select(exp_m1_half(rt), pt.real - L::splat(1.0))
    }

    /// ∫₀^s u (`Flow::integral`).
    #[inline(always)]
    pub(super) fn integral(&self, pt: &Point4<L>) -> L {
        let f = &self.flow;
        f.a * self.grown(pt) / f.r + f.p * pt.ec + f.q * pt.es - f.p
    }

    /// `Flow::rounding` of a flow from a state (`tight`): (for u, for ∫ u).
    #[inline(always)]
    pub(super) fn rounding(&self, pt: &Point4<L>) -> (L, L) {
        let v = L::splat;
        let (f, one, t) = (&self.flow, v(1.0), pt.t);
        let (cm, sm) = (pt.decay, pt.decay * t.min(one / f.omega));
        let real = pt.real * (one + f.r.abs() * t);
        let grow = one + (f.sigma.abs() + f.omega2.abs().sqrt()) * t;
        let (cm, sm) = (cm * grow, sm * grow);
        let [sa, sd, sp, sq] = f.size;
        let z = sa * real + self.sb * cm + sd * sm;
        let int = v(3.0) * sa * t * (one + real) + sp * (one + cm) + sq * sm;
        (v(f64::EPSILON) * z, v(f64::EPSILON) * int)
    }

    /// `Flow::responses` of the states (x0, 0, 0) and (0, 0, x2): each one's (u, ∫ u) at
    /// `pt`, the flow being linear in its start.
    #[inline(always)]
    pub(super) fn responses(&self, x0: L, x2: L, pt: &Point4<L>) -> [(L, L); 2] {
        let grown = self.grown(pt);
        let a0 = self.p0 * x0 / self.gap;
        let a2 = x2 / self.gap;
        [
            self.response(a0, x0 - a0, grown, pt),
            self.response(a2, -a2, grown, pt),
        ]
    }

    /// One response of `responses`: the pair part (a, b) of a start, (u, ∫ u) at `pt`. A
    /// method, not a closure: the compiler left the closure out of line in the eight-lane
    /// kernel, its lanes passed through memory (callgrind, BENCHMARKS.md's tenth session).
    #[inline(always)]
    fn response(&self, a: L, b: L, grown: L, pt: &Point4<L>) -> (L, L) {
        let f = &self.flow;
        let d = -a * f.r + f.sigma * b;
        let (p, q) = antiderivative(f.sigma, self.p0, b, d);
        let z = a * pt.real + b * pt.ec + d * pt.es;
        (z, a * grown / f.r + p * pt.ec + q * pt.es - p)
    }
}

/// `flow::antiderivative`: P and Q of the pair part's antiderivative.
#[inline(always)]
fn antiderivative<L: Lane>(sigma: L, p0: L, b: L, d: L) -> (L, L) {
    let p = -(d + sigma * b) / p0;
    (p, b + sigma * p)
}

#[cfg(test)]
mod tests {
    /// Estrin's sum is libm's `exp_m1` (what the scalar unloading takes) within 4 ulp over
    /// |x| < 1/2, and exactly 0 at 0.
    #[test]
    fn exp_m1_half_is_libms_to_four_ulp() {
        assert_eq!(
            super::exp_m1_half(wide::f64x4::splat(0.0)).to_array()[0],
            0.0
        );
        for i in -5000..5000 {
            let x = f64::from(i) / 10_000.0 + 1.234_567e-5;
            let got = super::exp_m1_half(wide::f64x4::splat(x)).to_array()[0];
            let want = x.exp_m1();
            let ulps = (got - want).abs() / (f64::EPSILON * want.abs());
            assert!(ulps <= 4.0, "{x}: {got} vs {want}, {ulps} ulp");
        }
    }
}
