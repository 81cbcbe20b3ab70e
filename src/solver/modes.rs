//! The modes of the linear law's cubic — its real root r and oscillating pair −σ ± iω — and a
//! motion's coefficients over the basis they span, e^{rτ}, e^{−στ} C(τ), e^{−στ} S(τ) (C = cos
//! ωτ, S = sin(ωτ)/ω): one core for the map's fast flow (`map::fast`) and the oblique impact's
//! phases in closed form (`oblique::closed`), which before each found and used them their own
//! way (docs/model.md §5, docs/oblique.md §2).

use super::propagator::modes_of;

/// The cubic's modes: the real root r and the pair s² + 2σs + (σ² + ω²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Modes {
    pub(crate) r: f64,
    pub(crate) sigma: f64,
    pub(crate) omega2: f64,
    /// (r + σ)² + ω² = p'(r): the real root's distance from the pair (squared).
    pub(crate) gap: f64,
    /// σ² + ω², the deflated quadratic's constant term.
    pub(crate) p0: f64,
}

impl Modes {
    /// The modes of the linear law's phase of slope k (1 loading, K_r/K_p unloading) at
    /// (λ, ζ): the cubic s³ + 2ζ(k + λ) s² + k s + 2ζkλ, Cardano's cube root taken by `cbrt`
    /// (`propagator::modes_of`). Unchecked: each user says which modes it takes.
    pub(crate) fn of_phase(lambda: f64, zeta: f64, k: f64, cbrt: fn(f64) -> f64) -> Modes {
        let cubic = [2.0 * zeta * (k + lambda), k, 2.0 * zeta * k * lambda];
        let (r, sigma, omega2, gap, p0) = modes_of(cubic, cbrt);
        Modes {
            r,
            sigma,
            omega2,
            gap,
            p0,
        }
    }

    /// The coefficients [A, B, D] of f = A e^{rτ} + e^{−στ}(B C + D S) from (f, f', f'') at
    /// τ = 0, and their rounding scales. A is the residue at r of the Laplace transform,
    /// N(r)/gap, with N(s) = f s² + (f' + a₂f) s + (f'' + a₂f' + a₁f). As a₂ = 2σ − r and
    /// a₁ = σ² + ω² − 2σr (the roots' sums), N(r) = (σ² + ω²) f + 2σ f' + f'': free of the r²
    /// terms that cancel where the real mode is fast (their rounding, ε f r², would cost D
    /// ε|r| f and the unloading's integral as much: it put the map's bound 2e4 times over
    /// 1e-13 at r = −2e5). B = f − A and D = f' − A r + σB match f and f' at 0.
    pub(crate) fn coefficients(&self, x: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let (r, sigma) = (self.r, self.sigma);
        let a = (self.p0 * x[0] + 2.0 * sigma * x[1] + x[2]) / self.gap;
        let sa = (self.p0 * x[0].abs() + 2.0 * (sigma * x[1]).abs() + x[2].abs()) / self.gap;
        let b = x[0] - a;
        let d = x[1] - a * r + sigma * b;
        let sb = x[0].abs() + sa;
        (
            [a, b, d],
            [sa, sb, x[1].abs() + sa * r.abs() + sigma.abs() * sb],
        )
    }

    /// The derivatives' rows from the coefficients [A, B, D]: row n = (A rⁿ, Bₙ, Dₙ), so that
    /// f⁽ⁿ⁾(τ) = A rⁿ e^{rτ} + e^{−στ}(Bₙ C + Dₙ S), since (e^{−στ}(c C + s S))' =
    /// e^{−στ}((s − σc) C + (−ω²c − σs) S) (u = (C, S) has u' = (−ω² S, C)).
    pub(crate) fn rows<const N: usize>(&self, [a, b, d]: [f64; 3]) -> [[f64; 3]; N] {
        let (r, sigma, omega2) = (self.r, self.sigma, self.omega2);
        let mut rows = [[0.0; 3]; N];
        let (mut ar, mut c, mut s) = (a, b, d);
        for row in &mut rows {
            *row = [ar, c, s];
            (ar, c, s) = (ar * r, s - sigma * c, -omega2 * c - sigma * s);
        }
        rows
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rows are the derivatives: each row at τ, against the central difference of the row
    /// before, for a fast real mode, a slow one and a pair that barely decays.
    #[test]
    fn the_rows_are_the_derivatives() {
        for (lambda, zeta, k) in [(0.2, 0.05, 1.0), (1e3, 0.3, 1.0), (1.0, 0.1, 4.0)] {
            let m = Modes::of_phase(lambda, zeta, k, f64::cbrt);
            let (c, _) = m.coefficients([0.3, 1.0, -0.7]);
            let rows: [[f64; 3]; 4] = m.rows(c);
            let omega = m.omega2.sqrt();
            let f = |n: usize, t: f64| {
                let [a, b, d] = rows[n];
                let e = (-m.sigma * t).exp();
                a * (m.r * t).exp() + e * (b * (omega * t).cos() + d * (omega * t).sin() / omega)
            };
            assert!((f(0, 0.0) - 0.3).abs() < 1e-12 && (f(1, 0.0) - 1.0).abs() < 1e-12);
            assert!(
                (f(2, 0.0) + 0.7).abs() < 1e-9 * (1.0 + m.r.abs()),
                "{lambda} {zeta}"
            );
            let (t, h) = (0.37, 1e-6);
            for n in 1..4 {
                let diff = (f(n - 1, t + h) - f(n - 1, t - h)) / (2.0 * h);
                let scale = 1.0 + f(n, t).abs() + f(n - 1, t).abs() / h * 1e-9;
                assert!(
                    (diff - f(n, t)).abs() < 1e-5 * scale,
                    "{lambda} {zeta} {k} row {n}"
                );
            }
        }
    }
}
