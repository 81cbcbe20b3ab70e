//! The kernel's transcendental functions over any [`Lane`], inline, from the lane primitives
//! alone: the same bits in every lane type, and in the AVX2 kernel one ymm register through
//! them (no call out to `wide`'s SSE2 `exp` and `atan2`: `avx.rs` says why by hand). Both
//! stay within 2 ulp of libm's over the kernel's arguments (`exp_is_libms_to_two_ulp`,
//! `atan2_is_libms_to_two_ulp`); the series of the short steps (`exp_small`, `cos_sinc_sq`) are
//! flow.rs's, term for term. [`Sums`] says how a flow sums them: by Horner's rule for the
//! linear law's kernel, by Estrin's scheme for the flattening's.

use super::lane::Lane;
use crate::solver::series::INV_FACTORIAL;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, LOG2_E, PI};

/// The coefficients (−1)^{k·alt}/(step·k + first)! for k = N − 1 down to 0: a series in
/// [`horner`]'s order (highest degree first).
const fn series<const N: usize>(step: usize, first: usize, alt: bool) -> [f64; N] {
    let mut c = [0.0; N];
    let mut i = 0;
    while i < N {
        let k = N - 1 - i;
        let sign = if alt && k % 2 == 1 { -1.0 } else { 1.0 };
        c[i] = sign * INV_FACTORIAL[step * k + first];
        i += 1;
    }
    c
}

/// eʳ to r¹³, [`exp`]'s series.
const EXP_SERIES: [f64; 14] = series(1, 0, false);
/// eˣ to x¹⁰, [`exp_small`]'s.
const EXP_SMALL_SERIES: [f64; 11] = series(1, 0, false);
/// (eˣ − 1)/x to x⁵, [`exp_m1_small`]'s.
const EXP_M1_SMALL_SERIES: [f64; 6] = series(1, 1, false);
/// cos x and sin(x)/x to x¹⁰, in x², [`cos_sinc_sq`]'s.
const COS_SERIES: [f64; 6] = series(2, 0, true);
const SINC_SERIES: [f64; 6] = series(2, 1, true);

/// `Σ c[i] x^{n−1−i}` by Horner's rule, `c` highest degree first: `c[0] x + c[1]`, times x
/// plus `c[2]`, …, each step one fused multiply-add ([`Lane::mul_add`]: half the instructions of a
/// product and a sum, one rounding, and the chain's latency a step shorter). A `while` loop over a constant array rather than an iterator's `fold`, which the
/// compiler did not inline into the AVX2 kernel (a call, and the lane operations inside it
/// calls too: 22 % of a Monte Carlo sample's instructions by callgrind); this one unrolls.
#[inline(always)]
fn horner<L: Lane>(x: L, c: &[f64]) -> L {
    let mut sum = L::splat(c[0]);
    let mut i = 1;
    while i < c.len() {
        sum = sum.mul_add(x, L::splat(c[i]));
        i += 1;
    }
    sum
}

/// Σ rᵏ/k!, k ≤ 13 ([`exp`]'s series), by Estrin's scheme: seven pairs (1/k! + r/(k + 1)!)
/// by one multiply-add each, then pairs of pairs with r², r⁴ and r⁸ — four multiply-adds deep
/// after r⁸ where Horner's rule chains thirteen. By hand, as `estrin.rs` (the scalar path's
/// short steps): a fixed series over a [`Lane`], which no crate sums.
#[inline(always)]
fn estrin14<L: Lane>(r: L) -> L {
    let (r2, f) = (r * r, &INV_FACTORIAL);
    let r4 = r2 * r2;
    let low = r2.mul_add(pair(r, f, 2), pair(r, f, 0));
    let low = r4.mul_add(r2.mul_add(pair(r, f, 6), pair(r, f, 4)), low);
    let high = r4.mul_add(pair(r, f, 12), r2.mul_add(pair(r, f, 10), pair(r, f, 8)));
    (r4 * r4).mul_add(high, low)
}

