//! An independent integration of the oblique impact's tangential motion (docs/oblique.md §5),
//! for the tests: the equations of motion themselves — ṽ_x' = F̃_t, (Rω/v_y)' = −F̃_t/κ,
//! F̃_t = −k̃ũ − c̃ṽ_c, ũ' = ṽ_c while sticking and (sμF̄' − c̃ṽ_c')/k̃ on the cap while
//! sliding (LAMMPS's reset, docs/oblique.md §1) — integrated
//! by the `differential-equations` crate's DOP853 at a tolerance of 1e-13, with an event at
//! every stick/slip switch located by integrating to it, and a restart at each end of a
//! normal phase (where F̄' may jump). It shares with [`super::solve`] the model's rules and the
//! normal motion, and nothing of the closed forms: the sticking oscillation, the sliding
//! impulse and the switches' search are all the integrator's.

use super::tangential::Mode;
use super::{NormalMotion, Oblique, ObliqueError, Scaled, prepare};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::dop853;
use crate::solver::each_step::{EachStep, EndState};
use crate::solver::roots::brent;
use differential_equations::ode::ODE;

type X = [f64; 3];

/// The integrator's relative tolerance (absolute: 1e-2 of it; the state is of order 1).
const RTOL: f64 = 1e-13;

/// The outgoing tangential motion, normalized by v_y: ṽ_x and Rω/v_y at separation, and the
/// number of switches met.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outgoing {
    /// v_x,out / v_y.
    pub vx: f64,
    /// R ω_out / v_y.
    pub spin: f64,
    /// Stick/slip switches.
    pub switches: usize,
}

struct Sys<'a, P: NormalMotion> {
    path: &'a P,
    s: Scaled,
    mode: Mode,
}

impl<P: NormalMotion> Sys<'_, P> {
    /// The switch function of the mode: positive where the phase must end.
    fn switch(&self, t: f64, x: &X) -> f64 {
        let p = self.path.at(t);
        let vc = x[0] - x[1];
        let s = &self.s;
        match self.mode {
            Mode::Stick => (s.kt * x[2] + s.ct * vc).abs() - s.mu * p.force,
            Mode::Slip(sg) => s.mu * (p.rate + s.ct * s.g * p.force) / s.kt - sg * vc,
        }
    }
}

impl<P: NormalMotion> ODE<f64, X> for Sys<'_, P> {
    fn diff(&self, t: f64, x: &X, dx: &mut X) {
        let s = &self.s;
        let ft = -s.kt * x[2] - s.ct * (x[0] - x[1]);
        dx[0] = ft;
        dx[1] = -ft / s.kappa;
        dx[2] = match self.mode {
            Mode::Stick => x[0] - x[1],
            // k̃ũ = sμF̄ − c̃ṽ_c held on the cap, ṽ_c' = (1 + 1/κ)F̃_t
            Mode::Slip(sg) => {
                (sg * s.mu * self.path.at(t).rate - s.ct * (1.0 + 1.0 / s.kappa) * ft) / s.kt
            }
        };
    }
}

/// Watches the switch function over each step (its end and four points inside, on the dense
/// output) and stops at the first step where it turns positive after a negative value; the
/// crossing is then located by integrating from the step's start (`locate`), not on the dense
/// output, whose error at this tolerance is far above the integration's.
struct Watcher<'a, 'b, P: NormalMotion> {
    sys: &'b Sys<'a, P>,
    armed: bool,
    /// The step's start (τ, x) and the bracket [τa, τb] of the crossing.
    hit: Option<((f64, X), f64, f64)>,
    last: (f64, X),
}

impl<P: NormalMotion> EachStep<X> for Watcher<'_, '_, P> {
    fn watch(
        &mut self,
        (t_prev, y_prev): (f64, &X),
        (t_curr, y_curr): (f64, &X),
        at: &mut impl FnMut(f64) -> X,
    ) -> bool {
        self.last = (t_curr, *y_curr);
        // the integrator's first call, at the start itself: nothing has moved (with a dashpot
        // the trial force k̃ũ + c̃ṽ_c there is 0 only to rounding, which marks no switch)
        if t_curr <= t_prev {
            return false;
        }
        let mut ta = t_prev;
        for j in 1..=5 {
            let t = t_prev + (t_curr - t_prev) * j as f64 / 5.0;
            let x = if j == 5 { *y_curr } else { at(t) };
            let g = self.sys.switch(t, &x);
            // a function not yet negative since the phase began marks no switch (as in
            // `tangential`: the modes agree there to second order)
            if g > 0.0 && self.armed {
                self.hit = Some(((t_prev, *y_prev), ta, t));
                return true;
            }
            if g < 0.0 {
                self.armed = true;
                ta = t;
            }
        }
        false
    }
}

/// One DOP853 run from (τ0, x0) to τ1 into `out`.
fn run_to<P: NormalMotion, O: EachStep<X>>(
    sys: &Sys<'_, P>,
    (t0, x0): (f64, X),
    t1: f64,
    out: &mut O,
) {
    let ran = dop853::run(sys, (t0, &x0), t1, (RTOL, 1_000_000), out);
    assert!(ran, "DOP853 runs");
}

