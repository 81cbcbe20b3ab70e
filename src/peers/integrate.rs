//! One normalized impact x'' = −F̄(x, x'), x(0) = 0, x'(0) = 1, integrated to the end of
//! contact by an embedded Runge–Kutta 8(5,3) pair (Dormand–Prince DOP853; coefficients from
//! the `differential-equations` crate's tableau, step control after Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, §II.10) with the end located on the step itself.
//!
//! Why hand-written rather than the crate's solver: the exact calibration runs one impact per
//! root-finding iteration and the bench target is one Hunt–Crossley impact in ≤ 10 µs and one
//! calibration in ≤ 0.5 ms (BENCHMARKS.md). The state is two numbers; the crate's generic
//! solver allocates its solution and event machinery per call, while this loop allocates
//! nothing unless histories are asked for, and it can switch to w = x^{1/p} as the independent
//! variable near x = 0, which the crate's solvers cannot (`w_phase`).

use super::dop853::{Hermite, step_with};
use crate::solver::roots::newton_bracketed_from;

/// Steps allowed before the run is declared unresolved (no impact here takes 1 000).
const MAX_STEPS: usize = 100_000;

/// A normalized contact law: the force on the ball and the function whose down-crossing
/// (while the ball moves out, x' < 0) ends the contact, with its time derivative.
pub trait Law {
    /// F̄(x, x'), already clipped where the model clips it.
    fn force(&self, x: f64, v: f64) -> f64;
    /// The force that drives the motion: F̄ continued smoothly past where a clip would act.
    /// Until the contact ends the two are equal (the clip acts only after the end event), and
    /// stepping with the smooth one keeps the last step, whose end sits on the clip, of full
    /// order: with the clipped force its error estimate passed a step 400 times less accurate
    /// than the tolerance (clipped Kelvin–Voigt, ζ = 0.05, against the closed form).
    fn drive(&self, x: f64, v: f64) -> f64 {
        self.force(x, v)
    }
    /// g(x, x') = 0 ends the contact.
    fn end(&self, x: f64, v: f64) -> f64;
    /// dg/dτ along the motion (a = −F̄).
    fn end_rate(&self, x: f64, v: f64, a: f64) -> f64;
    /// dF̄/dτ along the motion (a = −F̄), for locating the peak force.
    fn force_rate(&self, x: f64, v: f64, a: f64) -> f64;
    /// Time after which a ball still in contact is declared to have no rebound
    /// (Kelvin–Voigt with tension, overdamped, creeps back to x = 0 forever).
    fn horizon(&self) -> f64 {
        1e4
    }
    /// Whether the ball is known never to leave once it has turned (unloading starts): the run
    /// then ends there with no rebound.
    fn stays_after_turning(&self) -> bool {
        false
    }
    /// p such that the force is smooth in w = x^{1/p} near x = 0 (see `w_phase`).
    fn smoothing_power(&self) -> Option<i32> {
        None
    }
    /// Whether the contact ends at x = 0 (rather than where a clipped force lets go).
    fn ends_at_zero(&self) -> bool {
        false
    }
}

/// Indentation below which the start runs in w = x^{1/p}; at the end, the fraction of the peak
/// indentation below which it does.
const W_START: f64 = 0.05;
const W_END: f64 = 0.3;

/// The end of one normalized impact.
#[derive(Debug, Clone, Default)]
pub struct Run {
    /// The contact ended (F̄ or x back to 0 while moving out).
    pub rebound: bool,
    /// τ at the end (or at the horizon).
    pub tau: f64,
    /// (x, x') at the end.
    pub end: [f64; 2],
    /// Peak force and peak indentation seen at the steps (refined at the turning point).
    pub f_max: f64,
    pub x_max: f64,
    /// τ of the turning point x' = 0 (unloading starts).
    pub tau_unload: f64,
    /// F̄ at the end (0 where the force let go; η δ̇ < 0 for Kelvin–Voigt with tension).
    pub f_end: f64,
    /// Accepted and rejected steps.
    pub steps: usize,
    /// The step budget ran out.
    pub unresolved: bool,
}

