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

/// The arithmetic of the fast series (`power::series_of`) and sums (`super::fused`) needs: IEEE f64 operations, lane by lane.
pub(super) trait Coef:
    Copy + std::ops::Add<Output = Self> + std::ops::Sub<Output = Self> + std::ops::Mul<Output = Self>
{
    fn splat(x: f64) -> Self;
    /// self · a + b with one rounding (IEEE fusedMultiplyAdd), lane by lane: the same bits
    /// on every CPU, one instruction where it has FMA.
    fn mul_add(self, a: Self, b: Self) -> Self;
}

impl Coef for f64 {
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn mul_add(self, a: f64, b: f64) -> f64 {
        f64::mul_add(self, a, b)
    }
}

/// The step after which the last two terms of series of order `order`, whose norms (each
/// term's largest size relative to its series' scale) are given, stay below `eps`:
/// h = min over j ∈ {N − 1, N} of (ε / a_j)^{1/j}, two `powf` whatever the number of series.
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

/// [`step_of_norms`] without `powf`: the same rule, h = 2^min_j (log₂(ε/a_j) / j), with
/// log₂ and 2^y by short series ([`log2_core`], [`exp2_core`]) good to 2e-6 in log₂ a, so
/// to 1e-7 relative in h at the orders used (j ≥ 19): the truncation moves by (1 + 1e-7)^j, far
/// inside ε. The fast paths' rule (`rules::Sums::Quick` and `Fused`); two `powf` were 14 % of a batched
/// elastic–plastic impact (perf, BENCHMARKS.md, twelfth session). Written by hand: it must be
/// the same IEEE operations in `super::batch`'s steps as here, which no libm promises.
#[inline(always)]
pub(super) fn quick_step_of_norms(next_to_last: f64, last: f64, order: usize, eps: f64) -> f64 {
    let y = if is_plain(next_to_last) && is_plain(last) {
        quick_exponent(next_to_last, last, order, eps)
    } else {
        let log_eps = log2_core(eps);
        let rule = |a: f64, j: usize| {
            if a == 0.0 {
                f64::INFINITY
            } else {
                let log_a = if is_plain(a) { log2_core(a) } else { a.log2() };
                exponent(log_eps, log_a, j)
            }
        };
        rule(next_to_last, order - 1).min(rule(last, order))
    };
    if is_in_reach(y) {
        exp2_core(y)
    } else {
        y.exp2()
    }
}

/// The exponent y of [`quick_step_of_norms`]'s h = 2^y where both norms are positive and
/// normal ([`is_plain`]), without a branch: the lanes' (`super::batch`, which takes
/// [`quick_step_of_norms`] itself for a lane where they are not, or where y is not
/// [`is_in_reach`]).
#[inline(always)]
pub(super) fn quick_exponent(next_to_last: f64, last: f64, order: usize, eps: f64) -> f64 {
    let log_eps = log2_core(eps);
    let y1 = exponent(log_eps, log2_core(next_to_last), order - 1);
    y1.min(exponent(log_eps, log2_core(last), order))
}

/// log₂((ε/a)^{1/j}) from log₂ ε and log₂ a: the rule's exponent for one term.
#[inline(always)]
fn exponent(log_eps: f64, log_a: f64, j: usize) -> f64 {
    (log_eps - log_a) * (1.0 / j as f64)
}

/// Positive and normal: where [`log2_core`] holds.
#[inline(always)]
pub(super) fn is_plain(x: f64) -> bool {
    x.is_normal() && x > 0.0
}

/// Within ±1000: where [`exp2_core`] holds.
#[inline(always)]
pub(super) fn is_in_reach(y: f64) -> bool {
    y.abs() <= 1000.0
}

/// 2⁵²: a float at least this large has no fraction, and its last bits are the integer.
const TWO_52: f64 = 4_503_599_627_370_496.0;

/// log₂ x to 2e-6 for positive normal x ([`is_plain`]): x = 2^e m, m ∈ [1, 2),
/// log₂ m = (2/ln 2) atanh t with t = (m − 1)/(m + 1) ∈ [0, 1/3], its series to t⁹ (the next
/// term is below 2e-6). e is read as a float by the 2⁵² trick, so that no conversion
/// instruction AVX-512F lacks is needed.
#[inline(always)]
fn log2_core(x: f64) -> f64 {
    let bits = x.to_bits();
    let e = f64::from_bits((bits >> 52) | TWO_52.to_bits()) - (TWO_52 + 1023.0);
    let m = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    let atanh =
        t * (1.0 + t2 * (1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0)))));
    e + 2.0 * std::f64::consts::LOG2_E * atanh
}

