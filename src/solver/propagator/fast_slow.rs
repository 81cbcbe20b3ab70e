//! The flow of a phase whose fastest mode is real and far faster than the other two, split into
//! that mode and a 2×2 flow on the slow plane, both in closed form.
//!
//! Why: the three-node Newton form multiplies w by A, whose entries are of the fast rate
//! (2ζk ~ 2e4 at ζ = 1e4), to get a slow state's derivative (~1e-4 of it in a creep): the
//! rounding of that product is ~ε|s1||w|, and the third divided difference carries it on as
//! ~ε|s1|τ|w|. Over a creep (λ = 3.3e-5, ζ = 1e4) that closed the energy balance only to
//! 1.03e-6, and below λ = 1e-6 it turned the indentation negative (λ = 1.9e-8, ζ = 1e4: an
//! unload at z̄ = −1.4e-5 and no rebound, where the ball leaves with e = 0.60).
//!
//! The phase matrix has the structure of `exact::system`, on w = (u, v, σȳ):
//!     A = [[−a, 1, b], [−k, 0, 0], [c, 0, −d]],  a = 2ζk, b = 2ζλ/σ, c = 2ζkσ, d = 2ζλ,
//! with bc = ad and characteristic polynomial s³ + (a+d) s² + k s + kd. For a root s, with
//! D = s + d, the right and left eigenvectors are
//!     v = (1, −k/s, c/D),   uᵀ = (1, 1/s, b/D),
//! and p(s) = D (s² + k) + a s² = 0 gives D = −a s²/(s² + k) without cancelling s against d.
//! The fast mode's amplitude is ξ = uᵀw/(uᵀv); the slow plane is uᵀw = 0, coordinatised by
//! η = (w2, w3) with w1 = −η1/s − (b/D) η2, on which the flow is η' = B η,
//!     B = [[k/s, k b/D], [−c/s, k d/s²]]
//! (the last entry is −(cb/D + d) = −d (a + D)/D, with a + D = a k/(s² + k)). Every entry is a
//! product or a quotient of the coefficients: B is exact to rounding at its own, slow, scale.

use super::Roots;
use nalgebra::{Matrix2, Vector2, Vector3};

/// The fastest root must be this many times the others' moduli for the split to be used.
/// Below it the Newton form's amplification (the ratio itself) is harmless.
const SEPARATION: f64 = 8.0;

/// The per-phase constants of the split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastSlow {
    /// The fast root.
    s1: f64,
    /// Its right eigenvector, first entry 1.
    v: Vector3<f64>,
    /// Its left eigenvector over uᵀv: ξ = u·w.
    u: Vector3<f64>,
    /// w1 of a point on the slow plane from η = (w2, w3).
    lift: Vector2<f64>,
    /// The flow on the slow plane.
    b: Matrix2<f64>,
    /// The slow pair: its centre and ((s2 − s3)/2)², as in `Roots`.
    centre: f64,
    q: f64,
}

impl FastSlow {
    /// The split of the phase w' = A w with A as in the module doc (a = 2ζk, d = 2ζλ, scale σ),
    /// when its leftmost real root `s1` is at least `SEPARATION` times the pair's modulus.
    pub fn new(zk: f64, zl: f64, k: f64, sigma: f64, roots: &Roots) -> Option<Self> {
        let Roots { s1, centre, q } = *roots;
        let pair = if q < 0.0 {
            (centre * centre - q).sqrt()
        } else {
            centre.abs() + q.sqrt()
        };
        // (written so that a NaN anywhere reads as unusable)
        let usable = zk > 0.0 && k > 0.0 && sigma > 0.0 && s1 < 0.0 && -s1 >= SEPARATION * pair;
        if !usable {
            return None;
        }
        let (b, c) = (zl / sigma, zk * sigma);
        let r = (s1 * s1 + k) / (s1 * s1); // 1 + k/s1²
        // c/D and b/D with 1/D = −(s1² + k)/(a s1²)
        let c_d = -sigma * r;
        let b_d = -b * r / zk;
        let v = Vector3::new(1.0, -k / s1, c_d);
        let u = Vector3::new(1.0, 1.0 / s1, b_d);
        // uᵀv = p'(s1)/(s1 D): for separated roots it is not small
        let uv = u.dot(&v);
        let bm = Matrix2::new(k / s1, k * b_d, -c / s1, k * zl / (s1 * s1));
        let split = FastSlow {
            s1,
            v,
            u: u / uv,
            lift: Vector2::new(-1.0 / s1, -b_d),
            b: bm,
            centre,
            q,
        };
        split.is_finite().then_some(split)
    }

