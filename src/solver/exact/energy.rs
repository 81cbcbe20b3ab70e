//! The exact solver's energy audit: the dashpot's dissipation ∫ ȳ'²/(2ζ) dτ, by quadrature on
//! the exact flow of each phase (Eq. 2's dashpot).

use super::modes::Modes;
use super::search::eval_anchored;
use super::{Segment, y_scale};

/// ∫ ȳ'²/(2ζ) dτ = ∫ 2ζ (F̄ − λȳ)² dτ over one segment, by Gauss–Legendre on the search grid.
pub(super) fn dashpot_energy(seg: &Segment, lambda: f64, zeta: f64) -> f64 {
    if zeta == 0.0 {
        return 0.0;
    }
    let modes = Modes::new(seg.anchors[0].1.roots());
    // F̄ − λȳ = ȳ'/2ζ, read off the flow's derivative (w3 = σȳ): the split flow forms it mode
    // by mode, where F̄ and λȳ apart are near equals in a creep
    let scale = 2.0 * zeta * y_scale(lambda);
    let integrand = |t: f64| {
        let (_, dw) = eval_anchored(&seg.anchors, t);
        let r = dw[2] / scale;
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
