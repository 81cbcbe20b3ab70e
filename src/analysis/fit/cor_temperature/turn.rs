//! Where a shifted dashpot turns the COR back (docs/model.md §10.4): Arrhenius's c(T) is
//! monotone in T and has no pole, but the model's COR is not monotone in c (§5: for λ > 0 it
//! falls with c on the large-ζ branch, reaches a minimum and climbs back to 1 as the dashpot
//! locks). A shift carried past that minimum has the ball's COR turn back with temperature,
//! a turn its data need not show: [`cor_turn`] finds it on a path of dashpots,
//! [`damping_temperature`] the temperature the shift gives it at.

use super::GAS_CONSTANT;
use crate::conditions::ZERO_CELSIUS;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate};

/// Sampling density of the scan, points per decade of c: the COR's minimum is broad in ln c
/// (the squash ball's COR is within 1 % of its minimum over a factor 1.3 in c), so a grid of
/// 1.33 × steps brackets it; the golden section then refines it.
const PER_DECADE: f64 = 8.0;

/// The dashpots the scan stays within, kg/s: inside the parameters' range (1e-15 … 1e15)
/// with room for the bracket's neighbours.
const C_RANGE: [f64; 2] = [1e-12, 1e14];

/// A COR above the minimum by less than this is not a turn (the solvers' own noise).
const RISE: f64 = 1e-9;

/// The COR of `p` with its dashpot at `c`, by the summary solver; `None` where it does not solve.
fn cor_at(p: &ImpactParams, law: ContactLaw, c: f64) -> Option<f64> {
    let params = ImpactParams { damping: c, ..*p };
    simulate(&params, law, &SolveOptions::default())
        .ok()
        .map(|r| r.cor)
        .filter(|e| e.is_finite())
}

/// The dashpot at which the COR of the ball `p` (its other parameters and speed kept) under
/// `law`, followed from `c_from` (kg/s) toward larger c (`rising`) or smaller, first has a
/// minimum: where it turns back. The path runs 12 decades (within `C_RANGE`; dashpots the
/// solver refuses, ζ above 1e6, are left out). `None` where the COR does not turn on it (to
/// `RISE`: it only rises, or only falls).
pub fn cor_turn(p: &ImpactParams, law: ContactLaw, c_from: f64, rising: bool) -> Option<f64> {
    let clamp = |c: f64| c.clamp(C_RANGE[0], C_RANGE[1]);
    let a = clamp(c_from).ln();
    let b = clamp(c_from * if rising { 1e12 } else { 1e-12 }).ln();
    if !(a.is_finite() && b.is_finite()) || a == b {
        return None;
    }
    let n = ((b - a).abs() / std::f64::consts::LN_10 * PER_DECADE).ceil() as usize;
    // a first step of 0.1 % gives the COR's direction at c_from: a turn within the grid's
    // first step is then bracketed too
    let first = a + (b - a).signum() * 1e-3;
    let grid: Vec<(f64, f64)> = std::iter::once(a)
        .chain(std::iter::once(first))
        .chain((1..=n).map(|i| a + (b - a) * i as f64 / n as f64))
        .filter_map(|x| cor_at(p, law, x.exp()).map(|e| (x, e)))
        .collect();
    // the first point that the path's next one does not undercut
    let i = (1..grid.len().saturating_sub(1)).find(|&i| grid[i + 1].1 >= grid[i].1)?;
    let low = grid[i].1;
    let rises_after = grid[i + 1..].iter().any(|&(_, e)| e - low > RISE);
    if grid[0].1 - low <= RISE || !rises_after {
        return None;
    }
    Some(golden(p, law, grid[i - 1].0, grid[i + 1].0).exp())
}

