//! Finding τ_m (the first zero of z̄') and τ_f (the first zero of z̄ after it).
//!
//! Where the pair oscillates, the pair's own zeros — a phase each, one `atan2`, and its cosine
//! and sine without `sin_cos` — start Householder's fourth-order steps, which settle in one or
//! two evaluations of the flow ([`refine_both`]). The two events are refined side by side:
//! neither waits for the other, so their chains of divisions and exponentials overlap.
//! Everywhere else, and wherever those steps do not settle on falling crossings in the pair's
//! lobes, τ_m then τ_f come from safeguarded Halley steps inside brackets found by doubling
//! steps of at most a quarter of the pair's period ([`first_fall`]).

use super::flow::{Flow, Point};
use crate::solver::roots::halley_bracketed_from;
use std::f64::consts::{FRAC_PI_2, PI};

/// Longest contact the fast path follows (τ); past it the exact solver's creep handling is
/// the one to trust.
pub(super) const TAU_MAX: f64 = 1e3;
/// Most bracket steps per event.
const MAX_STEPS: usize = 400;
/// Most Householder steps per event before [`first_fall`] takes over.
pub(super) const MAX_REFINE: usize = 6;
/// A Householder step this small against the flow's time scale (ρ|h|, ρ from the derivatives'
/// ratios) leaves the root good to ~(ρh)⁴/ρ ≈ 1e-16/ρ: the last one is taken, not evaluated.
pub(super) const SETTLED: f64 = 1e-4;

/// A root of z̄^{(k)}: τ, and the flow's jet at a point near it (the last point evaluated),
/// from which values at τ follow by Taylor's series.
pub(super) struct Root {
    /// τ.
    pub t: f64,
    /// Where the flow was last evaluated.
    pub point: Point,
    /// z̄, z̄', …, z̄^{(5)} at `point`.
    pub jet: [f64; 6],
}

impl Root {
    /// z̄^{(j)} at the root (j ≤ 1), from the jet at `point` by Taylor's series to h⁴.
    pub fn derivative(&self, j: usize) -> f64 {
        taylor(&self.jet[j..j + 5], self.t - self.point.t)
    }
}

/// Σ c_i hⁱ/i! over the first five c_i.
pub(super) fn taylor(c: &[f64], h: f64) -> f64 {
    c[0] + h * (c[1] + h / 2.0 * (c[2] + h / 3.0 * (c[3] + h / 4.0 * c[4])))
}

/// τ_m (where z̄'(0) = 1 first falls through 0) and τ_f (where z̄ next does), or `None`
/// where neither path settles within [`TAU_MAX`]. Each falls back on its own: where the pair
/// part of z̄' starts negative (P ≤ 0, a fast real mode carries z̄'(0) = 1), τ_f's phase may
/// still hold.
pub(super) fn events(flow: &Flow, zeta: f64) -> Option<(Root, Root)> {
    let (step0, cap) = steps(flow, zeta);
    let [peak, end] = match phase_guesses(flow) {
        Some(guesses) => refine_both(flow, guesses),
        None => [None, None],
    };
    let peak = match peak {
        Some(peak) => peak,
        None => first_fall(flow, 1, (0.0, 1.0), (step0, cap), false)?,
    };
    if let Some(end) = end
        && end.t > peak.t
    {
        return Some((peak, end));
    }
    // unloading takes about as long as loading: a first step just short of τ_m brackets τ_f
    // within one or two steps
    let (step, z_m) = ((0.9 * peak.t).min(cap), peak.derivative(0));
    let end = first_fall(flow, 0, (peak.t, z_m), (step, cap), false)?;
    Some((peak, end))
}