/// `c[k] + x·c[k + 1]` by one multiply-add, `c` lowest degree first: a pair of Estrin's
/// scheme. A function, not a closure: a closure stayed a call out of the eight-lane AVX2
/// kernel (callgrind: `flattening_lanes8_avx2` 5 980 -> 8 110 instructions a call with them).
#[inline(always)]
pub fn pair<L: Lane>(x: L, c: &[f64], k: usize) -> L {
    x.mul_add(L::splat(c[k + 1]), L::splat(c[k]))
}

/// 1.5·2⁵²: (x + ROUND) − ROUND is x rounded to the nearest integer (ties to even) for
/// |x| < 2⁵¹, the addition's own rounding doing it.
const ROUND: f64 = 6_755_399_441_055_744.0;

/// ln 2 in two parts (fdlibm's `e_exp.c`): the high part's last 21 bits are zero, so k·LN2_HI
/// is exact for |k| < 2²¹ and x − k·LN2_HI loses nothing.
const LN2_HI: f64 = f64::from_bits(0x3FE6_2E42_FEE0_0000);
const LN2_LO: f64 = f64::from_bits(0x3DEA_39EF_3579_3C76);

/// 2ⁿ for an integer n ∈ [−1022, 1023], exactly: n + 2⁵² + 1023 holds n's biased exponent
/// in its last bits, which [`Lane::shl52`] moves into the exponent field.
#[inline(always)]
fn pow2<L: Lane>(n: L) -> L {
    (n + L::splat(4_503_599_627_370_496.0 + 1023.0)).shl52()
}

/// eˣ: x = k ln 2 + r with |r| ≤ ln 2 / 2, e^r by its Taylor series to r¹³ (the first term
/// left out, r¹⁴/14! < 4.3e-18, is under a twentieth of an ulp), times 2ᵏ in two exact halves
/// so that k reaches ±2 000. Beyond ±1 400 the answer is 0 or ∞ already: x is clamped there
/// to keep k in range. NaN stays NaN.
#[inline(always)]
pub fn exp<L: Lane>(x: L) -> L {
    exp_by(x, false)
}

/// [`exp`] with its series by Estrin's scheme ([`estrin14`]): within 2 ulp of libm's as well
/// (`estrin_sums_are_horners_to_two_ulp`), some 35 cycles shorter on a dependent chain.
#[inline(always)]
pub fn exp_estrin<L: Lane>(x: L) -> L {
    exp_by(x, true)
}

/// [`exp`]'s body; `estrin` a constant at each call, so one of the two sums is compiled.
#[inline(always)]
fn exp_by<L: Lane>(x: L, estrin: bool) -> L {
    let v = L::splat;
    let x = x.max(v(-1400.0)).min(v(1400.0));
    let k = (x * v(LOG2_E) + v(ROUND)) - v(ROUND);
    let r = (x - k * v(LN2_HI)) - k * v(LN2_LO);
    let series = if estrin {
        estrin14(r)
    } else {
        horner(r, &EXP_SERIES)
    };
    let half = (k * v(0.5) + v(ROUND)) - v(ROUND);
    series * pow2(half) * pow2(k - half)
}

/// Cephes' `atan` rational P(z²)/Q(z²) for |z| ≤ 0.66 (Moshier, Cephes Math Library, atan.c):
/// atan z = z + z·z²·P/Q, P of degree 4 and Q monic of degree 5.
#[allow(clippy::excessive_precision)] // Cephes' digits as published: the same f64s
const ATAN_P: [f64; 5] = [
    -8.750_608_600_031_904_122_785E-1,
    -1.615_753_718_733_365_076_637E1,
    -7.500_855_792_314_704_667_340E1,
    -1.228_866_684_490_136_173_410E2,
    -6.485_021_904_942_025_371_773E1,
];
#[allow(clippy::excessive_precision)] // as ATAN_P
const ATAN_Q: [f64; 6] = [
    1.0,
    2.485_846_490_142_306_297_962E1,
    1.650_270_098_316_988_542_046E2,
    4.328_810_604_912_902_668_951E2,
    4.853_903_996_359_136_964_868E2,
    1.945_506_571_482_613_964_425E2,
];

/// π/2 − `FRAC_PI_2`: the bits of π/2 past an f64's.
const PI_2_TAIL: f64 = 6.123_233_995_736_766e-17;

