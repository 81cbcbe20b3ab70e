//! An independent summary of a stiff impact under the Hertz or elastic–plastic law (issue 54
//! item 10): COR, F̄_m, τ_f, z̄_m, z̄_f and ȳ at separation by an implicit method, stable
//! whatever the dashpot's rate 2ζ(k + λ) (`extrapolation`: the linearly implicit Euler
//! method, extrapolated), and so independent of the explicit Taylor steps. It is the reference the stiff cells' fast answers
//! (`taylor::stiff_summary`, explicit steps in their thousands) are held to in
//! tests/physics/map_stiff.rs: the adaptive solver's stiff runs are good to 1e-6 only
//! (docs/numerics.md), too loose to check 1e-9 by. Not a fast path: in the mildly stiff range
//! of the maps (the rate a few hundred to some 10⁴ times the contact's) the extrapolated
//! Euler steps lose their order to the stiff transient and take ~10³ steps at 1e-12; the map's
//! corner took 7.7 s CPU on it against 5.4 s by the adaptive solver, so it was not wired in.
//!
//! The phases are those of the Taylor steps, in the normalized units of docs/model.md §5:
//!
//! - a 3/2-power branch (the Hertz loading from first touch, the elastic–plastic unloading of
//!   Eq. 12) in the variable σ with dτ = s dσ, where z̄ = z̄₀ + b s², F̄ = a s³ and the system
//!   is polynomial, smooth through first touch and separation (`Branch`):
//!
//!   ```text
//!       ds/dσ = (ᾱ' − 2ζ(a s³ − λȳ))/(2b),   dᾱ'/dσ = −a s⁴,
//!       dȳ/dσ = 2ζ s (a s³ − λȳ),            dτ/dσ = s;
//!   ```
//!
//!   separation is the simple zero s = 0, where ᾱ', ȳ and τ stand still to first order (their
//!   rates carry a factor s), so it is found to the rounding of the state; the turn
//!   (ds/dσ = 0) is a maximum of s, so z̄_m = z̄₀ + b s_max² is found to the square of its
//!   place's error;
//! - the elastic–plastic straight stretch (Eq. 11, slope 1 in these units) in τ, a linear
//!   system (`Stretch`), from yield (s = √z̄_p) to the turn.
//!
//! `None` where the impact leaves that path (it reloads, turns twice, runs out of steps or
//! does not leave).

mod extrapolation;

use super::taylor::Summary;
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;
use extrapolation::{System, Tolerance, X};

/// The steps' tolerance, relative and absolute (the normalized states are of order one): the
/// answer then meets the Taylor steps to some 1e-11 (tests/physics/map_stiff.rs), inside the
/// 1e-9 the fast paths promise against the adaptive solver (docs/numerics.md).
const TOL: Tolerance = Tolerance {
    rtol: 1e-12,
    atol: 1e-12,
};
/// Macro steps of one impact, accepted, rejected and spent on events.
const MAX_STEPS: usize = 20_000;
/// How far past its peak (s = 1) the unloading may go before it is a reload (left to the
/// adaptive solver): the turn is found to the rounding, s overshoots 1 by its square.
const RELOAD: f64 = 1e-9;

/// A 3/2-power branch z̄ = z₀ + b s², F̄ = a s³, state (s, ᾱ', ȳ, τ), in σ (dτ = s dσ).
struct Branch {
    b: f64,
    a: f64,
    lambda: f64,
    zeta: f64,
}

impl Branch {
    /// z̄' = ᾱ' − ȳ' at the state: ds/dσ times 2b.
    fn closing(&self, x: &X) -> f64 {
        let s = x[0];
        x[1] - 2.0 * self.zeta * (self.a * s * s * s - self.lambda * x[2])
    }
}

impl System for Branch {
    fn f(&self, x: &X) -> X {
        let s = x[0];
        let s3 = s * s * s;
        [
            self.closing(x) / (2.0 * self.b),
            -self.a * s3 * s,
            2.0 * self.zeta * s * (self.a * s3 - self.lambda * x[2]),
            s,
        ]
    }
    fn jacobian(&self, x: &X) -> [[f64; 4]; 4] {
        let (s, y) = (x[0], x[2]);
        let (z, l, a, b) = (self.zeta, self.lambda, self.a, self.b);
        [
            [-3.0 * z * a * s * s / b, 0.5 / b, z * l / b, 0.0],
            [-4.0 * a * s * s * s, 0.0, 0.0, 0.0],
            [
                2.0 * z * (4.0 * a * s * s * s - l * y),
                0.0,
                -2.0 * z * l * s,
                0.0,
            ],
            [1.0, 0.0, 0.0, 0.0],
        ]
    }
}