fn rhs<L: Law>(law: &L, y: [f64; 2]) -> [f64; 2] {
    [y[1], -law.drive(y[0], y[1])]
}

/// One step of the impact in time (autonomous: x' = v, v' = −F̄).
fn step<L: Law>(law: &L, y: [f64; 2], k0: [f64; 2], h: f64) -> ([f64; 2], f64) {
    step_with(&|_, y| rhs(law, y), (0.0, y), k0, h)
}

/// The impact near x = 0 with w = x^{1/p} as the independent variable and (τ, v) as the
/// state: dτ/dw = p w^{p−1}/v, dv/dw = −F̄(w^p, v) p w^{p−1}/v. Where F̄ holds x^{3/2} and
/// x^{1/4} it is not smooth in τ at x = 0 (x ≈ τ makes the force ∝ τ^{3/2}), and the time
/// steps shrink and are rejected by the dozen there; in w (p = 2 for x^{3/2}, 4 for x^{1/4})
/// the right-hand side is a polynomial over v, and a few steps cross the region. Valid while v
/// stays away from 0, which `stop` ensures. Runs from `w0` towards `w1` until `stop(x, v)`
/// or w1; returns (w, τ, v, steps).
fn w_phase<L: Law>(
    law: &L,
    p: i32,
    (w0, w1): (f64, f64),
    (tau0, v0): (f64, f64),
    stop: impl Fn(f64, f64) -> bool,
) -> (f64, f64, f64, usize) {
    let pf = p as f64;
    let f = |w: f64, s: [f64; 2]| {
        let dxdw = pf * w.powi(p - 1);
        let x = w.powi(p);
        [dxdw / s[1], -law.drive(x, s[1]) * dxdw / s[1]]
    };
    let (mut w, mut s) = (w0, [tau0, v0]);
    let mut h = 0.25 * (w1 - w0);
    let mut steps = 0;
    while steps < 1000 {
        let hs = if (w + h - w1) * (w1 - w0).signum() > 0.0 {
            w1 - w
        } else {
            h
        };
        let (s1, err) = step_with(&f, (w, s), f(w, s), hs);
        steps += 1;
        if err.is_nan() || err > 1.0 || s1[1].abs() < 0.25 * v0.abs() {
            h = hs / 3.0;
            continue;
        }
        w += hs;
        s = s1;
        if w == w1 || stop(w.powi(p), s[1]) {
            break;
        }
        h = hs / grow(err).clamp(1.0 / 6.0, 3.0);
    }
    (w, s[0], s[1], steps)
}

/// What a run is for: the COR alone (no peaks located), the summary with the peaks, or the
/// histories' pass, landing steps on τ = j·spacing and recording (τ, F̄, x) there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Want {
    Cor,
    Peaks,
    History(f64),
}

impl Want {
    /// (locate the peaks, sample spacing or 0)
    fn parts(self) -> (bool, f64) {
        match self {
            Want::Cor => (false, 0.0),
            Want::Peaks => (true, 0.0),
            Want::History(every) => (true, every),
        }
    }
}