/// τ_m alone (the loading's turn, where z̄' first falls through 0): from the pair's phase
/// where it oscillates, by the bracket search otherwise (as [`events`] finds it). Only the
/// peak's guess is formed (not τ_f's: the unloading after flattening is another flow).
pub(super) fn peak(flow: &Flow, zeta: f64) -> Option<Root> {
    let phased = peak_phase(flow).and_then(|(theta_m, p, q)| {
        let guess = (p > 0.0).then(|| peak_point(flow, theta_m, p, q))?;
        refine(flow, guess, 1)
    });
    phased.or_else(|| first_fall(flow, 1, (0.0, 1.0), steps(flow, zeta), false))
}

/// The first zero of z̄ (τ_f) of a flow that starts at a turn (z̄'(0) = 0, z̄(0) > 0 and
/// z̄''(0) < 0: the unloading after flattening, `super::flatten`), from the pair's phase by
/// Householder's steps where it oscillates ([`separation_guess`] after the phase 0, then
/// [`refine`]); `None` where the pair does not oscillate or the steps do not settle on a
/// falling crossing within a quarter of the pair's period past the guess (the caller's bracket
/// search answers there).
pub(super) fn fall_from_turn(flow: &Flow) -> Option<Root> {
    if flow.omega <= 0.0 {
        return None;
    }
    refine(flow, separation_guess(flow, 0.0), 0)
}

/// The bracket search's first step and longest one: a quarter of the pair's period where it
/// oscillates, and never past the initial decay of z̄' (time scale 1/(2ζ) when the dashpot is
/// stiff).
fn steps(flow: &Flow, zeta: f64) -> (f64, f64) {
    let quarter = if flow.omega > 0.0 {
        FRAC_PI_2 / flow.omega
    } else {
        f64::INFINITY
    };
    (0.25f64.min(0.5 / zeta).min(quarter), quarter.min(2.0))
}

/// The pair's own zeros of z̄' and z̄ as points, where it oscillates (the first `None` where
/// P = D + σA ≤ 0).
///
/// z̄' has the pair part e^{−στ}(P cos ωτ + Q sin ωτ), Q = (Aω² − σD)/ω, whose first zero is
/// ωτ = atan2(P, −Q) ∈ (0, π), with (cos, sin) = (−Q, P) over their norm ([`peak_phase`]);
/// z̄'s zero the first after it ([`separation_guess`]; after 0 where P ≤ 0).
fn phase_guesses(flow: &Flow) -> Option<[Option<Point>; 2]> {
    let (theta_m, p, q) = peak_phase(flow)?;
    Some([
        (p > 0.0).then(|| peak_point(flow, theta_m, p, q)),
        Some(separation_guess(flow, theta_m)),
    ])
}

/// The pair's part of z̄' at the loading's start (z̄ = A e^{rτ} + e^{−στ}(−A C + D S)):
/// P = D + σA and Q = (Aω² − σD)/ω, and the phase of its first zero, atan2(P, −Q) ∈ (0, π)
/// (0 where P ≤ 0); `None` where the pair does not oscillate.
fn peak_phase(flow: &Flow) -> Option<(f64, f64, f64)> {
    let w = flow.omega;
    if w <= 0.0 {
        return None;
    }
    let p = flow.d + flow.sigma * flow.a;
    let q = (flow.a * flow.omega2 - flow.sigma * flow.d) / w;
    let theta_m = if p > 0.0 { p.atan2(-q) } else { 0.0 };
    Some((theta_m, p, q))
}

/// The point at the phase θ_m = atan2(P, −Q), its (cos, sin) = (−Q, P) over their norm.
fn peak_point(flow: &Flow, theta_m: f64, p: f64, q: f64) -> Point {
    let norm_m = (p * p + q * q).sqrt();
    flow.at_phase(theta_m / flow.omega, (-q / norm_m, p / norm_m))
}

