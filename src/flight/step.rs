//! One flight between two contacts: the equations of motion (docs/flight.md §1) and their
//! integration by Dormand–Prince 5(4) with step control, written here rather than taken from
//! `differential-equations` because a shot must cost microseconds (the crate's solver builds
//! a `Solution` and its dense output on every call) and because the events are located by
//! integrating to them from the step's start, not on a dense output. The crate's DOP853 is the
//! independent check (tests/physics/flight.rs, `an_independent_dop853_agrees`).

use super::aero::Aero;
use crate::drop::G;

/// The state: x, y (m), v_x, v_y (m/s), ω (rad/s) and the drag's work per unit mass (J/kg).
pub type Y = [f64; 6];

/// The relative and absolute tolerance of a step (its error norm ≤ 1).
pub const TOL: f64 = 5e-12;

/// A ball in the air: its aerodynamics and what they act on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// The air and the models.
    pub aero: Aero,
    /// R (m).
    pub radius: f64,
    /// ½ ρ A / m (1/m), A = πR².
    pub q: f64,
}

impl Body {
    /// A ball of `mass` and `radius` in `aero`.
    pub fn new(aero: Aero, mass: f64, radius: f64) -> Body {
        let q = 0.5 * aero.air_density * std::f64::consts::PI * radius * radius / mass;
        Body { aero, radius, q }
    }

    /// dY/dt: gravity, drag −½ρAC_D|v|v, lift ½ρAC_L|v| sign(ω) (v_y, −v_x) (topspin pushes
    /// a ball moving in +x down), dω/dt by the decay, and the drag's power |F_D·v|/m.
    /// C_D|v| and C_L|v| are formed by the models from R|ω| and |v| with as few divisions on
    /// the way as each needs (`Drag::cd_flying`, `Lift::lift_per_speed`): a step is six of
    /// these in a row, each waiting on the last (benches/shot.rs).
    #[inline]
    pub fn rate(&self, y: &Y) -> Y {
        let (vx, vy, w) = (y[2], y[3], y[4]);
        let v = (vx * vx + vy * vy).sqrt();
        let rw = self.radius * w.abs();
        let cd = self
            .aero
            .drag
            .cd_flying(self.aero.air_density, self.radius, v, rw, w);
        let d = self.q * cd * v;
        let l = self.aero.lift.lift_per_speed(self.q, rw, v).copysign(w);
        [
            vx,
            vy,
            -d * vx + l * vy,
            -G - d * vy - l * vx,
            self.aero.decay.rate(w, v),
            d * v * v,
        ]
    }

