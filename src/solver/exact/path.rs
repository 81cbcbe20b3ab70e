//! The exact run's flow read at any τ: the normal force F̄, its rate F̄' and the ball's speed
//! ᾱ', which the oblique impact's tangential motion is driven by (docs/oblique.md §2). Each
//! phase keeps its anchored propagators, so a reading costs one propagator evaluation.

use super::search::eval_anchored;
use super::{Segment, l};
use nalgebra::{Matrix3, Vector3};

/// How many grid steps [`NormalPath::grid`] takes by its step matrix before reading the flow
/// exactly again (each step's rounding is relative to the state: sixteen keep it near 1e-15).
const EXACT_EVERY: usize = 16;

/// Most terms of a power series of the flow ([`NormalPath::local`], the grid's step matrix).
const MAX_TERMS: usize = 40;

/// Σ Mⁿ hⁿ/n! while ‖M h‖∞ ≤ 1 and the terms fall below 1e-18 of the first (a 3×3 flow over
/// one grid step: `None` beyond, and the propagator reads it instead).
fn series_exp(m: &Matrix3<f64>, h: f64) -> Option<Matrix3<f64>> {
    let mh = m * h;
    // NaN-aware: a NaN norm takes the propagator too
    if norm_inf(&mh).is_nan() || norm_inf(&mh) > 1.0 {
        return None;
    }
    let mut term = Matrix3::identity();
    let mut sum = term;
    for n in 1..MAX_TERMS {
        term = term * mh / n as f64;
        sum += term;
        if norm_inf(&term) < 1e-18 {
            return Some(sum);
        }
    }
    None
}

