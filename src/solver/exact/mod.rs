//! The exact solver for the linearized (bilinear) law, Eqs. 21–22, in normalized form
//! (MODEL.md §5). The state is (z̄, ᾱ', ȳ) rather than (ᾱ, ᾱ', ȳ): z̄ = ᾱ − ȳ is the small
//! difference of two large numbers as the ball settles, and carrying it directly keeps its
//! relative precision (at λ = 0 the resting mode then has no z̄ component at all).
//! Each phase is a linear ODE; with w = x − (s, 0, 0) (s = z̄_f while unloading, which makes
//! the affine unloading law homogeneous) it reads w' = A(k) w with
//!     A(k) = [[−2ζk, 1, 2ζλ], [−k, 0, 0], [2ζk, 0, −2ζλ]],
//! k = 1 while loading and k = F̄_m/(z̄_m − z̄_f) while unloading. Its flow is evaluated exactly
//! (`Propagator`); only the events need root finding: z̄' = 0 (unload), z̄ = z̄_f (F = 0,
//! separation), z̄ = z̄_m (reload).

use super::propagator::{FastSlow, Propagator, Roots, cubic_roots};
use super::roots::{halley_bracketed_from, newton_bracketed_from};
use super::{EventKind, Outcome, SolveOptions};
use crate::model::contact::{Contact, Unloading};
use crate::model::params::Normalized;
use energy::dashpot_energy;
use nalgebra::{Matrix3, Vector3};

mod energy;

/// More phase switches than this would mean a reload cycle that never settles.
pub(super) const MAX_PHASES: usize = 64;
/// Hard cap on search steps per phase (the step rule reaches every event in far fewer).
pub(super) const MAX_STEPS: usize = 20_000;

/// How far past z̄_m, in rounding units of the state, z̄ must rise before an unloading phase
/// turns back to loading. The unload is located where z̄' = 0 only to rounding, and at a slow
/// turning point (a creep, z̄'' ~ 1e-12) z̄ may go on rising by a rounding after it: read as a
/// reload, that started a loading phase already past its peak, which went on past it for 3e4
/// ω0⁻¹ (λ = 3.2e-8, ζ = 1e4, z̄_p = 1.3e-5: e = 0.27 for the 0.666 of a 40-digit reference).
const RELOAD_SLACK: f64 = 1e3;

/// The contact indentation z̄ − s (or a derivative) as a functional of w.
fn l(v: &Vector3<f64>) -> f64 {
    v[0]
}

/// What the third state carries: w = (z̄ − s, ᾱ', σȳ), σ = λ (the recoil spring's force) for a
/// soft spring, λ < 1, else 1. Why: a ball creeping into a weak dashpot against a soft spring
/// (λ ~ 1e-6, ζ ~ 1e4) drives ȳ to hundreds while z̄ − s stays ~1e-5, and the propagator's
/// rounding is relative to the whole state; measured against a 40-digit reference, the
/// dissipation along z̄ came out 1.4e-6 of the impact energy wrong, 5.5e-7 scaled. A stiff
/// spring keeps ȳ ≤ F̄/λ small already, and scaling by a large λ would put entries of 2ζλ²
/// into the matrix (λ = ζ = 1e6: 1e12 beside 1) and break the propagation.
fn y_scale(lambda: f64) -> f64 {
    if lambda > 0.0 { lambda.min(1.0) } else { 1.0 }
}

/// The phase's matrix on w = (z̄ − s, ᾱ', σȳ), the similarity diag(1, 1, σ) of MODEL.md §5's
/// system with F̄ = k (z̄ − s), and its characteristic polynomial (which σ does not change).
fn system(lambda: f64, zeta: f64, k: f64) -> (Matrix3<f64>, [f64; 3]) {
    let (zk, zl) = (2.0 * zeta * k, 2.0 * zeta * lambda);
    let sigma = y_scale(lambda);
    let a = Matrix3::new(-zk, 1.0, zl / sigma, -k, 0.0, 0.0, zk * sigma, 0.0, -zl);
    (a, [2.0 * zeta * (k + lambda), k, 2.0 * zeta * k * lambda])
}