    fn is_finite(&self) -> bool {
        self.v.iter().chain(self.u.iter()).all(|x| x.is_finite())
            && self.b.iter().chain(self.lift.iter()).all(|x| x.is_finite())
    }

    /// The state w0 split into the fast amplitude and the slow plane's start.
    pub fn start(&self, w0: &Vector3<f64>) -> SplitState {
        let xi = self.u.dot(w0);
        let eta = Vector2::new(w0[1] - self.v[1] * xi, w0[2] - self.v[2] * xi);
        let beta = self.b * eta - eta * self.centre;
        SplitState {
            w0: *w0,
            xi,
            eta,
            beta,
        }
    }

    /// w and its first three derivatives at τ from a start.
    pub fn jet(&self, st: &SplitState, tau: f64) -> [Vector3<f64>; 4] {
        let (ec, es) = pair_flow(self.centre, self.q, tau);
        let mut eta = st.eta * ec + st.beta * es;
        let mut fast = st.xi * (self.s1 * tau).exp();
        let mut jet: [Vector3<f64>; 4] = std::array::from_fn(|i| {
            if i > 0 {
                eta = self.b * eta;
                fast *= self.s1;
            }
            self.v * fast + Vector3::new(self.lift.dot(&eta), eta[0], eta[1])
        });
        if tau == 0.0 {
            // the start exactly: recombined, a contact starting at F = 0 would read F ~ 1e-17
            jet[0] = st.w0;
        }
        jet
    }
}

/// Where a split flow starts: w0, the fast amplitude ξ, the slow point η, and (B − cI) η.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SplitState {
    w0: Vector3<f64>,
    xi: f64,
    eta: Vector2<f64>,
    beta: Vector2<f64>,
}

/// The two scalar functions of e^{Bτ} = e^{cτ} (C I + S (B − cI)) for a 2×2 B with eigenvalues
/// c ± √q: (e^{cτ} C, e^{cτ} S), with C = cosh(√q τ), S = sinh(√q τ)/√q (cos and sin/√−q for
/// q < 0). For a real pair each exponential is formed in one piece: e^{cτ} and cosh(√q τ)
/// apart overflow against each other once √q τ > 709.
pub(in crate::solver) fn pair_flow(centre: f64, q: f64, tau: f64) -> (f64, f64) {
    let x2 = q * tau * tau;
    if x2.abs() < 0.25 {
        let ec = (centre * tau).exp();
        return (ec * coshc(x2), ec * super::sinhc(q, tau));
    }
    if q > 0.0 {
        let h = q.sqrt();
        let (ep, em) = (((centre + h) * tau).exp(), ((centre - h) * tau).exp());
        (0.5 * (ep + em), (ep - em) / (2.0 * h))
    } else {
        let b = (-q).sqrt();
        let ec = (centre * tau).exp();
        let (sn, cs) = (b * tau).sin_cos();
        (ec * cs, ec * sn / b)
    }
}

/// cosh(√x2) as a series in x2 = q τ², for |x2| < 0.25, to the term 0.25⁸/16! ≈ 7e-19.
fn coshc(x2: f64) -> f64 {
    let h = |d: f64, rest: f64| 1.0 + x2 / d * rest;
    h(
        2.0,
        h(12.0, h(30.0, h(56.0, h(90.0, h(132.0, h(182.0, 1.0)))))),
    )
}
