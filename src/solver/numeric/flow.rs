//! The adaptive run's flow read at any τ: what the oblique impact's tangential motion is driven
//! by for any contact law (docs/oblique.md §2), as `exact::NormalPath` is for the linear one.
//!
//! The run keeps the end (τ, x) of every accepted step of every phase, with the contact
//! branch in force (`Kept`). Between two such knots the force is the cubic Hermite
//! interpolant of F̄ and F̄' = (dF̄/dz̄) z̄' at the two ends — the model's force and rate,
//! exact at every knot — and the ball's speed is ᾱ' at the phase's start minus the exact
//! integral of that cubic: F̄, F̄' and ᾱ' are one consistent motion (ᾱ'' = −F̄ holds to
//! rounding, which the tangential closed forms and their energy balance rest on). Between
//! knots F̄ is good to the interpolation error, O(h⁴ F̄⁗) for a step h (tests/physics/oblique_laws.rs
//! holds the linear law's numeric flow against its exact one).

use super::X;
use super::impact::{Impact, Phase};
use crate::model::contact::ContactLaw;
use crate::solver::exact::PathPoint;

/// One phase as kept: its branch and the knots from its start to its end.
pub(super) struct Kept {
    pub imp_phase: Phase,
    pub knots: Vec<(f64, X)>,
}

/// One step of the flow: [τa, τb], the cubic Hermite data of F̄ at its ends, and ᾱ' and
/// ᾱ = z̄ + ȳ at τa (the integrator's state at the knot).
#[derive(Debug, Clone, Copy)]
struct Piece {
    ta: f64,
    tb: f64,
    fa: f64,
    fb: f64,
    /// dF̄/dτ at the ends.
    da: f64,
    db: f64,
    va: f64,
    aa: f64,
}

impl Piece {
    /// The Hermite basis at s ∈ [0, 1], h = τb − τa: (F̄, dF̄/dτ, ∫_τa^τ F̄).
    fn eval(&self, tau: f64) -> (f64, f64, f64) {
        let h = self.tb - self.ta;
        if h <= 0.0 {
            return (self.fa, self.da, 0.0);
        }
        let s = ((tau - self.ta) / h).clamp(0.0, 1.0);
        let (s2, s3) = (s * s, s * s * s);
        let (ma, mb) = (self.da * h, self.db * h);
        let f = (2.0 * s3 - 3.0 * s2 + 1.0) * self.fa
            + (s3 - 2.0 * s2 + s) * ma
            + (-2.0 * s3 + 3.0 * s2) * self.fb
            + (s3 - s2) * mb;
        let df = ((6.0 * s2 - 6.0 * s) * self.fa
            + (3.0 * s2 - 4.0 * s + 1.0) * ma
            + (-6.0 * s2 + 6.0 * s) * self.fb
            + (3.0 * s2 - 2.0 * s) * mb)
            / h;
        let s4 = s2 * s2;
        let int = h
            * ((s4 / 2.0 - s3 + s) * self.fa
                + (s4 / 4.0 - 2.0 * s3 / 3.0 + s2 / 2.0) * ma
                + (-s4 / 2.0 + s3) * self.fb
                + (s4 / 4.0 - s3 / 3.0) * mb);
        (f, df, int)
    }

    /// ᾱ at τ in the piece: ᾱ(τa) + ᾱ'(τa)(τ − τa) − ∫_τa^τ ∫_τa^σ F̄, the Hermite cubic
    /// integrated twice (the antiderivative of `eval`'s integral).
    fn displacement(&self, tau: f64) -> f64 {
        let h = self.tb - self.ta;
        if h <= 0.0 {
            return self.aa;
        }
        let s = ((tau - self.ta) / h).clamp(0.0, 1.0);
        let (s2, s3) = (s * s, s * s * s);
        let (s4, s5) = (s2 * s2, s2 * s3);
        let (ma, mb) = (self.da * h, self.db * h);
        let int2 = h
            * h
            * ((s5 / 10.0 - s4 / 4.0 + s2 / 2.0) * self.fa
                + (s5 / 20.0 - s4 / 6.0 + s3 / 6.0) * ma
                + (-s5 / 10.0 + s4 / 4.0) * self.fb
                + (s5 / 20.0 - s4 / 12.0) * mb);
        self.aa + self.va * s * h - int2
    }
}

/// dF̄/dz̄ on the branch in force, taken from inside the contact where the branch ends (first
/// touch z̄ = 0, separation z̄ = z̄_f): there `Impact::stiffness` is 0, the slope of no force,
/// while the flow's rate at its ends is the contact's (1 for the linear law at first touch,
/// F̄_m/(z̄_m − z̄_f) at its separation; 0 for a 3/2-power branch, whose slope vanishes there).
fn inside_stiffness(imp: &Impact, z: f64) -> f64 {
    let c = &imp.contact;
    match imp.phase {
        Phase::Loading if z <= 0.0 => c.loading_stiffness(f64::MIN_POSITIVE),
        Phase::Unloading(u) if z <= u.z_f && c.law == ContactLaw::Linear && u.z_m > u.z_f => {
            u.f_m / (u.z_m - u.z_f)
        }
        _ => imp.stiffness(z),
    }
}