/// atan2(y, x) for finite y, x, in (−π, π] as libm's: folded to t = min/max of |y|, |x| in
/// [0, 1], t > 0.66 turned to π/4 + atan((t − 1)/(t + 1)), then unfolded by the octant
/// (π/2 − ·, π − ·, the sign of y). atan2(±0, ±0) is ±0 or ±π as libm's.
#[inline(always)]
pub fn atan2<L: Lane>(y: L, x: L) -> L {
    let v = L::splat;
    let (ax, ay) = (x.abs(), y.abs());
    let swap = ay.gt(ax);
    let (num, den) = (swap.select(ax, ay), swap.select(ay, ax));
    let zero = den.eq(v(0.0));
    let t = num / zero.select(v(1.0), den);
    let mid = t.gt(v(0.66));
    let z = mid.select(t - v(1.0), t) / mid.select(t + v(1.0), v(1.0));
    let zz = z * z;
    let p = horner(zz, &ATAN_P);
    let q = horner(zz, &ATAN_Q);
    let atan_z = z * (zz * p / q) + z;
    let angle =
        mid.select(v(FRAC_PI_4), v(0.0)) + (atan_z + mid.select(v(0.5 * PI_2_TAIL), v(0.0)));
    let angle = swap.select((v(FRAC_PI_2) - angle) + v(PI_2_TAIL), angle);
    let angle = x
        .sign_negative()
        .select((v(PI) - angle) + v(2.0 * PI_2_TAIL), angle);
    y.sign_negative().select(-angle, angle)
}

/// SLEEF's minimax polynomial for 1/∛d on [0.5, 1), C0 … C5 (Shibata et al., SLEEF, Boost
/// licence), as `wide` 1.7's `f64x4::cbrt` takes them.
#[allow(clippy::excessive_precision)] // the digits as `wide` gives them: the same f64s
const CBRT_C: [f64; 6] = [
    2.2307275302496609725722,
    -3.85841935510444988821632,
    6.03990368989458747961407,
    -5.73353060922947843636166,
    2.96155103020039511818595,
    -0.640245898480692909870982,
];

/// ∛x: `wide` 1.7's `f64x4::cbrt` operation for operation (its multiply-adds as a product
/// then a sum, as `wide` runs them without FMA), so the same bits
/// (`cbrt_is_wides_bit_for_bit`), inline over the lane primitives where `wide`'s was a call
/// of some 330 instructions for four on SSE2 (BENCHMARKS.md, "Two registers in one stream").
/// a = |x| = 2^(e−1)·d with d ∈ [0.5, 1) (subnormals scaled by 2⁵⁴ first), 1/∛d by the
/// polynomial and one Newton step, ∛d = d·(1/∛d)² and one more step, times 2^{e/3} as
/// 2ᵏ·∛2^(e − 3k); ±0, ±∞ and NaN are x itself.
#[inline(always)]
pub fn cbrt<L: Lane>(x: L) -> L {
    let v = L::splat;
    let one = v(1.0);
    let a = x.abs();
    let (zero, inf, nan) = (a.eq(v(0.0)), a.eq(v(f64::INFINITY)), x.ne(x));
    let tiny = a.lt(v(f64::MIN_POSITIVE));
    let a = tiny.select(a * v(1.8014398509481984e16), a);
    // the exponent of a, and its fraction d (exponent bits set to 2⁻¹'s)
    let two52 = v(4_503_599_627_370_496.0);
    let e = ((a.shr52() | two52) - v(4_503_599_627_370_496.0 + 1023.0)) + one;
    let d = (a & v(f64::from_bits(0x000F_FFFF_FFFF_FFFF))) | v(0.5);
    // each by hand: `CBRT_C.map(v)` stayed a call out of the AVX2 kernel (callgrind)
    let (c0, c1, c2) = (v(CBRT_C[0]), v(CBRT_C[1]), v(CBRT_C[2]));
    let (c3, c4, c5) = (v(CBRT_C[3]), v(CBRT_C[4]), v(CBRT_C[5]));
    let (d2, d4) = (d * d, (d * d) * (d * d));
    let mut r = (c3 * d + c2) * d2 + ((c5 * d + c4) * d4 + (c1 * d + c0));
    let r4 = (r * r) * (r * r);
    r = r - (d * r4 - r) * v(1.0 / 3.0);
    let mut y = (d * r) * r;
    y = y - v(2.0 / 3.0) * y * (y * r - one);
    // 2^{e/3}: k = e/3 toward zero (e − 2 below zero), the rest ∛2 or ∛4
    let three = v(3.0);
    let e_adj = e.lt(v(0.0)).select(e - v(2.0), e);
    let q = e_adj / three;
    let k = q.sign_negative().select(-(-q).floor(), q.floor());
    let rest = e - three * k;
    y = rest.eq(one).select(y * v(1.2599210498948732), y);
    y = rest.eq(v(2.0)).select(y * v(1.5874010519681994), y);
    y = y * pow2(k);
    y = tiny.select(y / v(262_144.0), y);
    let y = x.sign_negative().select(-y, y);
    (nan | zero | inf).select(x, y)
}