/// The first zero of the pair part of z̄, e^{−στ}(B cos ωτ + (D/ω) sin ωτ) (B = −A on the
/// loading: the jet's first row), at a phase past `after`: ωτ = θ + kπ, θ = atan(−Bω/D) ∈
/// [−π/2, π/2] (θ + kπ ≥ 0 then never cancels: as ω → 0 the root ωτ → 0 keeps its digits),
/// with (cos, sin) = ±(D/ω, −B) over their norm.
fn separation_guess(flow: &Flow, after: f64) -> Point {
    let w = flow.omega;
    let [_, b, d] = flow.jet_row(0);
    let flip = if d < 0.0 { -1.0 } else { 1.0 };
    let (a, dw) = (-flip * b, flip * d / w);
    let theta = a.atan2(dw);
    let k = ((after - theta) / PI).floor() + 1.0;
    let odd = (k as i64) % 2 != 0;
    let norm_f = if odd { -1.0 } else { 1.0 } / (a * a + dw * dw).sqrt();
    flow.at_phase((theta + k * PI) / w, (dw * norm_f, a * norm_f))
}

/// τ_m and τ_f from their guesses by Householder's fourth-order steps, side by side; each
/// `None` when it does not settle within [`MAX_REFINE`] steps inside (0, [`TAU_MAX`]),
/// settles on a rising crossing, or moves more than a quarter of the pair's period past its
/// guess (beyond the pair's lobe, where another root may come first).
fn refine_both(flow: &Flow, guesses: [Option<Point>; 2]) -> [Option<Root>; 2] {
    let mut points = guesses;
    let mut roots: [Option<Root>; 2] = [None, None];
    for _ in 0..MAX_REFINE {
        // i = 0: τ_m, the root of z̄' (jet[1..5]); i = 1: τ_f, the root of z̄ (jet[0..4])
        for (i, (slot, root)) in points.iter_mut().zip(&mut roots).enumerate() {
            let Some(point) = slot else { continue };
            let jet: [f64; 6] = flow.jet(point);
            let (h, settled) = householder(&jet[1 - i..5 - i]);
            let t = point.t - h;
            if !(t > 0.0 && t < TAU_MAX) {
                *slot = None;
            } else if settled {
                *root = Some(Root {
                    t,
                    point: *point,
                    jet,
                });
                *slot = None;
            } else {
                *point = flow.shift(point, -h).unwrap_or_else(|| flow.at(t));
            }
        }
        if points.iter().all(Option::is_none) {
            break;
        }
    }
    let quarter = FRAC_PI_2 / flow.omega;
    for (root, guess) in roots.iter_mut().zip(&guesses) {
        if let (Some(r), Some(g)) = (&root, guess)
            && r.t - g.t > quarter
        {
            *root = None;
        }
    }
    roots
}

/// One root of z̄^{(k)} (k = 1: τ_m, k = 0: τ_f) from its guess, as [`refine_both`] refines
/// each of its two (the same steps, the same settling test), without the bookkeeping of two:
/// the flattening's turn and separation each need one. The chain each root waits on is
/// shorter: the step over one division ([`householder_one_division`]) and the point turned
/// by Estrin's sums (`Flow::shift_short`); the root is the same to rounding
/// (`one_division_is_householder`).
fn refine(flow: &Flow, guess: Point, k: usize) -> Option<Root> {
    let mut point = guess;
    for _ in 0..MAX_REFINE {
        let jet: [f64; 6] = flow.jet(&point);
        let (h, settled) = householder_one_division(&jet[k..k + 4]);
        let t = point.t - h;
        if !(t > 0.0 && t < TAU_MAX) {
            return None;
        }
        if settled {
            let lobe = t - guess.t <= FRAC_PI_2 / flow.omega;
            return lobe.then_some(Root { t, point, jet });
        }
        point = flow.shift_short(&point, -h).unwrap_or_else(|| flow.at(t));
    }
    None
}

