//! A fast summary of one linear-law impact without flattening: COR, F̄_m and τ_f, no history,
//! in closed form (issue 21, "Speed").
//!
//! Without flattening (or while z̄_m ≤ z̄_p) the force is F̄ = z̄ on loading and unloading
//! alike, so one linear flow holds from first touch to separation (docs/model.md §5):
//! z̄''' + 2ζ(1+λ) z̄'' + z̄' + 2ζλ z̄ = 0, z̄(0) = 0, z̄'(0) = 1, z̄''(0) = −2ζ. With r the real
//! root of its cubic that stands apart and s² + 2σs + (σ² + ω²) the quadratic factor of the
//! other two,
//!
//! ```text
//! z̄(τ) = A e^{rτ} + e^{−στ} (−A C(τ) + D S(τ)),   C = cos ωτ,  S = sin(ωτ)/ω,
//! A = 2(σ − ζ)/((r + σ)² + ω²),  D = 1 − (r + σ) A,
//! ```
//!
//! with cosh and sinh(ντ)/ν where ω² = −ν² < 0. What keeps it exact where the complex pair
//! turns real (ω² → 0): the pair is never split into its two roots (which a double root would
//! leave with only half the digits), only σ and ω² enter, and C and S are smooth in ω² (the
//! exact solver's roots keep the pair so too: `propagator::cubic`).
//!
//! τ_m is the first zero of z̄' (F̄_m = z̄(τ_m)), τ_f the first zero of z̄ after it, both by
//! safeguarded Halley steps inside brackets found by doubling steps of at most a quarter of
//! the pair's period (τ_f's first step just short of τ_m: unloading takes about as long); e = ∫₀^τ_f z̄ dτ − 1 (ᾱ'' = −F̄, ᾱ'(0) = 1), in closed form too. Cases it does not
//! settle quickly — no rebound (λ = 0, ζ ≥ 1), slow creeps, flattening — and those whose
//! rounding bound (`Flow::rounding`) cannot keep 1e-13 return `None`: the
//! caller runs the exact solver.

use crate::solver::propagator::isolated_root;
use crate::solver::roots::halley_bracketed_from;

/// One impact's summary, normalized.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// The COR e (Eq. 6).
    pub cor: f64,
    /// F̄_m = z̄_m.
    pub max_force: f64,
    /// τ_f.
    pub contact_time: f64,
}

/// Longest contact the fast path follows (τ); past it the exact solver's creep handling is
/// the one to trust.
const TAU_MAX: f64 = 1e3;
/// What multiplies ε times the terms' sizes in [`Flow::rounding`]: the roots, A, D, P, Q
/// carry a few roundings each (measured over tests/map_precision.rs's grid: the differences to
/// the exact solver stay below 2 ε times the terms' sizes).
const ROUNDING_FACTOR: f64 = 1.0;
/// The relative precision a summary must keep, by the bound of [`Flow::rounding`], to be
/// returned: the exact solver (`bouncelab run`) keeps 1e-12 and the map promises its values
/// to 1e-12; a summary that cannot is left to it.
const KEEP: f64 = 1e-13;
/// Most bracket steps per event.
const MAX_STEPS: usize = 400;

/// The flow z̄(τ) in closed form.
struct Flow {
    /// The scales of A, D, P, Q's rounding: Σ|terms|/|denominator| as each was formed.
    size: [f64; 4],
    r: f64,
    sigma: f64,
    omega2: f64,
    a: f64,
    d: f64,
    /// The antiderivative of e^{−στ}(−A C + D S) is e^{−στ}(P C + Q S).
    p: f64,
    q: f64,
}

impl Flow {
    fn new(lambda: f64, zeta: f64) -> Option<Flow> {
        let (a2, a1, a0) = (2.0 * zeta * (1.0 + lambda), 1.0, 2.0 * zeta * lambda);
        let (r, p1, p0) = isolated_root([a2, a1, a0]);
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
        Some(Flow {
            size,
            r,
            sigma,
            omega2,
            a,
            d,
            p,
            q,
        })
    }

    /// (e^{−στ} C, e^{−στ} S) without overflow: the product form while ντ is moderate, the
    /// two real exponentials apart beyond (ν is then far from 0, no cancellation).
    fn cs(&self, t: f64) -> (f64, f64) {
        let (s, w2) = (self.sigma, self.omega2);
        if w2 > 0.0 {
            let w = w2.sqrt();
            let (sn, cn) = (w * t).sin_cos();
            let e = (-s * t).exp();
            (e * cn, e * sn / w)
        } else if w2 < 0.0 {
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
        }
    }

    /// (z̄, z̄', z̄'', z̄''') at τ.
    fn jet(&self, t: f64) -> [f64; 4] {
        let (ec, es) = self.cs(t);
        let (s, w2) = (self.sigma, self.omega2);
        // g = B C + D S and its derivatives, all under e^{−στ}: with u = (C, S),
        // u' = (−ω² S, C), and (e^{−στ} g)' = e^{−στ}(g' − σ g)
        let mut g = -self.a * ec + self.d * es;
        let mut dg = self.a * w2 * es + self.d * ec;
        let ex = self.a * (self.r * t).exp();
        let mut out = [0.0; 4];
        let mut rk = 1.0;
        for o in &mut out {
            *o = ex * rk + g;
            // next derivative: (g, g') → (g' − σ g, g'' − σ g') with g'' = −ω² g
            let (ng, ndg) = (dg - s * g, -w2 * g - s * dg);
            (g, dg) = (ng, ndg);
            rk *= self.r;
        }
        out
    }