/// The straight stretch F̄ = (z̄ − z̄_p) + f_p, state (z̄, ᾱ', ȳ, τ), in τ.
struct Stretch {
    zp: f64,
    fp: f64,
    lambda: f64,
    zeta: f64,
}

impl Stretch {
    fn force(&self, x: &X) -> f64 {
        (x[0] - self.zp) + self.fp
    }
    /// z̄' = ᾱ' − ȳ'.
    fn closing(&self, x: &X) -> f64 {
        x[1] - 2.0 * self.zeta * (self.force(x) - self.lambda * x[2])
    }
}

impl System for Stretch {
    fn f(&self, x: &X) -> X {
        let f = self.force(x);
        let dy = 2.0 * self.zeta * (f - self.lambda * x[2]);
        [x[1] - dy, -f, dy, 1.0]
    }
    fn jacobian(&self, _: &X) -> [[f64; 4]; 4] {
        let (z, l) = (self.zeta, self.lambda);
        [
            [-2.0 * z, 1.0, 2.0 * z * l, 0.0],
            [-1.0, 0.0, 0.0, 0.0],
            [2.0 * z, 0.0, -2.0 * z * l, 0.0],
            [0.0; 4],
        ]
    }
}

/// The summary of the impact of `n` under `law` (Hertz or elastic–plastic), or `None` (see the
/// module's introduction).
pub fn summary(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    let ok = |x: f64| x.is_finite() && x >= 0.0;
    let fine = ok(n.lambda) && ok(n.zeta) && n.kappa.is_finite() && n.kappa > 0.0;
    if !fine || law == ContactLaw::Linear || n.zp_bar.is_nan() || n.zp_bar <= 0.0 {
        return None;
    }
    let zp = if law == ContactLaw::Hertz {
        f64::INFINITY
    } else {
        n.zp_bar
    };
    let mut run = Run { steps: 0, h: 0.01 };
    let hertz = Branch {
        b: 1.0,
        a: n.kappa,
        lambda: n.lambda,
        zeta: n.zeta,
    };
    let first = [0.0, 1.0, 0.0, 0.0];
    let yield_s = zp.sqrt();
    match run.branch(&hertz, first, yield_s, false)? {
        BranchEnd::Separated { x, s_max } => {
            let z_m = s_max * s_max;
            finish(&run, x, z_m, n.kappa * z_m * s_max, 0.0)
        }
        BranchEnd::Yield(x) => {
            let stretch = Stretch {
                zp,
                fp: n.kappa * zp * yield_s,
                lambda: n.lambda,
                zeta: n.zeta,
            };
            let top = run.stretch(&stretch, [zp, x[1], x[2], x[3]])?;
            let (z_m, f_m) = (top[0], stretch.force(&top));
            let contact = Contact {
                law,
                zp_bar: zp,
                kappa: n.kappa,
            };
            let z_f = contact.permanent_indentation(z_m);
            let unload = Branch {
                b: z_m - z_f,
                a: f_m,
                lambda: n.lambda,
                zeta: n.zeta,
            };
            if unload.b.is_nan() || unload.b <= 0.0 {
                return None;
            }
            match run.branch(&unload, [1.0, top[1], top[2], top[3]], f64::INFINITY, true)? {
                BranchEnd::Separated { x, .. } => finish(&run, x, z_m, f_m, z_f),
                BranchEnd::Yield(_) => None,
            }
        }
    }
}

/// The summary from the separation state `x` (s, ᾱ', ȳ, τ).
fn finish(run: &Run, x: X, z_m: f64, f_m: f64, z_f: f64) -> Option<Summary> {
    let s = Summary {
        cor: (-x[1]).clamp(0.0, 1.0),
        max_force: f_m,
        contact_time: x[3],
        max_indentation: z_m,
        permanent_indentation: z_f,
        element_displacement: x[2],
        steps: run.steps,
    };
    let finite = [s.cor, s.max_force, s.contact_time, s.max_indentation]
        .iter()
        .all(|v| v.is_finite());
    (finite && s.contact_time > 0.0 && x[1] < 0.0).then_some(s)
}

/// How a 3/2-power branch ended.
enum BranchEnd {
    /// At separation (s = 0), the branch's largest s reached on the way.
    Separated { x: X, s_max: f64 },
    /// At yield (s = the branch's yield), before any turn.
    Yield(X),
}