/// The phase's fast/slow split (a real mode far faster than the other two), if it has one.
fn split(lambda: f64, zeta: f64, k: f64, roots: &Roots) -> Option<FastSlow> {
    let (zk, zl) = (2.0 * zeta * k, 2.0 * zeta * lambda);
    FastSlow::new(zk, zl, k, y_scale(lambda), roots)
}

/// w and its first three derivatives at τ.
struct Jet([Vector3<f64>; 4]);

fn jet(p: &Propagator, tau: f64) -> Jet {
    Jet(p.jet(tau))
}

/// An event function g(τ) watched for a crossing in one direction.
#[derive(Clone, Copy)]
enum Watch {
    /// z̄' falling through 0.
    RateFalls,
    /// z̄ − s rising through the target.
    Rises(f64),
    /// z̄ − s falling through the target.
    Falls(f64),
}

impl Watch {
    /// (g, g', g'') from the jet.
    fn eval(self, j: &Jet) -> (f64, f64, f64) {
        let [w, aw, a2w, a3w] = &j.0;
        match self {
            Watch::RateFalls => (l(aw), l(a2w), l(a3w)),
            Watch::Rises(t) | Watch::Falls(t) => (l(w) - t, l(aw), l(a2w)),
        }
    }
    fn rising(self) -> bool {
        matches!(self, Watch::Rises(_))
    }
}

/// The time scales of a phase's modes, worked out once per phase.
#[derive(Clone, Copy)]
struct Modes {
    /// (|s|, Re s, part of an oscillating pair) for each mode that enters z̄: modes with s = 0
    /// (λ = 0) carry w1 = w3... in the (z̄, ᾱ', ȳ) state they have no z̄ component at all.
    live: [(f64, f64, bool); 3],
    count: usize,
    /// Smallest |Re s| among them.
    slowest: f64,
    /// The time after which no event can come (see `settle_time`), if any.
    settle: Option<f64>,
}

impl Modes {
    fn new(roots: &Roots) -> Self {
        let all = roots.all();
        // |s| as √(norm²): hypot's overflow care is not needed at these magnitudes
        let norms = all.map(|s| s.norm_sqr().sqrt());
        let mut live = [(0.0, 0.0, false); 3];
        let mut count = 0;
        for (i, s) in all.iter().enumerate() {
            // The zero root of λ = 0 is not a mode. Every other is, however slow: the recoil
            // spring's relaxation at λ = 3.1e-12 (s ≈ −2ζλ, fifteen decades below the dashpot's
            // rate) is what pushes the ball back out at τ ≈ 2e4; cut below 1e-12 of the fastest
            // root, the phase "settled" while the ball still moved and the run reported no
            // rebound. The same cut on a complex pair (λ = ζ = 1e6) had made a bounce with e = 1
            // read as none. Following a slow mode is cheap: the step doubles with τ.
            let oscillation = i > 0 && roots.q < 0.0;
            if norms[i] > 0.0 {
                live[count] = (norms[i], s.re, oscillation);
                count += 1;
            }
        }
        let slowest = live[..count]
            .iter()
            .map(|m| m.1.abs())
            .fold(f64::INFINITY, f64::min);
        let mut modes = Modes {
            live,
            count,
            slowest,
            settle: None,
        };
        modes.settle = modes.settle_time();
        modes
    }

    /// Step length at τ. Modes with e^{Re s τ} < e^{−36} are gone. An oscillating pair limits
    /// the step to one time constant (a quarter period at most). A fastest mode that is real
    /// only decays: a monotone exponential plus what the slower modes do over one of their own
    /// time constants has a monotone derivative, so at most one extremum per step (which
    /// `crossing_in` checks), and the step may double with τ up to the next mode's time
    /// constant. Never past two time constants of the slowest mode: the Newton form sums terms
    /// that do not all decay, and over a longer step their cancellation would eat the relative
    /// precision of a state that has.
    fn step(&self, tau: f64) -> f64 {
        let mut first: Option<(f64, bool)> = None; // fastest alive: (|s|, oscillating)
        let mut second: f64 = 0.0; // |s| of the next fastest alive, other than its pair
        for &(norm, re, osc) in &self.live[..self.count] {
            if re * tau < -36.0 {
                continue;
            }
            match first {
                Some((n, o)) if norm > n => {
                    if !(o && osc) {
                        second = second.max(n);
                    }
                    first = Some((norm, osc));
                }
                Some((n, o)) => {
                    if !(o && osc && norm == n) {
                        second = second.max(norm);
                    }
                }
                None => first = Some((norm, osc)),
            }
        }
        let h = match first {
            None => tau.max(1.0),
            // 1.5 time constants < a quarter period (π/2b ≥ π/2|s|): one extremum at most
            Some((n, true)) => 1.5 / n,
            Some((n, false)) if second > 0.0 => (1.0 / n).max(tau).min(1.0 / second),
            Some((n, false)) => (1.0 / n).max(tau),
        };
        if self.slowest > 0.0 && self.slowest.is_finite() {
            h.min(2.0 / self.slowest)
        } else {
            h
        }
    }

