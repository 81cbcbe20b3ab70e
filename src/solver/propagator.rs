//! Exact propagation of one linear phase, w' = A w, w(0) = w0, with A a real 3×3 matrix whose
//! characteristic polynomial is s³ + a2 s² + a1 s + a0 (all a_i ≥ 0: a passive system).
//!
//! Why hand-written: nalgebra's matrix exponential costs microseconds per evaluation, and the
//! event search evaluates w(τ) dozens of times per impact. Here e^{Aτ} is written through the
//! interpolating polynomial of e^{sτ} at the eigenvalues (Newton divided differences, Opitz):
//!
//! ```text
//! e^{Aτ} = f[s1] I + f[s1,s2] (A − s1 I) + f[s1,s2,s3] (A − s1 I)(A − s2 I),
//! ```
//!
//! which is exact for any A, defective ones included (critical damping, ζ = 1 at λ = 0), as long
//! as the divided differences are formed without cancellation. Coincident pairs are handled by
//! series (sinh x / x, (eˣ−1)/x); only a near-triple root would cancel, and there the
//! propagator falls back to nalgebra's matrix exponential. A phase whose fastest mode is real
//! and far faster than the others is split instead (`fast_slow`): the Newton form would carry
//! the rounding of A w at the fast rate into the slow modes.

pub use fast_slow::FastSlow;
pub(in crate::solver) use fast_slow::pair_flow;

mod cubic;
mod fast_slow;
pub(crate) use cubic::modes_of;
pub use cubic::{Roots, cubic_roots};
use fast_slow::SplitState;
use nalgebra::{Complex, Matrix3, Vector3};

type C = Complex<f64>;

/// (eᶻ − 1)/z without cancellation near z = 0.
fn phi1(z: C) -> C {
    if z.norm_sqr() < 0.25 {
        // Σ zⁿ/(n+1)!, 20 terms: |z|²⁰/21! < 1e-25
        let mut term = C::new(1.0, 0.0);
        let mut sum = term;
        for n in 1..20 {
            term = term * z / (n as f64 + 1.0);
            sum += term;
        }
        sum
    } else {
        (z.exp() - 1.0) / z
    }
}

/// sinh(√q τ)/√q (q ≥ 0) or sin(√−q τ)/√−q (q < 0), continuous through q = 0.
fn sinhc(q: f64, tau: f64) -> f64 {
    let x2 = q * tau * tau;
    if x2.abs() < 0.25 {
        // τ Σ x²ⁿ/(2n+1)! to n = 7 in Horner form; the next term is below 0.25⁸/17! ≈ 4e-20
        let h = |d: f64, rest: f64| 1.0 + x2 / d * rest;
        tau * h(
            6.0,
            h(20.0, h(42.0, h(72.0, h(110.0, h(156.0, h(210.0, 1.0)))))),
        )
    } else if q > 0.0 {
        let r = q.sqrt();
        (r * tau).sinh() / r
    } else {
        let r = (-q).sqrt();
        (r * tau).sin() / r
    }
}

#[derive(Debug, Clone, Copy)]
struct Nodes {
    s1: f64,
    s2: C,
    d12: C,
    inv_d12: C,
    inv_d31: C,
}

#[derive(Debug, Clone)]
enum Form {
    /// `w(τ) = f[s1] u0 + Re(f[s1,s2] − s2 f[s1,s2,s3]) u1 + Re(f[s1,s2,s3]) A u1` (f's
    /// divided differences at the nodes), with the node differences' reciprocals kept: eval is
    /// the solver's inner loop.
    Newton {
        u0: Vector3<f64>,
        u1: Vector3<f64>,
        au1: Vector3<f64>,
        nodes: Nodes,
    },
    /// Near-triple root: nalgebra's matrix exponential.
    Expm { w0: Vector3<f64> },
    /// A fast real mode and a slow plane, each in closed form.
    Split { split: FastSlow, start: SplitState },
}

/// The exact flow of one linear phase.
#[derive(Debug, Clone)]
pub struct Propagator {
    a: Matrix3<f64>,
    roots: Roots,
    form: Form,
}

impl Propagator {
    /// The flow of w' = A w from w(0) = w0, where `poly` = [a2, a1, a0] are the coefficients
    /// of A's characteristic polynomial s³ + a2 s² + a1 s + a0.
    pub fn new(a: Matrix3<f64>, poly: [f64; 3], w0: Vector3<f64>) -> Self {
        Self::with_roots(a, cubic_roots(poly), None, w0)
    }

