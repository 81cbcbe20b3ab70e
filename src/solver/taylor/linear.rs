//! A phase on a linear branch, F̄ = k (z̄ − z̄₀) + F̄₀ (the linear law's loading and unloading,
//! Eqs. 21–22; the elastic–plastic law's straight stretch, Eq. 11), integrated by Taylor
//! series in τ. The system is linear, so each coefficient costs a few operations:
//!
//! ```text
//! z̄' = ᾱ' − ȳ',   ᾱ'' = −F̄,   ȳ' = 2ζ(F̄ − λȳ).
//! ```

use super::poly::{self, EPS};
use super::rules::{Rules, Sums};
use super::{Budget, Point, Sys};

/// The series' length on the elastic–plastic straight stretch: order 24, not the linear
/// law's `poly::ORDER`, 20. A coefficient costs a few operations here, so a longer series is
/// cheap, and it takes the stretch from yield to the peak in one step where order 20 took
/// two: past yield 1.65 → 1.51 µs an impact batched over every preset at 0.6–60 m/s, against
/// 1.52–1.55 at order 22 and 1.54–1.61 at 28 (BENCHMARKS.md, fourteenth session). The linear law's
/// flattening keeps order 20, so its answers keep their bits.
pub(super) const STRETCH_LEN: usize = 25;

/// The linear phases' rules: within `poly::EPS`, by the quick step rule and roots (no
/// reference is built on them), unfused (the linear law's answers keep their bits).
const RULES: Rules = Rules {
    eps: EPS,
    sums: Sums::Quick,
};

/// The branch F̄ = k (z̄ − z̄₀) + F̄₀.
#[derive(Debug, Clone, Copy)]
pub(super) struct Branch {
    pub k: f64,
    pub z0: f64,
    pub f0: f64,
}

/// How a phase on a linear branch ended.
#[derive(Debug, Clone, Copy)]
pub(super) enum End {
    /// z̄' = 0: the peak z̄_m, unloading starts here.
    Turned(Point),
    /// F̄ = 0: the ball left at this point.
    Separated(Point),
}

/// The Taylor coefficients of (z̄, ᾱ', ȳ) at x. Of order j ≥ 1, F̄_j = k z̄_j (k the branch's
/// slope), so with a = 2ζk, b = 2ζλ, ȳ'_j = a z̄_j − b ȳ_j; with a_j = a/(j + 1) and
/// b_j = b/(j + 1), which hold no coefficient, z̄_{j+1} = (ᾱ'_j/(j + 1) + b_j ȳ_j) − a_j z̄_j
/// and ȳ_{j+1} = a_j z̄_j − b_j ȳ_j: one order's z̄ and ȳ reach the next through a product
/// and a sum or two, the series' cost being that chain's latency, not its arithmetic.
fn series<const L: usize>(sys: &Sys, br: &Branch, x: [f64; 3]) -> [[f64; L]; 3] {
    let (mut z, mut v, mut y) = ([0.0; L], [0.0; L], [0.0; L]);
    (z[0], v[0], y[0]) = (x[0], x[1], x[2]);
    let two_zeta = 2.0 * sys.zeta;
    let (a, b) = (two_zeta * br.k, two_zeta * sys.lambda);
    // order 0: F̄_0 = k (z̄_0 − z̄₀) + F̄₀
    let f = br.k * (z[0] - br.z0) + br.f0;
    let yd = two_zeta * f - b * y[0];
    (z[1], v[1], y[1]) = (v[0] - yd, -f, yd);
    for k in 1..L - 1 {
        let inv = 1.0 / (k + 1) as f64;
        let (a_k, b_k) = (a * inv, b * inv);
        z[k + 1] = (v[k] * inv + b_k * y[k]) - a_k * z[k];
        v[k + 1] = -(br.k * z[k]) * inv;
        y[k + 1] = a_k * z[k] - b_k * y[k];
    }
    [z, v, y]
}

fn at<const L: usize>(c: &[[f64; L]; 3], h: f64, tau: f64) -> Point {
    Point {
        tau: tau + h,
        z: poly::eval_estrin(&c[0], h),
        v: poly::eval_estrin(&c[1], h),
        y: poly::eval_estrin(&c[2], h),
    }
}

/// Run the phase from `start` until z̄' falls through 0 (loading: `peak` is `None`) or, with
/// the peak z̄_m given (unloading), until F̄ falls to 0; a rise past z̄_m (a reload), or the
/// budget running out, gives `None`.
pub(super) fn run<const L: usize>(
    sys: &Sys,
    br: &Branch,
    start: Point,
    peak: Option<f64>,
    budget: &mut Budget,
) -> Option<End> {
    let mut x = [start.z, start.v, start.y];
    let mut tau = start.tau;
    // F̄ = 0 where z̄ = z̄₀ − F̄₀/k
    let z_free = br.z0 - br.f0 / br.k;
    loop {
        budget.take()?;
        let c = series::<L>(sys, br, x);
        let h = RULES.step(&c, &x.map(|xi| xi.abs().max(1.0)));
        if !(h.is_finite() && h > 0.0) {
            return None;
        }
        match peak {
            None => {
                let dz = poly::derivative(&c[0]);
                let dz_end = poly::eval_estrin(&dz, h);
                if dz_end <= 0.0 {
                    let turn = RULES.root(&dz, 0.0, h, dz_end);
                    return Some(End::Turned(at(&c, turn, tau)));
                }
            }
            Some(z_m) => {
                let z_end = poly::eval_estrin(&c[0], h);
                if z_end > z_m {
                    return None;
                }
                if z_end <= z_free {
                    let leave = RULES.root(&c[0], z_free, h, z_end);
                    let mut p = at(&c, leave, tau);
                    p.z = z_free;
                    return Some(End::Separated(p));
                }
            }
        }
        let p = at(&c, h, tau);
        (x, tau) = ([p.z, p.v, p.y], p.tau);
        if tau > budget.tau_max {
            return None;
        }
    }
}
