//! The exact solver for the linearized (bilinear) law, Eqs. 21–22, in normalized form
//! (docs/model.md §5). The state is (z̄, ᾱ', ȳ) rather than (ᾱ, ᾱ', ȳ): z̄ = ᾱ − ȳ is the small
//! difference of two large numbers as the ball settles, and carrying it directly keeps its
//! relative precision (at λ = 0 the resting mode then has no z̄ component at all).
//! Each phase is a linear ODE; with w = x − (s, 0, 0) (s = z̄_f while unloading, which makes
//! the affine unloading law homogeneous) it reads w' = A(k) w with
//!     A(k) = [[−2ζk, 1, 2ζλ], [−k, 0, 0], [2ζk, 0, −2ζλ]],
//! k = 1 while loading and k = F̄_m/(z̄_m − z̄_f) while unloading. Its flow is evaluated exactly
//! (`Propagator`); only the events need root finding: z̄' = 0 (unload), z̄ = z̄_f (F = 0,
//! separation), z̄ = z̄_m (reload).

use super::propagator::{FastSlow, Propagator, Roots, cubic_roots};
use super::{EventKind, Outcome, Sample, SolveOptions, Unresolved};
use crate::model::contact::{Contact, Unloading};
use crate::model::params::Normalized;
use energy::dashpot_energy;
use modes::Modes;
use nalgebra::{Matrix3, Vector3};
use search::{Anchors, Watch, eval_anchored, search};

mod energy;
mod modes;
mod path;
mod search;
pub use path::{LocalFlow, NormalPath, PathPoint};

/// More phase switches than this would mean a reload cycle that never settles.
pub(super) const MAX_PHASES: usize = 64;
/// Hard cap on search steps per phase (the step rule reaches every event in far fewer).
pub(super) const MAX_STEPS: usize = 20_000;

/// How far past z̄_m, in rounding units of the state, z̄ must rise before an unloading phase
/// turns back to loading. The unload is located where z̄' = 0 only to rounding, and at a slow
/// turning point (a creep, z̄'' ~ 1e-12) z̄ may go on rising by a rounding after it, which must
/// not read as a reload: that would start a loading phase already past its peak
/// (tests/physics/solver_agreement.rs, `creeps_match_a_40_digit_reference`, λ = 3.2e-8, ζ = 1e4).
const RELOAD_SLACK: f64 = 1e3;

/// The contact indentation z̄ − s (or a derivative) as a functional of w.
fn l(v: &Vector3<f64>) -> f64 {
    v[0]
}

/// What the third state carries: w = (z̄ − s, ᾱ', σȳ), σ = λ (the recoil spring's force) for a
/// soft spring, λ < 1, else 1. Why: a ball creeping into a weak dashpot against a soft spring
/// (λ ~ 1e-6, ζ ~ 1e4) drives ȳ to hundreds while z̄ − s stays ~1e-5, and the propagator's
/// rounding is relative to the whole state: scaled, the dissipation along z̄ keeps its digits
/// (tests/physics/solver_agreement.rs, `creeps_match_a_40_digit_reference`). A stiff
/// spring keeps ȳ ≤ F̄/λ small already, and scaling by a large λ would put entries of 2ζλ²
/// into the matrix (λ = ζ = 1e6: 1e12 beside 1) and break the propagation.
fn y_scale(lambda: f64) -> f64 {
    if lambda > 0.0 { lambda.min(1.0) } else { 1.0 }
}

/// The phase's matrix on w = (z̄ − s, ᾱ', σȳ), the similarity diag(1, 1, σ) of docs/model.md §5's
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

/// The linear system of a phase with slope k, with what its search needs: computed once for
/// each slope (without flattening the unloading line is the loading one, k = z̄_m/z̄_m = 1
/// exactly: same matrix, same roots and time scales as the phase before).
#[derive(Clone, Copy)]
struct PhaseSystem {
    k: f64,
    roots: Roots,
    modes: Modes,
    fast_slow: Option<FastSlow>,
}

/// The state one phase hands to the next.
struct ExactRunner<'a> {
    lambda: f64,
    zeta: f64,
    contact: &'a Contact,
    /// Keep every anchor of every phase: sampling and the energy audit revisit them; a summary
    /// needs only where each phase ended.
    keep: bool,
    /// (z̄, ᾱ', ȳ) and τ where the next phase starts, and its branch.
    x: Vector3<f64>,
    tau: f64,
    phase: Phase,
    out: Outcome,
    segments: Vec<Segment>,
    system: Option<PhaseSystem>,
    phases_left: usize,
}

pub(crate) fn solve(n: &Normalized, contact: &Contact, opts: &SolveOptions) -> Outcome {
    run(n, contact, opts.samples > 0 || opts.energy).finish(opts)
}

/// The run and its flow, which the oblique impact reads at any τ (src/oblique/).
pub(crate) fn solve_path(
    n: &Normalized,
    contact: &Contact,
    opts: &SolveOptions,
) -> (Outcome, NormalPath) {
    let mut run = run(n, contact, true);
    let segments = std::mem::take(&mut run.segments);
    let out = run.finish_with(opts, &segments);
    (out, NormalPath::new(segments, y_scale(n.lambda)))
}

fn run<'a>(n: &Normalized, contact: &'a Contact, keep: bool) -> ExactRunner<'a> {
    let mut run = ExactRunner {
        lambda: n.lambda,
        zeta: n.zeta,
        contact,
        keep,
        x: Vector3::new(0.0, 1.0, 0.0),
        tau: 0.0,
        phase: Phase::Loading,
        out: Outcome::default(),
        segments: Vec::new(),
        system: None,
        phases_left: MAX_PHASES,
    };
    while run.run_phase() {}
    run
}

