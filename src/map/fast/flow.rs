//! The flow z̄(τ) = A e^{rτ} + e^{−στ}(−A C(τ) + D S(τ)) in closed form (the module's
//! introduction gives A, D and why only σ and ω² enter), its derivatives, its integral and a
//! bound on their rounding, all from one [`Point`]: the three transcendental values at τ,
//! computed once.

use super::estrin;
use crate::solver::series;
use modes::{Modes, abs_sum, antiderivative, flow, modes, quick_cbrt};

#[path = "modes.rs"]
mod modes;

/// What multiplies ε times the terms' sizes in [`Flow::rounding`]: the roots, A, D, P, Q
/// carry a few roundings each (measured over tests/physics/map_precision.rs's grid: the differences to
/// the exact solver stay below 2 ε times the terms' sizes).
const ROUNDING_FACTOR: f64 = 1.0;

/// The flow of one (λ, ζ).
pub(super) struct Flow {
    /// The scales of A, B, D, P, Q's rounding: Σ|terms|/|denominator| as each was formed.
    size: [f64; 5],
    /// Whether the integral's real term A(e^{rτ} − 1)/r takes `exp_m1` while |rτ| < 1/2
    /// (beyond, e^{rτ} − 1 keeps all but 3ε), so that its rounding is bounded by
    /// 3 size(A) τ (1 + e^{rτ}) (|e^{rτ} − 1|/|r| ≤ τ max(1, e^{rτ})): a flow from a state
    /// (`from_state`), whose A's scale does not vanish with r. [`Flow::new`] keeps `exp_m1`
    /// to |rτ| < 1e-3 and the bound size(A)(1 + e^{rτ})/|r| (its A's scale vanishes with r,
    /// and the cells the summary answers, hence the map's values, stay as they were).
    tight: bool,
    /// (r + σ)² + ω² and σ² + ω², kept for [`Flow::responses`].
    gap: f64,
    p0: f64,
    /// The real root standing apart.
    pub r: f64,
    /// The pair's decay rate: s² + 2σs + (σ² + ω²).
    pub sigma: f64,
    /// ω²: positive for an oscillating pair, negative (−ν²) for a real one.
    pub omega2: f64,
    /// ω = √ω² for an oscillating pair, 0 otherwise.
    pub omega: f64,
    /// The real mode's amplitude A.
    pub a: f64,
    /// The pair's S coefficient D.
    pub d: f64,
    /// The antiderivative of e^{−στ}(−A C + D S) is e^{−στ}(P C + Q S).
    p: f64,
    q: f64,
    /// z̄^{(k)} = A r^k e^{rτ} + c_k e^{−στ} C + s_k e^{−στ} S, k < [`JET`]: rows (A r^k, c_k,
    /// s_k), so that a jet's entries are independent sums, not a chain.
    jet: [[f64; 3]; JET],
}

/// The most derivatives a jet gives (z̄ … z̄^{(5)}).
pub(super) const JET: usize = 6;

/// The flow's transcendental values at one τ: e^{rτ}, e^{−στ} C(τ) and e^{−στ} S(τ).
#[derive(Clone, Copy)]
pub(super) struct Point {
    /// τ.
    pub t: f64,
    /// e^{rτ}.
    real: f64,
    /// e^{−στ} where the pair oscillates (unused otherwise).
    decay: f64,
    /// e^{−στ} C(τ).
    ec: f64,
    /// e^{−στ} S(τ).
    es: f64,
}

impl Flow {
    /// The flow at (λ, ζ), or `None` where its modes do not separate (the gap (r + σ)² + ω²
    /// vanishes) or the pair does not decay.
    pub fn new(lambda: f64, zeta: f64) -> Option<Flow> {
        Flow::with_modes(modes(lambda, zeta, f64::cbrt)?, zeta, 2.0 * zeta * lambda)
    }