    /// One Dormand–Prince 5(4) step of size `h` from `y0` whose first stage is `k1`: the
    /// fifth-order state, its rate (the next step's first stage) and the error norm's square
    /// (the step is accepted where it is at most 1; its square root is left to `next_size`'s
    /// power, one operation fewer between a step and the next).
    pub fn step(&self, y0: &Y, k1: &Y, h: f64) -> (Y, Y, f64) {
        let at = |ks: &[(&Y, f64)]| -> Y {
            let mut y = *y0;
            for (k, a) in ks {
                for i in 0..6 {
                    y[i] += h * a * k[i];
                }
            }
            y
        };
        let k2 = self.rate(&at(&[(k1, 1.0 / 5.0)]));
        let k3 = self.rate(&at(&[(k1, 3.0 / 40.0), (&k2, 9.0 / 40.0)]));
        let k4 = self.rate(&at(&[
            (k1, 44.0 / 45.0),
            (&k2, -56.0 / 15.0),
            (&k3, 32.0 / 9.0),
        ]));
        let k5 = self.rate(&at(&[
            (k1, 19372.0 / 6561.0),
            (&k2, -25360.0 / 2187.0),
            (&k3, 64448.0 / 6561.0),
            (&k4, -212.0 / 729.0),
        ]));
        let k6 = self.rate(&at(&[
            (k1, 9017.0 / 3168.0),
            (&k2, -355.0 / 33.0),
            (&k3, 46732.0 / 5247.0),
            (&k4, 49.0 / 176.0),
            (&k5, -5103.0 / 18656.0),
        ]));
        let y1 = at(&[
            (k1, 35.0 / 384.0),
            (&k3, 500.0 / 1113.0),
            (&k4, 125.0 / 192.0),
            (&k5, -2187.0 / 6784.0),
            (&k6, 11.0 / 84.0),
        ]);
        let k7 = self.rate(&y1);
        // the fifth- minus the fourth-order weights
        let e = [
            71.0 / 57600.0,
            0.0,
            -71.0 / 16695.0,
            71.0 / 1920.0,
            -17253.0 / 339200.0,
            22.0 / 525.0,
            -1.0 / 40.0,
        ];
        let ks = [k1, &k2, &k3, &k4, &k5, &k6, &k7];
        let mut sum = 0.0;
        // the work is a diagnostic: x, y, v_x, v_y and ω set the step
        for i in 0..5 {
            let err: f64 = h * (0..7).map(|j| e[j] * ks[j][i]).sum::<f64>();
            let scale = TOL + TOL * y0[i].abs().max(y1[i].abs());
            sum += (err / scale).powi(2);
        }
        (y1, k7, sum / 5.0)
    }

    /// The state `h` after `y0` in steps no longer than `h0`, the first of size ≤ `h0`
    /// (a sample or an event inside an accepted step: one step from its start).
    pub fn advance(&self, y0: &Y, h: f64) -> Y {
        if h == 0.0 {
            return *y0;
        }
        self.step(y0, &self.rate(y0), h).0
    }
}

/// The size of the step after one of size `h` whose error norm's square is `err2`: the
/// usual 0.9 err^(−1/5), as 0.9 (err²)^(−1/10), held to 0.2 … 5 times `h`.
pub fn next_size(h: f64, err2: f64) -> f64 {
    let f = if err2 == 0.0 {
        5.0
    } else {
        (0.9 * err2.powf(-0.1)).clamp(0.2, 5.0)
    };
    h * f
}

/// The step size h* in [0, h] at which component `i` (0: x, 1: y) of one step from `y0` reaches
/// `target`, given that it has not at 0 and has at h: safeguarded Newton on h (its derivative
/// the component's rate, the velocity y[i + 2]), every value one step from `y0`; the h* whose
/// state is nearest the target, and that state. `k1` is the rate at `y0` and `y_h` the step of
/// size h from it, both already computed by the accepted step (taken, not recomputed: the same
/// numbers to the last bit, a step and a rate fewer per event; benches/shot.rs).
pub fn locate(
    body: &Body,
    (y0, k1): (&Y, &Y),
    (h, y_h): (f64, &Y),
    i: usize,
    target: f64,
) -> (f64, Y) {
    debug_assert!(i < 2, "locate finds x or y");
    let at = |x: f64| body.step(y0, k1, x).0;
    let above = y0[i] > target;
    let (mut lo, mut hi) = (0.0, h);
    let (f0, f1) = (y0[i] - target, y_h[i] - target);
    let mut x = if f0 != f1 { h * f0 / (f0 - f1) } else { h };
    let mut best = (h, *y_h, f1.abs());
    for _ in 0..60 {
        let y = at(x);
        let f = y[i] - target;
        if f.abs() < best.2 {
            best = (x, y, f.abs());
        }
        if f == 0.0 {
            break;
        }
        if (f > 0.0) == above {
            lo = x;
        } else {
            hi = x;
        }
        // d(x, y)/dt is (v_x, v_y): `rate`'s first two components, copied from the state
        let slope = y[i + 2];
        let mut next = x - f / slope;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - x).abs() <= f64::EPSILON * x.abs() {
            break;
        }
        x = next;
    }
    (best.0, best.1)
}