/// Integrate from x = 0, x' = 1 until the contact ends.
pub fn run<L: Law>(law: &L, want: Want, samples: &mut Vec<[f64; 3]>) -> Run {
    let (peaks, sample_every) = want.parts();
    let mut out = Run {
        f_max: law.force(0.0, 1.0),
        ..Run::default()
    };
    let record = sample_every > 0.0;
    // the histories' pass lands on sample times and stays in τ throughout
    let smooth = law.smoothing_power().filter(|_| !record);
    let (mut tau, mut y, mut h) = match smooth {
        Some(p) => start_in_w(law, p, &mut out),
        None => (0.0, [0.0, 1.0], 1e-3),
    };
    let mut k0 = rhs(law, y);
    let mut n_sampled = 0usize;
    let mut rising = law.force_rate(0.0, 1.0, k0[1]) > 0.0;
    while out.steps < MAX_STEPS {
        let next_sample = n_sampled as f64 * sample_every;
        if record && tau >= next_sample {
            samples.push([tau, law.force(y[0], y[1]), y[0]]);
            n_sampled += 1;
            continue;
        }
        let landing = record && tau + h >= next_sample;
        let hs = if landing { next_sample - tau } else { h };
        let (y1, err) = step(law, y, k0, hs);
        out.steps += 1;
        let at = (tau, y, k0);
        if y1[1] < 0.0 && law.end(y1[0], y1[1]) <= 0.0 {
            match land_on_end(law, at, hs) {
                Ok(end) => return finish(law, out, at, end, peaks.then_some(rising)),
                Err(shorter) => h = shorter,
            }
            continue;
        }
        if err.is_nan() || err > 1.0 {
            h = hs
                / if err.is_finite() {
                    grow(err).clamp(1.5, 3.0)
                } else {
                    3.0
                };
            continue;
        }
        let (f1, a1) = (law.force(y1[0], y1[1]), -law.drive(y1[0], y1[1]));
        let rising1 = law.force_rate(y1[0], y1[1], a1) > 0.0;
        // the overdamped Kelvin–Voigt run ends at its turning point, so it needs it located
        if peaks || law.stays_after_turning() {
            refine_peaks(law, &mut out, at, hs, (y1, rising, rising1));
        }
        rising = rising1;
        out.f_max = out.f_max.max(f1);
        out.x_max = out.x_max.max(y1[0]);
        if y1[1] <= 0.0 && law.stays_after_turning() {
            out.tau = out.tau_unload;
            out.end = [out.x_max, 0.0];
            out.f_end = law.force(out.x_max, 0.0);
            return out;
        }
        if let Some(p) = smooth.filter(|_| law.ends_at_zero())
            && y1[1] < 0.0
            && y1[0] < W_END * out.x_max
        {
            return end_in_w(law, p, out, (tau + hs, y1));
        }
        (tau, y, k0) = (
            if landing { next_sample } else { tau + hs },
            y1,
            [y1[1], a1],
        );
        if !landing {
            h = hs / grow(err).clamp(1.0 / 6.0, 3.0);
        }
        if tau > law.horizon() {
            (out.f_end, out.tau, out.end) = (f1, tau, y);
            return out;
        }
    }
    (out.unresolved, out.tau, out.end) = (true, tau, y);
    out
}

/// Hairer's step-size factor: the next step is h / grow(err), grow = err^{1/8}/0.9 (three
/// square roots: a third of `powf`'s cost, which showed in the profile).
fn grow(err: f64) -> f64 {
    err.sqrt().sqrt().sqrt() / 0.9
}

/// The start of contact in w = x^{1/p}, up to x = `W_START` (or earlier, while v stays well
/// away from 0 and the force is still rising, so that no peak is passed there): (τ, y, h).
fn start_in_w<L: Law>(law: &L, p: i32, out: &mut Run) -> (f64, [f64; 2], f64) {
    let stop =
        |x: f64, v: f64| x >= W_START || v < 0.6 || law.force_rate(x, v, -law.drive(x, v)) <= 0.0;
    let w1 = W_START.powf(1.0 / p as f64);
    let (w, t, v, n) = w_phase(law, p, (0.0, w1), (0.0, 1.0), stop);
    let y = [w.powi(p), v];
    out.steps += n;
    out.f_max = law.force(y[0], y[1]);
    out.x_max = y[0];
    (t, y, 0.05)
}

/// The end of contact at x = 0 in w = x^{1/p}, from `y` at `tau` (moving out, x below
/// `W_END` of the peak, so v is well away from 0).
fn end_in_w<L: Law>(law: &L, p: i32, mut out: Run, (tau, y): (f64, [f64; 2])) -> Run {
    let w0 = y[0].powf(1.0 / p as f64);
    let (_, t, v, n) = w_phase(law, p, (w0, 0.0), (tau, y[1]), |_, _| false);
    out.steps += n;
    (out.rebound, out.tau, out.end, out.f_end) = (true, t, [0.0, v], 0.0);
    out
}

