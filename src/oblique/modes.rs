//! A phase of the linear law's normal motion in closed form (`closed`): its modes — the
//! cubic's real root r and oscillating pair −σ ± iω — the basis e^{rδ}, e^{−σδ} cos ωδ,
//! e^{−σδ} sin(ωδ)/ω they span, read exactly, turned by a step, or by short series, and a
//! component of the state as rows over that basis (docs/oblique.md §2).

use crate::solver::modes;
use crate::solver::series;
/// Rows kept of each component: f … f''' (τ_m's Halley steps on z̄' read z̄''').
pub(super) const ROWS: usize = 4;

/// The basis at δ = 0.
pub(super) const START: [f64; 3] = [1.0, 1.0, 0.0];

/// A phase's modes: the real root r and the oscillating pair −σ ± iω of its cubic
/// (`solver::modes`, the core the map's fast flow shares), and ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Modes {
    core: modes::Modes,
    pub(super) omega: f64,
}

impl Modes {
    /// The modes at slope k, or `None` unless the pair oscillates apart from the real root.
    pub(super) fn new(lambda: f64, zeta: f64, k: f64) -> Option<Modes> {
        let core = modes::Modes::of_phase(lambda, zeta, k, f64::cbrt);
        let (r, sigma, omega2, gap) = (core.r, core.sigma, core.omega2, core.gap);
        let ok = omega2 > 0.0 && gap > 0.0 && sigma >= 0.0 && r.is_finite() && gap.is_finite();
        ok.then(|| Modes {
            core,
            omega: omega2.sqrt(),
        })
    }

    /// The basis at δ: e^{rδ}, e^{−σδ} cos ωδ, e^{−σδ} sin(ωδ)/ω.
    pub(super) fn basis(&self, d: f64) -> [f64; 3] {
        let (sn, cs) = (self.omega * d).sin_cos();
        let decay = (-self.core.sigma * d).exp();
        [(self.core.r * d).exp(), decay * cs, decay * sn / self.omega]
    }

    /// The basis h after `b`: e^{rh} times the first, the pair turned by the angle sum
    /// (C(δ+h) = C cos ωh − ω² S S(h), S(δ+h) = S cos ωh + C S(h)) and decayed; `turn` is
    /// `Modes::basis` at h.
    pub(super) fn step(&self, b: &[f64; 3], turn: &[f64; 3]) -> [f64; 3] {
        [
            b[0] * turn[0],
            b[1] * turn[1] - self.core.omega2 * b[2] * turn[2],
            b[2] * turn[1] + b[1] * turn[2],
        ]
    }

    /// `Modes::basis` at a short δ (every rate times |δ| ≤ `SHORT`) by the exponential's,
    /// cosine's and sin x/x's series: a few dozen multiplications in place of `exp`, `exp`
    /// and `sin_cos`.
    pub(super) fn basis_short(&self, d: f64) -> [f64; 3] {
        let (cos, sinc) = cos_sinc(self.omega * d);
        let decay = exp_short(-self.core.sigma * d);
        [exp_short(self.core.r * d), decay * cos, decay * sinc * d]
    }

    /// Fastest |s| of the three modes.
    pub(super) fn fastest(&self) -> f64 {
        self.core
            .r
            .abs()
            .max((self.core.sigma * self.core.sigma + self.core.omega2).sqrt())
    }

    /// A component's rows from f, f', f'' at δ = 0: row n = (c_r rⁿ, c_n, s_n), so that
    /// f⁽ⁿ⁾(δ) = row n · basis(δ), since (e^{−σδ}(c C + s S))' = e^{−σδ}((s − σc) C +
    /// (−ω²c − σs) S).
    pub(super) fn rows(&self, x: [f64; 3]) -> Rows {
        let (coefficients, [size, _, _]) = self.core.coefficients(x);
        Rows {
            rows: self.core.rows(coefficients),
            size,
        }
    }
}

/// Largest |rate × δ| for `Modes::basis_short`: the series' first terms left out,
/// x¹⁷/17! and x¹⁸/18!, are below 1e-25 at x = 1/4.
pub(super) const SHORT: f64 = 0.25;

/// eˣ for |x| ≤ `SHORT`: Σ xᵏ/k!, k ≤ 16.
fn exp_short(x: f64) -> f64 {
    series::exp_to::<16>(x)
}

/// (cos x, sin(x)/x) for |x| ≤ `SHORT`, each to x¹⁶.
fn cos_sinc(x: f64) -> (f64, f64) {
    series::cos_sinc_to::<8>(x)
}

/// One component's derivatives as rows over the basis, and the scale of its coefficients'
/// rounding (Σ|terms|/gap of c_r as it was formed).
#[derive(Debug, Clone, Copy)]
pub(super) struct Rows {
    rows: [[f64; 3]; ROWS],
    size: f64,
}

impl Rows {
    /// f⁽ⁿ⁾ at a basis.
    pub(super) fn at(&self, n: usize, b: &[f64; 3]) -> f64 {
        let [a, c, s] = self.rows[n];
        a * b[0] + c * b[1] + s * b[2]
    }

    /// A bound on the rounding of f at δ (basis `b`): ε times the terms summed and the
    /// coefficients' own rounding carried by the modes, each exponential's argument good to
    /// ε·rate·δ. Only its order of magnitude matters: it tells the cases that keep 1e-13
    /// from those (a small COR, a near-triple root) that do not (`closed`'s `KEEP`).
    pub(super) fn rounding(&self, m: &Modes, d: f64, b: &[f64; 3]) -> f64 {
        let [a, c, s] = self.rows[0];
        let decay = (b[1] * b[1] + m.core.omega2 * b[2] * b[2]).sqrt();
        let sm = decay * d.min(1.0 / m.omega);
        let terms = a.abs() * b[0] + c.abs() * decay + s.abs() * sm;
        let carried =
            self.size * (b[0] + decay * (1.0 + (m.core.r.abs() + m.core.sigma) / m.omega));
        let grow = 1.0 + (m.core.r.abs() + m.core.sigma + m.omega) * d;
        8.0 * f64::EPSILON * grow * (terms + carried)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The short basis (series) is the basis (exp, exp, sin_cos) to a few ε of its terms'
    /// size, over steps up to `SHORT` of the fastest rate, on the tennis ball's loading and
    /// a flattened unloading's modes and a stiffer pair's; the grid's turned basis is too.
    #[test]
    fn the_short_basis_is_the_basis() {
        for (lambda, zeta, k) in [(1.0, 0.09, 1.0), (1.0, 0.09, 2.7), (0.4, 0.6, 1.0)] {
            let m = Modes::new(lambda, zeta, k).unwrap();
            for f in [-1.0, -0.3, 0.01, 0.5, 1.0] {
                let d = f * SHORT / m.fastest();
                let (a, b) = (m.basis_short(d), m.basis(d));
                let size = b[0].abs() + b[1].abs() + m.omega * b[2].abs();
                for i in 0..3 {
                    let scale = if i == 2 { m.omega } else { 1.0 };
                    let miss = (a[i] - b[i]).abs() * scale;
                    assert!(
                        miss <= 4.0 * f64::EPSILON * size,
                        "{lambda} {zeta} {k} δ {d}"
                    );
                }
            }
            let (h, tau) = (0.1, 0.7);
            let turned = m.step(&m.basis(tau), &m.basis(h));
            let there = m.basis(tau + h);
            for i in 0..3 {
                assert!(
                    (turned[i] - there[i]).abs() < 8.0 * f64::EPSILON,
                    "{lambda} {zeta}"
                );
            }
        }
    }
}
