//! Vertical flight of a ball between bounces under gravity and quadratic air drag
//! F = ½ ρ C_d A v² (docs/drop.md, "Flight"). Every quantity is a closed form; the test
//! `closed_forms_follow_the_integrated_flight` (tests/physics/drop_flight.rs) integrates the ODE
//! m v' = −m g ∓ k v|v| directly and checks them.
//!
//! With k = ½ ρ C_d A and x = k/m (1/m), the terminal speed is v_t = √(g/x) and:
//!
//! - fall from rest through s:  v² = (g/x)(1 − e^{−2 x s}),  t = (v_t/g) artanh(v/v_t),
//!   s(t) = (1/x) ln cosh(g t/v_t),  v(t) = v_t tanh(g t/v_t);
//! - rise from speed u:  h_max = (1/(2x)) ln(1 + x u²/g),  t_up = (v_t/g) atan(u/v_t),
//!   h(t) = (1/x) ln(cos(θ0 − g t/v_t)/cos θ0),  v(t) = v_t tan(θ0 − g t/v_t), θ0 = atan(u/v_t).
//!
//! Each form is written with `exp_m1`/`ln_1p` so that x → 0 tends to the vacuum forms
//! (v² = 2 g s, h_max = u²/(2g)) without loss of digits: the drag-free limit is continuous
//! (test `vanishing_drag_tends_to_vacuum`). x = 0 exactly takes the vacuum forms.

use serde::Serialize;

/// Standard gravity (m/s²), the CGPM's conventional value.
pub const G: f64 = 9.80665;
/// Air density at 20 °C and 101.325 kPa (kg/m³).
pub const AIR_DENSITY: f64 = 1.204;
/// Drag coefficient of a smooth sphere below the drag crisis (Reynolds numbers 10³ … 10⁵, those
/// of the drop tests here).
pub const SPHERE_DRAG_COEFFICIENT: f64 = 0.47;

/// The air a ball falls through.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Air {
    /// ρ (kg/m³).
    pub density: f64,
    /// C_d, dimensionless.
    pub drag_coefficient: f64,
}

impl Default for Air {
    fn default() -> Self {
        Air {
            density: AIR_DENSITY,
            drag_coefficient: SPHERE_DRAG_COEFFICIENT,
        }
    }
}

/// A ball in vertical flight: its mass and its drag constant per unit mass.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Flight {
    /// x = k/m = ½ ρ C_d π R² / m (1/m); 0 in vacuum.
    pub drag_per_mass: f64,
}

impl Flight {
    /// The flight of a ball of `mass` (kg) and `radius` (m) through `air` (`None`: vacuum).
    pub fn new(mass: f64, radius: f64, air: Option<Air>) -> Flight {
        let k = air.map_or(0.0, |a| {
            0.5 * a.density * a.drag_coefficient * std::f64::consts::PI * radius * radius
        });
        Flight {
            drag_per_mass: k / mass,
        }
    }

    /// Flight without air: free fall under gravity alone.
    pub fn vacuum() -> Flight {
        Flight { drag_per_mass: 0.0 }
    }

    /// Terminal speed v_t = √(g m/k) (m/s); infinite in vacuum.
    pub fn terminal_speed(&self) -> f64 {
        (G / self.drag_per_mass).sqrt()
    }

