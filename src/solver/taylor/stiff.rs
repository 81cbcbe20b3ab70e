//! The phases where the dashpot is stiff (2ζ̂(k + λ̂) τ̂ > `STIFF`: the recoil element follows
//! its slow manifold F̄ ≈ λȳ), by the implicit steps of `radau` on the same systems the
//! Taylor series integrate: a 3/2-power branch in σ (dτ = s dσ, `power`), a linear branch in
//! τ (`linear`). The steps follow the slow motion (their size from the collocation
//! polynomial's leading coefficient, `Step::ratio`), and each event (a turn, yield,
//! separation) is found by shortening the step until its end meets it: an end point of a
//! Radau IIA step carries the method's full order, its dense output does not.
//! tests/taylor.rs holds the answers to the adaptive solver's.

use super::radau::{self, Step, System};
use super::{Budget, Point, Sys, linear, power};

/// The step's h/ρ aimed at (ρ the radius of convergence of the solution's series): the
/// error of an order-9 step is some 1e-5 (h/ρ)^{10}, below 1e-15 here.
const THETA: f64 = 0.08;
/// A step whose h/ρ came out above this is taken again, shorter.
const REJECT: f64 = 0.16;
/// The first step, in the phase's variable.
const H0: f64 = 0.02;

/// A 3/2-power branch in σ: x = (s, ᾱ', ȳ), as `power` writes it.
struct PowerSys<'a> {
    sys: &'a Sys,
    br: &'a power::Branch,
}

impl System for PowerSys<'_> {
    fn f(&self, x: [f64; 3]) -> [f64; 3] {
        let [s, v, y] = x;
        let (a, b) = (self.br.a, self.br.b);
        let yd = 2.0 * self.sys.zeta * (a * s * s * s - self.sys.lambda * y);
        [(v - yd) / (2.0 * b), -a * s * s * s * s, s * yd]
    }
    fn jac(&self, x: [f64; 3]) -> [[f64; 3]; 3] {
        let [s, _, y] = x;
        let (a, b, tz, l) = (self.br.a, self.br.b, 2.0 * self.sys.zeta, self.sys.lambda);
        let yd = tz * (a * s * s * s - l * y);
        let dyd_ds = tz * 3.0 * a * s * s;
        [
            [-dyd_ds / (2.0 * b), 1.0 / (2.0 * b), tz * l / (2.0 * b)],
            [-4.0 * a * s * s * s, 0.0, 0.0],
            [yd + s * dyd_ds, 0.0, -tz * l * s],
        ]
    }
    fn dtau(&self, x: [f64; 3]) -> f64 {
        x[0]
    }
}

/// A linear branch in τ: x = (z̄, ᾱ', ȳ), as `linear` writes it.
struct LinearSys<'a> {
    sys: &'a Sys,
    br: &'a linear::Branch,
}

impl System for LinearSys<'_> {
    fn f(&self, x: [f64; 3]) -> [f64; 3] {
        let [z, v, y] = x;
        let f = self.br.k * (z - self.br.z0) + self.br.f0;
        let yd = 2.0 * self.sys.zeta * (f - self.sys.lambda * y);
        [v - yd, -f, yd]
    }
    fn jac(&self, _: [f64; 3]) -> [[f64; 3]; 3] {
        let (k, tz, l) = (self.br.k, 2.0 * self.sys.zeta, self.sys.lambda);
        [
            [-tz * k, 1.0, tz * l],
            [-k, 0.0, 0.0],
            [tz * k, 0.0, -tz * l],
        ]
    }
    fn dtau(&self, _: [f64; 3]) -> f64 {
        1.0
    }
}

/// One step from `x` of size about `h`, shortened until Newton contracts and the step stays
/// within the solution's radius (`REJECT`).
fn advance<T: System>(sys: &T, x: [f64; 3], mut h: f64, budget: &mut Budget) -> Option<Step> {
    loop {
        budget.take()?;
        if !(h.is_finite() && h > 0.0) {
            return None;
        }
        match radau::step(sys, x, h) {
            Some(st) => {
                let r = st.ratio();
                if r > REJECT {
                    h *= THETA / r;
                    continue;
                }
                return Some(st);
            }
            None => h *= 0.25,
        }
    }
}

/// The next step's size after `st`.
fn next_h(st: &Step) -> f64 {
    let r = st.ratio();
    let grow = if r > 0.0 { THETA / r } else { 4.0 };
    st.h * grow.clamp(0.2, 4.0)
}