    /// The time after which no event can come: the slowest mode is real and every other has
    /// decayed relative to it by e^{−70}, or it has itself fallen below e^{−600} (the faster
    /// ones then underflow to exact zeros, which must not read as crossings). `None` while an
    /// oscillation dominates the tail.
    fn settle_time(&self) -> Option<f64> {
        let live = &self.live[..self.count];
        let &(_, slow, complex) = live.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
        if complex {
            return None;
        }
        let floor = 600.0 / slow.abs();
        // The next mode is any other slower than the slowest by more than the slowest's own
        // rounding. Measured against the fastest mode instead (1e-9 of it, as this was), two
        // slow modes of a creep (λ = 1e-9, ζ = 3000, z̄_p = 1e-7: −6.2e-6 and −1.6e-4 beside
        // −1.7e5) read as one, the phase "settled" once the fast one had decayed (τ = 4e-4),
        // and the run reported no rebound where the ball leaves at τ ≈ 4.2e4 with e ≈ 0.03.
        // Counting a near-double root as two only makes the settle time later: safe.
        let next = live
            .iter()
            .map(|m| m.1)
            .filter(|&re| re < slow - 1e-9 * slow.abs())
            .fold(f64::NEG_INFINITY, f64::max);
        if next.is_finite() {
            Some((70.0 / (slow - next)).min(floor))
        } else {
            Some(floor)
        }
    }
}

/// A crossing inside [a, b]: a sign change in the watched direction, or one hidden behind an
/// extremum (g' changes sign inside and the extremum lies across zero).
fn crossing_in(
    watch: Watch,
    f: &mut impl FnMut(f64) -> Jet,
    (ta, ga, da): (f64, f64, f64),
    (tb, gb, db): (f64, f64, f64),
) -> Option<f64> {
    let sign = if watch.rising() { 1.0 } else { -1.0 };
    let (ga, gb, da, db) = (sign * ga, sign * gb, sign * da, sign * db);
    let g = |f: &mut dyn FnMut(f64) -> Jet, t: f64| {
        let (g, d, dd) = watch.eval(&f(t));
        (sign * g, sign * d, sign * dd)
    };
    if ga < 0.0 && gb >= 0.0 {
        return Some(halley_bracketed_from(|t| g(f, t), (ta, ga), (tb, gb)));
    }
    if ga < 0.0 && gb < 0.0 && da > 0.0 && db < 0.0 {
        let rate = |t| {
            let (_, d, dd) = g(f, t);
            (d, dd)
        };
        let tm = newton_bracketed_from(rate, (ta, da), (tb, db));
        let (gm, _, _) = g(f, tm);
        if gm > 1e-14 * (ga.abs() + gb.abs()) {
            return Some(halley_bracketed_from(|t| g(f, t), (ta, ga), (tm, gm)));
        }
    }
    None
}

/// The flow of one phase as a chain of anchors: (local τ of the anchor, flow from there).
type Anchors = Vec<(f64, Propagator)>;

fn eval_anchored(anchors: &Anchors, tau: f64) -> (Vector3<f64>, Vector3<f64>) {
    let i = anchors
        .partition_point(|(t0, _)| *t0 <= tau)
        .saturating_sub(1);
    let (t0, p) = &anchors[i];
    p.eval(tau - t0)
}