    /// Speed after falling `s` from rest: v² = (g/x)(1 − e^{−2xs}).
    pub fn fall_speed(&self, s: f64) -> f64 {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return (2.0 * G * s).sqrt();
        }
        (G * -(-2.0 * x * s).exp_m1() / x).sqrt()
    }

    /// Time to fall `s` from rest: t = (v_t/g) a, a = artanh(v/v_t) = arcosh(e^{xs}) (the
    /// inverse of `fall_at`'s s = (1/x) ln cosh a). Past xs = 1 (v/v_t = 0.93) it is read as
    /// a = xs + ln(1 + √(1 − e^{−2xs})): artanh loses the digits of 1 − v/v_t there and, v/v_t
    /// rounded to 1, gave t = ∞ from `drop --height 3000` on (tests/physics/drop_flight.rs,
    /// `a_fall_from_high_up_takes_a_finite_time`). Below, artanh as before: both agree to a
    /// few rounding units at the switch, and the drops of the goldens keep their bits.
    pub fn fall_time(&self, s: f64) -> f64 {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return (2.0 * s / G).sqrt();
        }
        let vt = self.terminal_speed();
        let a = if x * s <= 1.0 {
            (self.fall_speed(s) / vt).atanh()
        } else {
            x * s + (-(-2.0 * x * s).exp_m1()).sqrt().ln_1p()
        };
        (vt / G) * a
    }

    /// Distance fallen and speed (both ≥ 0, downward) at time `t` after release from rest:
    /// s = (1/x) ln cosh a, v = v_t tanh a, a = g t/v_t.
    pub fn fall_at(&self, t: f64) -> (f64, f64) {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return (0.5 * G * t * t, G * t);
        }
        let vt = self.terminal_speed();
        let a = G * t / vt;
        // ln cosh a = ln(1 + 2 sinh²(a/2)); for large a, a − ln 2 + ln(1 + e^{−2a})
        let ln_cosh = if a < 20.0 {
            (2.0 * (0.5 * a).sinh().powi(2)).ln_1p()
        } else {
            a - std::f64::consts::LN_2 + (-2.0 * a).exp().ln_1p()
        };
        (ln_cosh / x, vt * a.tanh())
    }

    /// Apex height above the launch point for an upward speed `u`: (1/(2x)) ln(1 + x u²/g).
    pub fn rise_height(&self, u: f64) -> f64 {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return u * u / (2.0 * G);
        }
        (x * u * u / G).ln_1p() / (2.0 * x)
    }

    /// Time to the apex for an upward speed `u`: (v_t/g) atan(u/v_t).
    pub fn rise_time(&self, u: f64) -> f64 {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return u / G;
        }
        let vt = self.terminal_speed();
        (vt / G) * (u / vt).atan()
    }

    /// Height above the launch point and upward speed at time `t` (≤ the rise time) after
    /// leaving with speed `u`: h = (1/x) ln(cos(θ0 − b)/cos θ0), v = v_t tan(θ0 − b), where
    /// b = g t/v_t; the ratio of cosines is 1 − 2 sin²(b/2) + tan θ0 sin b.
    pub fn rise_at(&self, u: f64, t: f64) -> (f64, f64) {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return (u * t - 0.5 * G * t * t, u - G * t);
        }
        let vt = self.terminal_speed();
        let (theta0, b) = ((u / vt).atan(), G * t / vt);
        let ratio_m1 = -2.0 * (0.5 * b).sin().powi(2) + (u / vt) * b.sin();
        (ratio_m1.ln_1p() / x, vt * (theta0 - b).tan())
    }

    /// The upward speed that rises to `h`: the inverse of [`Flight::rise_height`],
    /// u² = (g/x)(e^{2xh} − 1).
    pub fn launch_speed_for(&self, h: f64) -> f64 {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return (2.0 * G * h).sqrt();
        }
        (G * (2.0 * x * h).exp_m1() / x).sqrt()
    }

    /// How fast [`Flight::launch_speed_for`] grows with the height, du/dh: from
    /// u² = (g/x)(e^{2xh} − 1), 2u du = 2g e^{2xh} dh, so du/dh = g e^{2xh}/u (g/u in vacuum,
    /// where u = √(2gh)); infinite at h = 0.
    pub fn launch_speed_slope(&self, h: f64) -> f64 {
        G * (2.0 * self.drag_per_mass * h).exp() / self.launch_speed_for(h)
    }

    /// The fall from rest that ends at speed `v`: the inverse of [`Flight::fall_speed`],
    /// s = −ln(1 − x v²/g)/(2x); `None` at or above the terminal speed, which no fall reaches.
    pub fn fall_height_for(&self, v: f64) -> Option<f64> {
        let x = self.drag_per_mass;
        if x == 0.0 {
            return Some(v * v / (2.0 * G));
        }
        let a = x * v * v / G;
        (a < 1.0).then(|| -(-a).ln_1p() / (2.0 * x))
    }
}
