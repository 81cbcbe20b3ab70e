//! Truncated power series: their values, their first roots on a step, and the step a series
//! of order [`ORDER`] (or any other, by its length) can take within [`EPS`] (or a given
//! error: Jorba & Zou's rule, from its last two coefficients).

/// The series' order: about −ln ε / 2, where Taylor's method does the least work per unit
/// of time at a step's error ε (Jorba & Zou, "A software package for the numerical
/// integration of ODEs by means of high-order Taylor methods", 2005).
pub(super) const ORDER: usize = 20;
/// Coefficients of a series of order [`ORDER`].
pub(super) const LEN: usize = ORDER + 1;
/// The truncation error allowed per step, relative to the state's scale: below the rounding
/// of the state itself, so that the step's error is its rounding.
pub(super) const EPS: f64 = 1e-17;

/// A truncated power series Σ c_k h^k.
pub(super) type Series = [f64; LEN];

/// Σ c_k h^k (Horner).
pub(super) fn eval<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ck| acc * h + ck)
}

/// d/dh Σ c_k h^k.
pub(super) fn eval_d<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    let mut acc = 0.0f64;
    for k in (1..L).rev() {
        acc = acc * h + k as f64 * c[k];
    }
    acc
}

/// The series of the derivative (order one less; its last coefficient 0).
pub(super) fn derivative<const L: usize>(c: &[f64; L]) -> [f64; L] {
    let mut d = [0.0; L];
    for k in 1..L {
        d[k - 1] = k as f64 * c[k];
    }
    d
}

/// The step after which every series' last two terms, each relative to its `scales` entry,
/// stay below [`EPS`]: h = min over j ∈ {N − 1, N} of (ε / max_i |c_ij|/scale_i)^{1/j}. The
/// norms are taken first, so that the step costs two `powf` whatever the number of series.
pub(super) fn step(c: &[Series], scales: &[f64]) -> f64 {
    step_within(c, scales, EPS)
}

/// [`step`] for series of any order (their length less one) within the error `eps`.
pub(super) fn step_within<const L: usize>(c: &[[f64; L]], scales: &[f64], eps: f64) -> f64 {
    let order = L - 1;
    let norm = |j: usize| {
        c.iter()
            .zip(scales)
            .map(|(ci, s)| ci[j].abs() / s)
            .fold(0.0, f64::max)
    };
    step_of_norms(norm(order - 1), norm(order), order, eps)
}

/// [`step_within`] from the norms of the last two terms of series of order `order`.
pub(super) fn step_of_norms(next_to_last: f64, last: f64, order: usize, eps: f64) -> f64 {
    let rule = |a: f64, j: usize| {
        if a == 0.0 {
            f64::INFINITY
        } else {
            (eps / a).powf(1.0 / j as f64)
        }
    };
    rule(next_to_last, order - 1).min(rule(last, order))
}

/// The first h in (0, `end`] where `c(h) = target`, given that `c(0) − target` and
/// `c(end) − target` differ in sign (or the latter is 0): Newton's steps inside a bracket that
/// bisection keeps, to the rounding of h.
pub(super) fn root<const L: usize>(c: &[f64; L], target: f64, end: f64) -> f64 {
    let g = |h: f64| eval(c, h) - target;
    let (mut lo, mut hi) = (0.0, end);
    let (g_lo, g_hi) = (g(lo), g(hi));
    if g_hi == 0.0 {
        return end;
    }
    let rising = g_lo < g_hi;
    // the secant through the ends starts Newton close to a simple root
    let mut h = if g_hi != g_lo {
        (end * g_lo / (g_lo - g_hi)).clamp(0.0, end)
    } else {
        0.5 * end
    };
    for _ in 0..100 {
        let v = g(h);
        if v == 0.0 {
            return h;
        }
        if (v < 0.0) == rising {
            lo = h;
        } else {
            hi = h;
        }
        let d = eval_d(c, h);
        let mut next = h - v / d;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let settled = (next - h).abs() <= 4.0 * f64::EPSILON * next.abs().max(f64::MIN_POSITIVE);
        h = next;
        if settled || hi - lo <= 2.0 * f64::EPSILON * hi {
            break;
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eval_and_root_of_a_known_polynomial() {
        // (h − 0.3)(h + 2) = h² + 1.7 h − 0.6
        let mut c = [0.0; LEN];
        c[0] = -0.6;
        c[1] = 1.7;
        c[2] = 1.0;
        assert!((eval(&c, 0.3)).abs() < 1e-16);
        assert!((eval_d(&c, 0.3) - 2.3).abs() < 1e-15);
        assert!((root(&c, 0.0, 1.0) - 0.3).abs() < 1e-16);
        assert!((derivative(&c)[0] - 1.7).abs() == 0.0);
    }

    #[test]
    fn the_step_keeps_the_last_terms_below_eps() {
        // the exponential's series: c_k = 1/k!
        let mut c = [0.0; LEN];
        let mut f = 1.0;
        for (k, ck) in c.iter_mut().enumerate() {
            if k > 0 {
                f *= k as f64;
            }
            *ck = 1.0 / f;
        }
        let h = step(&[c], &[1.0]);
        assert!(c[ORDER] * h.powi(ORDER as i32) <= EPS * 1.000_001);
        assert!(h > 1.0 && h < 3.0, "{h}");
        // and the sum at h is e^h to the rounding
        assert!((eval(&c, h) - h.exp()).abs() < 4e-16 * h.exp());
    }
}