/// Where a phase's search ended.
struct Found {
    /// Local τ of the event, or of the point after which none can come.
    len: f64,
    /// The index of the watch that fired.
    hit: Option<usize>,
    /// Steps taken.
    steps: usize,
    /// The step budget ran out before an event or the settle time: the phase is unresolved.
    exhausted: bool,
    /// The anchors laid down on the way (all of them when kept, else none) and the last one.
    anchors: Anchors,
    last: (f64, Propagator),
}

/// The first event among `watches` in a phase, or the τ at which none can come any more, with
/// the anchors laid down on the way (all of them when `keep` — for sampling and the energy
/// audit — else only the last).
fn search(first: Propagator, modes: &Modes, watches: &[Watch], keep: bool) -> Found {
    debug_assert!(watches.len() <= 2, "a phase watches at most two events");
    let values = |j: &Jet, t: f64| {
        let mut v = [(t, 0.0, 0.0); 2];
        for (slot, w) in v.iter_mut().zip(watches) {
            let (g, d, _) = w.eval(j);
            *slot = (t, g, d);
        }
        v
    };
    let mut ta = 0.0;
    let mut va = values(&jet(&first, 0.0), 0.0);
    // the anchor in use; earlier ones are kept only when asked (no allocation otherwise)
    let mut current = (0.0, first);
    let mut anchors: Anchors = Vec::new();
    // the anchor in use joins the kept ones only when they are kept (no allocation otherwise)
    let finish = |len: f64,
                  hit: Option<usize>,
                  steps: usize,
                  exhausted: bool,
                  current: (f64, Propagator),
                  anchors: &mut Anchors| {
        if keep {
            anchors.push(current.clone());
        }
        Found {
            len,
            hit,
            steps,
            exhausted,
            anchors: std::mem::take(anchors),
            last: current,
        }
    };
    for step in 1..=MAX_STEPS {
        let tb = ta + modes.step(ta);
        let (t0, p) = &current;
        let mut f = |t: f64| jet(p, t - t0);
        let jb = f(tb);
        let vb = values(&jb, tb);
        let mut best: Option<(f64, usize)> = None;
        for (i, w) in watches.iter().enumerate() {
            if let Some(t) = crossing_in(*w, &mut f, va[i], vb[i])
                && best.is_none_or(|(bt, _)| t < bt)
            {
                best = Some((t, i));
            }
        }
        if let Some((t, i)) = best {
            return finish(t, Some(i), step, false, current, &mut anchors);
        }
        let next = (tb, current.1.restart(jb.0[0]));
        let previous = std::mem::replace(&mut current, next);
        if keep {
            anchors.push(previous);
        }
        if modes.settle.is_some_and(|s| tb > s) {
            return finish(tb, None, step, false, current, &mut anchors);
        }
        ta = tb;
        va = vb;
    }
    finish(ta, None, MAX_STEPS, true, current, &mut anchors)
}

/// One phase as solved: global start, local length, and its flow.
struct Segment {
    start: f64,
    len: f64,
    k: f64,
    s: f64,
    anchors: Anchors,
}

#[derive(Clone, Copy)]
enum Phase {
    Loading,
    Unloading(Unloading),
}

