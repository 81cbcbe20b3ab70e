//! The tangential motion in closed form, phase by phase (docs/oblique.md §2), in the normal
//! impact's units (`Scaled`). While the contact point sticks, u'' = −ω̃_t² u with
//! ω̃_t² = k̃(1 + 1/κ): a harmonic oscillator, whatever F̄ does. While it slides with
//! s = ±1, F̃_t = −sμF̄ and ṽ_c' = g F̃_t integrate to the normal impulse:
//! ṽ_c(τ) = ṽ_c(τ0) − sμg (ᾱ'(τ0) − ᾱ'(τ)). Only the switches need a root find:
//! stick → slip when k̃|u| reaches μF̄, slip → stick when sṽ_c < μF̄'/k̃.
//!
//! With a tangential dashpot c̃ (LAMMPS's linear_history rule, docs/oblique.md §1) the stick is
//! a damped oscillator, ũ'' + 2βũ' + ω̃_t²ũ = 0 (β = gc̃/2), the trial force is
//! f = k̃ũ + c̃ṽ_c, a slide holds ũ = (sμF̄ − c̃ṽ_c)/k̃, and the switches are |f| = μF̄ and
//! sṽ_c < μ(F̄' + c̃gF̄)/k̃. With c̃ = 0 every expression is the undamped one, bit for bit.

use super::damped::{self, slip_spring};
use super::{MAX_PHASES, NormalMotion, ObliqueError, Scaled};
use crate::solver::exact::PathPoint;
use serde::Serialize;
use switch::find_switch;

mod switch;

/// How the contact point moves in a phase.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Mode {
    /// It sticks: u' = v_c, F_t = −K_t u − c_t v_c, |F_t| ≤ μ F_n.
    Stick,
    /// It slides with F_t = −s μ F_n and u reset to (s μ F_n − c_t v_c)/K_t, s = ±1 (the
    /// trial force's sign when it got there).
    Slip(f64),
}

/// One phase of the contact, normalized: τ from `start` to `end`, and the state it starts
/// from (u ω0/v_y, v_c/v_y, and ᾱ' = α'/v_y for the impulse of a slide).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Phase {
    /// τ at its start.
    pub start: f64,
    /// τ at its end.
    pub end: f64,
    /// Stick or slip.
    pub mode: Mode,
    /// ũ at the start.
    pub u0: f64,
    /// ṽ_c at the start.
    pub vc0: f64,
    /// ᾱ' at the start.
    pub vel0: f64,
}

impl Phase {
    /// (ũ, ṽ_c) at τ in this phase, `p` the normal motion at τ.
    pub(crate) fn state(&self, s: &Scaled, p: &PathPoint, tau: f64) -> (f64, f64) {
        match self.mode {
            Mode::Stick if s.ct > 0.0 => self.damped_state(s, tau - self.start),
            Mode::Stick => self.stick_state(s, (s.omega_t * (tau - self.start)).sin_cos()),
            Mode::Slip(sg) => {
                let vc = self.vc0 - sg * s.mu * s.g * (self.vel0 - p.velocity);
                (slip_spring(s, sg, p.force, vc), vc)
            }
        }
    }

    /// (ũ, ṽ_c) of a damped stick δ after its start (`damped::Start::state`).
    pub(crate) fn damped_state(&self, s: &Scaled, delta: f64) -> (f64, f64) {
        self.damped_start().state(s, delta)
    }

    fn damped_start(&self) -> damped::Start {
        damped::Start {
            u0: self.u0,
            vc0: self.vc0,
        }
    }

    /// (ũ, ṽ_c) of a stick from sin and cos of ω̃_t (τ − start).
    fn stick_state(&self, s: &Scaled, (sn, cs): (f64, f64)) -> (f64, f64) {
        let w = s.omega_t;
        (
            self.u0 * cs + self.vc0 * sn / w,
            -self.u0 * w * sn + self.vc0 * cs,
        )
    }

    /// A stick's switch function and its rate from its state (ũ, ṽ_c): |f| − μF̄ with the
    /// trial force f = k̃ũ + c̃ṽ_c, f' = k̃ṽ_c − c̃g f (ṽ_c' = −g f while sticking).
    fn stick_switch(s: &Scaled, p: &PathPoint, (u, vc): (f64, f64)) -> (f64, f64) {
        if s.ct > 0.0 {
            let f = s.kt * u + s.ct * vc;
            let rate = f.signum() * (s.kt * vc - s.ct * s.g * f) - s.mu * p.rate;
            return (f.abs() - s.mu * p.force, rate);
        }
        let rate = s.kt * u.signum() * vc - s.mu * p.rate;
        (s.kt * u.abs() - s.mu * p.force, rate)
    }

