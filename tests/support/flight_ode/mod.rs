//! The flight's equations of motion written anew (docs/flight.md §1) and integrated by the
//! `differential_equations` crate's DOP853 with events: the independent check of a shot's
//! landings (tests/physics/flight.rs).

use bouncelab::flight::{Aero, Decay, aero::reynolds};
use bouncelab::solver::each_step::{EachStep, EndState, Watched};
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;

/// The equations of motion written anew (docs/flight.md §1) for the crate's DOP853.
pub struct Air {
    pub aero: Aero,
    pub r: f64,
    pub q: f64,
}

pub type X = [f64; 5];

impl ODE<f64, X> for Air {
    fn diff(&self, _t: f64, s: &X, d: &mut X) {
        let [_, _, vx, vy, w] = *s;
        let v = (vx * vx + vy * vy).sqrt();
        let sp = self.r * w.abs() / v;
        let cd = self
            .aero
            .drag
            .cd(reynolds(self.aero.air_density, v, self.r), sp, w);
        let cl = if w == 0.0 {
            0.0
        } else {
            self.aero.lift.cl(sp) * w.signum()
        };
        // F_D = −½ρAC_D|v|v; F_L = ½ρAC_L|v|² along (v_y, −v_x)/|v| for topspin
        let drag = -self.q * cd * v;
        let lift = self.q * cl * v;
        d[0] = vx;
        d[1] = vy;
        d[2] = drag * vx + lift * vy;
        d[3] = -G + drag * vy - lift * vx;
        d[4] = match self.aero.decay {
            Decay::None => 0.0,
            Decay::Time { tau } => -w / tau,
            Decay::PerMetre { k } => -k * v * w,
        };
    }
}

/// Stops at the first step that ends with y < R.
pub struct Below {
    r: f64,
    hit: Option<(f64, X, f64)>,
}

impl EachStep<X> for Below {
    fn watch(
        &mut self,
        (t_prev, y_prev): (f64, &X),
        (t, y): (f64, &X),
        _: &mut impl FnMut(f64) -> X,
    ) -> bool {
        if y[1] < self.r {
            self.hit = Some((t_prev, *y_prev, t));
            return true;
        }
        false
    }
}

pub fn dop853(air: &Air, t0: f64, x0: &X, t1: f64, out: &mut impl EachStep<X>) {
    let mut m = ExplicitRungeKutta::dop853()
        .rtol(1e-13)
        .atol(1e-13)
        .max_steps(10_000_000);
    solve_ode(&mut m, air, t0, t1, x0, &mut Watched(out)).expect("DOP853 runs");
}

/// The state at t1 from (t0, x0).
pub fn to(air: &Air, t0: f64, x0: &X, t1: f64) -> X {
    if t1 <= t0 {
        return *x0;
    }
    let mut last = EndState(t0, *x0);
    dop853(air, t0, x0, t1, &mut last);
    last.1
}

/// The landing after (t0, x0): the step that goes below R, then bisection on t, every value
/// integrated from that step's start.
pub fn land(air: &Air, t0: f64, x0: &X) -> (f64, X) {
    let mut below = Below {
        r: air.r,
        hit: None,
    };
    dop853(air, t0, x0, t0 + 100.0, &mut below);
    let (ta, xa, tb) = below.hit.expect("lands");
    let (mut lo, mut hi) = (ta, tb);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if to(air, ta, &xa, mid)[1] >= air.r {
            lo = mid
        } else {
            hi = mid
        }
    }
    (hi, to(air, ta, &xa, hi))
}
