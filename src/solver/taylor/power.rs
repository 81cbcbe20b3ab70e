//! A phase on a 3/2-power branch, z̄ = z̄₀ + b s², F̄ = a s³ (Hertz loading, Eq. 7; the
//! elastic–plastic unloading, Eq. 12), integrated by Taylor series in the variable σ with
//! dτ = s dσ. In σ the system is polynomial,
//!
//! ```text
//! ds/dσ = (ᾱ' − ȳ')/(2b),   dᾱ'/dσ = −a s⁴,   dȳ/dσ = s ȳ',   dτ/dσ = s,
//! ȳ' = 2ζ(a s³ − λȳ),
//! ```
//!
//! so its Taylor coefficients follow from Cauchy products alone, and the square root of z̄
//! that makes the system singular in τ at first touch and at separation (s = 0) is gone:
//! separation is a simple zero of s in σ, at which ᾱ' and τ are stationary (dᾱ'/dσ = −a s⁴,
//! dτ/dσ = s), so the COR and the contact time carry none of the root's error.

use super::poly;
use super::rules::Rules;
use super::{Budget, Point, Sys};

mod fast;
pub(super) use fast::{Coefs, series_of};

/// The branch z̄ = z̄₀ + b s², F̄ = a s³.
#[derive(Debug, Clone, Copy)]
pub(super) struct Branch {
    /// z̄₀: where the branch carries no force (0 loading, z̄_f unloading).
    pub z0: f64,
    /// b: z̄ − z̄₀ = b s² (1 loading, z̄_m − z̄_f unloading).
    pub b: f64,
    /// a: F̄ = a s³ (κ loading, F̄_m unloading).
    pub a: f64,
}

/// How a phase on a power branch ended.
#[derive(Debug, Clone, Copy)]
pub(super) enum End {
    /// F̄ = 0: the ball left at this point.
    Separated(Point),
    /// s reached the yield value: the linear stretch of the elastic–plastic law starts here.
    Yield(Point),
}

/// A phase's end and the largest s it reached (at a turn, z̄' = 0).
#[derive(Debug, Clone, Copy)]
pub(super) struct Run {
    pub end: End,
    pub s_max: f64,
}

/// The Taylor coefficients of (s, ᾱ', ȳ, τ) at x to order L − 1 (Cauchy products, each O(k)
/// at order k, summed in the order of i): the Hertz table's reference ([`run`], from
/// `super::hertz_reference`), whose nodes tests/physics/hertz_table.rs holds to the committed
/// file's bits. The fast paths take [`series_of`].
pub(super) fn series<const L: usize>(sys: &Sys, br: &Branch, x: [f64; 4]) -> [[f64; L]; 4] {
    let (mut s, mut v, mut y, mut t) = ([0.0; L], [0.0; L], [0.0; L], [0.0; L]);
    let (mut p, mut q, mut yd) = ([0.0; L], [0.0; L], [0.0; L]);
    (s[0], v[0], y[0], t[0]) = (x[0], x[1], x[2], x[3]);
    let two_zeta = 2.0 * sys.zeta;
    let half_b = 0.5 / br.b;
    for k in 0..L - 1 {
        // p = s², q = s³, r = s⁴ = p², sy = s ȳ'
        p[k] = square(&s, k);
        q[k] = (0..=k).map(|i| p[i] * s[k - i]).sum();
        let r = square(&p, k);
        yd[k] = two_zeta * (br.a * q[k] - sys.lambda * y[k]);
        let sy: f64 = (0..=k).map(|i| s[i] * yd[k - i]).sum();
        let inv = 1.0 / (k + 1) as f64;
        s[k + 1] = (v[k] - yd[k]) * half_b * inv;
        v[k + 1] = -br.a * r * inv;
        y[k + 1] = sy * inv;
        t[k + 1] = s[k] * inv;
    }
    [s, v, y, t]
}

/// The k-th coefficient of c², by the product's symmetry (half the terms).
fn square<const L: usize>(c: &[f64; L], k: usize) -> f64 {
    let half: f64 = (0..k.div_ceil(2)).map(|i| c[i] * c[k - i]).sum();
    let middle = if k.is_multiple_of(2) {
        c[k / 2] * c[k / 2]
    } else {
        0.0
    };
    2.0 * half + middle
}