    /// [`Flow::new`], Cardano's cube root taken by `quick_cbrt` (within an ulp of the
    /// correctly rounded one; Newton's steps polish the root on the cubic either way): the
    /// flattening's loading (`super::flatten`; the summary keeps `f64::cbrt`, whose maps are pinned by goldens).
    #[inline]
    pub fn new_quick(lambda: f64, zeta: f64) -> Option<Flow> {
        Flow::with_modes(modes(lambda, zeta, quick_cbrt)?, zeta, 2.0 * zeta * lambda)
    }

    /// The flow of the modes `m` from the loading's start (z̄, z̄', z̄'') = (0, 1, −2ζ);
    /// `a0` = 2ζλ, the cubic's constant term.
    #[inline]
    fn with_modes(m: Modes, zeta: f64, a0: f64) -> Option<Flow> {
        let (r, sigma, omega2, gap) = (m.r, m.sigma, m.omega2, m.gap);
        // Z(s) = (s + a0)/cubic (Laplace, z̄(0) = 0, z̄'(0) = 1, z̄''(0) = −2ζ): A is the
        // residue at r, (r + a0)/p'(r) = 2(σ − ζ)/gap; D from matching at s = −σ,
        // (σ − a0 + A ω²)/(σ + r) = 1 − (r + σ) A. Of each two equal forms the one whose
        // terms are smaller is taken, and `size` keeps Σ|terms|/|denominator|: the scale of
        // each coefficient's rounding (a large ζ with a small λ makes (r + σ) A ≈ 1: that
        // form lost 2e-11 in F̄_m at λ = 7e-6, ζ = 271).
        let sum = |t: [f64; 3], den: f64| (t.iter().sum::<f64>() / den, abs_sum(t) / den.abs());
        let a = [
            sum([r, a0, 0.0], gap),
            sum([2.0 * sigma, -2.0 * zeta, 0.0], gap),
        ];
        let (a, sa) = if a[0].1 <= a[1].1 { a[0] } else { a[1] };
        let d = [
            (1.0 - (r + sigma) * a, 1.0 + (r + sigma).abs() * sa),
            (
                (sigma - a0 + a * omega2) / (sigma + r),
                (sigma.abs() + a0 + sa * omega2.abs()) / (sigma + r).abs(),
            ),
        ];
        let (d, sd) = if d[0].1 <= d[1].1 { d[0] } else { d[1] };
        Some(flow(&m, [a, -a, d], [sa, sa, sd]))
    }

    /// The flow at (λ, ζ) from any state (z̄, z̄', z̄'') at τ = 0: the unloading after
    /// flattening starts so (`super::flatten`). [`Flow::responses`] gives what an error in
    /// that state carries to τ (the flow is linear in it); [`Flow::rounding`] bounds this
    /// evaluation's own.
    #[inline]
    pub fn from_state(lambda: f64, zeta: f64, x: [f64; 3]) -> Option<Flow> {
        let m = modes(lambda, zeta, quick_cbrt)?;
        let (coefficients, sizes) = m.coefficients(x);
        let mut flow = flow(&m, coefficients, sizes);
        flow.tight = true;
        Some(flow)
    }

    /// The transcendental values at τ: (e^{−στ} C, e^{−στ} S) without overflow — the product
    /// form while ντ is moderate, the two real exponentials apart beyond (ν is then far from
    /// 0, no cancellation).
    pub fn at(&self, t: f64) -> Point {
        let (s, w2) = (self.sigma, self.omega2);
        if w2 > 0.0 {
            let (sn, cn) = (self.omega * t).sin_cos();
            return self.at_phase(t, (cn, sn));
        }
        let (ec, es) = if w2 < 0.0 {
            let v = (-w2).sqrt();
            if v * t < 20.0 {
                let e = (-s * t).exp();
                (e * (v * t).cosh(), e * (v * t).sinh() / v)
            } else {
                let (up, down) = (((v - s) * t).exp(), (-(s + v) * t).exp());
                (0.5 * (up + down), 0.5 * (up - down) / v)
            }
        } else {
            let e = (-s * t).exp();
            (e, e * t)
        };
        Point {
            t,
            real: (self.r * t).exp(),
            decay: 0.0,
            ec,
            es,
        }
    }