/// The state at τ, integrated from (τ0, x0) in the current mode.
fn integrate_to<P: NormalMotion>(sys: &Sys<'_, P>, (t0, x0): (f64, X), t: f64) -> X {
    if t <= t0 {
        return x0;
    }
    let mut end = EndState(t0, x0);
    run_to(sys, (t0, x0), t, &mut end);
    end.1
}

/// The first τ in [τa, τb] where the switch function turns positive, every value integrated
/// from the step's start; the state there. When it is not negative at τa (a phase that has
/// just begun), a negative value is looked for closer to τa first, as `tangential` does.
fn locate<P: NormalMotion>(sys: &Sys<'_, P>, from: (f64, X), ta: f64, tb: f64) -> (f64, X) {
    let g = |t: f64| sys.switch(t, &integrate_to(sys, from, t));
    let gb = g(tb);
    let below = std::iter::once(ta)
        .chain((1..48).map(|j| ta + (tb - ta) * 0.5f64.powi(j)))
        .map(|t| (t, g(t)))
        .find(|&(_, gt)| gt < 0.0);
    let t = match below {
        Some((a, ga)) if gb > 0.0 => brent(g, a, tb, ga, gb, 1e-15 * tb.max(1.0)),
        _ => ta,
    };
    (t, integrate_to(sys, from, t))
}

/// Integrate the tangential motion from ṽ_x = `vx`, Rω/v_y = `spin` at first touch over the
/// normal motion `path`.
pub fn integrate(path: &impl NormalMotion, s: &Scaled, vx: f64, spin: f64) -> Outgoing {
    let tf = path.end();
    let mut stops: Vec<f64> = path.kinks().into_iter().filter(|&k| k < tf).collect();
    stops.push(tf);
    let p0 = path.at(0.0);
    let vc = vx - spin;
    let mode = if s.kt * vc.abs() <= s.mu * p0.rate {
        Mode::Stick
    } else {
        Mode::Slip(vc.signum())
    };
    let mut sys = Sys { path, s: *s, mode };
    // with a dashpot the spring starts on the reset, k̃ũ + c̃ṽ_c = 0 (the cap is 0 there)
    let (mut t, mut x) = (0.0, [vx, spin, -s.ct * vc / s.kt]);
    let mut switches = 0;
    // At first contact the switch function starts at 0 with the slope K̃|ṽ_c| − μF̄'(0) (stick)
    // or its negative over K̃ (slip): where that is not 0 the function is negative at once, so
    // a return through 0 is a switch even inside the integrator's first step, where a short
    // stick (K̃|ṽ_c| just under μF̄'(0)) dips between the five points a step watches
    // (tests/physics/oblique_scan.rs).
    let mut armed = s.kt * vc.abs() != s.mu * p0.rate;
    for &stop in &stops {
        while t < stop {
            let mut w = Watcher {
                sys: &sys,
                armed,
                hit: None,
                last: (t, x),
            };
            run_to(&sys, (t, x), stop, &mut w);
            match w.hit {
                Some((from, ta, tb)) => {
                    (t, x) = locate(&sys, from, ta, tb);
                    switches += 1;
                    assert!(
                        switches < 100_000,
                        "switching without end at τ = {t}, mode {:?}, x {x:?}",
                        sys.mode
                    );
                    armed = false;
                    sys.mode = match sys.mode {
                        Mode::Stick => {
                            let vc = x[0] - x[1];
                            let sg = (s.kt * x[2] + s.ct * vc).signum();
                            x[2] = (sg * s.mu * path.at(t).force - s.ct * vc) / s.kt;
                            Mode::Slip(sg)
                        }
                        Mode::Slip(_) => Mode::Stick,
                    };
                }
                None => {
                    armed = w.armed;
                    (t, x) = (stop, w.last.1);
                }
            }
        }
    }
    Outgoing {
        vx: x[0],
        spin: x[1],
        switches,
    }
}

/// The oblique impact of [`super::solve`] integrated this way: v_x and ω at separation (m/s,
/// rad/s) and the number of switches.
pub fn solve(
    params: &ImpactParams,
    v: f64,
    oblique: &Oblique,
) -> Result<(f64, f64, usize), ObliqueError> {
    solve_law(params, ContactLaw::Linear, v, oblique)
}

/// The oblique impact of [`super::solve_law`] integrated this way, on any law's normal flow.
pub fn solve_law(
    params: &ImpactParams,
    law: ContactLaw,
    v: f64,
    oblique: &Oblique,
) -> Result<(f64, f64, usize), ObliqueError> {
    let p = prepare(params, law, v, oblique)?;
    let r = oblique.radius;
    let out = integrate(&p.path, &p.scaled, p.vx / p.vy, r * oblique.spin / p.vy);
    Ok((out.vx * p.vy, out.spin * p.vy / r, out.switches))
}