    /// The switch function and its rate in either mode, F̄'' = `curvature`: a slide's
    /// G' = μ(F̄'' + c̃gF̄')/k̃ + μgF̄, since sṽ_c' = −μgF̄ (ṽ_c' = g F̃_t, F̃_t = −sμF̄).
    fn switch_rate(&self, s: &Scaled, p: &PathPoint, curvature: f64, tau: f64) -> (f64, f64) {
        let (g, rate) = self.switch(s, p, tau);
        match self.mode {
            Mode::Stick => (g, rate),
            Mode::Slip(_) if s.ct > 0.0 => (
                g,
                s.mu * (curvature + s.ct * s.g * p.rate) / s.kt + s.mu * s.g * p.force,
            ),
            Mode::Slip(_) => (g, s.mu * curvature / s.kt + s.mu * s.g * p.force),
        }
    }

    /// The switch function: the phase goes on while G ≤ 0 and ends where it turns positive.
    /// Stick: G = |k̃ũ + c̃ṽ_c| − μF̄; slip: G = μ(F̄' + c̃gF̄)/k̃ − sṽ_c (the cap then grows
    /// faster than the trial force would, whose rate on the slide is k̃ṽ_c − c̃sμgF̄). With its
    /// rate in a stick (else 0).
    fn switch(&self, s: &Scaled, p: &PathPoint, tau: f64) -> (f64, f64) {
        let (u, vc) = self.state(s, p, tau);
        match self.mode {
            Mode::Stick => Phase::stick_switch(s, p, (u, vc)),
            Mode::Slip(sg) if s.ct > 0.0 => {
                (s.mu * (p.rate + s.ct * s.g * p.force) / s.kt - sg * vc, 0.0)
            }
            Mode::Slip(sg) => (s.mu * p.rate / s.kt - sg * vc, 0.0),
        }
    }

    /// The largest |F̃_t| over the phase, exactly: while sticking k̃|ũ| with ũ harmonic (its
    /// amplitude where a crest falls inside, else an end); while sliding μF̄, and F̄ is
    /// monotone between the normal phase ends `kinks` (its peaks are unloads), so its largest
    /// value is at an end of this phase or at a kink inside it.
    /// `ends` is the normal motion at the phase's start and end.
    pub(crate) fn max_friction(
        &self,
        s: &Scaled,
        path: &impl NormalMotion,
        kinks: &[f64],
        ends: (PathPoint, PathPoint),
    ) -> f64 {
        match self.mode {
            Mode::Stick if s.ct > 0.0 => self.damped_start().max_force(s, self.end - self.start),
            Mode::Stick => {
                let w = s.omega_t;
                let (a, b) = (self.u0, self.vc0 / w);
                let len = self.end - self.start;
                let first = b.atan2(a).rem_euclid(std::f64::consts::PI) / w;
                let ends = [self.start, self.end].map(|t| {
                    let (sn, cs) = (w * (t - self.start)).sin_cos();
                    (a * cs + b * sn).abs()
                });
                let crest = if first <= len { a.hypot(b) } else { 0.0 };
                s.kt * ends[0].max(ends[1]).max(crest)
            }
            Mode::Slip(_) => {
                let inside = kinks.iter().filter(|&&k| k > self.start && k < self.end);
                let force = inside
                    .map(|&t| path.at(t).force)
                    .fold(ends.0.force.max(ends.1.force), f64::max);
                s.mu * force
            }
        }
    }
}

/// The phases of one contact, with the normal motion where each starts and at τ_f (the
/// energy and the peak friction read them again).
pub(crate) struct Run {
    pub phases: Vec<Phase>,
    pub starts: Vec<PathPoint>,
    pub end: PathPoint,
    pub vc_in: f64,
}

impl Run {
    /// The normal motion at the start and at the end of phase `i`.
    pub(crate) fn ends(&self, i: usize) -> (PathPoint, PathPoint) {
        (self.starts[i], *self.starts.get(i + 1).unwrap_or(&self.end))
    }
}