pub(crate) fn solve(n: &Normalized, contact: &Contact, opts: &SolveOptions) -> Outcome {
    let (lambda, zeta) = (n.lambda, n.zeta);
    let mut x = Vector3::new(0.0, 1.0, 0.0);
    let mut tau = 0.0;
    let mut phase = Phase::Loading;
    let mut out = Outcome::default();
    // sampling and the energy audit revisit every phase; a summary needs only where each ended
    let keep = opts.samples > 0 || opts.energy;
    let mut segments: Vec<Segment> = Vec::new();
    let mut cached: Option<(f64, Roots, Modes, Option<FastSlow>)> = None;
    let mut phases_left = MAX_PHASES;
    loop {
        if phases_left == 0 {
            out.unresolved = Some("more than 64 load–unload phases");
            break;
        }
        phases_left -= 1;
        let (k, s) = match phase {
            Phase::Loading => (1.0, 0.0),
            Phase::Unloading(u) => (u.f_m / (u.z_m - u.z_f), u.z_f),
        };
        let (a, poly) = system(lambda, zeta, k);
        // Without flattening the unloading line is the loading one (k = z̄_m/z̄_m = 1 exactly):
        // same matrix, same roots and time scales as the phase before.
        let (roots, modes, fast_slow) = match cached {
            Some((ck, r, m, f)) if ck == k => (r, m, f),
            _ => {
                let r = cubic_roots(poly);
                (r, Modes::new(&r), split(lambda, zeta, k, &r))
            }
        };
        cached = Some((k, roots, modes, fast_slow));
        let w0 = x - Vector3::new(s, 0.0, 0.0);
        let prop = Propagator::with_roots(a, roots, fast_slow, w0);
        let z_start = l(&w0) + s;
        let watches: &[Watch] = match phase {
            Phase::Loading => &[Watch::RateFalls],
            // separation at z̄ = z̄_f (F = 0); reload once z̄ rises past z̄_m, whose value is
            // taken from w0 itself so that the start is not mistaken for a crossing
            Phase::Unloading(_) => &[
                Watch::Falls(0.0),
                Watch::Rises(l(&w0) + RELOAD_SLACK * f64::EPSILON * (z_start.abs() + w0.amax())),
            ],
        };
        let Found {
            len,
            hit,
            steps,
            exhausted,
            anchors,
            last: (t0, last),
        } = search(prop, &modes, watches, keep);
        out.steps += steps;
        if exhausted {
            out.unresolved = Some("the step budget of a phase ran out before its end");
        }
        let (w, _) = last.eval(len - t0);
        let z_end = l(&w) + s;
        x = w + Vector3::new(s, 0.0, 0.0);
        out.contact_work += match phase {
            Phase::Loading => contact.loading_work(z_end) - contact.loading_work(z_start),
            Phase::Unloading(u) => {
                contact.unloading_work(z_end, &u) - contact.unloading_work(z_start, &u)
            }
        };
        segments.push(Segment {
            start: tau,
            len,
            k,
            s,
            anchors,
        });
        tau += len;
        let next = match (phase, hit) {
            (Phase::Loading, Some(_)) => {
                let u = contact.unload_from(z_end);
                out.events.push((tau, EventKind::Unload, z_end));
                Some(Phase::Unloading(u))
            }
            (Phase::Unloading(_), Some(1)) => {
                out.events.push((tau, EventKind::Reload, z_end));
                Some(Phase::Loading)
            }
            (Phase::Unloading(_), Some(_)) => {
                out.events.push((tau, EventKind::Separation, z_end));
                out.rebound = true;
                None
            }
            (_, None) => None,
        };
        match phase {
            Phase::Loading => {
                out.z_max = out.z_max.max(z_end);
                out.f_max = out.f_max.max(contact.loading_force(z_end));
            }
            Phase::Unloading(u) => out.z_f = u.z_f,
        }
        match next {
            Some(p) => phase = p,
            None => break,
        }
    }
    out.tau_end = tau;
    out.velocity_end = x[1];
    out.y_end = x[2] / y_scale(lambda);
    if opts.energy {
        out.dashpot = Some(
            segments
                .iter()
                .map(|seg| dashpot_energy(seg, lambda, zeta))
                .sum(),
        );
    }
    out.samples = sample(&segments, tau, opts.samples, y_scale(lambda));
    out
}

fn sample(segments: &[Segment], tau_end: f64, count: usize, sigma: f64) -> Vec<[f64; 4]> {
    let mut samples = Vec::with_capacity(count);
    let mut i = 0;
    for j in 0..count {
        let t = if count > 1 {
            tau_end * j as f64 / (count - 1) as f64
        } else {
            0.0
        };
        while i + 1 < segments.len() && t > segments[i].start + segments[i].len {
            i += 1;
        }
        let seg = &segments[i];
        let (w, _) = eval_anchored(&seg.anchors, (t - seg.start).clamp(0.0, seg.len));
        // (τ, F̄, z̄, ᾱ = z̄ + ȳ)
        samples.push([
            t,
            (seg.k * l(&w)).max(0.0),
            l(&w) + seg.s,
            l(&w) + seg.s + w[2] / sigma,
        ]);
    }
    samples
}