/// The state at an event h where s is known (the yield value, or 0 at separation), by the
/// rules' sums (`Rules::eval`: Estrin's where quick, three chains of ⌈log₂ L⌉ products
/// where Horner's are L long; in the batch as alone, so the same bits). A quiet step's end
/// keeps Horner's sums ([`at`]), which the batch takes in lanes, where they are faster.
fn state_at<const L: usize>(c: &[[f64; L]; 4], h: f64, s: f64, rules: Rules) -> [f64; 4] {
    [
        s,
        rules.eval(&c[1], h),
        rules.eval(&c[2], h),
        rules.eval(&c[3], h),
    ]
}

/// The state at a step's end h, by the rules' Horner sums (`super::batch`'s in lanes).
fn at<const L: usize>(c: &[[f64; L]; 4], h: f64, rules: Rules) -> [f64; 4] {
    c.each_ref().map(|cv| rules.horner(cv, h))
}

/// Run the phase from `start` on branch `br` until the ball leaves (s = 0) or, loading, s
/// reaches `s_yield` (∞: never). `unloading`: the phase starts at the peak (s = 1) and a
/// rise past it (a reload) is left to the adaptive solver (`None`); loading, every turn's s
/// is kept in `s_max`. `None` also when the budget runs out. Series of order L − 1, each
/// step by `rules`.
pub(super) fn run<const L: usize>(
    sys: &Sys,
    br: &Branch,
    start: Point,
    s_yield: f64,
    unloading: bool,
    rules: Rules,
    budget: &mut Budget,
) -> Option<Run> {
    let mut phase = Phase::new(*br, start, s_yield, unloading, rules);
    loop {
        budget.take()?;
        let c = series::<L>(sys, br, phase.x);
        match phase.advance(&c, budget) {
            Next::Go => {}
            Next::Done(run) => return Some(run),
            Next::Fail => return None,
        }
    }
}

/// A phase under way: its branch, the state (s, ᾱ', ȳ, τ) where the next step starts, and
/// what [`run`] keeps between steps. [`run`] drives it one impact at a time; `super::batch`
/// drives several in step, their series computed in lanes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Phase {
    pub br: Branch,
    pub x: [f64; 4],
    s_max: f64,
    s_yield: f64,
    unloading: bool,
    /// How its steps and events are taken.
    pub rules: Rules,
}

/// What a step left of a phase.
pub(super) enum Next {
    /// The phase goes on from the step's end.
    Go,
    /// The phase ended in the step.
    Done(Run),
    /// The steps cannot follow it (see [`run`]).
    Fail,
}

impl Phase {
    /// The phase from `start` on `br` (see [`run`]).
    pub(super) fn new(
        br: Branch,
        start: Point,
        s_yield: f64,
        unloading: bool,
        rules: Rules,
    ) -> Phase {
        let s0 = ((start.z - br.z0) / br.b).max(0.0).sqrt();
        Phase {
            br,
            x: [s0, start.v, start.y, start.tau],
            s_max: s0,
            s_yield,
            unloading,
            rules,
        }
    }

    fn point(&self, x: [f64; 4]) -> Point {
        Point {
            tau: x[3],
            z: self.br.z0 + self.br.b * x[0] * x[0],
            v: x[1],
            y: x[2],
        }
    }

    /// Whether [`Phase::advance`] would take the whole step `h` with no event — no failure,
    /// no turn, no yield, no separation — given the series' values there: s(h) (`s_end`) and
    /// s'(0), s'(h) (`ds0`, `dsh`). Such a step's end is the state at h, which
    /// `super::batch` evaluates in lanes ([`Phase::take`]); any other step is `advance`'s.
    pub(super) fn is_quiet(&self, h: f64, s_end: f64, ds0: f64, dsh: f64) -> bool {
        let turn = !self.unloading && ds0 > 0.0 && dsh <= 0.0;
        h.is_finite()
            && h > 0.0
            && !(self.unloading && s_end > 1.0)
            && !turn
            && s_end < self.s_yield
            && !(s_end <= 0.0 && self.x[0] > 0.0)
    }

    /// A quiet step's end `x` ([`Phase::is_quiet`]): as [`Phase::advance`] ends such a step.
    pub(super) fn take(&mut self, x: [f64; 4], budget: &Budget) -> Next {
        self.x = x;
        if self.x[3] > budget.tau_max {
            return Next::Fail;
        }
        Next::Go
    }

    /// The phase's scales: each component's size, at least 1 (`step`'s).
    pub(super) fn scales(&self) -> [f64; 4] {
        self.x.map(|xi| xi.abs().max(1.0))
    }