/// The step from `st.x0` whose end meets g = 0, g(x0) and g(end of `st`) of opposite signs
/// (or the latter 0): secant steps on the step's size, started from the dense output's root,
/// each a full step, to the rounding of h.
fn locate<T: System>(
    sys: &T,
    st: &Step,
    g: impl Fn([f64; 3]) -> f64,
    budget: &mut Budget,
) -> Option<Step> {
    let (g0, g1) = (g(st.x0), g(st.end()));
    if g1 == 0.0 {
        return Some(*st);
    }
    // the dense output's root, by bisection on θ
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (g(st.dense(mid)) > 0.0) == (g0 > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let (mut h_prev, mut g_prev) = (st.h, g1);
    let mut h = (0.5 * (lo + hi) * st.h).clamp(f64::MIN_POSITIVE, st.h);
    let mut best = *st;
    for _ in 0..10 {
        budget.take()?;
        best = radau::step(sys, st.x0, h)?;
        let gh = g(best.end());
        if gh == 0.0 || gh == g_prev {
            break;
        }
        let next = (h - gh * (h - h_prev) / (gh - g_prev)).clamp(0.0, st.h);
        (h_prev, g_prev) = (h, gh);
        let settled = (next - h).abs() <= 2.0 * f64::EPSILON * h;
        h = next;
        if settled || h == 0.0 {
            break;
        }
    }
    Some(best)
}

/// `power::run` for a stiff phase: the same branch, start, events and answers.
pub(super) fn power_run(
    sys: &Sys,
    br: &power::Branch,
    start: Point,
    s_yield: f64,
    unloading: bool,
    budget: &mut Budget,
) -> Option<power::Run> {
    let ph = PowerSys { sys, br };
    let s0 = ((start.z - br.z0) / br.b).max(0.0).sqrt();
    let mut x = [s0, start.v, start.y];
    let mut tau = start.tau;
    let mut s_max = s0;
    let point = |x: [f64; 3], tau: f64| Point {
        tau,
        z: br.z0 + br.b * x[0] * x[0],
        v: x[1],
        y: x[2],
    };
    let mut h = H0;
    loop {
        let st = advance(&ph, x, h, budget)?;
        let e = st.end();
        if unloading && e[0] > 1.0 {
            return None;
        }
        // loading: a turn (s' falls through 0) whose s may pass the yield value even where
        // the step's end is back below it
        let ds = |x: [f64; 3]| ph.f(x)[0];
        let mut yield_in = None;
        if !unloading && ds(x) > 0.0 && ds(e) <= 0.0 {
            let turn = locate(&ph, &st, ds, budget)?;
            if turn.end()[0] >= s_yield {
                yield_in = Some(turn);
            } else {
                s_max = s_max.max(turn.end()[0]);
            }
        }
        if yield_in.is_none() && e[0] >= s_yield {
            yield_in = Some(st);
        }
        if let Some(within) = yield_in {
            let at = locate(&ph, &within, |x| x[0] - s_yield, budget)?;
            let mut end = at.end();
            end[0] = s_yield;
            return Some(power::Run {
                end: power::End::Yield(point(end, tau + at.dtau)),
                s_max: s_max.max(s_yield),
            });
        }
        if e[0] <= 0.0 && x[0] > 0.0 {
            let at = locate(&ph, &st, |x| x[0], budget)?;
            let mut end = at.end();
            end[0] = 0.0;
            return Some(power::Run {
                end: power::End::Separated(point(end, tau + at.dtau)),
                s_max,
            });
        }
        x = e;
        tau += st.dtau;
        if tau > budget.tau_max {
            return None;
        }
        h = next_h(&st);
    }
}

/// `linear::run` for a stiff loading phase (no peak yet): to the turn z̄' = 0.
pub(super) fn linear_turn(
    sys: &Sys,
    br: &linear::Branch,
    start: Point,
    budget: &mut Budget,
) -> Option<linear::End> {
    let ph = LinearSys { sys, br };
    let mut x = [start.z, start.v, start.y];
    let mut tau = start.tau;
    let dz = |x: [f64; 3]| ph.f(x)[0];
    if dz(x) <= 0.0 {
        return Some(linear::End::Turned(start));
    }
    let mut h = H0;
    loop {
        let st = advance(&ph, x, h, budget)?;
        let e = st.end();
        if dz(e) <= 0.0 {
            let at = locate(&ph, &st, dz, budget)?;
            let [z, v, y] = at.end();
            return Some(linear::End::Turned(Point {
                tau: tau + at.dtau,
                z,
                v,
                y,
            }));
        }
        x = e;
        tau += st.dtau;
        if tau > budget.tau_max {
            return None;
        }
        h = next_h(&st);
    }
}