/// 2^y to 1e-7 relative for |y| ≤ 1000 ([`is_in_reach`]): y = n + f, f ∈ [0, 1),
/// 2^f = e^{f ln 2} by its series to the 8th power (the next term is below 2e-7), 2^n by the
/// exponent's bits. n is y rounded by the 2⁵² trick, less one where that rounded up: no
/// `floor` (a libm call on the baseline target).
#[inline(always)]
pub(super) fn exp2_core(y: f64) -> f64 {
    let rounded = (y + 1.5 * TWO_52) - 1.5 * TWO_52;
    let n = if rounded > y { rounded - 1.0 } else { rounded };
    let z = (y - n) * std::f64::consts::LN_2;
    // Σ_{k ≤ 8} z^k/k! by Estrin's pairs: four short chains, not Horner's eight links
    let (z2, c) = (z * z, |k: usize| 1.0 / FACTORIALS[k]);
    let low = (c(0) + c(1) * z) + z2 * (c(2) + c(3) * z);
    let high = (c(4) + c(5) * z) + z2 * (c(6) + c(7) * z);
    let z4 = z2 * z2;
    let sum = low + z4 * (high + z4 * (1.0 / 40320.0));
    // n + 1023 ∈ [23, 2023]: its bits above 2⁵² are the biased exponent of 2^n
    let biased = ((n + 1023.0) + TWO_52).to_bits() & 0x7ff;
    sum * f64::from_bits(biased << 52)
}

/// k! for k < 8.
const FACTORIALS: [f64; 8] = [1.0, 1.0, 2.0, 6.0, 24.0, 120.0, 720.0, 5040.0];

/// The first h in (0, `end`] where `c(h) = target`, given that `c(0) − target` and
/// `c(end) − target` differ in sign (or the latter is 0): Newton's steps inside a bracket that
/// bisection keeps, to the rounding of h.
pub(super) fn root<const L: usize>(c: &[f64; L], target: f64, end: f64) -> f64 {
    let ends = (eval(c, 0.0) - target, eval(c, end) - target);
    root_with(c, target, end, ends, eval, eval_d, Stop::Bracket)
}

/// [`root`] with its sums by Estrin's scheme ([`eval_estrin`]): the fast paths' roots
/// (`rules::Sums::Quick`). Horner's sums of order 28 are 28 dependent multiply–adds each, and
/// Newton's steps wait on them; the roots were a quarter of a batched elastic–plastic impact
/// (perf, BENCHMARKS.md, twelfth session). c(0) is c₀, and c(end) is `c_end`, which the
/// caller has already summed.
pub(super) fn root_quick<const L: usize>(c: &[f64; L], target: f64, end: f64, c_end: f64) -> f64 {
    root_quick_by(c, target, end, c_end, eval_estrin, Stop::Rounding)
}

/// [`root_quick`] with the sums `sum` (value and slope alike), ended as `stop` says:
/// Estrin's by a product and a sum at the first Newton step within the rounding, or fused
/// and a step sooner where it can (`super::fused::root`).
#[inline(always)]
pub(super) fn root_quick_by<const L: usize>(
    c: &[f64; L],
    target: f64,
    end: f64,
    c_end: f64,
    sum: fn(&[f64; L], f64) -> f64,
    stop: Stop,
) -> f64 {
    let d = derivative(c);
    let ends = (c[0] - target, c_end - target);
    root_with(c, target, end, ends, sum, move |_, h| sum(&d, h), stop)
}

/// When a root's search ([`root_with`]) stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Stop {
    /// When Newton's step is within h's rounding, or the bracket has closed: [`root`], the
    /// reference's.
    Bracket,
    /// At the first Newton step within h's rounding: [`root_quick`].
    Rounding,
    /// One Newton step sooner where it can: where the error left after a step δₙ, C δₙ² by
    /// Newton's quadratic convergence with its rate C taken from the last two steps
    /// (δₙ ≈ C δₙ₋₁²), is within h's rounding, that step is the last, and the step that
    /// would only confirm it is not taken: the fused roots (`super::fused::root`).
    Predicted,
}

/// Σ c_k h^k by Estrin's scheme: the pairs c_{2i} + c_{2i+1} h, then the pairs of those with
/// h², and so on: ⌈log₂ L⌉ dependent steps instead of Horner's L − 1. Its rounding is
/// bounded as Horner's (both sum the same products, each with at most ⌈log₂ L⌉ or L
/// roundings), and tests/physics/taylor.rs holds the answers it gives to the references.
#[inline(always)]
pub(super) fn eval_estrin<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    estrin_by(c, h, |low, high, x| low + high * x)
}

/// Estrin's scheme with each pair c_{2i} + c_{2i+1} x taken by `pair(c_{2i}, c_{2i+1}, x)`:
/// a product and a sum ([`eval_estrin`]), or one fused multiply–add (`super::fused`).
#[inline(always)]
pub(super) fn estrin_by<const L: usize>(
    c: &[f64; L],
    h: f64,
    pair: impl Fn(f64, f64, f64) -> f64,
) -> f64 {
    let mut b = *c;
    let (mut n, mut x) = (L, h);
    while n > 1 {
        let half = n.div_ceil(2);
        for i in 0..half {
            b[i] = if 2 * i + 1 < n {
                pair(b[2 * i], b[2 * i + 1], x)
            } else {
                b[2 * i]
            };
        }
        n = half;
        x = x * x;
    }
    b[0]
}