    /// The same flow started afresh from w0 (roots already known, and the split of the phase
    /// when it has one). Re-anchoring along the way keeps rounding relative to the current
    /// state, not to the start of the phase.
    pub fn with_roots(
        a: Matrix3<f64>,
        roots: Roots,
        split: Option<FastSlow>,
        w0: Vector3<f64>,
    ) -> Self {
        if let Some(split) = split {
            let start = split.start(&w0);
            let form = Form::Split { split, start };
            return Propagator { a, roots, form };
        }
        let [s1, _, s3] = roots.all();
        let scale = roots
            .s1
            .abs()
            .max(roots.centre.abs())
            .max(roots.q.abs().sqrt());
        let form = if (s3 - s1).norm_sqr() <= 1e-8 * scale * scale {
            Form::Expm { w0 }
        } else {
            let u1 = a * w0 - w0 * roots.s1;
            let [_, s2, _] = roots.all();
            let d12 = s2 - s1;
            let nodes = Nodes {
                s1: roots.s1,
                s2,
                d12,
                inv_d12: d12.inv(),
                inv_d31: (s3 - s1).inv(),
            };
            Form::Newton {
                u0: w0,
                u1,
                au1: a * u1,
                nodes,
            }
        };
        Propagator { a, roots, form }
    }

    /// The same phase's flow started afresh from w0.
    pub fn restart(&self, w0: Vector3<f64>) -> Self {
        let split = match &self.form {
            Form::Split { split, .. } => Some(*split),
            _ => None,
        };
        Self::with_roots(self.a, self.roots, split, w0)
    }

    /// The eigenvalues of A.
    pub fn roots(&self) -> &Roots {
        &self.roots
    }

    /// The phase's matrix A.
    pub fn matrix(&self) -> &Matrix3<f64> {
        &self.a
    }

    /// w(τ) and its first three derivatives. The split forms them mode by mode; the others
    /// as A w, A² w, A³ w.
    pub fn jet(&self, tau: f64) -> [Vector3<f64>; 4] {
        if let Form::Split { split, start } = &self.form {
            return split.jet(start, tau);
        }
        let (w, aw) = self.eval(tau);
        let a2w = self.a * aw;
        [w, aw, a2w, self.a * a2w]
    }

    /// w(τ) and w'(τ) = A w(τ).
    pub fn eval(&self, tau: f64) -> (Vector3<f64>, Vector3<f64>) {
        let w = match &self.form {
            Form::Newton { u0, .. } if tau == 0.0 => *u0,
            Form::Newton {
                u0,
                u1,
                au1,
                nodes: n,
            } => {
                let e1 = (n.s1 * tau).exp();
                // e^{s2 τ} and f[s2,s3] share e^{cτ} (c the pair's centre) and, for a complex
                // pair, sin/cos(bτ); for a real pair s2 = c − h, e^{±hτ}.
                let ec = (self.roots.centre * tau).exp();
                let q = self.roots.q;
                let (e2, f23) = if q < 0.0 {
                    let b = (-q).sqrt();
                    let (sn, cs) = (b * tau).sin_cos();
                    let f23 = if (b * tau).abs() < 0.5 {
                        ec * sinhc(q, tau)
                    } else {
                        ec * sn / b
                    };
                    (C::new(ec * cs, ec * sn), f23)
                } else {
                    // e^{s2 τ} and e^{s3 τ} each in one exponential: as e^{cτ} e^{∓hτ} they are
                    // 0 · ∞ = NaN once hτ > 709 (λ = 6e-12, ζ = 1 runs to τ = 1.5e10)
                    let h = q.sqrt();
                    let e2 = ((self.roots.centre - h) * tau).exp();
                    let f23 = if h * tau < 0.5 {
                        ec * sinhc(q, tau)
                    } else {
                        (((self.roots.centre + h) * tau).exp() - e2) / (2.0 * h)
                    };
                    (C::new(e2, 0.0), f23)
                };
                let z = n.d12 * tau;
                let f12 = if z.norm_sqr() < 0.25 {
                    phi1(z) * (e1 * tau)
                } else {
                    (e2 - e1) * n.inv_d12
                };
                let f123 = (C::new(f23, 0.0) - f12) * n.inv_d31;
                let g1 = (f12 - n.s2 * f123).re;
                u0 * e1 + u1 * g1 + au1 * f123.re
            }
            Form::Expm { w0 } => (self.a * tau).exp() * w0,
            Form::Split { split, start } => {
                let [w, dw, ..] = split.jet(start, tau);
                return (w, dw);
            }
        };
        (w, self.a * w)
    }
}

