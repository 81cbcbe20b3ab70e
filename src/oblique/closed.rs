//! The linear law's normal motion in closed form, phase by phase: what an oblique impact is
//! driven by (docs/oblique.md §2), read from two exponentials and a sine at any τ, without the
//! exact solver's propagators and search (issue 31, "Speed").
//!
//! In a phase of slope k (1 while loading, F̄_m/(z̄_m − z̄_f) while unloading) the state
//! w = (z̄ − s, ᾱ', ȳ) solves w' = A(k) w (src/solver/exact/mod.rs), so each component solves
//! the phase's cubic s³ + 2ζ(k + λ)s² + k s + 2ζkλ = 0. With r its real root and
//! s² + 2σs + σ² + ω² the factor of an oscillating pair (ω² > 0), each component is
//!
//! ```text
//! f(δ) = c_r e^{rδ} + e^{−σδ}(c_c cos ωδ + c_s sin(ωδ)/ω),   δ = τ − τ_start,
//! c_r = (f'' + 2σf' + (σ² + ω²) f)/((r + σ)² + ω²),  c_c = f − c_r,  c_s = f' − r c_r + σ c_c,
//! ```
//!
//! from f, f', f'' at the phase's start (docs/model.md §5: ᾱ'' = −F̄, ȳ' = 2ζ(F̄ − λȳ),
//! z̄ = ᾱ − ȳ). Loading starts from z̄ = (0, 1, −2ζ), ᾱ' = (1, 0, −1), ȳ = (0, 0, 2ζ). At the
//! unload the state and F̄ carry over; of the second derivatives, ȳ'' = 2ζ(F̄' − λȳ') moves
//! by 2ζ(k − 1) z̄' as F̄' = k z̄' changes slope (z̄' = 0 there but for rounding), z̄'' by the
//! opposite. The events — τ_m where z̄' falls through 0, τ_f where z̄ − z̄_f does — are
//! bracketed by steps of 1.5 time constants of the fastest mode (the exact solver's step
//! rule: one extremum a step at most) and found by Halley's method.
//!
//! Where this does not hold — a pair that does not oscillate, a reload, an extremum inside a
//! step that might hide a crossing, a rounding bound above 1e-13 of the COR or F̄_m —
//! `ClosedPath::solve` returns `None` and the exact solver runs (`NormalAt`).
//! `the_closed_form_is_the_exact_flow` (src/oblique/tests.rs) holds the two together.

use super::modes::{Modes, Rows, SHORT, START};
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::ImpactParams;
use crate::solver::exact::PathPoint;
use crate::solver::roots::halley_bracketed_from;
use crate::solver::{EventKind, ImpactResponse, Method, Outcome, to_si};

/// Most bracketing steps of one event.
const MAX_STEPS: usize = 64;
/// The relative precision the closed form must keep by its rounding bound, as the map's fast
/// summary does (src/map/fast/mod.rs): the exact solver keeps 1e-12.
const KEEP: f64 = 1e-13;
/// Grid steps taken by the step's rotation before the basis is read exactly again (each step's
/// rounding is relative to the basis: sixteen keep it near 1e-15, as `NormalPath::grid`).
const EXACT_EVERY: usize = 16;

/// One phase: where it starts and ends (τ), its slope, modes, and z̄ − s and ᾱ' as rows.
#[derive(Debug, Clone)]
struct Part {
    start: f64,
    end: f64,
    k: f64,
    modes: Modes,
    z: Rows,
    v: Rows,
}

impl Part {
    /// F̄, F̄', ᾱ' at a basis, and F̄''.
    fn point(&self, b: &[f64; 3]) -> (PathPoint, f64) {
        (self.motion(b), self.k * self.z.at(2, b))
    }

    /// F̄, F̄', ᾱ' at a basis.
    fn motion(&self, b: &[f64; 3]) -> PathPoint {
        PathPoint {
            force: (self.k * self.z.at(0, b)).max(0.0),
            rate: self.k * self.z.at(1, b),
            velocity: self.v.at(0, b),
        }
    }

    /// The basis at τ (clamped to the phase).
    fn basis(&self, tau: f64) -> [f64; 3] {
        self.modes
            .basis((tau - self.start).clamp(0.0, self.end - self.start))
    }
}

/// The normal motion of a linear-law impact in closed form: loading, then unloading.
#[derive(Debug, Clone)]
pub struct ClosedPath {
    parts: [Part; 2],
}

