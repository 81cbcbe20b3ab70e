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

/// The linear law's rules: within `poly::EPS`, by the quick step rule and roots (no
/// reference is built on them), unfused (its answers keep their bits).
const RULES: Rules = Rules {
    eps: EPS,
    sums: Sums::Quick,
};

/// The elastic–plastic stretch's rules: [`RULES`] with the fused roots, which end a Newton
/// step sooner (`poly::Stop::Predicted`), and the step's norms by the scales' reciprocals
/// (`Rules::step`). [`run_by`]'s own sums (the turn's slope, the state at an event) stay
/// `poly::eval_estrin`'s, unfused, whatever the rules.
const STRETCH_RULES: Rules = Rules {
    eps: EPS,
    sums: Sums::Fused,
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

/// [`series`] by four chains, for the elastic–plastic straight stretch ([`stretch`]). Past
/// order 1 the system is homogeneous, c_{j+1} = M c_j / (j + 1) with M's rows (−a, 1, b),
/// (−k, 0, 0) and (a, 0, −b) ([`series`]'s a, b), so c_{j+4} = M⁴ c_j / ((j+1)(j+2)(j+3)(j+4)):
/// four chains of a quarter the length, each link a 3 × 3 product, where [`series`] waits on
/// every order in turn. A product and a sum each rounded apart (no `mul_add`: this code has no
/// FMA compilation, where it would be a call to libm's `fma`). tests: `chains_are_the_series`.
fn series_in_chains<const L: usize>(sys: &Sys, br: &Branch, x: [f64; 3]) -> [[f64; L]; 3] {
    let mut c = [[0.0; L]; 3];
    let two_zeta = 2.0 * sys.zeta;
    let (a, b) = (two_zeta * br.k, two_zeta * sys.lambda);
    // orders 0 and 1 as `series` has them: F̄_0 = k (z̄_0 − z̄₀) + F̄₀
    let f = br.k * (x[0] - br.z0) + br.f0;
    let yd = two_zeta * f - b * x[2];
    for (cv, (x0, x1)) in c.iter_mut().zip(x.into_iter().zip([x[1] - yd, -f, yd])) {
        (cv[0], cv[1]) = (x0, x1);
    }
    let m = [[-a, 1.0, b], [-br.k, 0.0, 0.0], [a, 0.0, -b]];
    let product = |p: &[[f64; 3]; 3], q: &[[f64; 3]; 3]| -> [[f64; 3]; 3] {
        p.map(|row| std::array::from_fn(|j| row[0] * q[0][j] + row[1] * q[1][j] + row[2] * q[2][j]))
    };
    let m4 = {
        let m2 = product(&m, &m);
        product(&m2, &m2)
    };
    // c_{j+n} = p c_j · scale
    let mut link = |p: &[[f64; 3]; 3], j: usize, n: usize, scale: f64| {
        let cj = [c[0][j], c[1][j], c[2][j]];
        for (cv, row) in c.iter_mut().zip(p) {
            cv[j + n] = (row[0] * cj[0] + row[1] * cj[1] + row[2] * cj[2]) * scale;
        }
    };
    for j in 1..4.min(L - 1) {
        link(&m, j, 1, 1.0 / (j + 1) as f64);
    }
    for j in 1..L.saturating_sub(4) {
        link(
            &m4,
            j,
            4,
            1.0 / ((j + 1) * (j + 2) * (j + 3) * (j + 4)) as f64,
        );
    }
    c
}

/// The state at h after a step from τ = `tau` with the series `c` (Estrin's sums, unfused).
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
/// budget running out, gives `None`: the linear law's branches.
pub(super) fn run<const L: usize>(
    sys: &Sys,
    br: &Branch,
    start: Point,
    peak: Option<f64>,
    budget: &mut Budget,
) -> Option<End> {
    run_by::<L>(sys, br, start, peak, RULES, series::<L>, budget)
}

/// The elastic–plastic straight stretch (Eq. 11) from yield at `start` to the turn, as
/// [`run`] loads, by order 24 ([`STRETCH_LEN`]) in chains ([`series_in_chains`]) and with
/// [`STRETCH_RULES`].
pub(super) fn stretch(sys: &Sys, br: &Branch, start: Point, budget: &mut Budget) -> Option<End> {
    let series = series_in_chains::<STRETCH_LEN>;
    run_by::<STRETCH_LEN>(sys, br, start, None, STRETCH_RULES, series, budget)
}

/// [`run`] with the `rules` and the series `series_of` ([`series`] or [`series_in_chains`]).
fn run_by<const L: usize>(
    sys: &Sys,
    br: &Branch,
    start: Point,
    peak: Option<f64>,
    rules: Rules,
    series_of: impl Fn(&Sys, &Branch, [f64; 3]) -> [[f64; L]; 3],
    budget: &mut Budget,
) -> Option<End> {
    let mut x = [start.z, start.v, start.y];
    let mut tau = start.tau;
    // F̄ = 0 where z̄ = z̄₀ − F̄₀/k
    let z_free = br.z0 - br.f0 / br.k;
    loop {
        budget.take()?;
        let c = series_of(sys, br, x);
        let h = rules.step(&c, &x.map(|xi| xi.abs().max(1.0)));
        if !(h.is_finite() && h > 0.0) {
            return None;
        }
        match peak {
            None => {
                let dz = poly::derivative(&c[0]);
                let dz_end = poly::eval_estrin(&dz, h);
                if dz_end <= 0.0 {
                    let turn = rules.root(&dz, 0.0, h, dz_end);
                    return Some(End::Turned(at(&c, turn, tau)));
                }
            }
            Some(z_m) => {
                let z_end = poly::eval_estrin(&c[0], h);
                if z_end > z_m {
                    return None;
                }
                if z_end <= z_free {
                    let leave = rules.root(&c[0], z_free, h, z_end);
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Two paths to the same series: [`series_in_chains`] (M⁴ in four chains) agrees with
    /// [`series`] (order by order) term by term, and so do their sums over a step, on
    /// stretches from soft to stiff, lightly to heavily damped.
    #[test]
    fn chains_are_the_series() {
        for (i, &(zeta, lambda, k)) in [
            (0.05, 0.5, 1.0),
            (0.17, 1.35, 0.6),
            (0.4, 3.0, 2.5),
            (1.2, 0.2, 8.0),
            (3.0, 10.0, 0.3),
        ]
        .iter()
        .enumerate()
        {
            let sys = Sys { lambda, zeta };
            let br = Branch {
                k,
                z0: 0.3,
                f0: 0.2,
            };
            let x = [0.35, 0.8 - 0.1 * i as f64, 0.05 * i as f64];
            let one = series::<STRETCH_LEN>(&sys, &br, x);
            let four = series_in_chains::<STRETCH_LEN>(&sys, &br, x);
            let h = STRETCH_RULES.step(&one, &x.map(|xi| xi.abs().max(1.0)));
            for v in 0..3 {
                for j in 0..STRETCH_LEN {
                    let d = (four[v][j] - one[v][j]).abs();
                    assert!(d <= 1e-13 * one[v][j].abs(), "{i} {v} {j}: {d:e}");
                }
                for t in [0.25, 0.5, 1.0] {
                    let (a, b) = (poly::eval(&four[v], t * h), poly::eval(&one[v], t * h));
                    assert!((a - b).abs() <= 4e-16 * b.abs().max(1.0), "{i} {v} {t}");
                }
            }
        }
    }
}
