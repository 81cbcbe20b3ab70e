//! The lanes' roots: Householder's steps for τ_m and τ_f side by side (`search::refine_both`
//! in the scalar path), and the Taylor series that gives values at a root from the last jet.

use super::super::lane::Lane;
use super::super::math::{Horner, Sums};
use super::{Flow4, Point4, Root4};
use crate::map::fast::search::{MAX_REFINE, SETTLED, TAU_MAX};
use std::f64::consts::FRAC_PI_2;

/// `search::householder`: the step and the lanes where it is the last one on a falling
/// crossing.
#[inline(always)]
pub(super) fn householder<L: Lane, S: Sums>(f: &[L]) -> (L, L) {
    let v = L::splat;
    let one = v(1.0);
    let inv = one / f[1];
    let (u, c2, c3) = (f[0] * inv, f[2] * inv, f[3] * inv);
    let h = if S::SHORT {
        // the same step times f1³/f1³ (u = f0/f1, c2 = f2/f1, c3 = f3/f1): one quotient on
        // the chain where the form below waits on two (1/f1, then the step's)
        let (f0, f1, f2) = (f[0], f[1], f[2]);
        let f1f1 = f1 * f1;
        let den = f1f1 * f1 - f0 * f1 * f2 + S::over(f0 * f0 * f[3], 6.0);
        f0 * (f1f1 - v(0.5) * f0 * f2) / den
    } else {
        u * (one - v(0.5) * u * c2) / (one - u * c2 + S::over(u * u * c3, 6.0))
    };
    let settled = (c2 * h).abs().le(v(SETTLED))
        & (c3.abs() * h * h).le(v(SETTLED * SETTLED))
        & f[1].lt(v(0.0));
    (h, settled)
}

/// `search::refine_both`: τ_m (i = 0, the root of z̄') and τ_f (i = 1, of z̄) from their
/// guesses, side by side; the lanes where each settled within [`MAX_REFINE`] steps inside
/// (0, [`TAU_MAX`]) and within a quarter of the pair's period of its guess — τ_m where
/// P > 0 (`pos`); where P ≤ 0 its guess is τ = 0 and it must be z̄''s first zero
/// ([`Flow4::falls_once`], `slope` from [`Flow4::guesses`]).
#[inline(always)]
pub(super) fn refine_both<L: Lane>(
    flow: &Flow4<L>,
    guesses: [Point4<L>; 2],
    live: L,
    (pos, slope): (L, L),
) -> ([Root4<L>; 2], [L; 2]) {
    let v = L::splat;
    let mut points = guesses;
    let mut active = [live, live];
    let mut found = [v(0.0), v(0.0)];
    // each by hand: `guesses.map(…)` stayed a call out of the AVX2 kernel (callgrind)
    let root = |point: Point4<L>| Root4 {
        t: point.t,
        point,
        jet: [v(0.0); 6],
    };
    let mut roots = [root(guesses[0]), root(guesses[1])];
    for _ in 0..MAX_REFINE {
        for i in 0..2 {
            if !active[i].any() {
                continue;
            }
            let point = points[i];
            let jet = flow.jet(&point);
            let (h, settled) = householder::<L, Horner>(&jet[1 - i..5 - i]);
            let t = point.t - h;
            let inside = t.gt(v(0.0)) & t.lt(v(TAU_MAX));
            let now = active[i] & inside & settled;
            roots[i] = Root4 {
                t: now.select(t, roots[i].t),
                point: Point4::select(now, point, roots[i].point),
                jet: select6(now, jet, roots[i].jet),
            };
            found[i] |= now;
            active[i] &= inside & !settled;
            if !active[i].any() {
                // every lane of this event settled or left: no next point to turn to
                continue;
            }
            let (shifted, fits) = flow.shift(&point, -h);
            let far = active[i] & !fits;
            points[i] = if far.any() {
                Point4::select(fits, shifted, flow.at(t))
            } else {
                shifted
            };
        }
        if !(active[0] | active[1]).any() {
            break;
        }
    }
    let quarter = v(FRAC_PI_2) / flow.omega;
    let near = |i: usize| (roots[i].t - guesses[i].t).le(quarter);
    // the proof that τ_m comes first only where some lane needs it (P ≤ 0: rare on the map)
    let first = if (live & !pos).any() {
        pos.select(near(0), flow.falls_once(roots[0].t, &roots[0].point, slope))
    } else {
        near(0)
    };
    // a real pair: z̄ has one zero after 0 and z̄' one before it (`hyper.rs`), no lobe to keep
    let (first, near_f) = (flow.hyper | first, flow.hyper | near(1));
    let ok_f = found[1] & near_f & roots[1].t.gt(roots[0].t);
    (roots, [found[0] & first, ok_f])
}

/// `search::refine`'s steps for one root: Householder's on z̄^{(k)} (k = 0: z̄ itself, 1: z̄')
/// from `start` in the lanes of `live`, each step from the flow shifted (or, past its reach,
/// re-evaluated); the root, and the lanes where it settled on a falling crossing inside
/// (0, [`TAU_MAX`]) within [`MAX_REFINE`] steps. Each caller adds where its root must lie (the
/// flattening: within a quarter period of its guess; an overtaken pair: between τ_m and the
/// pair's zero).
#[inline(always)]
pub(super) fn householder_root<L: Lane, S: Sums>(
    f: &Flow4<L, S>,
    start: Point4<L>,
    live: L,
    k: usize,
) -> (Root4<L>, L) {
    let v = L::splat;
    let (mut point, mut active, mut found) = (start, live, v(0.0).ne(v(0.0)));
    let mut root = Root4 {
        t: start.t,
        point: start,
        jet: [v(0.0); 6],
    };
    for _ in 0..MAX_REFINE {
        let jet = f.jet(&point);
        let (h, settled) = householder::<L, S>(&jet[k..k + 4]);
        let t = point.t - h;
        let inside = t.gt(v(0.0)) & t.lt(v(TAU_MAX));
        let now = active & inside & settled;
        root = Root4 {
            t: now.select(t, root.t),
            point: Point4::select(now, point, root.point),
            jet: select6(now, jet, root.jet),
        };
        found |= now;
        active &= inside & !settled;
        if !active.any() {
            break;
        }
        let (shifted, fits) = f.shift(&point, -h);
        point = if (active & !fits).any() {
            Point4::select(fits, shifted, f.at(t))
        } else {
            shifted
        };
    }
    (root, found)
}

/// Six values lane by lane: `yes` where the mask is true, else `no`.
#[inline(always)]
pub(super) fn select6<L: Lane>(mask: L, yes: [L; 6], mut no: [L; 6]) -> [L; 6] {
    for (n, y) in no.iter_mut().zip(yes) {
        *n = mask.select(y, *n);
    }
    no
}

/// `search::taylor`, its quotients h/2, h/3, h/4 as `S` forms them (`Sums::over`).
#[inline(always)]
pub(super) fn taylor<L: Lane, S: Sums>(c: &[L], h: L) -> L {
    let over = S::over::<L>;
    c[0] + h * (c[1] + over(h, 2.0) * (c[2] + over(h, 3.0) * (c[3] + over(h, 4.0) * c[4])))
}
