//! An independent integration of the oblique impact's tangential motion (docs/oblique.md §5),
//! for the tests: the equations of motion themselves — ṽ_x' = F̃_t, (Rω/v_y)' = −F̃_t/κ,
//! F̃_t = −k̃ũ, ũ' = ṽ_c while sticking and sμF̄'/k̃ on the cap while sliding — integrated
//! by the `differential-equations` crate's DOP853 at a tolerance of 1e-13, with an event at
//! every stick/slip switch located on the step's dense output, and a restart at each end of a
//! normal phase (where F̄' may jump). It shares with [`super::solve`] the model's rules and the
//! normal motion, and nothing of the closed forms: the sticking oscillation, the sliding
//! impulse and the switches' search are all the integrator's.

use super::tangential::Mode;
use super::{NormalMotion, Oblique, ObliqueError, Scaled, prepare};
use crate::model::params::ImpactParams;
use crate::solver::roots::brent;
use differential_equations::interpolate::Interpolation;
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::prelude::{ControlFlag, Solout};
use differential_equations::solution::Solution;

type X = [f64; 3];

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
        match self.mode {
            Mode::Stick => self.s.kt * x[2].abs() - self.s.mu * p.force,
            Mode::Slip(sg) => self.s.mu * p.rate / self.s.kt - sg * vc,
        }
    }
}

impl<P: NormalMotion> ODE<f64, X> for Sys<'_, P> {
    fn diff(&self, t: f64, x: &X, dx: &mut X) {
        let ft = -self.s.kt * x[2];
        dx[0] = ft;
        dx[1] = -ft / self.s.kappa;
        dx[2] = match self.mode {
            Mode::Stick => x[0] - x[1],
            Mode::Slip(sg) => sg * self.s.mu * self.path.at(t).rate / self.s.kt,
        };
    }
}

/// Watches the switch function over each step (its end and four points inside, on the dense
/// output) and stops at the first crossing into positive after a negative value.
struct Watcher<'a, 'b, P: NormalMotion> {
    sys: &'b Sys<'a, P>,
    armed: bool,
    hit: Option<(f64, X)>,
    last: (f64, X),
}

impl<P: NormalMotion> Solout<f64, X> for Watcher<'_, '_, P> {
    fn solout<I>(
        &mut self,
        t_curr: f64,
        t_prev: f64,
        y_curr: &X,
        _y_prev: &X,
        interp: &mut I,
        _s: &mut Solution<f64, X>,
    ) -> ControlFlag<f64, X>
    where
        I: Interpolation<f64, X> + ?Sized,
    {
        self.last = (t_curr, *y_curr);
        let mut at = |t: f64| {
            if t == t_curr {
                *y_curr
            } else {
                interp.interpolate(t).unwrap_or(*y_curr)
            }
        };
        let mut prev: Option<(f64, f64)> = None;
        for j in 1..=5 {
            let t = t_prev + (t_curr - t_prev) * j as f64 / 5.0;
            let g = self.sys.switch(t, &at(t));
            if g > 0.0 {
                let start = match prev {
                    Some(p) if self.armed => p,
                    _ if !self.armed => (t_prev, 0.0),
                    _ => (t_prev, self.sys.switch(t_prev, &at(t_prev))),
                };
                let root = if start.1 < 0.0 {
                    let f = |t: f64| self.sys.switch(t, &at(t));
                    brent(f, start.0, t, start.1, g, 1e-15 * t_curr.max(1.0))
                } else {
                    start.0
                };
                self.hit = Some((root, at(root)));
                return ControlFlag::Terminate;
            }
            if g < 0.0 {
                self.armed = true;
                prev = Some((t, g));
            }
        }
        ControlFlag::Continue
    }
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
    let (mut t, mut x) = (0.0, [vx, spin, 0.0]);
    let mut switches = 0;
    let mut armed = false;
    for &stop in &stops {
        while t < stop {
            let mut method = ExplicitRungeKutta::dop853()
                .rtol(1e-13)
                .atol(1e-15)
                .max_steps(10_000_000);
            let mut w = Watcher {
                sys: &sys,
                armed,
                hit: None,
                last: (t, x),
            };
            solve_ode(&mut method, &sys, t, stop, &x, &mut w).expect("DOP853 runs");
            match w.hit {
                Some((th, xh)) => {
                    (t, x) = (th, xh);
                    switches += 1;
                    armed = false;
                    sys.mode = match sys.mode {
                        Mode::Stick => {
                            let sg = x[2].signum();
                            x[2] = sg * s.mu * path.at(t).force / s.kt;
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
    let p = prepare(params, v, oblique)?;
    let r = oblique.radius;
    let out = integrate(&p.path, &p.scaled, p.vx / p.vy, r * oblique.spin / p.vy);
    Ok((out.vx * p.vy, out.spin * p.vy / r, out.switches))
}
