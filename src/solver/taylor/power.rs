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

use super::poly::{self, Rules};
use super::{Budget, Point, Sys};

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
/// `super::hertz_reference`), whose nodes tests/hertz_table.rs holds to the committed
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

/// The system's coefficients as [`series_of`] takes them, in lanes of type `T`.
#[derive(Clone, Copy)]
pub(super) struct Coefs<T> {
    /// 2ζ
    pub two_zeta: T,
    /// λ
    pub lambda: T,
    /// a
    pub a: T,
    /// −a
    pub minus_a: T,
    /// 1/(2b)
    pub half_b: T,
}

impl Coefs<f64> {
    /// [`series`]'s coefficients of `sys` on `br`.
    pub(super) fn of(sys: &Sys, br: &Branch) -> Coefs<f64> {
        Coefs {
            two_zeta: 2.0 * sys.zeta,
            lambda: sys.lambda,
            a: br.a,
            minus_a: -br.a,
            half_b: 0.5 / br.b,
        }
    }
}

/// The arithmetic [`series_of`] needs: IEEE f64 operations, lane by lane.
pub(super) trait Coef:
    Copy + std::ops::Add<Output = Self> + std::ops::Sub<Output = Self> + std::ops::Mul<Output = Self>
{
    fn splat(x: f64) -> Self;
    /// self · a + b with one rounding (IEEE fusedMultiplyAdd), lane by lane: the same bits
    /// on every CPU, one instruction where it has FMA.
    fn mul_add(self, a: Self, b: Self) -> Self;
}

impl Coef for f64 {
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn mul_add(self, a: f64, b: f64) -> f64 {
        f64::mul_add(self, a, b)
    }
}

/// [`series`]'s coefficients with each product's sums reordered, the fast paths' series:
/// for f64 in `super::summary`, in lanes in `super::batch`. At order n the four products
/// (s², s³ = s·s², s⁴ = (s²)², s·ȳ') take their terms of 1 ≤ i ≤ n − 1 in one loop over
/// the pairs (i, n − i), each of its six coefficients loaded once for six fused
/// multiply–adds ([`Coef::mul_add`]) where a product at a time loads two for one (the lanes'
/// series were bound by their loads: BENCHMARKS.md, fourteenth session). The pairs go from
/// the middle out, so the one holding order n − 1's coefficients comes last, and the terms
/// of the coefficients order n computes (s₀p_n, p₀p_n, s₀ȳ'_n) after them: an order waits on
/// the one before for a few sums, not for a whole chain. A lane runs f64's IEEE operations
/// in the same order, so its coefficients are the f64 path's bits (tests/taylor_batch.rs
/// `batched_summaries_are_the_single_ones_bit_for_bit`).
#[inline(always)]
pub(super) fn series_of<T: Coef, const L: usize>(k: Coefs<T>, x: [T; 4], c: &mut [[T; L]; 4]) {
    let zero = T::splat(0.0);
    let two = T::splat(2.0);
    let [s, v, y, t] = c;
    let (mut p, mut yd) = ([zero; L], [zero; L]);
    (s[0], v[0], y[0], t[0]) = (x[0], x[1], x[2], x[3]);
    for n in 0..L - 1 {
        let (q, r, sy);
        if n == 0 {
            p[0] = s[0] * s[0];
            q = s[0] * p[0];
            r = p[0] * p[0];
            yd[0] = k.two_zeta * (k.a * q - k.lambda * y[0]);
            sy = s[0] * yd[0];
        } else {
            let older = older_terms(s, &p, &yd, n);
            p[n] = (two * s[0]).mul_add(s[n], older.ss);
            q = s[0].mul_add(p[n], older.sp);
            r = (two * p[0]).mul_add(p[n], older.pp);
            yd[n] = k.two_zeta * (k.a * q - k.lambda * y[n]);
            sy = s[0].mul_add(yd[n], older.sy);
        }
        let inv = T::splat(1.0 / (n + 1) as f64);
        s[n + 1] = (v[n] - yd[n]) * k.half_b * inv;
        v[n + 1] = k.minus_a * r * inv;
        y[n + 1] = sy * inv;
        t[n + 1] = s[n] * inv;
    }
}

/// The terms of order n ≥ 1 of s², s·s², (s²)² and s·ȳ' that hold no coefficient order n
/// computes: all but s₀s_n, s₀p_n, p₀p_n and s₀ȳ'_n ([`series_of`]).
struct Older<T> {
    ss: T,
    sp: T,
    pp: T,
    sy: T,
}

/// [`Older`] of order n ≥ 1: the pairs (i, n − i), 1 ≤ i < n − i, from the middle out, two
/// partial sums for the mixed products; then the middle term (n even), then s_n p₀ and
/// s_n ȳ'₀ (s_n is order n − 1's).
#[inline(always)]
fn older_terms<T: Coef, const L: usize>(s: &[T; L], p: &[T; L], yd: &[T; L], n: usize) -> Older<T> {
    let m = T::splat(-0.0);
    let (mut ss, mut pp, mut sp, mut ps, mut sy, mut ys) = (m, m, m, m, m, m);
    let mut i = (n - 1) / 2;
    while i >= 1 {
        let j = n - i;
        ss = s[i].mul_add(s[j], ss);
        pp = p[i].mul_add(p[j], pp);
        sp = s[i].mul_add(p[j], sp);
        ps = p[i].mul_add(s[j], ps);
        sy = s[i].mul_add(yd[j], sy);
        ys = yd[i].mul_add(s[j], ys);
        i -= 1;
    }
    let two = T::splat(2.0);
    let (mut ss, mut pp, mut sp, mut sy) = (two * ss, two * pp, sp + ps, sy + ys);
    if n.is_multiple_of(2) {
        let h = n / 2;
        ss = s[h].mul_add(s[h], ss);
        pp = p[h].mul_add(p[h], pp);
        sp = s[h].mul_add(p[h], sp);
        sy = s[h].mul_add(yd[h], sy);
    }
    Older {
        ss,
        sp: s[n].mul_add(p[0], sp),
        pp,
        sy: s[n].mul_add(yd[0], sy),
    }
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

fn at<const L: usize>(c: &[[f64; L]; 4], h: f64) -> [f64; 4] {
    [
        poly::eval(&c[0], h),
        poly::eval(&c[1], h),
        poly::eval(&c[2], h),
        poly::eval(&c[3], h),
    ]
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

    /// One step from `self.x` given the series `c` there: the step the series allow by the
    /// phase's rules, the first event in it (a turn, yield, separation), and the state at its
    /// end.
    pub(super) fn advance<const L: usize>(&mut self, c: &[[f64; L]; 4], budget: &Budget) -> Next {
        let h = self.rules.step(c, &self.scales());
        if !(h.is_finite() && h > 0.0) {
            return Next::Fail;
        }
        self.advance_by(c, h, poly::eval(&c[0], h), None, budget)
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
        let (ds0, dsh) = ds.unwrap_or_else(|| (c[0][1], poly::eval(&poly::derivative(&c[0]), h)));
        let turns = !self.unloading && ds0 > 0.0 && dsh <= 0.0;
        // the turn and s there
        let turn = turns.then(|| {
            let t = self.rules.root(&poly::derivative(&c[0]), 0.0, h, dsh);
            (t, poly::eval(&c[0], t))
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
        self.take(at(c, h), budget)
    }
}
