//! The eigenvalues of a phase: the roots of its characteristic cubic, polished by Newton.

use super::C;
use crate::solver::roots::newton_bracketed;

/// The eigenvalues of a phase: one real root and either a complex pair or two more reals.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roots {
    /// The leftmost real root (the fastest real mode).
    pub s1: f64,
    /// Centre of the other two, (s2 + s3)/2.
    pub centre: f64,
    /// ((s2 − s3)/2)²: negative for a complex pair (−b²), non-negative for two reals.
    pub q: f64,
}

impl Roots {
    /// All three roots as complex numbers: s1, then the pair (s2 with the non-negative
    /// imaginary part; for real roots s2 ≤ s3, so that s1 ≤ s2 ≤ s3).
    pub fn all(&self) -> [C; 3] {
        let c = C::new(self.centre, 0.0);
        if self.q < 0.0 {
            let h = C::new(0.0, (-self.q).sqrt());
            [C::new(self.s1, 0.0), c + h, c - h]
        } else {
            let h = C::new(self.q.sqrt(), 0.0);
            [C::new(self.s1, 0.0), c - h, c + h]
        }
    }
}

pub(super) fn eval_cubic(a: [f64; 3], s: C) -> (C, C) {
    let [a2, a1, a0] = a;
    let p = ((s + a2) * s + a1) * s + a0;
    let dp = (s * 3.0 + 2.0 * a2) * s + a1;
    (p, dp)
}

fn polish(a: [f64; 3], mut s: C) -> C {
    for _ in 0..3 {
        let (p, dp) = eval_cubic(a, s);
        if dp.norm_sqr() == 0.0 {
            break;
        }
        let step = p / dp;
        s -= step;
        if step.norm_sqr() <= 1e-32 * s.norm_sqr() {
            break;
        }
    }
    s
}

/// A pair closer than this (((s2 − s3)/2)² < NEAR_DOUBLE · centre²) is near-double: its
/// roots are not polished one by one on the cubic, where p' ≈ 0 leaves each with only half
/// the digits (a centre off by ~1e-8 cost τ_f 2.5e-8 at λ = 0.02, ζ = 1.7861026411617908;
/// tests/physics/map_precision.rs). Its centre and q from the quadratic factor are exact to rounding
/// (q to ε·centre² absolute, which the flow, smooth in q, sees only as ε). Below it, a
/// polished root would lose at most ~ε/√NEAR_DOUBLE = 1e2 ε to its neighbour.
const NEAR_DOUBLE: f64 = 1e-4;

/// s³ + a2 s² + a1 s + a0 = (s − r)(s² + p1 s + p0). Backward division (p0 = −a0/r) is
/// stable when r is the larger root, |r|³ ≥ a0 = |r|·|p0|; forward division (p1 = a2 + r)
/// when it is the smaller.
fn deflate([a2, a1, a0]: [f64; 3], r: f64) -> (f64, f64) {
    if r != 0.0 && r.abs().powi(3) >= a0 {
        let p0 = -a0 / r;
        ((p0 - a1) / r, p0)
    } else {
        let p1 = a2 + r;
        (p1, a1 + r * p1)
    }
}