/// The flow of an adaptive run over [0, τ_f], step by step.
#[derive(Debug, Clone)]
pub struct NumericPath {
    pieces: Vec<Piece>,
    /// τ where each phase of the run ends (unload, yield, reload, separation).
    phase_ends: Vec<f64>,
}

impl NumericPath {
    /// The flow of the kept phases, the run starting at ᾱ' = 1.
    pub(super) fn new(imp: &Impact, kept: &[Kept]) -> NumericPath {
        let mut pieces: Vec<Piece> = Vec::new();
        let mut phase_ends = Vec::new();
        let mut v = 1.0;
        for k in kept {
            let probe = Impact {
                lambda: imp.lambda,
                zeta: imp.zeta,
                contact: imp.contact,
                phase: k.imp_phase,
            };
            let point = |x: &X| {
                let (f, ydot) = probe.force_and_rate(x);
                (f, inside_stiffness(&probe, x[0]) * (x[1] - ydot))
            };
            for pair in k.knots.windows(2) {
                let ((ta, xa), (tb, xb)) = (pair[0], pair[1]);
                if tb <= ta {
                    continue;
                }
                let ((fa, da), (fb, db)) = (point(&xa), point(&xb));
                let piece = Piece {
                    ta,
                    tb,
                    fa,
                    fb,
                    da,
                    db,
                    va: v,
                    aa: xa[0] + xa[2],
                };
                v -= piece.eval(tb).2;
                pieces.push(piece);
            }
            if let Some(&(t, _)) = k.knots.last() {
                phase_ends.push(t);
            }
        }
        NumericPath { pieces, phase_ends }
    }

    /// τ_f, the end of the last step.
    pub fn end(&self) -> f64 {
        self.pieces.last().map_or(0.0, |p| p.tb)
    }

    /// τ where each step ends, in order: F̄'' may jump there, and F̄' where a phase ends.
    pub fn boundaries(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces.iter().map(|p| p.tb)
    }

    /// τ where each phase of the run ends, in order.
    pub fn phase_ends(&self) -> &[f64] {
        &self.phase_ends
    }

    /// The number of steps.
    pub fn steps(&self) -> usize {
        self.pieces.len()
    }

    /// The ball's largest displacement toward the wall, ᾱ_max: at the zero of ᾱ', where ᾱ
    /// peaks (ᾱ'' = −F̄ ≤ 0: ᾱ' only falls, `exact::NormalPath::peak_displacement`), located by
    /// safeguarded Newton inside the first step that ends with ᾱ' ≤ 0, ᾱ there read on the
    /// step's cubic integrated twice from the integrator's state at its start; at τ_f when
    /// the ball never turns. Good to the integrator's tolerance.
    pub fn peak_displacement(&self) -> f64 {
        let turn = self.pieces.iter().find(|p| p.va - p.eval(p.tb).2 <= 0.0);
        let Some(p) = turn.or(self.pieces.last()) else {
            return 0.0;
        };
        let end = p.va - p.eval(p.tb).2;
        if end > 0.0 {
            return p.displacement(p.tb);
        }
        let tau = crate::solver::roots::newton_bracketed(
            |t| {
                let (f, _, int) = p.eval(t);
                (p.va - int, -f)
            },
            p.ta,
            p.tb,
        );
        p.displacement(tau)
    }

    /// The normal motion at τ (clamped to [0, τ_f]); at a step's end, the step that ends there.
    pub fn at(&self, tau: f64) -> PathPoint {
        let Some(last) = self.pieces.len().checked_sub(1) else {
            return PathPoint {
                force: 0.0,
                rate: 0.0,
                velocity: 1.0,
            };
        };
        let i = self.pieces.partition_point(|p| p.tb < tau).min(last);
        let piece = &self.pieces[i];
        let (f, df, int) = piece.eval(tau);
        PathPoint {
            force: f.max(0.0),
            rate: df,
            velocity: piece.va - int,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Hermite cubic reproduces a cubic exactly, its rate is its derivative and its
    /// integral its antiderivative.
    #[test]
    fn a_piece_is_exact_on_a_cubic() {
        let f = |t: f64| 1.0 + 2.0 * t - 0.5 * t * t + 0.3 * t * t * t;
        let df = |t: f64| 2.0 - t + 0.9 * t * t;
        let int = |t: f64| t + t * t - t * t * t / 6.0 + 0.075 * t.powi(4);
        let (ta, tb) = (0.4, 1.3);
        let p = Piece {
            ta,
            tb,
            fa: f(ta),
            fb: f(tb),
            da: df(ta),
            db: df(tb),
            va: 0.0,
            aa: 0.0,
        };
        for t in [0.4, 0.55, 0.9, 1.21, 1.3] {
            let (pf, pd, pi) = p.eval(t);
            assert!((pf - f(t)).abs() < 1e-14, "{t}");
            assert!((pd - df(t)).abs() < 1e-13, "{t}");
            assert!((pi - (int(t) - int(ta))).abs() < 1e-14, "{t}");
        }
    }
}