/// One Householder step (d = 3) on f from (f, f', f'', f'''): the step h to subtract, and
/// whether it is the last (ρ|h| ≤ [`SETTLED`], ρ = max(|f''/f'|, |f'''/f'|^½)) on a falling
/// crossing.
fn householder(f: &[f64]) -> (f64, bool) {
    let inv = 1.0 / f[1];
    let (u, c2, c3) = (f[0] * inv, f[2] * inv, f[3] * inv);
    // h = u (1 − u f''/2f') / (1 − u f''/f' + u² f'''/6f')
    let h = u * (1.0 - 0.5 * u * c2) / (1.0 - u * c2 + u * u * c3 / 6.0);
    let settled = (c2 * h).abs() <= SETTLED && c3.abs() * h * h <= SETTLED * SETTLED;
    (h, settled && f[1] < 0.0)
}

/// [`householder`]'s step and test with the step over one division, its fraction times f'³:
/// h = 3f(2f'² − f f'')/(6f'(f'² − f f'') + f² f'''), where [`householder`] waits on 1/f'
/// and then on its quotient; 1/f' for the settling test is formed beside it, off that chain.
fn householder_one_division(f: &[f64]) -> (f64, bool) {
    let (f0, f1, f2, f3) = (f[0], f[1], f[2], f[3]);
    let f0f2 = f0 * f2;
    let h = 3.0 * f0 * (2.0 * f1 * f1 - f0f2) / (6.0 * f1 * (f1 * f1 - f0f2) + f0 * f0 * f3);
    let inv = 1.0 / f1;
    let (c2, c3) = (f2 * inv, f3 * inv);
    let settled = (c2 * h).abs() <= SETTLED && c3.abs() * h * h <= SETTLED * SETTLED;
    (h, settled && f1 < 0.0)
}

/// The first τ after `t0` (where the `k`-th derivative of z̄ is `g0`, known) where that
/// derivative falls through 0 (k = 1: the peak; k = 0: separation), or `None` within
/// [`TAU_MAX`] and [`MAX_STEPS`] — or, with `falling`, wherever the next derivative is seen
/// rising before the crossing (after flattening, z̄ rising again reloads: another branch).
pub(super) fn first_fall(
    flow: &Flow,
    k: usize,
    (t0, g0): (f64, f64),
    (step0, cap): (f64, f64),
    falling: bool,
) -> Option<Root> {
    let (mut a, mut ga) = (t0, g0);
    let mut step = step0;
    for _ in 0..MAX_STEPS {
        let b = a + step;
        let point = flow.at(b);
        let jet: [f64; 6] = flow.jet(&point);
        let gb = jet[k];
        if ga > 0.0 && gb <= 0.0 {
            return Some(bracketed(flow, k, (a, ga), (point, jet)));
        }
        if b > TAU_MAX || (falling && jet[k + 1] > 0.0) {
            return None;
        }
        // the next step doubles, or ends just past the root Householder's step predicts if
        // that is nearer: the bracket then closes tightly round it
        let (h, _) = householder(&jet[k..k + 4]);
        step = (step * 2.0).min(cap);
        if h < 0.0 && -h < step {
            step = -h * (1.0 + 1e-3);
        }
        (a, ga) = (b, gb);
    }
    None
}