/// A trial step from `y` of size `h` passed the end of contact, where the force has a kink,
/// so its error estimate says nothing about the step that stops at the end. The end is
/// located on re-taken steps; `Ok((s, y_end))` when the step landing there is accurate, else
/// `Err(shorter h)` to approach it (a kinked step would be rejected again and again).
fn land_on_end<L: Law>(
    law: &L,
    (_, y, k0): (f64, [f64; 2], [f64; 2]),
    h: f64,
) -> Result<(f64, [f64; 2]), f64> {
    let (s, y_end) = crossing(law, (y, k0), h, |y1, a| {
        (law.end(y1[0], y1[1]), law.end_rate(y1[0], y1[1], a))
    });
    let err = if s > 0.0 { step(law, y, k0, s).1 } else { 0.0 };
    if err <= 1.0 {
        Ok((s, y_end))
    } else {
        Err(s / grow(err).clamp(1.5, 3.0))
    }
}

/// The point inside the step from `y` (size `h`) where `g` (with its rate) crosses zero.
fn crossing<L: Law>(
    law: &L,
    (y, k0): ([f64; 2], [f64; 2]),
    h: f64,
    g: impl Fn([f64; 2], f64) -> (f64, f64),
) -> (f64, [f64; 2]) {
    let eval = |s: f64| {
        let y1 = if s == 0.0 { y } else { step(law, y, k0, s).0 };
        (y1, g(y1, -law.drive(y1[0], y1[1])))
    };
    let (g0, g1) = (eval(0.0).1.0, eval(h).1.0);
    let s = if g0 == 0.0 {
        0.0
    } else if g1 == 0.0 || (g0 > 0.0) == (g1 > 0.0) {
        h
    } else {
        newton_bracketed_from(|s| eval(s).1, (0.0, g0), (h, g1))
    };
    (s, eval(s).0)
}

/// The end of contact at `s` into the step from `y` at `tau` (`y_end` there).
fn finish<L: Law>(
    law: &L,
    mut out: Run,
    (tau, y, k0): (f64, [f64; 2], [f64; 2]),
    (s, y_end): (f64, [f64; 2]),
    rising: Option<bool>,
) -> Run {
    let f_end = law.force(y_end[0], y_end[1]);
    if let Some(rising) = rising {
        let a_end = -law.drive(y_end[0], y_end[1]);
        let rising_end = law.force_rate(y_end[0], y_end[1], a_end) > 0.0;
        refine_peaks(law, &mut out, (tau, y, k0), s, (y_end, rising, rising_end));
    }
    out.rebound = true;
    out.f_end = f_end;
    out.tau = tau + s;
    out.end = y_end;
    out.steps += 1;
    out
}

/// Inside a step of size `h` ending at `y1`: the turning point x' = 0 (peak indentation, start
/// of unloading) and a peak of the force (dF/dτ from + to −), each located on the step.
fn refine_peaks<L: Law>(
    law: &L,
    out: &mut Run,
    (tau, y, k0): (f64, [f64; 2], [f64; 2]),
    h: f64,
    (y1, rising0, rising1): ([f64; 2], bool, bool),
) {
    let hermite = Hermite::new((y, k0), y1, -law.drive(y1[0], y1[1]), h);
    if y[1] > 0.0 && y1[1] <= 0.0 {
        // x' = 0: x is flat there, so the interpolant's root (error ~h⁵) and one real step to
        // it give x_m to the integrator's tolerance
        let s = hermite.root(|p| p[1], h);
        let yt = step(law, y, k0, s).0;
        out.tau_unload = tau + s;
        out.x_max = out.x_max.max(yt[0]);
        out.f_max = out.f_max.max(law.force(yt[0], yt[1]));
    }
    if rising0 && !rising1 {
        // dF̄/dτ = 0: F̄ is flat there too; located on the interpolant, F̄_m from a real step
        let s = hermite.root(|p| law.force_rate(p[0], p[1], p[2]), h);
        let yp = step(law, y, k0, s).0;
        out.f_max = out.f_max.max(law.force(yp[0], yp[1]));
    }
}