#[cfg(test)]
mod tests {
    use super::cubic::eval_cubic;
    use super::*;

    fn check_roots(a: [f64; 3]) {
        let r = cubic_roots(a);
        for s in r.all() {
            let (p, _) = eval_cubic(a, s);
            let scale = 1.0 + s.norm().powi(3) + a[0] + a[1] * s.norm() + a[2] * s.norm_sqr();
            assert!(p.norm() < 1e-13 * scale, "root {s} of {a:?}: p = {p}");
        }
    }

    #[test]
    fn roots_of_assorted_cubics() {
        for &(lambda, zeta) in &[
            (0.0, 0.5),
            (0.0, 1.0),
            (0.0, 3.0),
            (1.3, 0.16),
            (0.125, 0.7698),
            (1e4, 1e4),
            (1e-4, 1e-4),
            (1.0, 0.0),
        ] {
            for k in [1.0, 7.5] {
                check_roots([2.0 * zeta * (k + lambda), k, 2.0 * zeta * k * lambda]);
            }
        }
    }

    fn rhs(lambda: f64, zeta: f64, k: f64) -> (Matrix3<f64>, [f64; 3]) {
        let a = Matrix3::new(
            0.0,
            1.0,
            0.0,
            -k,
            0.0,
            k,
            2.0 * zeta * k,
            0.0,
            -2.0 * zeta * (k + lambda),
        );
        (a, [2.0 * zeta * (k + lambda), k, 2.0 * zeta * k * lambda])
    }

    /// The split flow against nalgebra's matrix exponential, derivatives included, where the
    /// modes are far enough apart for the split and close enough for expm to be a reference.
    #[test]
    fn split_agrees_with_matrix_exponential() {
        let w0 = Vector3::new(0.3, -0.7, 0.1);
        for &(lambda, zeta, k) in &[
            (0.0, 3.0, 1.0),
            (0.0, 30.0, 7.5),
            (0.01, 5.0, 1.0),
            (0.2, 40.0, 1.0),
            (3.0, 20.0, 2.0),
            (1e-3, 200.0, 1.0),
        ] {
            let sigma = if lambda > 0.0 {
                f64::min(lambda, 1.0)
            } else {
                1.0
            };
            let (zk, zl) = (2.0 * zeta * k, 2.0 * zeta * lambda);
            let a = Matrix3::new(-zk, 1.0, zl / sigma, -k, 0.0, 0.0, zk * sigma, 0.0, -zl);
            let roots = cubic_roots([zk + zl, k, k * zl]);
            let split = FastSlow::new(zk, zl, k, sigma, &roots);
            assert!(
                split.is_some(),
                "λ={lambda} ζ={zeta}: no split for {roots:?}"
            );
            let p = Propagator::with_roots(a, roots, split, w0);
            for tau in [0.0, 0.01, 0.7, 2.0, 5.0, 40.0] {
                let exact = (a * tau).exp() * w0;
                let jet = p.jet(tau);
                // the reference's derivatives are A ⁿ w: their own rounding grows as ‖A‖ⁿ ‖w‖
                let mut d = exact;
                let mut tol = 1e-12 * (1.0 + exact.norm());
                for (n, w) in jet.iter().enumerate() {
                    assert!(
                        (w - d).norm() < tol,
                        "λ={lambda} ζ={zeta} τ={tau} derivative {n}: {w} vs {d}"
                    );
                    d = a * d;
                    tol *= a.norm();
                }
            }
        }
    }

    #[test]
    fn agrees_with_matrix_exponential() {
        let w0 = Vector3::new(0.3, -0.7, 0.1);
        for &(lambda, zeta) in &[
            (0.0, 0.3),
            (0.0, 1.0),
            (0.0, 1.0 + 1e-9),
            (0.4, 0.61),
            (1.3, 0.16),
            (0.125, 0.7698),
            (2.0, 30.0),
            (1.0, 0.0),
        ] {
            let (a, poly) = rhs(lambda, zeta, 1.0);
            let p = Propagator::new(a, poly, w0);
            for tau in [0.0, 0.01, 0.7, 2.0, 5.0] {
                let exact = (a * tau).exp() * w0;
                let (w, _) = p.eval(tau);
                assert!(
                    (w - exact).norm() < 1e-12,
                    "λ={lambda} ζ={zeta} τ={tau}: {w} vs {exact}"
                );
            }
        }
    }
}