/// The root of z̄^{(k)} inside [a, b] (falling: g(a) > 0 ≥ g(b)) by Householder's steps from
/// b (its jet is known) while they stay inside the shrinking bracket and settle; safeguarded
/// Halley steps otherwise.
fn bracketed(flow: &Flow, k: usize, (a, ga): (f64, f64), (end, jet_b): (Point, [f64; 6])) -> Root {
    let (mut lo, mut hi) = (a, end.t);
    let gb = jet_b[k];
    let (mut point, mut jet) = (end, jet_b);
    for _ in 0..MAX_REFINE {
        let (h, settled) = householder(&jet[k..k + 4]);
        let t = point.t - h;
        if !(t >= lo && t <= hi) {
            break;
        }
        if settled {
            return Root { t, point, jet };
        }
        point = flow.at(t);
        jet = flow.jet(&point);
        if jet[k] > 0.0 {
            lo = t;
        } else {
            hi = t;
        }
    }
    let g = |t: f64| {
        let j: [f64; 4] = flow.jet(&flow.at(t));
        (j[k], j[k + 1], j[k + 2])
    };
    let t = halley_bracketed_from(g, (a, ga), (end.t, gb));
    let point = flow.at(t);
    Root {
        t,
        point,
        jet: flow.jet(&point),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The one-division step is Householder's to a few ε of the step (seeded jets, f' of
    /// either sign, steps from 1e-9 to 0.3 of the scale), and settles where it does.
    #[test]
    fn one_division_is_householder() {
        let mut seeded = crate::seeded::Seeded::new(0x9e37_79b9_7f4a_7c15);
        let mut next = || seeded.uniform() - 0.5;
        for _ in 0..10_000 {
            let f1 = 10f64.powf(6.0 * next()) * next().signum();
            let u = 10f64.powf(-9.0 + 8.0 * (next() + 0.5)) * next().signum();
            let f = [u * f1, f1, f1 * next(), f1 * next()];
            let ((h, settled), (h1, settled1)) = (householder(&f), householder_one_division(&f));
            assert!(
                (h - h1).abs() <= 8.0 * f64::EPSILON * h.abs(),
                "{f:?}: {h} vs {h1}"
            );
            let near = |c: f64| ((c - SETTLED) / SETTLED).abs() < 1e-12;
            let ratios = [f[2] / f[1] * h, (f[3] / f[1]).abs().sqrt() * h];
            if !ratios.iter().any(|&c| near(c.abs())) {
                assert_eq!(settled, settled1, "{f:?}");
            }
        }
    }

    /// The bracket search alone, as `events` falls back on it.
    fn by_brackets(flow: &Flow, zeta: f64) -> Option<(f64, f64)> {
        let (step0, cap) = steps(flow, zeta);
        let peak = first_fall(flow, 1, (0.0, 1.0), (step0, cap), false)?;
        let z_m = peak.derivative(0);
        let end = first_fall(
            flow,
            0,
            (peak.t, z_m),
            ((0.9 * peak.t).min(cap), cap),
            false,
        )?;
        Some((peak.t, end.t))
    }

    /// Whichever way `events` finds them — both from the pair's phases, one of them by the
    /// bracket search, or both so — τ_m and τ_f are the roots the bracket search alone finds
    /// (the first falling crossings), to 1e-13, over λ = 1e-4 … 1e4 and ζ = 1e-3 … 1e3; and
    /// the phase path answers for most of the plane (it is the fast one).
    #[test]
    fn events_find_the_roots_the_brackets_find() {
        let (mut phased, mut oscillating) = (0, 0);
        for (lambda, zeta) in crate::model::params::test_plane(10) {
            let Some(flow) = Flow::new(lambda, zeta) else {
                continue;
            };
            if let Some(guesses) = phase_guesses(&flow) {
                oscillating += 1;
                let [peak, end] = refine_both(&flow, guesses);
                phased += matches!((peak, end), (Some(p), Some(e)) if e.t > p.t) as usize;
            }
            let Some((peak, end)) = events(&flow, zeta) else {
                continue;
            };
            let (tm, tf) = by_brackets(&flow, zeta).expect("brackets find both roots");
            let rel = |a: f64, b: f64| (a - b).abs() / b;
            assert!(
                rel(peak.t, tm) < 1e-13,
                "λ = {lambda}, ζ = {zeta}: τ_m {} vs {tm}",
                peak.t
            );
            assert!(
                rel(end.t, tf) < 1e-13,
                "λ = {lambda}, ζ = {zeta}: τ_f {} vs {tf}",
                end.t
            );
        }
        assert!(phased * 10 >= oscillating * 9, "{phased} of {oscillating}");
    }
}
