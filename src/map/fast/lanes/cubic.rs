//! The flow's cubic s³ + 2ζ(1 + λ)s² + s + 2ζλ in the lanes: its real root standing apart and
//! the deflated quadratic (`kernel.rs`'s `Flow4::new` and the flattening's unloading take
//! them), as `propagator::modes_of` finds them in the scalar path.

use super::super::lane::Lane;
use super::super::math::{Sums, cbrt};

/// Most Newton steps for the slowest of three real roots (from 0, `hyper.rs`).
const MAX_NEWTON_THREE: usize = 16;

/// The real root r of s³ + a2 s² + s + a0 that the flow stands apart and the deflated
/// quadratic (p1, p0), the lanes where it answers, and the lanes of three real roots. Where
/// the other two are a complex pair: the lone root as `propagator::modes_of` gives it
/// (Cardano, then at most four Newton steps that must settle). Where all three are real
/// (Cardano's discriminant ≤ 0): the slowest, by Newton from 0, which falls to it
/// monotonically (`hyper.rs` says why), in at most [`MAX_NEWTON_THREE`] steps that must settle.
#[inline(always)]
pub(super) fn lone_real_root<L: Lane, S: Sums>(a2: L, a0: L) -> (L, L, L, L, L) {
    let v = L::splat;
    let (one, zero) = (v(1.0), v(0.0));
    // the quotients as `S` forms them (`Sums::over`): Newton's steps below settle the root to
    // 4ε whatever Cardano's start's last bits
    let shift = S::over(a2, 3.0);
    let p = one - a2 * shift;
    let q = (v(2.0) * shift * shift - one) * shift + a0;
    let disc = v(0.25) * q * q + S::over(p * p * p, 27.0);
    let three = disc.le(zero);
    let sign = q.sign_negative().select(v(-1.0), one);
    let u = cbrt(v(-0.5) * q - sign * disc.sqrt());
    let ok = disc.gt(zero) & u.ne(zero);
    let mut r = three.select(zero, u - p / (v(3.0) * u) - shift);
    let mut done = zero.ne(zero);
    for _ in 0..4 {
        let (next, small) = newton(r, a2, a0);
        r = done.select(r, next);
        done |= small;
        // every lane settled: the steps left would keep r as it is (`done` selects it), so
        // stopping gives the same bits and takes their divisions off a lone cell's chain
        if !(!done).any() {
            break;
        }
    }
    // the lanes of three real roots go on alone; every other lane keeps its four steps
    let mut k = 4;
    while k < MAX_NEWTON_THREE && (three & !done).any() {
        let (next, small) = newton(r, a2, a0);
        r = (done | !three).select(r, next);
        done |= three & small;
        k += 1;
    }
    let ok = (ok | three) & done & r.ne(zero);
    // deflate: the division form where r³ dominates a0, else the multiplication form
    let first = (r.abs() * r.abs() * r.abs()).ge(a0);
    let p0_div = -a0 / r;
    let p1_div = (p0_div - one) / r;
    let p1_mul = a2 + r;
    let p0_mul = one + r * p1_mul;
    (
        r,
        first.select(p1_div, p1_mul),
        first.select(p0_div, p0_mul),
        ok,
        three,
    )
}

/// One Newton step on s³ + a2 s² + s + a0 from r: the next r, and the lanes where the step
/// was within 4ε of it. A function, not a closure: a closure stayed a call out of the AVX2
/// kernel, and every lane operation inside it a call too (callgrind).
#[inline(always)]
fn newton<L: Lane>(r: L, a2: L, a0: L) -> (L, L) {
    let v = L::splat;
    let one = v(1.0);
    let value = ((r + a2) * r + one) * r + a0;
    let slope = (v(3.0) * r + v(2.0) * a2) * r + one;
    let step = value / slope;
    let next = r - step;
    (next, step.abs().le(v(4.0 * f64::EPSILON) * next.abs()))
}