    /// The point at τ where the pair oscillates and (cos ωτ, sin ωτ) are known: two `exp`.
    pub fn at_phase(&self, t: f64, (cos, sin): (f64, f64)) -> Point {
        let decay = (-self.sigma * t).exp();
        Point {
            t,
            real: (self.r * t).exp(),
            decay,
            ec: decay * cos,
            es: decay * sin / self.omega,
        }
    }

    /// The point `h` after `pt` where the pair oscillates and every rate times h is small
    /// (≤ [`SMALL`]): e^{rh}, e^{−σh}, cos ωh and sin(ωh)/ω by their series, the pair's
    /// values turned by the angle sum (C(τ+h) = C cos ωh − ω² S S(h), S(τ+h) = S cos ωh +
    /// C S(h)): a few dozen multiplications where [`Flow::at`] takes `sin_cos` and two `exp`.
    /// `None` otherwise.
    pub fn shift(&self, pt: &Point, h: f64) -> Option<Point> {
        self.shift_by(pt, h, exp_small, cos_sinc)
    }

    /// [`Flow::shift`] with the same series summed by Estrin's scheme (`super::estrin`): some
    /// four products deep where Horner's rule chains ten, the same terms, other roundings
    /// (within 2 ulp). The flattening's refinements take it (`search::refine`, one shift on
    /// each root's chain); the summary keeps [`Flow::shift`], whose maps goldens pin.
    pub fn shift_short(&self, pt: &Point, h: f64) -> Option<Point> {
        self.shift_by(pt, h, estrin::exp_small, estrin::cos_sinc)
    }

    /// [`Flow::shift`] with eˣ and (cos x, sin(x)/x) for |x| ≤ [`SMALL`] by `exp` and `cos_sinc`.
    #[inline(always)]
    fn shift_by(
        &self,
        pt: &Point,
        h: f64,
        exp: fn(f64) -> f64,
        cos_sinc: fn(f64) -> (f64, f64),
    ) -> Option<Point> {
        let rate = self.r.abs().max(self.sigma.abs()).max(self.omega);
        if !(self.omega > 0.0 && rate * h.abs() <= SMALL) {
            return None;
        }
        let (cos, sinc) = cos_sinc(self.omega * h);
        let (s_h, decay) = (h * sinc, exp(-self.sigma * h));
        let (ec, es) = (
            pt.ec * cos - self.omega2 * pt.es * s_h,
            pt.es * cos + pt.ec * s_h,
        );
        Some(Point {
            t: pt.t + h,
            real: pt.real * exp(self.r * h),
            decay: pt.decay * decay,
            ec: ec * decay,
            es: es * decay,
        })
    }

    /// (z̄, z̄', …, z̄^{(N−1)}) at a point, N ≤ [`JET`].
    pub fn jet<const N: usize>(&self, pt: &Point) -> [f64; N] {
        std::array::from_fn(|k| {
            let [ar, c, s] = self.jet[k];
            ar * pt.real + c * pt.ec + s * pt.es
        })
    }

    /// The jet's row k: (A r^k, c_k, s_k), z̄^{(k)} = A r^k e^{rτ} + e^{−στ}(c_k C + s_k S).
    pub fn jet_row(&self, k: usize) -> [f64; 3] {
        self.jet[k]
    }

    /// A bound on the rounding of z̄(τ) and ∫₀^τ z̄ as evaluated here: ε times the sizes of
    /// the terms summed (z̄ is their small difference where the ball nearly sticks), each
    /// exponential's argument good to ε·rate·τ, times [`ROUNDING_FACTOR`] for the roots'
    /// and coefficients' own rounding. Only the order of magnitude matters: it tells the
    /// cases that keep 1e-12 from those (small e, long contact) that do not. Returns (for z̄,
    /// for the integral).
    pub fn rounding(&self, pt: &Point) -> (f64, f64) {
        let t = pt.t;
        let (cm, sm) = if self.omega2 > 0.0 {
            (pt.decay, pt.decay * t.min(1.0 / self.omega))
        } else {
            (pt.ec, pt.es)
        };
        // each exponential's argument is good to ε·rate·τ: its term's rounding grows so
        let real = pt.real * (1.0 + self.r.abs() * t);
        let grow = 1.0 + (self.sigma.abs() + self.omega2.abs().sqrt()) * t;
        let (cm, sm) = (cm * grow, sm * grow);
        let k = ROUNDING_FACTOR * f64::EPSILON;
        let [sa, sb, sd, sp, sq] = self.size;
        let z = sa * real + sb * cm + sd * sm;
        let int = if self.r == 0.0 {
            sa * t
        } else if self.tight {
            3.0 * sa * t * (1.0 + real)
        } else {
            sa * (1.0 + real) / self.r.abs()
        };
        let int = int + sp * (1.0 + cm) + sq * sm;
        (k * z, k * int)
    }