/// The ∞-norm (largest row sum of magnitudes) of a 3×3 matrix.
fn norm_inf(m: &Matrix3<f64>) -> f64 {
    m.row_iter()
        .map(|r| r.iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// The normal motion on [τ_a, τ_a + δ_max] inside one phase as power series in δ = τ − τ_a,
/// from the exact state at τ_a: w(τ_a + δ) = Σ Aⁿ w(τ_a) δⁿ/n! (the phase's flow is linear),
/// summed until the terms fall below 1e-18 of the state. A reading is a few dozen
/// multiply-adds where the propagator takes three exponentials: the oblique impact's root
/// finding reads the flow here (src/oblique/tangential.rs).
#[derive(Debug, Clone)]
pub struct LocalFlow {
    tau0: f64,
    k: f64,
    /// The coefficients of z̄ − s (F̄/k before the clamp at 0) and of ᾱ'.
    z: [f64; MAX_TERMS],
    v: [f64; MAX_TERMS],
    terms: usize,
}

impl LocalFlow {
    /// The normal motion at τ (in [τ_a, τ_a + δ_max]).
    pub fn at(&self, tau: f64) -> PathPoint {
        self.at_with_curvature(tau).0
    }

    /// The normal motion at τ and F̄'' there (the series differentiated twice).
    pub fn at_with_curvature(&self, tau: f64) -> (PathPoint, f64) {
        let d = tau - self.tau0;
        let (mut z, mut dz, mut d2z, mut v) = (0.0, 0.0, 0.0, 0.0);
        for n in (0..self.terms).rev() {
            let (c, nf) = (self.z[n], n as f64);
            z = z * d + c;
            v = v * d + self.v[n];
            if n > 0 {
                dz = dz * d + nf * c;
            }
            if n > 1 {
                d2z = d2z * d + nf * (nf - 1.0) * c;
            }
        }
        let p = PathPoint {
            force: (self.k * z).max(0.0),
            rate: self.k * dz,
            velocity: v,
        };
        (p, self.k * d2z)
    }
}

/// The normal motion at one τ, normalized (docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathPoint {
    /// F̄ = F/(m v0 ω0), ≥ 0.
    pub force: f64,
    /// dF̄/dτ.
    pub rate: f64,
    /// ᾱ' = α'/v0, the speed toward the wall (1 at τ = 0, −e at separation).
    pub velocity: f64,
}

/// The flow of a solved linear-law impact over [0, τ_f], phase by phase.
pub struct NormalPath {
    segments: Vec<Segment>,
    /// The third state's scale σ (`y_scale`): w = (z̄ − s, ᾱ', σȳ).
    sigma: f64,
}

impl NormalPath {
    pub(super) fn new(segments: Vec<Segment>, sigma: f64) -> NormalPath {
        NormalPath { segments, sigma }
    }

    /// The ball's largest displacement toward the wall, ᾱ_max = max (z̄ + ȳ), read exactly
    /// off the flow. Why at ᾱ' = 0: ᾱ'' = −F̄ ≤ 0 through the contact, so ᾱ' falls from 1 and
    /// ᾱ rises while ᾱ' > 0 and falls after — its one peak is the zero of ᾱ', located by
    /// safeguarded Newton on (ᾱ', −F̄) inside the first phase that ends with ᾱ' ≤ 0. A ball
    /// that never turns (it sinks into the dashpot, no rebound) peaks at τ_f.
    pub fn peak_displacement(&self) -> f64 {
        let turn = self.segments.iter().enumerate().find_map(|(i, seg)| {
            let end = seg.start + seg.len;
            (self.at_in(i, end).velocity <= 0.0).then_some((i, seg.start, end))
        });
        let Some((i, a, b)) = turn else {
            let last = self.segments.len().saturating_sub(1);
            return self.displacement_in(last, self.end());
        };
        let tau = crate::solver::roots::newton_bracketed(
            |t| {
                let p = self.at_in(i, t);
                (p.velocity, -p.force)
            },
            a,
            b,
        );
        self.displacement_in(i, tau)
    }

    /// ᾱ = z̄ + ȳ at τ read on phase `i` (τ clamped to the phase); 0 with no phase.
    fn displacement_in(&self, i: usize, tau: f64) -> f64 {
        let Some(seg) = self.segments.get(i) else {
            return 0.0;
        };
        let (w, _) = eval_anchored(&seg.anchors, (tau - seg.start).clamp(0.0, seg.len));
        l(&w) + seg.s + w[2] / self.sigma
    }

    /// τ where each phase ends (unload, reload, separation), in order: F̄' may jump there.
    pub fn boundaries(&self) -> impl Iterator<Item = f64> + '_ {
        self.segments.iter().map(|s| s.start + s.len)
    }

    /// τ_f, the end of the last phase.
    pub fn end(&self) -> f64 {
        self.segments.last().map_or(0.0, |s| s.start + s.len)
    }

    /// The normal motion at τ (clamped to [0, τ_f]); at a phase boundary, the phase that
    /// ends there.
    pub fn at(&self, tau: f64) -> PathPoint {
        let i = self
            .segments
            .partition_point(|s| s.start + s.len < tau)
            .min(self.segments.len().saturating_sub(1));
        self.at_in(i, tau)
    }

    /// The normal motion at τ read on phase `i` (τ clamped to the phase).
    pub fn at_in(&self, i: usize, tau: f64) -> PathPoint {
        let seg = &self.segments[i];
        let (w, dw) = eval_anchored(&seg.anchors, (tau - seg.start).clamp(0.0, seg.len));
        PathPoint {
            force: (seg.k * l(&w)).max(0.0),
            rate: seg.k * l(&dw),
            velocity: w[1],
        }
    }

    /// The motion at τ_j = j h for j = 0, 1, … while j h < τ_f, then at τ_f, as [`Self::at`]
    /// reads it but stepped: w(τ + h) = e^{A h} w(τ) with e^{A h} read once per phase from its
    /// propagator, the flow read exactly at each phase's first point, every
    /// `EXACT_EVERY` steps and at τ_f. The oblique impact's search grid (src/oblique/): a
    /// point costs a 3×3 product instead of a propagator's exponentials.
    pub fn grid(&self, h: f64) -> Vec<PathPoint> {
        let tf = self.end();
        let n = (tf / h).ceil().max(1.0) as usize;
        let mut points = Vec::with_capacity(n + 1);
        let mut i = 0;
        // (phase, its step matrix and matrix, the state and steps since it was read exactly)
        let mut stepper: Option<(usize, Matrix3<f64>, Matrix3<f64>)> = None;
        let mut w = Vector3::zeros();
        let mut since = 0;
        for j in 0..=n {
            let tau = if j == n { tf } else { j as f64 * h };
            while i + 1 < self.segments.len() && self.segments[i].start + self.segments[i].len < tau
            {
                i += 1;
            }
            let seg = &self.segments[i];
            let same = stepper.as_ref().is_some_and(|(k, _, _)| *k == i);
            if !same || since >= EXACT_EVERY || j == n {
                w = eval_anchored(&seg.anchors, (tau - seg.start).clamp(0.0, seg.len)).0;
                since = 0;
                if !same {
                    let p = &seg.anchors[0].1;
                    let phi = series_exp(p.matrix(), h).unwrap_or_else(|| {
                        let col = |k: usize| p.restart(Vector3::ith(k, 1.0)).eval(h).0;
                        Matrix3::from_columns(&[col(0), col(1), col(2)])
                    });
                    stepper = Some((i, phi, *p.matrix()));
                }
            } else if let Some((_, phi, _)) = &stepper {
                w = phi * w;
                since += 1;
            }
            let a = stepper.as_ref().map_or(Matrix3::zeros(), |s| s.2);
            let dw = a * w;
            points.push(PathPoint {
                force: (seg.k * l(&w)).max(0.0),
                rate: seg.k * l(&dw),
                velocity: w[1],
            });
        }
        points
    }

    /// The motion on [a, b] as power series ([`LocalFlow`]), when [a, b] lies inside one phase
    /// and the series converges fast there (‖A‖∞ (b − a) ≤ 1); `None` otherwise.
    pub fn local(&self, a: f64, b: f64) -> Option<LocalFlow> {
        let i = self.segments.partition_point(|s| s.start + s.len < a);
        let seg = self.segments.get(i)?;
        if a < seg.start || b > seg.start + seg.len {
            return None;
        }
        let (t0, p) = {
            let j = seg
                .anchors
                .partition_point(|(t0, _)| *t0 <= a - seg.start)
                .saturating_sub(1);
            (seg.anchors[j].0, &seg.anchors[j].1)
        };
        let m = p.matrix();
        let len = b - a;
        let reach = norm_inf(m) * len;
        if reach.is_nan() || reach > 1.0 {
            return None;
        }
        let (w, _) = p.eval(a - seg.start - t0);
        let scale = w.amax();
        let mut c = w;
        let mut out = LocalFlow {
            tau0: a,
            k: seg.k,
            z: [0.0; MAX_TERMS],
            v: [0.0; MAX_TERMS],
            terms: 0,
        };
        for n in 0..MAX_TERMS {
            out.z[n] = c[0];
            out.v[n] = c[1];
            out.terms = n + 1;
            // the next terms fall at least by ‖A‖∞ (b − a)/(n + 1) ≤ 1/(n + 1) each
            if c.amax() * len.powi(n as i32) <= 1e-18 * scale {
                return Some(out);
            }
            c = m * c / (n + 1) as f64;
        }
        None
    }

    /// The number of phases.
    pub fn phases(&self) -> usize {
        self.segments.len()
    }

    /// Where phase `i` starts and ends (τ).
    pub fn phase(&self, i: usize) -> (f64, f64) {
        let s = &self.segments[i];
        (s.start, s.start + s.len)
    }
}