    /// ᾱ (in the branch's units) where the ball's centre turns (ᾱ' falls through 0) within the
    /// step [`Phase::advance`] takes from here given the series `c`, on this branch (s there in
    /// [0, s_yield)); `None` where it does not turn in the step. α = z̄ + ȳ with
    /// z̄ = z̄₀ + b s²; the turn is the root of ᾱ'(σ), the series' second component, read as the
    /// step's events are (`Rules::root`), so it is α_max to the steps' own precision
    /// (`super::peak_displacement`).
    pub(super) fn centre_turn<const L: usize>(&self, c: &[[f64; L]; 4]) -> Option<f64> {
        if self.x[1] <= 0.0 || self.x[1].is_nan() {
            return None;
        }
        let h = self.rules.step(c, &self.scales());
        if !(h.is_finite() && h > 0.0) {
            return None;
        }
        let v_end = self.rules.horner(&c[1], h);
        if v_end > 0.0 || v_end.is_nan() {
            return None;
        }
        let t = self.rules.root(&c[1], 0.0, h, v_end);
        let s = self.rules.eval(&c[0], t);
        (s >= 0.0 && s < self.s_yield)
            .then(|| self.br.z0 + self.br.b * s * s + self.rules.eval(&c[2], t))
    }

    /// One step from `self.x` given the series `c` there: the step the series allow by the
    /// phase's rules, the first event in it (a turn, yield, separation), and the state at its
    /// end.
    pub(super) fn advance<const L: usize>(&mut self, c: &[[f64; L]; 4], budget: &Budget) -> Next {
        let h = self.rules.step(c, &self.scales());
        if !(h.is_finite() && h > 0.0) {
            return Next::Fail;
        }
        self.advance_by(c, h, self.rules.horner(&c[0], h), None, budget)
    }

    /// [`Phase::advance`] given the step `h` and s(h) (`s_end`), and s'(0), s'(h) (`ds`)
    /// where they are known: `super::batch` has them from its lanes, the same bits.
    pub(super) fn advance_by<const L: usize>(
        &mut self,
        c: &[[f64; L]; 4],
        h: f64,
        s_end: f64,
        ds: Option<(f64, f64)>,
        budget: &Budget,
    ) -> Next {
        if !(h.is_finite() && h > 0.0) {
            return Next::Fail;
        }
        if self.unloading && s_end > 1.0 {
            return Next::Fail;
        }
        // loading: a turn (s' falls through 0) in (0, h], whose s may pass the yield value
        // even where s(h) is back below it
        // s'(0) is the derivative's first coefficient
        let (ds0, dsh) =
            ds.unwrap_or_else(|| (c[0][1], self.rules.horner(&poly::derivative(&c[0]), h)));
        let turns = !self.unloading && ds0 > 0.0 && dsh <= 0.0;
        // the turn and s there
        let turn = turns.then(|| {
            let t = self.rules.root(&poly::derivative(&c[0]), 0.0, h, dsh);
            (t, self.rules.eval(&c[0], t))
        });
        let top = turn.map_or(s_end, |(_, s_turn)| s_turn.max(s_end));
        // the first of separation and yield in (0, h]
        let mut event: Option<(f64, bool)> = None;
        if top >= self.s_yield {
            let (upto, s_upto) = match turn {
                Some(turn) if s_end < self.s_yield => turn,
                _ => (h, s_end),
            };
            event = Some((self.rules.root(&c[0], self.s_yield, upto, s_upto), true));
        } else if s_end <= 0.0 && self.x[0] > 0.0 {
            event = Some((self.rules.root(&c[0], 0.0, h, s_end), false));
        }
        if let Some((t, s_turn)) = turn
            && t <= event.map_or(h, |e| e.0)
        {
            self.s_max = self.s_max.max(s_turn);
        }
        if let Some((h_event, yielded)) = event {
            let s = if yielded { self.s_yield } else { 0.0 };
            let end = state_at(c, h_event, s, self.rules);
            if yielded {
                self.s_max = self.s_max.max(self.s_yield);
                return Next::Done(Run {
                    end: End::Yield(self.point(end)),
                    s_max: self.s_max,
                });
            }
            return Next::Done(Run {
                end: End::Separated(self.point(end)),
                s_max: self.s_max,
            });
        }
        self.take(at(c, h, self.rules), budget)
    }
}