    /// A bound on the rounding of z̄(τ) and ∫₀^τ z̄ as evaluated here: ε times the sizes of
    /// the terms summed (z̄ is their small difference where the ball nearly sticks), each
    /// exponential's argument good to ε·rate·τ, times [`ROUNDING_FACTOR`] for the roots'
    /// and coefficients' own rounding. Only the order of magnitude matters: it tells the
    /// cases that keep 1e-12 from those (small e, long contact) that do not. Returns (for z̄, for the integral).
    fn rounding(&self, t: f64) -> (f64, f64) {
        let decay = (-self.sigma * t).exp();
        let (cm, sm) = if self.omega2 > 0.0 {
            (decay, decay * t.min(1.0 / self.omega2.sqrt()))
        } else {
            self.cs(t)
        };
        // each exponential's argument is good to ε·rate·τ: its term's rounding grows so
        let real = (self.r * t).exp() * (1.0 + self.r.abs() * t);
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
    fn integral(&self, t: f64) -> f64 {
        let real = if self.r == 0.0 {
            self.a * t
        } else {
            self.a * (self.r * t).exp_m1() / self.r
        };
        let (ec, es) = self.cs(t);
        real + self.p * ec + self.q * es - self.p
    }
}

/// Σ|terms|.
fn abs_sum(terms: [f64; 3]) -> f64 {
    terms.iter().map(|t| t.abs()).sum()
}

/// The first τ after `t0` (where the `k`-th derivative of z̄ is `g0`, known) where that
/// derivative falls through 0 (k = 1: the peak; k = 0: separation), or `None` within
/// [`TAU_MAX`] and [`MAX_STEPS`].
fn first_fall(flow: &Flow, k: usize, (t0, g0): (f64, f64), step0: f64, cap: f64) -> Option<f64> {
    let g = |t: f64| {
        let j = flow.jet(t);
        (j[k], j[k + 1], j[k + 2])
    };
    let (mut a, mut ga) = (t0, g0);
    let mut step = step0;
    for _ in 0..MAX_STEPS {
        let b = a + step;
        let gb = g(b).0;
        if ga > 0.0 && gb <= 0.0 {
            return Some(halley_bracketed_from(g, (a, ga), (b, gb)));
        }
        if b > TAU_MAX {
            return None;
        }
        (a, ga) = (b, gb);
        step = (step * 2.0).min(cap);
    }
    None
}

/// COR, F̄_m and τ_f of the normalized linear-law impact at (λ, ζ) without flattening (valid
/// with flattening at z̄_p while F̄_m ≤ z̄_p: the caller checks); `None` where the exact solver
/// must answer.
pub fn summary(lambda: f64, zeta: f64) -> Option<Summary> {
    if !(lambda.is_finite() && zeta.is_finite() && lambda >= 0.0 && zeta >= 0.0) {
        return None;
    }
    if zeta == 0.0 {
        // the contact spring alone: e = 1, F̄_m = 1, τ_f = π
        return Some(Summary {
            cor: 1.0,
            max_force: 1.0,
            contact_time: std::f64::consts::PI,
        });
    }
    let flow = Flow::new(lambda, zeta)?;
    // step: a quarter of the pair's period where it oscillates, and never past the initial
    // decay of z̄' (time scale 1/(2ζ) when the dashpot is stiff)
    let period = if flow.omega2 > 0.0 {
        std::f64::consts::FRAC_PI_2 / flow.omega2.sqrt()
    } else {
        f64::INFINITY
    };
    let step0 = 0.25f64.min(0.5 / zeta).min(period);
    let cap = period.min(2.0);
    // z̄'(0) = 1; z̄(τ_m) is the peak, known before τ_f's search starts from it
    let tau_m = first_fall(&flow, 1, (0.0, 1.0), step0, cap)?;
    let z_m = flow.jet(tau_m)[0];
    // unloading takes about as long as loading: a first step just short of τ_m brackets τ_f
    // within one or two steps
    let tau_f = first_fall(&flow, 0, (tau_m, z_m), (0.9 * tau_m).min(cap), cap)?;
    let cor = flow.integral(tau_f) - 1.0;
    // z̄' = 0 at τ_m and z̄ = 0 at τ_f: F̄_m and e are stationary in their τ, only the sums'
    // rounding enters; τ_f moves by z̄'s rounding over the slope it crosses 0 with
    let (dz_m, _) = flow.rounding(tau_m);
    let (dz_f, dint) = flow.rounding(tau_f);
    let slope = flow.jet(tau_f)[1].abs();
    let precise = dz_m <= KEEP * z_m && dint <= KEEP * cor.abs() && dz_f <= KEEP * slope * tau_f;
    precise.then_some(Summary {
        cor,
        max_force: z_m,
        contact_time: tau_f,
    })
}