/// The steps of one impact: how many were taken, and the next step's length.
struct Run {
    steps: usize,
    h: f64,
}

impl Run {
    /// One accepted macro step from `x` (rejections shrink it), its length and end.
    fn advance<S: System>(&mut self, sys: &S, x: &X) -> Option<(f64, X)> {
        loop {
            self.steps += 1;
            if self.steps > MAX_STEPS {
                return None;
            }
            let h = self.h;
            let step = extrapolation::step(sys, x, h, TOL);
            let Some(step) = step else {
                self.h *= 0.25;
                continue;
            };
            self.h = extrapolation::next_step(h, step.err);
            if step.err <= 1.0 {
                return Some((h, step.x));
            }
        }
    }

    /// The state where `g` is zero within the step (0, h] from `x`, g(x) and g(x + h) of
    /// opposite signs: by the Illinois variant of regula falsi on the step's length, each
    /// trial a step of its own.
    fn locate<S: System>(&mut self, sys: &S, x: &X, h: f64, g: impl Fn(&X) -> f64) -> Option<X> {
        let (mut lo, mut hi) = (0.0, h);
        let (mut g_lo, mut g_hi) = (g(x), g(&extrapolation::step(sys, x, h, TOL)?.x));
        let mut best = None;
        let mut side = 0;
        for _ in 0..60 {
            self.steps += 1;
            let t = if g_hi != g_lo {
                hi - g_hi * (hi - lo) / (g_hi - g_lo)
            } else {
                0.5 * (lo + hi)
            };
            let t = if t > lo && t < hi { t } else { 0.5 * (lo + hi) };
            let at = extrapolation::step(sys, x, t, TOL)?.x;
            let gt = g(&at);
            best = Some(at);
            if gt == 0.0 || (hi - lo) <= 1e-15 * h {
                break;
            }
            if (gt > 0.0) == (g_lo > 0.0) {
                (lo, g_lo) = (t, gt);
                if side == -1 {
                    g_hi *= 0.5;
                }
                side = -1;
            } else {
                (hi, g_hi) = (t, gt);
                if side == 1 {
                    g_lo *= 0.5;
                }
                side = 1;
            }
            if gt.abs() <= 1e-15 * (1.0 + at.iter().fold(0.0f64, |m, v| m.max(v.abs()))) {
                break;
            }
        }
        best
    }

    /// A 3/2-power branch from `x` (s, ᾱ', ȳ, τ) to separation, or to s = `yield_s` while s
    /// rises. `unloading`: the branch starts at its turn (s = 1) and may not rise past it.
    fn branch(
        &mut self,
        br: &Branch,
        mut x: X,
        yield_s: f64,
        unloading: bool,
    ) -> Option<BranchEnd> {
        let mut s_max = x[0];
        let mut turned = unloading;
        loop {
            let start = x;
            let (h, end) = self.advance(br, &start)?;
            if !turned && end[0] >= yield_s {
                let at = self.locate(br, &start, h, |x| x[0] - yield_s)?;
                return Some(BranchEnd::Yield(at));
            }
            let (g0, g1) = (br.closing(&start), br.closing(&end));
            if turned && g0 < 0.0 && g1 >= 0.0 {
                // closing again after the turn: a reload, left to the adaptive solver
                return None;
            }
            if !turned && g0 > 0.0 && g1 <= 0.0 {
                turned = true;
                // the turn, for s_max alone: the run goes on from the step's end
                let top = self.locate(br, &start, h, |x| br.closing(x))?;
                s_max = s_max.max(top[0]);
            }
            s_max = s_max.max(end[0]);
            if unloading && end[0] > 1.0 + RELOAD {
                return None;
            }
            if end[0] <= 0.0 && start[0] > 0.0 {
                let at = self.locate(br, &start, h, |x| x[0])?;
                return Some(BranchEnd::Separated { x: at, s_max });
            }
            x = end;
        }
    }

    /// The straight stretch from yield `x` (z̄, ᾱ', ȳ, τ) to its turn z̄' = 0.
    fn stretch(&mut self, st: &Stretch, mut x: X) -> Option<X> {
        loop {
            let start = x;
            let (h, end) = self.advance(st, &start)?;
            if st.closing(&end) <= 0.0 {
                return self.locate(st, &start, h, |x| st.closing(x));
            }
            if end[0] < st.zp {
                return None;
            }
            x = end;
        }
    }
}
