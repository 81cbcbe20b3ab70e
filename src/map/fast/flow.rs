//! The flow z̄(τ) = A e^{rτ} + e^{−στ}(−A C(τ) + D S(τ)) in closed form (the module's
//! introduction gives A, D and why only σ and ω² enter), its derivatives, its integral and a
//! bound on their rounding, all from one [`Point`]: the three transcendental values at τ,
//! computed once.

use crate::solver::propagator::{isolated_root, lone_real_root};

/// What multiplies ε times the terms' sizes in [`Flow::rounding`]: the roots, A, D, P, Q
/// carry a few roundings each (measured over tests/map_precision.rs's grid: the differences to
/// the exact solver stay below 2 ε times the terms' sizes).
const ROUNDING_FACTOR: f64 = 1.0;

/// The flow of one (λ, ζ).
pub(super) struct Flow {
    /// The scales of A, D, P, Q's rounding: Σ|terms|/|denominator| as each was formed.
    size: [f64; 4],
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
}

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
        let (a2, a1, a0) = (2.0 * zeta * (1.0 + lambda), 1.0, 2.0 * zeta * lambda);
        // λ = 0 has the root 0 exactly, which Cardano would leave at a rounding's distance
        let cubic = [a2, a1, a0];
        let lone = if a0 > 0.0 {
            lone_real_root(cubic)
        } else {
            None
        };
        let (r, p1, p0) = lone.unwrap_or_else(|| isolated_root(cubic));
        let sigma = 0.5 * p1;
        let omega2 = p0 - sigma * sigma;
        let gap = (r + sigma) * (r + sigma) + omega2;
        if !(gap > 0.0 && p0 > 0.0) {
            return None;
        }
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
        let b = -a;
        let p = -(d + sigma * b) / p0;
        let sp = (sd + sigma.abs() * sa) / p0;
        let q = b + sigma * p;
        let size = [sa, sd, sp, sa + sigma.abs() * sp];
        let omega = if omega2 > 0.0 { omega2.sqrt() } else { 0.0 };
        Some(Flow {
            size,
            r,
            sigma,
            omega2,
            omega,
            a,
            d,
            p,
            q,
        })
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

    /// (z̄, z̄', …, z̄^{(N−1)}) at a point.
    pub fn jet<const N: usize>(&self, pt: &Point) -> [f64; N] {
        let (s, w2) = (self.sigma, self.omega2);
        // g = −A C + D S and its derivatives, all under e^{−στ}: with u = (C, S),
        // u' = (−ω² S, C), and (e^{−στ} g)' = e^{−στ}(g' − σ g)
        let mut g = -self.a * pt.ec + self.d * pt.es;
        let mut dg = self.a * w2 * pt.es + self.d * pt.ec;
        let mut ex = self.a * pt.real;
        let mut out = [0.0; N];
        for o in &mut out {
            *o = ex + g;
            // next derivative: (g, g') → (g' − σ g, g'' − σ g') with g'' = −ω² g
            let (ng, ndg) = (dg - s * g, -w2 * g - s * dg);
            (g, dg) = (ng, ndg);
            ex *= self.r;
        }
        out
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
        let [sa, sd, sp, sq] = self.size;
        let z = sa * (real + cm) + sd * sm;
        let int = if self.r == 0.0 {
            sa * t
        } else {
            sa * (1.0 + real) / self.r.abs()
        };
        let int = int + sp * (1.0 + cm) + sq * sm;
        (k * z, k * int)
    }

    /// ∫₀^τ z̄ dτ.
    pub fn integral(&self, pt: &Point) -> f64 {
        let real = if self.r == 0.0 {
            self.a * pt.t
        } else {
            // e^{rτ} − 1 without the cancellation of a small rτ
            let em1 = if (self.r * pt.t).abs() < 0.5 {
                (self.r * pt.t).exp_m1()
            } else {
                pt.real - 1.0
            };
            self.a * em1 / self.r
        };
        real + self.p * pt.ec + self.q * pt.es - self.p
    }
}

/// Σ|terms|.
fn abs_sum(terms: [f64; 3]) -> f64 {
    terms.iter().map(|t| t.abs()).sum()
}