/// A real root of the cubic (a_i ≥ 0) that is not one of a near-double pair: bracketed Newton
/// in [−B, 0] finds some real root, which near a double root is good to half the digits only;
/// then the root apart from that pair, polished on the full cubic (it is simple there), and
/// the deflated quadratic (p1, p0).
pub(crate) fn isolated_root(a: [f64; 3]) -> (f64, f64, f64) {
    let [a2, a1, a0] = a;
    let p = |s: f64| (((s + a2) * s + a1) * s + a0, (3.0 * s + 2.0 * a2) * s + a1);
    let r = if a0 == 0.0 {
        0.0
    } else {
        // Lagrange's bound max(1, Σ a_i) lies left of every root, so p(−B) < 0 ≤ p(0) = a0:
        // cruder than Fujiwara's, but needs no cube root, and the bracketed iteration starts
        // from the secant point anyway. a0 = 0 (λ = 0 or ζ = 0) has the root 0 exactly.
        let bound = (a2 + a1 + a0).max(1.0) * 1.01;
        newton_bracketed(p, -bound, 0.0)
    };
    let (p1, p0) = deflate(a, r);
    let (c, q) = (-0.5 * p1, 0.25 * p1 * p1 - p0);
    if q <= 0.0 {
        return (r, p1, p0);
    }
    let h = q.sqrt();
    let (near, far) = if (r - (c + h)).abs() < (r - (c - h)).abs() {
        (c + h, c - h)
    } else {
        (c - h, c + h)
    };
    let (half, mid) = (0.5 * (r - near), 0.5 * (r + near));
    if half * half >= NEAR_DOUBLE * mid * mid {
        return (r, p1, p0);
    }
    let mut x = far;
    for _ in 0..4 {
        let (v, dv) = p(x);
        if dv == 0.0 {
            break;
        }
        x -= v / dv;
    }
    let (p1, p0) = deflate(a, x);
    (x, p1, p0)
}

/// The cubic's modes (a_i ≥ 0): its real root r and its deflated pair s² + 2σs + (σ² + ω²),
/// as `(r, σ, ω², (r + σ)² + ω², σ² + ω²)` — the lone root by Cardano ([`lone_real_root_with`],
/// its cube root by `cbrt`) where a0 > 0, else (and where Cardano does not settle) by
/// [`isolated_root`]: λ = 0 has the root 0 exactly, which Cardano would leave at a rounding's
/// distance. The third is the real root's distance from the pair, squared (p'(r)).
pub(crate) fn modes_of(a: [f64; 3], cbrt: fn(f64) -> f64) -> (f64, f64, f64, f64, f64) {
    let lone = if a[2] > 0.0 {
        lone_real_root_with(a, cbrt)
    } else {
        None
    };
    let (r, p1, p0) = lone.unwrap_or_else(|| isolated_root(a));
    let sigma = 0.5 * p1;
    let omega2 = p0 - sigma * sigma;
    let gap = (r + sigma) * (r + sigma) + omega2;
    (r, sigma, omega2, gap, p0)
}

/// The one real root of the cubic (a_i ≥ 0) where the other two are a complex pair, and the
/// deflated quadratic (p1, p0), as [`isolated_root`] gives them, without its bracketed
/// search: Cardano's root (u − p/3u with u the cube root free of cancellation, taken by
/// `cbrt`: one good to a few digits is enough) polished by Newton on the full cubic, where the
/// root is simple (to 4ε). `None` where the discriminant leaves three real roots, or the
/// polish does not settle: [`isolated_root`] answers there.
pub(crate) fn lone_real_root_with(
    a: [f64; 3],
    cbrt: impl Fn(f64) -> f64,
) -> Option<(f64, f64, f64)> {
    let [a2, a1, a0] = a;
    let shift = a2 / 3.0;
    // s = t − a2/3: t³ + p t + q = 0
    let p = a1 - a2 * shift;
    let q = (2.0 * shift * shift - a1) * shift + a0;
    let disc = 0.25 * q * q + p * p * p / 27.0;
    if disc.is_nan() || disc <= 0.0 {
        return None;
    }
    let u = cbrt(-0.5 * q - q.signum() * disc.sqrt());
    if u == 0.0 {
        return None;
    }
    let mut r = u - p / (3.0 * u) - shift;
    for _ in 0..4 {
        let v = ((r + a2) * r + a1) * r + a0;
        let dv = (3.0 * r + 2.0 * a2) * r + a1;
        let step = v / dv;
        r -= step;
        if step.abs() <= 4.0 * f64::EPSILON * r.abs() {
            let (p1, p0) = deflate(a, r);
            return Some((r, p1, p0));
        }
    }
    None
}