/// The search step: a fifth of the sticking oscillation's radian, and at least 32 steps over
/// the contact (the normal force's own scale; the crossings between steps are found by sign
/// changes and, while sticking, by the rate turning from rising to falling).
fn step(s: &Scaled, tf: f64) -> f64 {
    (0.2 / s.stick_rate()).min(tf / 32.0)
}

/// The search grid: τ_j = j h up to τ_f (the last point τ_f itself) and the normal motion there,
/// read once for the whole contact (`NormalMotion::grid`): every phase searches on the same
/// points, so the flow is read once a point whatever the number of phases.
pub(crate) struct Grid {
    h: f64,
    points: Vec<PathPoint>,
}

impl Grid {
    pub(crate) fn new(path: &impl NormalMotion, s: &Scaled) -> Grid {
        let h = Grid::step_of(s, path.end());
        Grid {
            h,
            points: path.grid(h),
        }
    }

    /// The step for the scaled problem `s` over a contact of τ_f.
    pub(crate) fn step_of(s: &Scaled, tf: f64) -> f64 {
        step(s, tf)
    }

    /// The grid's number of steps for `s` over a contact of τ_f (a float: it may be huge).
    pub(crate) fn steps(s: &Scaled, tf: f64) -> f64 {
        tf / step(s, tf)
    }

    /// The step.
    pub(crate) fn h(&self) -> f64 {
        self.h
    }

    /// τ of point j.
    fn tau(&self, j: usize, tf: f64) -> f64 {
        if j + 1 == self.points.len() {
            tf
        } else {
            j as f64 * self.h
        }
    }

    /// The first point after τ.
    fn after(&self, tau: f64) -> usize {
        ((tau / self.h).floor() as usize + 1).min(self.points.len() - 1)
    }
}

/// The tangential motion over the whole contact, from ṽ_c = `vc_in` at first touch, searched
/// on `grid` (the normal motion read once, `Grid::new`).
pub(crate) fn run(
    path: &impl NormalMotion,
    grid: &Grid,
    s: &Scaled,
    vc_in: f64,
) -> Result<Run, ObliqueError> {
    let tf = path.end();
    let p0 = grid.points[0];
    // at first contact F̄ = 0: the point sticks if the cap grows at least as fast as the spring;
    // with a dashpot the spring starts where the slide's reset puts it, k̃ũ + c̃ṽ_c = 0 (both
    // modes: the trial force is 0 there)
    let mode = if s.kt * vc_in.abs() <= s.mu * p0.rate {
        Mode::Stick
    } else {
        Mode::Slip(vc_in.signum())
    };
    let u0 = if s.ct > 0.0 {
        -s.ct * vc_in / s.kt
    } else {
        0.0
    };
    let mut phase = Phase {
        start: 0.0,
        end: tf,
        mode,
        u0,
        vc0: vc_in,
        vel0: p0.velocity,
    };
    let mut start_point = p0;
    let mut run = Run {
        phases: Vec::new(),
        starts: Vec::new(),
        end: *grid.points.last().expect("a grid has τ_f"),
        vc_in,
    };
    loop {
        if run.phases.len() >= MAX_PHASES {
            return Err(ObliqueError::Phases);
        }
        let switch = find_switch(path, grid, s, &phase, &start_point, tf);
        let Some(t) = switch.filter(|&t| t < tf) else {
            phase.end = tf;
            run.phases.push(phase);
            run.starts.push(start_point);
            return Ok(run);
        };
        phase.end = t;
        run.phases.push(phase);
        run.starts.push(start_point);
        let p = path.at(t);
        start_point = p;
        let (u, vc) = phase.state(s, &p, t);
        phase = match phase.mode {
            Mode::Stick => {
                // the trial force's sign: k̃ũ + c̃ṽ_c (k̃ũ alone without a dashpot)
                let f = if s.ct > 0.0 { s.kt * u + s.ct * vc } else { u };
                let sg = if f == 0.0 { vc.signum() } else { f.signum() };
                Phase {
                    start: t,
                    end: tf,
                    mode: Mode::Slip(sg),
                    u0: slip_spring(s, sg, p.force, vc),
                    vc0: vc,
                    vel0: p.velocity,
                }
            }
            Mode::Slip(_) => Phase {
                start: t,
                end: tf,
                mode: Mode::Stick,
                u0: u,
                vc0: vc,
                vel0: p.velocity,
            },
        };
    }
}
