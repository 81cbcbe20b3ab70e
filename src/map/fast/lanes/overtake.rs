//! τ_f where the real mode overtakes a slow pair: the pair oscillates, but so slowly (ω small,
//! near the band of three real roots: λ ≲ 0.15, ζ ≈ 0.7–1 on the map) that its own first zero
//! of z̄ lies far past τ_f, and Householder's steps from there (`refine::refine_both`) do not
//! settle within the pair's lobe. There A < 0 (the real mode pulls z̄ down) and z̄ crosses 0
//! where the decaying pair part meets the real mode:
//!
//! ```text
//! z̄ = e^{rτ} (−A) (ρ(τ) − 1),  ρ(τ) = e^{−(σ+r)τ} (D S − A C)/(−A),
//! ```
//!
//! so z̄ > 0 exactly where F(τ) = ln((D S − A C)/(−A))/(σ + r) > τ (σ + r > 0). From τ_m,
//! where z̄ > 0, the steps τ ← F(τ) climb towards F's first fixed point after τ_m — z̄'s first
//! zero after it — wherever F rises (each step less than the zero it climbs to); the pair's
//! first zero of z̄ after τ_m (the kernel's guess) bounds that zero from above (z̄ = A e^{rτ} <
//! 0 there). Four steps (F' ≈ 1/((σ + r)τ) ≈ 0.1 on the map's cells) make the start for
//! Householder's steps, which must settle on a falling crossing between τ_m and that bound;
//! elsewhere the lane goes to the scalar path, as before. The answers are the scalar path's
//! (its bracket search) to 1e-12: tests/physics/map_lanes.rs.

use super::super::lane::Lane;
use super::super::math::ln_guess;
use super::{Flow4, Root4, householder_root};

/// Fixed-point steps τ ← F(τ) for the start (see the module's introduction).
const CLIMBS: usize = 4;

impl<L: Lane> Flow4<L> {
    /// τ_f's start where the real mode overtakes the pair: [`CLIMBS`] steps τ ← F(τ) from
    /// τ_m (`t_m`), in the lanes of `late` (elsewhere τ_m itself, unused).
    #[inline(always)]
    fn overtaken_guess(&self, t_m: L, late: L) -> L {
        let v = L::splat;
        let rate = late.select(self.r + self.sigma, v(1.0));
        let minus_a = late.select(-self.a, v(1.0));
        let mut t = t_m;
        for _ in 0..CLIMBS {
            let (sin, cos) = (self.omega * t).sin_cos();
            let y = (self.d * sin / self.omega - self.a * cos) / minus_a;
            // ln_guess wants a positive normal argument: a lane that leaves it stops climbing
            let fine = late & y.gt(v(f64::MIN_POSITIVE)) & y.lt(v(f64::MAX));
            t = fine.select(ln_guess(fine.select(y, v(1.0))) / rate, t);
        }
        t
    }
}

/// τ_f in the lanes of `late` (their τ_m settled, their τ_f not: `refine::refine_both`),
/// where A < 0 and σ + r > 0: from [`Flow4::overtaken_guess`] by Householder's steps, as
/// `refine_both` takes them; the root and the lanes where it settled on a falling crossing
/// after τ_m and before `upper` (the pair's first zero of z̄ after τ_m).
#[inline(always)]
pub(super) fn refine_overtaken<L: Lane>(
    flow: &Flow4<L>,
    t_m: L,
    upper: L,
    late: L,
) -> (Root4<L>, L) {
    let v = L::splat;
    let zero = v(0.0);
    let late = late & flow.a.lt(zero) & (flow.r + flow.sigma).gt(zero);
    let guess = flow.overtaken_guess(t_m, late);
    let (root, found) = householder_root(flow, flow.at(guess), late, 0);
    let between = root.t.gt(t_m) & root.t.lt(upper);
    (root, found & between)
}