/// The first δ > 0 where g falls through 0 (g(0) = `g0` > 0 with rate `d0`), with (g, g', g'')
/// from `g`: bracketed by steps of `step`, found by Halley's method. `None` where a step ends
/// with g rising after falling (a minimum inside may hide a crossing), where `no_rise` and a
/// step ends with g' > 0 or g'' turning from positive to negative (a reload may come), or
/// where none comes within `MAX_STEPS`. Counts the evaluations in `evals`.
fn first_fall(
    g: impl Fn(f64) -> (f64, f64, f64),
    (g0, d0, dd0): (f64, f64, f64),
    step: f64,
    no_rise: bool,
    evals: &mut usize,
) -> Option<f64> {
    let (mut a, mut ga, mut da, mut dda) = (0.0, g0, d0, dd0);
    for _ in 0..MAX_STEPS {
        let b = a + step;
        let (gb, db, ddb) = g(b);
        *evals += 1;
        if !(gb.is_finite() && db.is_finite() && ddb.is_finite()) {
            return None;
        }
        if gb <= 0.0 {
            let mut count = 0;
            let t = halley_bracketed_from(
                |t| {
                    count += 1;
                    g(t)
                },
                (a, ga),
                (b, gb),
            );
            *evals += count;
            return Some(t);
        }
        if (da < 0.0 && db > 0.0) || (no_rise && (db > 0.0 || (dda > 0.0 && ddb < 0.0))) {
            return None;
        }
        (a, ga, da, dda) = (b, gb, db, ddb);
    }
    None
}

impl ClosedPath {
    /// The normal impact of `params` (v0 the normal speed) on the linear law, as `run` gives
    /// it, and its motion; `None` where the closed form does not answer (the module's
    /// introduction says where) and the exact solver must.
    pub(crate) fn solve(params: &ImpactParams) -> Option<(ImpactResponse, ClosedPath)> {
        let n = params.normalized();
        let (lambda, zeta) = (n.lambda, n.zeta);
        if !(lambda >= 0.0 && zeta > 0.0 && lambda.is_finite() && zeta.is_finite()) {
            return None;
        }
        let mut evals = 0;
        let load = Modes::new(lambda, zeta, 1.0)?;
        let z = load.rows([0.0, 1.0, -2.0 * zeta]);
        let v = load.rows([1.0, 0.0, -1.0]);
        let y = load.rows([0.0, 0.0, 2.0 * zeta]);
        let rate = |d: f64| {
            let b = load.basis(d);
            (z.at(1, &b), z.at(2, &b), z.at(3, &b))
        };
        let tau_m = first_fall(
            rate,
            (1.0, z.at(2, &START), z.at(3, &START)),
            1.5 / load.fastest(),
            false,
            &mut evals,
        )?;
        let b = load.basis(tau_m);
        let (z_m, dz) = (z.at(0, &b), z.at(1, &b));
        let contact = Contact {
            law: ContactLaw::Linear,
            zp_bar: n.zp_bar,
            kappa: n.kappa,
        };
        let u = contact.unload_from(z_m);
        if !(u.z_m > u.z_f && u.f_m > 0.0) {
            return None;
        }
        // without flattening the unloading line is the loading one: k = z̄_m/z̄_m = 1 exactly
        let k = u.f_m / (u.z_m - u.z_f);
        let unload = if k == 1.0 {
            load
        } else {
            Modes::new(lambda, zeta, k)?
        };
        let jump = 2.0 * zeta * (k - 1.0) * dz;
        let z2 = unload.rows([z_m - u.z_f, dz, z.at(2, &b) - jump]);
        let v2 = unload.rows([v.at(0, &b), -u.f_m, -k * dz]);
        let y2 = unload.rows([y.at(0, &b), y.at(1, &b), y.at(2, &b) + jump]);
        let gap = |d: f64| {
            let b = unload.basis(d);
            (z2.at(0, &b), z2.at(1, &b), z2.at(2, &b))
        };
        let start = (z_m - u.z_f, dz, z2.at(2, &START));
        let len = first_fall(gap, start, 1.5 / unload.fastest(), true, &mut evals)?;
        let b2 = unload.basis(len);
        let velocity_end = v2.at(0, &b2);
        let cor = -velocity_end;
        // what each answer's rounding may be, against what it must keep
        let dv = v.rounding(&load, tau_m, &b) + v2.rounding(&unload, len, &b2);
        let dz_m = z.rounding(&load, tau_m, &b);
        if !(cor > 0.0 && dv <= KEEP * cor && dz_m <= KEEP * z_m) {
            return None;
        }
        let tau_f = tau_m + len;
        let parts = [
            Part {
                start: 0.0,
                end: tau_m,
                k: 1.0,
                modes: load,
                z,
                v,
            },
            Part {
                start: tau_m,
                end: tau_f,
                k,
                modes: unload,
                z: z2,
                v: v2,
            },
        ];
        let ends = Outcome {
            rebound: true,
            tau_end: tau_f,
            velocity_end,
            y_end: y2.at(0, &b2),
            f_max: z_m,
            z_max: z_m,
            z_f: u.z_f,
            steps: evals,
            ..Outcome::default()
        };
        let z_end = z2.at(0, &b2) + u.z_f;
        Some((response(params, ends, (tau_m, z_end)), ClosedPath { parts }))
    }

