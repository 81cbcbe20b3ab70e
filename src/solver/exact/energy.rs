//! The exact solver's energy audit: the dashpot's dissipation ∫ ȳ'²/(2ζ) dτ, by quadrature on
//! the exact flow of each phase (Eq. 2's dashpot).

use super::{Modes, Segment, eval_anchored, l, y_scale};
use nalgebra::Vector3;

/// ∫ ȳ'²/(2ζ) dτ = ∫ 2ζ (F̄ − λȳ)² dτ over one segment, by Gauss–Legendre on the search grid.
pub(super) fn dashpot_energy(seg: &Segment, lambda: f64, zeta: f64) -> f64 {
    if zeta == 0.0 {
        return 0.0;
    }
    let modes = Modes::new(seg.anchors[0].1.roots());
    let split = (lambda == 0.0)
        .then(|| MaxwellSplit::new(zeta, seg.k))
        .flatten();
    let integrand = |t: f64| {
        let r = match &split {
            Some(m) => {
                let i = seg
                    .anchors
                    .partition_point(|(t0, _)| *t0 <= t)
                    .saturating_sub(1);
                let (t0, p) = &seg.anchors[i];
                seg.k * m.indentation(&p.eval(0.0).0, t - t0)
            }
            None => {
                let (w, _) = eval_anchored(&seg.anchors, t);
                seg.k * l(&w) - lambda / y_scale(lambda) * w[2]
            }
        };
        2.0 * zeta * r * r
    };
    let mut total = 0.0;
    let mut ta = 0.0;
    while ta < seg.len {
        let tb = (ta + modes.step(ta)).min(seg.len);
        total += gauss8(integrand, ta, tb);
        ta = tb;
    }
    total
}

/// 8-point Gauss–Legendre on [a, b].
fn gauss8(mut f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
    const X: [f64; 4] = [
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_3,
    ];
    const W: [f64; 4] = [
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];
    let (m, r) = (0.5 * (a + b), 0.5 * (b - a));
    (0..4)
        .map(|i| W[i] * (f(m - r * X[i]) + f(m + r * X[i])))
        .sum::<f64>()
        * r
}

/// Without a recoil spring (λ = 0) the dashpot's travel ȳ does not act back: z̄ − s and ᾱ'
/// alone make a 2×2 system, u' = ᾱ' − 2ζk u, ᾱ'' = −k u, with roots p1 (fast) and p2 of
/// s² + 2ζk s + k. Its propagator over the two roots, f[p1] I + f[p1,p2](A − p1 I), is free of
/// the 3×3 form's third divided difference, which over a long creep (ζ = 1e4: τ ~ 1e4 against
/// a fast rate ~1e6) multiplies the rounding of A w by |p1| τ: measured, the dissipation of
/// λ = 0, ζ = 1e4, z̄_p = 6e-9 then closed to 1.3e-6 of the impact energy.
struct MaxwellSplit {
    p1: f64,
    p2: f64,
}

impl MaxwellSplit {
    /// Only for real, distinct roots, where the split pays: a complex pair (ζ√k < 1) is an
    /// oscillation no longer than a few periods, not a creep.
    fn new(zeta: f64, k: f64) -> Option<Self> {
        let zk = 2.0 * zeta * k;
        let disc = zk * zk - 4.0 * k;
        if disc.is_nan() || disc <= 0.0 {
            return None;
        }
        // the larger root by the quadratic's product, k, not by a difference of near equals
        let p1 = -0.5 * (zk + disc.sqrt());
        Some(MaxwellSplit { p1, p2: k / p1 })
    }

    /// u(τ) from w = (u, ᾱ', ·) at τ = 0.
    fn indentation(&self, w: &Vector3<f64>, tau: f64) -> f64 {
        let (u0, v0) = (w[0], w[1]);
        let e1 = (self.p1 * tau).exp();
        let d = self.p2 - self.p1;
        // f[p1,p2] = e^{p1 τ} (e^{dτ} − 1)/d: by expm1 while dτ is small (the difference of
        // exponentials would cancel; a truncated series was good only to (dτ)²/6), by the
        // difference past it (where e^{dτ} alone could overflow against an underflowed e^{p1 τ})
        let f12 = if d * tau < 1.0 {
            e1 * (d * tau).exp_m1() / d
        } else {
            ((self.p2 * tau).exp() - e1) / d
        };
        // (A − p1 I) w, first row: (−2ζk − p1) u + ᾱ' = p2 u + ᾱ' (the roots sum to −2ζk),
        // without cancelling 2ζk against p1
        e1 * u0 + f12 * (self.p2 * u0 + v0)
    }
}