/// The minimum of the COR over ln c in [x0, x1] (bracketing it), by golden section to 1e-6
/// in ln c.
fn golden(p: &ImpactParams, law: ContactLaw, x0: f64, x1: f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let f = |x: f64| cor_at(p, law, x.exp()).unwrap_or(f64::INFINITY);
    let (mut lo, mut hi) = (x0.min(x1), x0.max(x1));
    let (mut c, mut d) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut fc, mut fd) = (f(c), f(d));
    while hi - lo > 1e-6 {
        if fc < fd {
            hi = d;
            (d, fd) = (c, fc);
            c = hi - g * (hi - lo);
            fc = f(c);
        } else {
            lo = c;
            (c, fc) = (d, fd);
            d = lo + g * (hi - lo);
            fd = f(d);
        }
    }
    (lo + hi) / 2.0
}

/// The temperature, °C, at which the shift c(T) = c_ref exp[(E_a/R)(1/T − 1/T_ref)] gives the
/// dashpot `c`: 1/T = 1/T_ref + (R/E_a) ln(c/c_ref). NaN without a shift (E_a = 0) or where
/// no temperature above absolute zero gives it.
pub fn damping_temperature(c_ref: f64, activation: f64, t_ref_c: f64, c: f64) -> f64 {
    let inverse = 1.0 / (t_ref_c + ZERO_CELSIUS) + GAS_CONSTANT / activation * (c / c_ref).ln();
    if activation == 0.0 || inverse.is_nan() || inverse <= 0.0 {
        return f64::NAN;
    }
    1.0 / inverse - ZERO_CELSIUS
}

#[cfg(test)]
mod tests {
    use super::super::shifted_damping;
    use super::*;

    fn squash() -> ImpactParams {
        ImpactParams {
            mass: 0.024,
            k_p: 38_400.0,
            damping: 8.04718,
            k_r: 7_680.0,
            z_p: 3.602e-3,
            // Eq. 16, K_p = 1.5 K_h √z_p (unused by the linear law)
            k_h: 38_400.0 / (1.5 * 3.602e-3f64.sqrt()),
            v0: 6.927,
        }
    }

    /// The squash ball's COR (λ = 0.2) falls as c rises from its 45 °C value, turns near
    /// c = 25 kg/s (a grid of --damping runs puts it between 22 and 28) and climbs back: found
    /// from 8 kg/s rising and from 200 kg/s falling; from 30 kg/s rising, and from 20 kg/s
    /// falling, the COR only rises: no turn.
    #[test]
    fn the_squash_ball_s_cor_turns_once() {
        let law = ContactLaw::Linear;
        let p = squash();
        let c = cor_turn(&p, law, 8.0, true).unwrap();
        assert!((22.0..28.0).contains(&c), "{c}");
        let back = cor_turn(&p, law, 200.0, false).unwrap();
        assert!((back / c - 1.0).abs() < 1e-4, "{back} {c}");
        // a path starting just short of the turn finds it within its first step
        let near = cor_turn(&p, law, c * 0.97, true).unwrap();
        assert!((near / c - 1.0).abs() < 1e-4, "{near} {c}");
        let e = |c: f64| cor_at(&p, law, c).unwrap();
        assert!(e(c) < e(c * 0.95) && e(c) < e(c * 1.05));
        assert_eq!(cor_turn(&p, law, 30.0, true), None);
        assert_eq!(cor_turn(&p, law, 20.0, false), None);
        // the Maxwell ball (λ = 0) has no turn: its COR rises with c throughout
        let maxwell = ImpactParams { k_r: 0.0, ..p };
        assert_eq!(cor_turn(&maxwell, law, 1.0, true), None);
    }

    #[test]
    fn the_temperature_of_a_dashpot_inverts_the_shift() {
        for t in [-40.0, 4.2, 36.1, 80.0] {
            let c = shifted_damping(8.04718, 20_381.9, 45.0, t);
            let back = damping_temperature(8.04718, 20_381.9, 45.0, c);
            assert!((back - t).abs() < 1e-9, "{t}: {back}");
        }
        assert!(damping_temperature(8.0, 0.0, 45.0, 9.0).is_nan());
        // no temperature makes a hot-side c this small: the shift's floor is c_ref·e^(−E_a/RT_ref)
        assert!(damping_temperature(8.0, 20_381.9, 45.0, 1e-6).is_nan());
    }
}