    /// The phase holding τ: at a boundary, the one that ends there (as `NormalPath::at`).
    fn part(&self, tau: f64) -> &Part {
        if tau <= self.parts[0].end {
            &self.parts[0]
        } else {
            &self.parts[1]
        }
    }

    /// The normal motion at τ (clamped to [0, τ_f]) and F̄'' there.
    pub fn with_curvature(&self, tau: f64) -> (PathPoint, f64) {
        let part = self.part(tau);
        self.separated(tau, part.point(&part.basis(tau)))
    }

    /// F̄ = 0 from τ_f on: separation is where it returns to 0 (the root's z̄ − z̄_f is 0 but
    /// for rounding, which would read as a force of a few ε).
    fn separated(&self, tau: f64, (mut p, curvature): (PathPoint, f64)) -> (PathPoint, f64) {
        if tau >= self.parts[1].end {
            p.force = 0.0;
        }
        (p, curvature)
    }

    /// The motion on [a, b], read from the basis at a turned by `Modes::basis_short` where
    /// [a, b] lies inside one phase and is short against its modes; else read anywhere.
    pub fn near(&self, a: f64, b: f64) -> Near<'_> {
        let i = usize::from(a > self.parts[0].end);
        let part = &self.parts[i];
        let inside = a >= part.start && b <= part.end;
        let short = part.modes.fastest() * (b - a) <= SHORT;
        let anchor = (inside && short).then(|| (i, a, b, part.basis(a)));
        Near { path: self, anchor }
    }
}

/// `ClosedPath::near`: the path, and the phase, the bracket and the basis at its start.
#[derive(Debug, Clone, Copy)]
pub struct Near<'a> {
    path: &'a ClosedPath,
    anchor: Option<(usize, f64, f64, [f64; 3])>,
}

impl Near<'_> {
    /// The normal motion at τ and F̄'' there.
    pub fn with_curvature(&self, tau: f64) -> (PathPoint, f64) {
        match self.anchor {
            Some((i, a, b, basis)) if tau >= a && tau <= b => {
                let part = &self.path.parts[i];
                let turn = part.modes.basis_short(tau - a);
                let p = part.point(&part.modes.step(&basis, &turn));
                self.path.separated(tau, p)
            }
            _ => self.path.with_curvature(tau),
        }
    }
}

impl super::NormalMotion for ClosedPath {
    fn at(&self, tau: f64) -> PathPoint {
        self.with_curvature(tau).0
    }
    fn end(&self) -> f64 {
        self.parts[1].end
    }
    fn kinks(&self) -> Vec<f64> {
        self.parts.iter().map(|p| p.end).collect()
    }
    /// The grid stepped: each phase's basis read exactly at its first point, every
    /// `EXACT_EVERY` steps and at τ_f, turned by `Modes::step` in between (a few
    /// multiplications a point).
    fn grid(&self, h: f64) -> Vec<PathPoint> {
        let tf = self.end();
        let n = (tf / h).ceil().max(1.0) as usize;
        let mut points = Vec::with_capacity(n + 1);
        let mut j = 0;
        for (i, part) in self.parts.iter().enumerate() {
            // the step's basis by its series where the step is short against the modes
            let turn = if part.modes.fastest() * h <= SHORT {
                part.modes.basis_short(h)
            } else {
                part.modes.basis(h)
            };
            let (mut b, mut since) = ([0.0; 3], EXACT_EVERY);
            // this phase's points: τ_j up to its end (the first), up to τ_f (the last)
            while j <= n {
                let tau = if j == n { tf } else { j as f64 * h };
                if i == 0 && tau > part.end {
                    break;
                }
                b = if since >= EXACT_EVERY || j == n {
                    since = 0;
                    part.basis(tau)
                } else {
                    since += 1;
                    part.modes.step(&b, &turn)
                };
                let p = part.motion(&b);
                points.push(if j == n {
                    PathPoint { force: 0.0, ..p }
                } else {
                    p
                });
                j += 1;
            }
        }
        points
    }
    fn local(&self, a: f64, b: f64) -> Option<super::Local<'_>> {
        Some(super::Local::Closed(self.near(a, b)))
    }
}

/// The response as the exact solver's run gives it: the normalized outcome `o` (no energy
/// audit, no samples) with its unload at (τ_m, z̄_m) and its separation at (τ_f, `z_end`),
/// turned into SI by the solver's own conversion (`solver::to_si`).
fn response(p: &ImpactParams, mut o: Outcome, (tau_m, z_end): (f64, f64)) -> ImpactResponse {
    o.event(tau_m, EventKind::Unload, o.z_max);
    o.event(o.tau_end, EventKind::Separation, z_end);
    to_si(p, p.normalized(), ContactLaw::Linear, Method::Exact, o)
}