/// Roots of s³ + a2 s² + a1 s + a0 with a_i ≥ 0.
pub fn cubic_roots(a: [f64; 3]) -> Roots {
    let (r, p1, p0) = isolated_root(a);
    let centre = -0.5 * p1;
    let q = centre * centre - p0;
    if q.abs() < NEAR_DOUBLE * centre * centre {
        // near-double pair: centre and q as the quadratic factor gives them
        return ordered(r, centre, q);
    }
    // a pair well apart: each root polished on the full cubic
    let h = if q < 0.0 {
        C::new(0.0, (-q).sqrt())
    } else {
        C::new(q.sqrt(), 0.0)
    };
    let s2 = polish(a, C::new(centre, 0.0) + h);
    if q < 0.0 {
        return Roots {
            s1: r,
            centre: s2.re,
            q: -(s2.im * s2.im),
        };
    }
    let s3 = polish(a, C::new(centre, 0.0) - h);
    let mut all = [r, s2.re, s3.re];
    all.sort_by(f64::total_cmp);
    Roots {
        s1: all[0],
        centre: 0.5 * (all[1] + all[2]),
        q: (0.5 * (all[2] - all[1])).powi(2),
    }
}

/// `Roots` from the real root r and the pair's centre and q. Three real roots: the leftmost
/// becomes s1 and `all()` puts the rightmost last, so that s3 − s1 is the widest spacing and
/// the last divided difference does not cancel. The pair (centre, q) is kept as it is while
/// r lies left of it.
fn ordered(r: f64, centre: f64, q: f64) -> Roots {
    if q < 0.0 || r <= centre - q.sqrt() {
        return Roots { s1: r, centre, q };
    }
    let h = q.sqrt();
    let mut all = [r, centre - h, centre + h];
    all.sort_by(f64::total_cmp);
    Roots {
        s1: all[0],
        centre: 0.5 * (all[1] + all[2]),
        q: (0.5 * (all[2] - all[1])).powi(2),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Where the pair is complex, Cardano's polished root and the bracketed search's are the
    /// same root with the same quadratic factor, to a few ulps, over the model's cubics
    /// s³ + 2ζ(1+λ)s² + s + 2ζλ (λ = 1e-4 … 1e4, ζ = 1e-3 … 1e3); and it declines only where
    /// three roots are real.
    #[test]
    fn cardano_finds_the_bracketed_root() {
        let (mut complex, mut answered) = (0, 0);
        for (lambda, zeta) in crate::model::params::test_plane(10) {
            let a = [2.0 * zeta * (1.0 + lambda), 1.0, 2.0 * zeta * lambda];
            let (r, p1, p0) = isolated_root(a);
            let pair_complex = p1 * p1 < 4.0 * p0;
            complex += pair_complex as usize;
            let Some((s, q1, q0)) = lone_real_root_with(a, f64::cbrt) else {
                continue;
            };
            answered += 1;
            assert!(
                pair_complex,
                "λ = {lambda}, ζ = {zeta}: an answer with 3 real roots"
            );
            // the root to a few ulps; the quadratic factor to a few ulps of the terms that
            // deflation sums (p1 = a2 + r can cancel)
            let close = |x: f64, y: f64, size: f64| (x - y).abs() <= 8.0 * f64::EPSILON * size;
            let (a2, a1, a0) = (a[0], a[1], a[2]);
            assert!(
                close(s, r, r.abs())
                    && close(q1, p1, a2 + r.abs())
                    && close(q0, p0, a1 + (a0 / r).abs() + (r * p1).abs()),
                "λ = {lambda}, ζ = {zeta}: {:?} vs {:?}",
                (s, q1, q0),
                (r, p1, p0)
            );
        }
        assert!(answered * 100 >= complex * 99, "{answered} of {complex}");
    }
}