/// [`root`]'s search with the sums `value` and `slope` (Σ c_k h^k and its derivative), given
/// c − target at 0 and at `end` (`ends`), ended as `stop` says.
#[inline(always)]
pub(super) fn root_with<const L: usize>(
    c: &[f64; L],
    target: f64,
    end: f64,
    (g_lo, g_hi): (f64, f64),
    value: fn(&[f64; L], f64) -> f64,
    slope: impl Fn(&[f64; L], f64) -> f64,
    stop: Stop,
) -> f64 {
    let quick = stop != Stop::Bracket;
    // the Newton step before, where there was one (NaN: none)
    let mut last_step = f64::NAN;
    let g = |h: f64| value(c, h) - target;
    let (mut lo, mut hi) = (0.0, end);
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
        let d = slope(c, h);
        let mut next = h - v / d;
        if quick && (next - h).abs() <= 4.0 * f64::EPSILON * h.abs() {
            // Newton's step is within h's rounding: h is the root to the rounding. Going on
            // as [`root`] does, a step that rounding puts just outside the bracket would
            // bisect back over some thirty halvings to the same root
            return if next > lo && next < hi { next } else { h };
        }
        let step = (next - h).abs();
        // C δₙ² with C = δₙ/δₙ₋₁², where the steps already fall fast (δₙ ≤ 1e-6 h)
        let left = step / (last_step * last_step) * step * step;
        let predicted = step <= 1e-6 * h.abs() && left <= 4.0 * f64::EPSILON * h.abs();
        if stop == Stop::Predicted && predicted && next > lo && next < hi {
            return next;
        }
        last_step = step;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
            // a halving: the step not taken says nothing of the next step's rate
            last_step = f64::NAN;
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
    fn the_quick_step_is_the_powf_rule_within_1e_7() {
        for order in [20, 28] {
            for &eps in &[1e-17, 1e-15] {
                for i in 0..2_000 {
                    // norms over 600 decades, either of the two the smaller
                    let a = 10f64.powf(-300.0 + 0.3 * i as f64);
                    let b = a * 10f64.powf(((i * 37) % 11) as f64 - 5.0);
                    let exact = step_of_norms(a, b, order, eps);
                    let quick = quick_step_of_norms(a, b, order, eps);
                    assert!(
                        (quick / exact - 1.0).abs() < 1e-7,
                        "{a:e} {b:e}: {quick} {exact}"
                    );
                }
                assert_eq!(quick_step_of_norms(0.0, 0.0, order, eps), f64::INFINITY);
                assert!(quick_step_of_norms(f64::NAN, f64::NAN, order, eps).is_nan());
                assert_eq!(quick_step_of_norms(f64::INFINITY, 1.0, order, eps), 0.0);
            }
        }
    }

    #[test]
    fn quick_roots_are_the_reference_roots_to_the_rounding() {
        // (h − 0.3)(h + 2) and the exponential's series less 1.5 (root ln 1.5)
        let mut quadratic = [0.0; LEN];
        (quadratic[0], quadratic[1], quadratic[2]) = (-0.6, 1.7, 1.0);
        let mut exp = [0.0; LEN];
        let mut f = 1.0;
        for (k, ck) in exp.iter_mut().enumerate() {
            f *= k.max(1) as f64;
            *ck = 1.0 / f;
        }
        for (c, target, root_true) in [(quadratic, 0.0, 0.3), (exp, 1.5, 1.5f64.ln())] {
            let quick = root_quick(&c, target, 1.0, eval(&c, 1.0));
            assert!(
                (quick - root_true).abs() <= 4.0 * f64::EPSILON,
                "{quick} {root_true}"
            );
            assert!((quick - root(&c, target, 1.0)).abs() <= 4.0 * f64::EPSILON);
            assert!((eval_estrin(&c, root_true) - eval(&c, root_true)).abs() < 4e-16);
        }
    }

    /// A search stopped a Newton step sooner (`Stop::Predicted`) lands where the bracketed
    /// reference does, to the rounding: series of order 28 whose terms fall as a phase's do,
    /// at 400 targets across their range.
    #[test]
    fn predicted_roots_are_the_reference_roots_to_the_rounding() {
        let mut worst: f64 = 0.0;
        for round in 0..400 {
            let mut c = [0.0; 29];
            for (k, ck) in c.iter_mut().enumerate().skip(2) {
                let sign = if (k * 7 + round) % 3 == 0 { -1.0 } else { 1.0 };
                *ck = sign * (1.0 + ((k * 13 + round * 5) % 17) as f64 / 17.0)
                    / (1.5 + (round % 7) as f64 / 4.0).powi(k as i32);
            }
            (c[0], c[1]) = (0.4 + (round % 50) as f64 / 100.0, -1.0);
            let c_end = eval_estrin(&c, 1.0);
            let target = c_end + (c[0] - c_end) * ((round * 37) % 97 + 1) as f64 / 99.0;
            let predicted = root_quick_by(&c, target, 1.0, c_end, eval_estrin, Stop::Predicted);
            let reference = root(&c, target, 1.0);
            worst = worst.max((predicted - reference).abs() / f64::EPSILON);
        }
        assert!(worst <= 4.0, "{worst} ulp");
    }
}