impl ExactRunner<'_> {
    /// Solve the next phase and turn to the one after it; false when the run is over.
    fn run_phase(&mut self) -> bool {
        if self.phases_left == 0 {
            self.out.unresolved = Some(Unresolved::ExactPhases);
            return false;
        }
        self.phases_left -= 1;
        let (k, s) = match self.phase {
            Phase::Loading => (1.0, 0.0),
            Phase::Unloading(u) => (u.f_m / (u.z_m - u.z_f), u.z_f),
        };
        let (a, poly) = system(self.lambda, self.zeta, k);
        let sys = self.system_for(k, poly);
        let w0 = self.x - Vector3::new(s, 0.0, 0.0);
        let prop = Propagator::with_roots(a, sys.roots, sys.fast_slow, w0);
        let z_start = l(&w0) + s;
        let (watches, count) = self.watches(&w0, z_start);
        let found = search(prop, &sys.modes, &watches[..count], self.keep);
        self.out.steps += found.steps;
        if found.exhausted {
            self.out.unresolved = Some(Unresolved::ExactPhaseSteps);
        }
        let (t0, last) = &found.last;
        let (w, _) = last.eval(found.len - t0);
        let z_end = l(&w) + s;
        self.x = w + Vector3::new(s, 0.0, 0.0);
        self.book_work(z_start, z_end);
        self.segments.push(Segment {
            start: self.tau,
            len: found.len,
            k,
            s,
            anchors: found.anchors,
        });
        self.tau += found.len;
        let next = self.transition(found.hit, z_end);
        match self.phase {
            Phase::Loading => {
                self.out.z_max = self.out.z_max.max(z_end);
                self.out.f_max = self.out.f_max.max(self.contact.loading_force(z_end));
            }
            Phase::Unloading(u) => self.out.z_f = u.z_f,
        }
        match next {
            Some(p) => self.phase = p,
            None => return false,
        }
        true
    }

    /// The phase system for slope k (characteristic polynomial `poly`), reused while k stays.
    fn system_for(&mut self, k: f64, poly: [f64; 3]) -> PhaseSystem {
        let sys = match self.system {
            Some(sys) if sys.k == k => sys,
            _ => {
                let roots = cubic_roots(poly);
                PhaseSystem {
                    k,
                    roots,
                    modes: Modes::new(&roots),
                    fast_slow: split(self.lambda, self.zeta, k, &roots),
                }
            }
        };
        self.system = Some(sys);
        sys
    }

    /// What the phase starting at w0 (z̄ = z_start) watches for: the turn while loading;
    /// separation at z̄ = z̄_f (F = 0) and a reload once z̄ rises past z̄_m while unloading, z̄_m
    /// taken from w0 itself so that the start is not mistaken for a crossing.
    fn watches(&self, w0: &Vector3<f64>, z_start: f64) -> ([Watch; 2], usize) {
        match self.phase {
            Phase::Loading => ([Watch::RateFalls; 2], 1),
            Phase::Unloading(_) => {
                let past = RELOAD_SLACK * f64::EPSILON * (z_start.abs() + w0.amax());
                ([Watch::Falls(0.0), Watch::Rises(l(w0) + past)], 2)
            }
        }
    }

    /// The contact's work over the phase, z̄ from `z_start` to `z_end` on its branch.
    fn book_work(&mut self, z_start: f64, z_end: f64) {
        let c = self.contact;
        self.out.contact_work += match self.phase {
            Phase::Loading => c.loading_work(z_end) - c.loading_work(z_start),
            Phase::Unloading(u) => c.unloading_work(z_end, &u) - c.unloading_work(z_start, &u),
        };
    }

    /// The branch after a phase that ended at τ on watch `hit` (its index), or without one.
    fn transition(&mut self, hit: Option<usize>, z_end: f64) -> Option<Phase> {
        let tau = self.tau;
        match (self.phase, hit) {
            (Phase::Loading, Some(_)) => {
                let u = self.contact.unload_from(z_end);
                self.out.event(tau, EventKind::Unload, z_end);
                Some(Phase::Unloading(u))
            }
            (Phase::Unloading(_), Some(1)) => {
                self.out.event(tau, EventKind::Reload, z_end);
                Some(Phase::Loading)
            }
            (Phase::Unloading(_), Some(_)) => {
                self.out.event(tau, EventKind::Separation, z_end);
                self.out.rebound = true;
                None
            }
            (_, None) => None,
        }
    }

    /// The outcome at the end of the run: the energy audit and the samples when asked for.
    fn finish(mut self, opts: &SolveOptions) -> Outcome {
        let segments = std::mem::take(&mut self.segments);
        self.finish_with(opts, &segments)
    }

    /// As `finish`, with the phases' flow held by the caller.
    fn finish_with(mut self, opts: &SolveOptions, segments: &[Segment]) -> Outcome {
        let (lambda, zeta) = (self.lambda, self.zeta);
        self.out.tau_end = self.tau;
        self.out.velocity_end = self.x[1];
        self.out.y_end = self.x[2] / y_scale(lambda);
        if opts.energy {
            let dashpot = segments.iter().map(|seg| dashpot_energy(seg, lambda, zeta));
            self.out.dashpot = Some(dashpot.sum());
        }
        self.out.samples = sample(segments, self.tau, opts.samples, y_scale(lambda));
        self.out
    }
}

fn sample(segments: &[Segment], tau_end: f64, count: usize, sigma: f64) -> Vec<Sample> {
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
        samples.push(Sample {
            tau: t,
            force: (seg.k * l(&w)).max(0.0),
            z: l(&w) + seg.s,
            alpha: l(&w) + seg.s + w[2] / sigma,
        });
    }
    samples
}