    /// A bound on the rounding of z̄^{(k)}(τ) as [`Flow::jet`] evaluates it, in the manner of
    /// [`Flow::rounding`]: the row's terms summed, and A, B, D's rounding carried through k
    /// derivatives (each at most a factor |r| on the real mode, 1 + |σ| + |ω| on the pair).
    pub fn derivative_rounding(&self, pt: &Point, k: usize) -> f64 {
        let t = pt.t;
        let (cm, sm) = if self.omega2 > 0.0 {
            (pt.decay, pt.decay * t.min(1.0 / self.omega))
        } else {
            (pt.ec.abs(), pt.es.abs())
        };
        let real = pt.real * (1.0 + self.r.abs() * t);
        let rho = self.sigma.abs() + self.omega2.abs().sqrt();
        let grow = 1.0 + rho * t;
        let (cm, sm) = (cm * grow, sm * grow);
        let [ar, c, s] = self.jet[k];
        let [sa, sb, sd, _, _] = self.size;
        let power = |x: f64| (0..k).fold(1.0, |p, _| p * x);
        let terms = ar.abs() * real + c.abs() * cm + s.abs() * sm;
        let carried = sa * power(self.r.abs()) * real + (sb * cm + sd * sm) * power(1.0 + rho);
        ROUNDING_FACTOR * f64::EPSILON * (terms + carried)
    }

    /// z̄(τ) and ∫₀^τ z̄ dτ at a point of the flow with the same modes from each state `x` at
    /// τ = 0 (not this flow's own): x's share in them, by linearity. The real mode's share
    /// of the integral, (e^{rτ} − 1)/r, is formed once for all.
    pub fn responses<const N: usize>(&self, xs: [[f64; 3]; N], pt: &Point) -> [(f64, f64); N] {
        let m = Modes {
            r: self.r,
            sigma: self.sigma,
            omega2: self.omega2,
            gap: self.gap,
            p0: self.p0,
        };
        let (grown, rate) = self.real_growth(pt);
        xs.map(|x| {
            let ([a, b, d], _) = m.coefficients(x);
            let (p, q) = antiderivative(&m, b, d);
            let z = a * pt.real + b * pt.ec + d * pt.es;
            (z, a * grown / rate + p * pt.ec + q * pt.es - p)
        })
    }

    /// ∫₀^τ z̄ dτ.
    pub fn integral(&self, pt: &Point) -> f64 {
        let (grown, rate) = self.real_growth(pt);
        self.a * grown / rate + self.p * pt.ec + self.q * pt.es - self.p
    }

    /// ∫₀^τ e^{rτ} dτ = (e^{rτ} − 1)/r as the pair (e^{rτ} − 1, r), and (τ, 1) where r = 0:
    /// the real mode's share of the integral of A e^{rτ} + e^{−στ}(B C + D S) is A times
    /// their quotient (the pair part's antiderivative is e^{−στ}(P C + Q S)).
    fn real_growth(&self, pt: &Point) -> (f64, f64) {
        if self.r == 0.0 {
            return (pt.t, 1.0);
        }
        // e^{rτ} − 1: the subtraction's absolute error, ε, is what `rounding` budgets
        // (ε|A|(1 + e^{rτ})/|r|); exp_m1 only where rτ is so small that it would leave
        // nothing of the difference (λ → 0)
        let near = if self.tight { 0.5 } else { 1e-3 };
        let em1 = if (self.r * pt.t).abs() < near {
            (self.r * pt.t).exp_m1()
        } else {
            pt.real - 1.0
        };
        (em1, self.r)
    }
}