/// `flow::exp_small`: Σ xᵏ/k!, k ≤ 10, good where |x| ≤ `SMALL` (flow.rs).
#[inline(always)]
pub fn exp_small<L: Lane>(x: L) -> L {
    horner(x, &EXP_SMALL_SERIES)
}

/// [`exp_small`] by Estrin's scheme, as `estrin::exp_small` sums the scalar path's: the
/// pairs by one multiply-add, then x² and x⁴, four multiply-adds deep after x⁴ where Horner's
/// rule chains ten (`estrin_sums_are_horners_to_two_ulp`).
#[inline(always)]
pub fn exp_small_estrin<L: Lane>(x: L) -> L {
    let (x2, f) = (x * x, &INV_FACTORIAL);
    let x4 = x2 * x2;
    let low = x2.mul_add(pair(x, f, 2), pair(x, f, 0));
    let mid = x2.mul_add(pair(x, f, 6), pair(x, f, 4));
    let high = x2.mul_add(L::splat(f[10]), pair(x, f, 8));
    x4.mul_add(x4.mul_add(high, mid), low)
}

/// eˣ − 1 = x Σ xᵏ/(k + 1)!, k ≤ 5, where |x| < 1e-3 (`flow::real_growth` takes `exp_m1`
/// there): the first term dropped is x⁷/7! < 2e-22 |x|, the sum's rounding a few ε |x|,
/// where e^x − 1 by subtraction would keep only |x|/ε of its digits.
#[inline(always)]
pub fn exp_m1_small<L: Lane>(x: L) -> L {
    x * horner(x, &EXP_M1_SMALL_SERIES)
}

/// `flow::cos_sinc` from x²: (cos x, sin(x)/x) to x¹⁰, good where |x| ≤ `SMALL` (flow.rs),
/// the same bits as the series of x·x. x² may be negative: x² = −y² gives (cosh y,
/// sinh(y)/y), the same series with every term positive (a real pair's short step,
/// `kernel.rs`), good where |y| ≤ `SMALL` as well (`cos_sinc_sq_is_cosh_and_sinhc_too`).
#[inline(always)]
pub fn cos_sinc_sq<L: Lane>(x2: L) -> (L, L) {
    (horner(x2, &COS_SERIES), horner(x2, &SINC_SERIES))
}

/// [`cos_sinc_sq`] by Estrin's scheme in y = x² (`estrin::cos_sinc`'s): the pairs by one
/// multiply-add, then y² and y⁴, three deep where Horner's rule chains five
/// (`estrin_sums_are_horners_to_two_ulp`).
#[inline(always)]
pub fn cos_sinc_sq_estrin<L: Lane>(x2: L) -> (L, L) {
    (estrin6(x2, &COS_SERIES), estrin6(x2, &SINC_SERIES))
}

/// Σ c[5 − k] yᵏ, k ≤ 5 (`c` highest degree first, as [`horner`] takes it) by Estrin's
/// scheme: (c₅ + c₄y) + y²(c₃ + c₂y) + y⁴(c₁ + c₀y).
#[inline(always)]
fn estrin6<L: Lane>(y: L, c: &[f64; 6]) -> L {
    let (v, y2) = (L::splat, y * y);
    let (low, mid) = (y.mul_add(v(c[4]), v(c[5])), y.mul_add(v(c[2]), v(c[3])));
    (y2 * y2).mul_add(y.mul_add(v(c[0]), v(c[1])), y2.mul_add(mid, low))
}

