//! The lanes' flow where the cubic's three roots are real (λ ≲ 0.24, ζ ≈ 0.64–5 on the map):
//! r the slowest, the pair s² + 2σs + (σ² − ν²) of the other two real, and z̄ = A e^{rτ} +
//! e^{−στ}(−A C + D S) with C = cosh ντ, S = sinh(ντ)/ν (docs/model.md's flow;
//! `flow::Flow::at`'s ω² < 0).
//!
//! - The root: p(s) = s³ + a2 s² + s + a0 has p(0) = a0 > 0 and p'(0) = 1, its roots are
//!   negative, and p is convex right of −a2/3, where the slowest root lies (it is at least
//!   their mean, −a2/3): Newton's steps from 0 fall to it and never pass it
//!   (`cubic::lone_real_root`). The slowest, as the scalar path's `isolated_root` mostly
//!   finds it: with the fastest as r the rounding bound (the pair's antiderivative over
//!   σ² − ν², the two slow roots' product) refused half the band where the scalar path answers.
//! - The events: z̄ and z̄' are sums of three exponentials, and such a sum has at most as many
//!   real zeros as its coefficients (ordered by rate) have sign changes, two (Descartes' rule
//!   for exponential sums). z̄(0) = 0 is one: z̄ has at most one zero after 0, and where
//!   Householder's steps settle on a falling crossing of z̄ at τ > 0 it is τ_f. z̄' goes from
//!   z̄'(0) = 1 to z̄'(τ_f) < 0 with at most two zeros: exactly one in (0, τ_f), τ_m. No lobe or
//!   first-fall test is needed (`refine::refine_both` drops them for these lanes).
//! - The guesses: τ_m from τ = 0 (as where P ≤ 0); τ_f from the zero of the slow two modes
//!   alone ([`Flow4::hyper_guess`]): the fast one has died away by then.
//! - The rounding: e^{−στ} sinh ντ as a difference of two exponentials loses up to
//!   ε e^{−στ} cosh ντ; `Flow4::rounding` counts S's terms as e^{−στ} cosh(ντ)/ν, so lanes where
//!   that cancellation costs 1e-13 (ν → 0, the pair nearly double) go to the scalar path.

use super::super::lane::Lane;
use super::super::math::{Sums, ln_guess};
use super::{Flow4, Point4};

impl<L: Lane, S: Sums> Flow4<L, S> {
    /// The point at τ where the pair is real: e^{−στ} cosh ντ and e^{−στ} sinh(ντ)/ν as half
    /// the sum and half the difference of e^{(ν−σ)τ} and e^{−(σ+ν)τ} (ν < σ: both decay, no
    /// overflow). `decay` carries e^{−στ} cosh ντ: the rounding bound reads `ec` for these
    /// lanes.
    #[inline(always)]
    pub(super) fn at_hyper(&self, t: L) -> Point4<L> {
        let v = L::splat;
        let nu = self.omega;
        let up = S::exp((nu - self.sigma) * t);
        let down = S::exp(-(self.sigma + nu) * t);
        let ec = v(0.5) * (up + down);
        Point4 {
            t,
            real: S::exp(self.r * t),
            decay: ec,
            ec,
            es: v(0.5) * (up - down) / nu,
        }
    }

    /// τ_f's guess where the pair is real: the zero of z̄ without its fastest mode. The pair
    /// part is e^{−στ}(½(D/ν − A) e^{ντ} + ½(−A − D/ν) e^{−ντ}), its slower mode (rate ν − σ)
    /// the first term; A e^{rτ} + ½(D/ν − A) e^{(ν−σ)τ} = 0 at τ = ln y/(r + σ − ν), y =
    /// (A − D/ν)/(2A), and the lanes where it exists (y > 1, as r + σ − ν ≥ 0: r is the slowest
    /// root; every lane whose pair oscillates too). Only a start for Householder's steps: the
    /// logarithm is [`ln_guess`]'s (1.1e-8).
    #[inline(always)]
    pub(super) fn hyper_guess(&self) -> (Point4<L>, L) {
        let v = L::splat;
        let one = v(1.0);
        let nu = self.omega;
        let y = (self.a - self.d / nu) / (v(2.0) * self.a);
        let rate = self.r + self.sigma - nu;
        let fine = !self.hyper | (y.gt(one) & y.lt(v(f64::MAX)) & rate.gt(v(0.0)));
        let y = fine.select(y, v(2.0));
        let rate = fine.select(rate, one);
        let t = ln_guess(y) / rate;
        (self.at_hyper(t), fine)
    }
}
