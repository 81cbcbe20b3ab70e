//! The fast paths' series of a 3/2-power phase ([`series_of`]): [`super::series`]'s
//! coefficients, summed for speed, in f64 or in lanes.

use super::super::poly::Coef;
use super::{Branch, Sys};

/// The system's coefficients as [`series_of`] takes them, in lanes of type `T`.
#[derive(Clone, Copy)]
pub(in crate::solver::taylor) struct Coefs<T> {
    /// 2ζ
    pub two_zeta: T,
    /// λ
    pub lambda: T,
    /// a
    pub a: T,
    /// −a
    pub minus_a: T,
    /// 1/(2b)
    pub half_b: T,
}

impl Coefs<f64> {
    /// An empty lane's: a force-free branch at rest (`super::super::batch`).
    pub(in crate::solver::taylor) const IDLE: Coefs<f64> = Coefs {
        two_zeta: 0.0,
        lambda: 0.0,
        a: 0.0,
        minus_a: 0.0,
        half_b: 0.5,
    };

    /// [`super::series`]'s coefficients of `sys` on `br`.
    pub(in crate::solver::taylor) fn of(sys: &Sys, br: &Branch) -> Coefs<f64> {
        Coefs {
            two_zeta: 2.0 * sys.zeta,
            lambda: sys.lambda,
            a: br.a,
            minus_a: -br.a,
            half_b: 0.5 / br.b,
        }
    }
}

/// [`super::series`]'s coefficients with each product's sums reordered, the fast paths' series:
/// for f64 in `super::summary`, in lanes in `super::batch`. At order n the four products
/// (s², s³ = s·s², s⁴ = (s²)², s·ȳ') take their terms of 1 ≤ i ≤ n − 1 in one loop over
/// the pairs (i, n − i), each of its six coefficients loaded once for six fused
/// multiply–adds ([`Coef::mul_add`]) where a product at a time loads two for one (the lanes'
/// series were bound by their loads: BENCHMARKS.md, fourteenth session). The pairs go from
/// the middle out, so the one holding order n − 1's coefficients comes last, and the terms
/// of the coefficients order n computes (s₀p_n, p₀p_n, s₀ȳ'_n) after them: an order waits on
/// the one before for a few sums, not for a whole chain. A lane runs f64's IEEE operations
/// in the same order, so its coefficients are the f64 path's bits (tests/physics/taylor_batch.rs
/// `batched_summaries_are_the_single_ones_bit_for_bit`). s² and ȳ' go to `scratch`, kept by
/// the caller from step to step: order n writes their n-th terms before any order reads
/// them, so it need not be cleared.
#[inline(always)]
pub(in crate::solver::taylor) fn series_of<T: Coef, const L: usize>(
    k: Coefs<T>,
    x: [T; 4],
    c: &mut [[T; L]; 4],
    scratch: &mut [[T; L]; 2],
) {
    let two = T::splat(2.0);
    let [s, v, y, t] = c;
    let [p, yd] = scratch;
    (s[0], v[0], y[0], t[0]) = (x[0], x[1], x[2], x[3]);
    for n in 0..L - 1 {
        let (q, r, sy);
        if n == 0 {
            p[0] = s[0] * s[0];
            q = s[0] * p[0];
            r = p[0] * p[0];
            yd[0] = k.two_zeta * (k.a * q - k.lambda * y[0]);
            sy = s[0] * yd[0];
        } else {
            let older = older_terms(s, p, yd, n);
            p[n] = (two * s[0]).mul_add(s[n], older.ss);
            q = s[0].mul_add(p[n], older.sp);
            r = (two * p[0]).mul_add(p[n], older.pp);
            yd[n] = k.two_zeta * (k.a * q - k.lambda * y[n]);
            sy = s[0].mul_add(yd[n], older.sy);
        }
        let inv = T::splat(1.0 / (n + 1) as f64);
        s[n + 1] = (v[n] - yd[n]) * k.half_b * inv;
        v[n + 1] = k.minus_a * r * inv;
        y[n + 1] = sy * inv;
        t[n + 1] = s[n] * inv;
    }
}

/// The terms of order n ≥ 1 of s², s·s², (s²)² and s·ȳ' that hold no coefficient order n
/// computes: all but s₀s_n, s₀p_n, p₀p_n and s₀ȳ'_n ([`series_of`]).
struct Older<T> {
    ss: T,
    sp: T,
    pp: T,
    sy: T,
}

/// [`Older`] of order n ≥ 1: the pairs (i, n − i), 1 ≤ i < n − i, from the middle out, two
/// partial sums for the mixed products; then the middle term (n even), then s_n p₀ and
/// s_n ȳ'₀ (s_n is order n − 1's).
#[inline(always)]
fn older_terms<T: Coef, const L: usize>(s: &[T; L], p: &[T; L], yd: &[T; L], n: usize) -> Older<T> {
    let m = T::splat(-0.0);
    let (mut ss, mut pp, mut sp, mut ps, mut sy, mut ys) = (m, m, m, m, m, m);
    let mut i = (n - 1) / 2;
    while i >= 1 {
        let j = n - i;
        ss = s[i].mul_add(s[j], ss);
        pp = p[i].mul_add(p[j], pp);
        sp = s[i].mul_add(p[j], sp);
        ps = p[i].mul_add(s[j], ps);
        sy = s[i].mul_add(yd[j], sy);
        ys = yd[i].mul_add(s[j], ys);
        i -= 1;
    }
    let two = T::splat(2.0);
    let (mut ss, mut pp, mut sp, mut sy) = (two * ss, two * pp, sp + ps, sy + ys);
    if n.is_multiple_of(2) {
        let h = n / 2;
        ss = s[h].mul_add(s[h], ss);
        pp = p[h].mul_add(p[h], pp);
        sp = s[h].mul_add(p[h], sp);
        sy = s[h].mul_add(yd[h], sy);
    }
    Older {
        ss,
        sp: s[n].mul_add(p[0], sp),
        pp,
        sy: s[n].mul_add(yd[0], sy),
    }
}