/// How a flow of the lanes (`kernel::Flow4`) sums its series and divides by a constant: the
/// linear law's kernel by [`Horner`] (its bits are the map's, the Monte Carlo's and the
/// golden outputs'), the flattening's by [`Estrin`] — a lone flattening cell
/// (`flattening_one`) is one dependent chain, which waits on every series and quotient on it.
pub trait Sums {
    /// Whether the flow shortens its chain beyond the sums: x/ω as x·(1/ω), the reciprocal
    /// formed once off the chain (`Flow4::at_phase`, the flattening's guesses), and
    /// Householder's step with one quotient where it took two (`refine::householder`).
    const SHORT: bool;
    /// eˣ ([`exp`], [`exp_estrin`]).
    fn exp<L: Lane>(x: L) -> L;
    /// eˣ for |x| ≤ `SMALL` ([`exp_small`], [`exp_small_estrin`]).
    fn exp_small<L: Lane>(x: L) -> L;
    /// (cos x, sin(x)/x) from x² ([`cos_sinc_sq`], [`cos_sinc_sq_estrin`]).
    fn cos_sinc_sq<L: Lane>(x2: L) -> (L, L);
    /// x/d for a constant d: a division, or a product by 1/d (4 cycles on the chain, not 14;
    /// within an ulp of the quotient).
    fn over<L: Lane>(x: L, d: f64) -> L;
}

/// Horner's rule and true quotients: the linear law's kernel.
pub struct Horner;

/// Estrin's scheme and products by reciprocals: the flattening's kernel.
pub struct Estrin;

impl Sums for Horner {
    const SHORT: bool = false;
    #[inline(always)]
    fn exp<L: Lane>(x: L) -> L {
        exp(x)
    }
    #[inline(always)]
    fn exp_small<L: Lane>(x: L) -> L {
        exp_small(x)
    }
    #[inline(always)]
    fn cos_sinc_sq<L: Lane>(x2: L) -> (L, L) {
        cos_sinc_sq(x2)
    }
    #[inline(always)]
    fn over<L: Lane>(x: L, d: f64) -> L {
        x / L::splat(d)
    }
}

impl Sums for Estrin {
    const SHORT: bool = true;
    #[inline(always)]
    fn exp<L: Lane>(x: L) -> L {
        exp_estrin(x)
    }
    #[inline(always)]
    fn exp_small<L: Lane>(x: L) -> L {
        exp_small_estrin(x)
    }
    #[inline(always)]
    fn cos_sinc_sq<L: Lane>(x2: L) -> (L, L) {
        cos_sinc_sq_estrin(x2)
    }
    #[inline(always)]
    fn over<L: Lane>(x: L, d: f64) -> L {
        x * L::splat(1.0 / d)
    }
}

/// ln x for positive normal x, to 1.1e-8 absolute — a start for Householder's steps
/// (`hyper.rs`), not a value kept: x = 2ᵉ·d with d ∈ [0.5, 1) (as [`cbrt`] splits it), ln d =
/// 2 artanh s, s = (d − 1)/(d + 1) ∈ [−1/3, 0), to s¹³ (the terms left out, at most
/// 2|s|¹⁵/15 over 1 − s², < 1.1e-8).
#[inline(always)]
pub fn ln_guess<L: Lane>(x: L) -> L {
    let v = L::splat;
    let one = v(1.0);
    let two52 = v(4_503_599_627_370_496.0);
    let e = ((x.shr52() | two52) - v(4_503_599_627_370_496.0 + 1023.0)) + one;
    let d = (x & v(f64::from_bits(0x000F_FFFF_FFFF_FFFF))) | v(0.5);
    let s = (d - one) / (d + one);
    let atanh = horner(
        s * s,
        &[
            1.0 / 13.0,
            1.0 / 11.0,
            1.0 / 9.0,
            1.0 / 7.0,
            1.0 / 5.0,
            1.0 / 3.0,
            1.0,
        ],
    );
    e * v(std::f64::consts::LN_2) + v(2.0) * s * atanh
}

#[cfg(test)]
#[path = "math_tests.rs"]
mod tests;