/// Largest |rate × h| for [`Flow::shift`]'s series: eleven terms of e^x leave x¹¹/11! ≈
/// 1e-21 at x = 1/16.
pub(super) const SMALL: f64 = 1.0 / 16.0;

/// eˣ for |x| ≤ [`SMALL`]: Σ xᵏ/k!, k ≤ 10.
fn exp_small(x: f64) -> f64 {
    series::exp_to::<10>(x)
}

/// (cos x, sin(x)/x) for |x| ≤ [`SMALL`], each to x¹⁰ (the next terms, x¹²/12! and x¹²/13!,
/// are below 1e-23).
fn cos_sinc(x: f64) -> (f64, f64) {
    series::cos_sinc_to::<5>(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// a within `ulps` units in the last place of b (of the smallest normal, where b is 0);
    /// `modes.rs`'s tests' too.
    pub(super) fn close(a: f64, b: f64, ulps: f64) -> bool {
        (a - b).abs() <= ulps * f64::EPSILON * b.abs().max(f64::MIN_POSITIVE)
    }

    /// The series agree with libm's exp, cos and sin to an ulp or two over |x| ≤ 1/16.
    #[test]
    fn the_small_series_are_exp_cos_and_sinc() {
        for i in -100..=100 {
            let x = SMALL * f64::from(i) / 100.0;
            assert!(close(exp_small(x), x.exp(), 2.0), "exp({x})");
            let (c, s) = cos_sinc(x);
            assert!(close(c, x.cos(), 2.0), "cos({x})");
            let sinc = if x == 0.0 { 1.0 } else { x.sin() / x };
            assert!(close(s, sinc, 2.0), "sin({x})/{x}");
        }
    }

    /// A point turned by `shift` or by `shift_short` is the point `at` evaluates there, over
    /// an oscillating flow (λ = 1, ζ = 0.1; 0.4, 0.3) and a stiff one (5, 20), to a few ε
    /// times each exponential's argument (`at` takes e^{rτ} from rτ, itself good to ε·|rτ|:
    /// what `rounding` counts); a step too long for the series is refused.
    #[test]
    fn a_shifted_point_is_the_point_there() {
        for (lambda, zeta) in [(1.0, 0.1), (0.4, 0.3), (5.0, 20.0)] {
            let flow = Flow::new(lambda, zeta).unwrap();
            let rate = flow.r.abs().max(flow.sigma.abs()).max(flow.omega);
            for (t, f) in [(1.5, 0.1), (3.2, -0.02), (0.7, 0.5), (2.0, -1.0)] {
                let h = f * SMALL / rate;
                let there = flow.at(t + h);
                let shifts = [flow.shift(&flow.at(t), h), flow.shift_short(&flow.at(t), h)];
                for (moved, how) in shifts.into_iter().zip(["shift", "shift_short"]) {
                    let moved = moved.unwrap();
                    let real = 4.0 * (1.0 + flow.r.abs() * t);
                    let pair = 4.0 * (1.0 + (flow.sigma + flow.omega) * t);
                    let size = there.ec.hypot(flow.omega * there.es);
                    let case = format!("{how}: λ = {lambda}, ζ = {zeta}, τ = {t}, h = {h}");
                    assert!(close(moved.real, there.real, real), "{case}");
                    let ec = (moved.ec - there.ec).abs();
                    assert!(ec <= pair * f64::EPSILON * size, "{case}");
                    let es = (moved.es - there.es).abs() * flow.omega;
                    assert!(es <= pair * f64::EPSILON * size, "{case}");
                }
            }
            assert!(flow.shift(&flow.at(1.0), 1.01 * SMALL / rate).is_none());
            assert!(
                flow.shift_short(&flow.at(1.0), 1.01 * SMALL / rate)
                    .is_none()
            );
        }
    }
}
