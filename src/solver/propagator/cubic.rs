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

/// Roots of s³ + a2 s² + a1 s + a0 with a_i ≥ 0.
pub fn cubic_roots(a: [f64; 3]) -> Roots {
    let [a2, a1, a0] = a;
    // A real root in [−B, 0]: p(0) = a0 ≥ 0, and −B lies left of every root, so p(−B) < 0. a0 = 0 (λ = 0 or ζ = 0) has the root 0 exactly.
    let r = if a0 == 0.0 {
        0.0
    } else {
        // Lagrange's bound max(1, Σ a_i): cruder than Fujiwara's, but needs no cube root, and
        // the bracketed iteration starts from the secant point anyway
        let bound = (a2 + a1 + a0).max(1.0) * 1.01;
        let p = |s: f64| (((s + a2) * s + a1) * s + a0, (3.0 * s + 2.0 * a2) * s + a1);
        newton_bracketed(p, -bound, 0.0)
    };
    // Deflate: s³ + a2 s² + a1 s + a0 = (s − r)(s² + p1 s + p0). Backward division
    // (p0 = −a0/r) is stable when r is the larger root, |r|³ ≥ a0 = |r|·|p0|; forward division
    // (p1 = a2 + r) when it is the smaller. The pair is then polished on the full cubic.
    let (p1, p0) = if r != 0.0 && r.abs().powi(3) >= a0 {
        let p0 = -a0 / r;
        ((p0 - a1) / r, p0)
    } else {
        let p1 = a2 + r;
        (p1, a1 + r * p1)
    };
    let centre = -0.5 * p1;
    let q = centre * centre - p0;
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
    // Three real roots: the leftmost becomes s1 and `all()` puts the rightmost last, so that
    // s3 − s1 is the widest spacing and the last divided difference does not cancel.
    let s3 = polish(a, C::new(centre, 0.0) - h);
    let mut all = [r, s2.re, s3.re];
    all.sort_by(f64::total_cmp);
    Roots {
        s1: all[0],
        centre: 0.5 * (all[1] + all[2]),
        q: (0.5 * (all[2] - all[1])).powi(2),
    }
}
