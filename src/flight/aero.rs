//! The air's forces on a spinning ball in the vertical plane (docs/flight.md §1–2): drag
//! C_D against the Reynolds number, Magnus lift C_L against the spin parameter S = R|ω|/|v|,
//! and the spin's decay. The published models are [`super::Published`]'s (`published.rs`),
//! each with its source in docs/flight.md §2; a ball with none takes the smooth sphere's C_D,
//! no lift and no decay, and says so ([`Aero::assumed`]).

use serde::Serialize;

/// Dynamic viscosity of air at 20 °C (Pa s), the Reynolds number's μ (docs/flight.md §2).
pub const AIR_VISCOSITY: f64 = 1.81e-5;
/// 1 rad/s in thousands of rpm: 30/(π · 1000).
const RAD_S_IN_KRPM: f64 = 30.0 / (std::f64::consts::PI * 1000.0);

/// The drag coefficient's model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Drag {
    /// C_D fixed.
    Constant {
        /// C_D.
        cd: f64,
    },
    /// A drag crisis: C_D = `cd_low` below Re = `re_low`, `cd_high` above `re_high`, and
    /// a smoothstep in ln Re between (docs/flight.md §2: the shape between is assumed), plus
    /// `cd_per_spin` × S (a spinning ball's extra drag, Smits & Smith's 0.18 S for golf).
    Crisis {
        /// Below this Re, `cd_low`.
        re_low: f64,
        /// C_D below the crisis.
        cd_low: f64,
        /// Above this Re, `cd_high`.
        re_high: f64,
        /// C_D above the crisis.
        cd_high: f64,
        /// dC_D/dS: the drag added by spin.
        cd_per_spin: f64,
    },
    /// C_D = `cd0` + `per_krpm` × |ω| in thousands of rpm: Nathan's calculator's spin
    /// drag (docs/flight.md §2, source 3: 0.3008 + 0.0292 per 1000 rpm), |ω| the present spin.
    Spin {
        /// C_D without spin.
        cd0: f64,
        /// dC_D per 1000 rpm.
        per_krpm: f64,
    },
}

impl Drag {
    /// C_D at Reynolds number `re`, spin parameter `s` = R|ω|/|v| and spin `w` (rad/s).
    #[inline]
    pub fn cd(&self, re: f64, s: f64, w: f64) -> f64 {
        match *self {
            Drag::Constant { cd } => cd,
            Drag::Spin { cd0, per_krpm } => cd0 + per_krpm * w.abs() * RAD_S_IN_KRPM,
            Drag::Crisis {
                re_low,
                cd_low,
                re_high,
                cd_high,
                cd_per_spin,
            } => {
                let crisis = if re <= re_low {
                    cd_low
                } else if re >= re_high {
                    cd_high
                } else {
                    // smoothstep in ln Re: C¹ at both ends (a kink costs the integrations
                    // their order, see `table`); the shape between is assumed
                    let f = (re / re_low).ln() / (re_high / re_low).ln();
                    cd_low + f * f * (3.0 - 2.0 * f) * (cd_high - cd_low)
                };
                crisis + cd_per_spin * s
            }
        }
    }
}

impl Drag {
    /// C_D in flight at speed `v` with R|ω| = `rw` and spin `w`, in air of density `rho`,
    /// ball radius `r`: [`Drag::cd`] with the Reynolds number and S = R|ω|/|v| formed only
    /// where the model uses them (S = 0 at rest).
    #[inline]
    pub fn cd_flying(&self, rho: f64, r: f64, v: f64, rw: f64, w: f64) -> f64 {
        match *self {
            Drag::Constant { cd } => cd,
            Drag::Spin { .. } => self.cd(0.0, 0.0, w),
            Drag::Crisis { .. } => {
                let s = if v == 0.0 { 0.0 } else { rw / v };
                self.cd(reynolds(rho, v, r), s, w)
            }
        }
    }
}

/// The lift coefficient's model, a function of S = R|ω|/|v| ≥ 0; the force's side is ω's sign.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Lift {
    /// C_L fixed (while the ball spins; none without spin).
    Constant {
        /// C_L.
        cl: f64,
    },
    /// C_L = c2 S/(c0 + c1 S): Štěpánek's tennis form 1/(2.022 + 0.981/S) is c2 = 1,
    /// c0 = 0.981, c1 = 2.022; Nathan's baseball form 1.120 S/(0.583 + 2.333 S) as written.
    Rational {
        /// c0.
        c0: f64,
        /// c1.
        c1: f64,
        /// c2.
        c2: f64,
    },
    /// C_L through tabulated (S, C_L) points by a monotone cubic, S increasing from (0, 0),
    /// held beyond the last point (Smits & Smith's golf table, docs/flight.md §2).
    Table {
        /// (S, C_L), S increasing.
        points: &'static [(f64, f64)],
    },
}

impl Lift {
    /// C_L at spin parameter `s` ≥ 0.
    #[inline]
    pub fn cl(&self, s: f64) -> f64 {
        match *self {
            Lift::Constant { cl } => cl,
            Lift::Rational { c0, c1, c2 } => c2 * s / (c0 + c1 * s),
            Lift::Table { points } => table(points, s),
        }
    }

    /// `q` C_L(S) |v| at S = `rw`/`v` (`rw` = R|ω| ≥ 0; `q` = ½ρA/m): the lift's
    /// acceleration over |v|, 0 without spin or speed. The rational form is taken as
    /// q c2 R|ω| |v|/(c0 |v| + c1 R|ω|): one division where C_L(S) has two one after the other
    /// (the same number to rounding; the other forms as before, bit for bit).
    #[inline]
    pub fn lift_per_speed(&self, q: f64, rw: f64, v: f64) -> f64 {
        if rw == 0.0 || v == 0.0 {
            return 0.0;
        }
        match *self {
            Lift::Constant { cl } => q * cl * v,
            Lift::Rational { c0, c1, c2 } => q * (c2 * rw * v / (c0 * v + c1 * rw)),
            Lift::Table { points } => q * table(points, rw / v) * v,
        }
    }
}

/// The monotone cubic Hermite interpolant (Fritsch & Butland's slopes, as SciPy's PCHIP) of
/// `points` (S increasing) at `s`: through every point, C¹, monotone where the data are,
/// continued straight with its slope below the first point and held at the last point's
/// value beyond it (its slope there 0: no extrapolation past the data). Smooth rather than
/// piecewise linear because a kink in a force costs the step-controlled integrations their
/// order at each crossing (tests/physics/flight.rs `an_independent_dop853_agrees` saw 2e-9 apart
/// with kinks); written here because it is a dozen lines on five points, on the hot path.
#[inline]
fn table(points: &[(f64, f64)], s: f64) -> f64 {
    let n = points.len();
    match n {
        0 => return 0.0,
        1 => return points[0].1,
        _ => {}
    }
    let secant = |i: usize| (points[i + 1].1 - points[i].1) / (points[i + 1].0 - points[i].0);
    let width = |i: usize| points[i + 1].0 - points[i].0;
    // the slope at point i
    let slope = |i: usize| -> f64 {
        if n == 2 {
            return secant(0);
        }
        let end = |h0: f64, h1: f64, d0: f64, d1: f64| {
            // three-point one-sided slope, kept to the secant's sign and under 3 secants
            let m = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
            if m.signum() != d0.signum() {
                0.0
            } else if d0.signum() != d1.signum() && m.abs() > 3.0 * d0.abs() {
                3.0 * d0
            } else {
                m
            }
        };
        if i == 0 {
            end(width(0), width(1), secant(0), secant(1))
        } else if i == n - 1 {
            0.0
        } else {
            let (d0, d1, h0, h1) = (secant(i - 1), secant(i), width(i - 1), width(i));
            if d0 * d1 <= 0.0 {
                0.0
            } else {
                let (w1, w2) = (2.0 * h1 + h0, h1 + 2.0 * h0);
                (w1 + w2) / (w1 / d0 + w2 / d1)
            }
        }
    };
    let (s0, c0) = points[0];
    if s <= s0 {
        return c0 + slope(0) * (s - s0);
    }
    let (sn, cn) = points[n - 1];
    if s >= sn {
        return cn;
    }
    let i = points
        .iter()
        .rposition(|p| p.0 <= s)
        .unwrap_or(0)
        .min(n - 2);
    let (h, t) = (width(i), (s - points[i].0) / width(i));
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * points[i].1
        + (t3 - 2.0 * t2 + t) * h * slope(i)
        + (-2.0 * t3 + 3.0 * t2) * points[i + 1].1
        + (t3 - t2) * h * slope(i + 1)
}

/// Smits & Smith's (1994) golf C_L against S, as tabulated from their model by the secondary
/// sources of docs/flight.md §2, source 5; Bearman & Harvey's (1976) measurements agree within 0.02
/// over 0.05 < S < 0.3 (docs/flight.md §2).
pub const GOLF_LIFT: [(f64, f64); 5] = [
    (0.0, 0.0),
    (0.04, 0.10),
    (0.10, 0.16),
    (0.20, 0.23),
    (0.40, 0.33),
];

/// How the spin decays in flight.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Decay {
    /// None.
    None,
    /// dω/dt = −ω/τ.
    Time {
        /// τ (s).
        tau: f64,
    },
    /// dω/dt = −k |v| ω (k in 1/m): Nathan's and Smits & Smith's rates grow with speed.
    PerMetre {
        /// k (1/m).
        k: f64,
    },
}

impl Decay {
    /// dω/dt at spin `w` and speed `v`.
    #[inline]
    pub fn rate(&self, w: f64, v: f64) -> f64 {
        match *self {
            Decay::None => 0.0,
            Decay::Time { tau } => -w / tau,
            Decay::PerMetre { k } => -k * v * w,
        }
    }
}

/// The air and a ball's aerodynamic models.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Aero {
    /// ρ (kg/m³).
    pub air_density: f64,
    /// C_D(Re).
    pub drag: Drag,
    /// C_L(S).
    pub lift: Lift,
    /// The spin's decay.
    pub decay: Decay,
    /// Whether the whole model is assumed (no published one found for the ball).
    pub assumed: bool,
    /// Where each part comes from, or what was assumed (docs/flight.md §2).
    pub source: &'static str,
}

/// Smooth sphere below the drag crisis (the drop tests' C_D, docs/drop.md).
const SMOOTH_CD: f64 = crate::drop::flight::SPHERE_DRAG_COEFFICIENT;

impl Aero {
    /// A ball with no published model: the smooth sphere's C_D = 0.47, no lift, no decay.
    pub fn assumed(rho: f64) -> Aero {
        Aero {
            air_density: rho,
            drag: Drag::Constant { cd: SMOOTH_CD },
            lift: Lift::Constant { cl: 0.0 },
            decay: Decay::None,
            assumed: true,
            source: "assumed: C_D 0.47 (smooth sphere), no lift, no spin decay (no \
                     published model for this ball: a preset names its with `aerodynamics`, \
                     docs/flight.md §2)",
        }
    }

    /// Vacuum: no drag, no lift (the spin's decay kept).
    pub fn vacuum(&self) -> Aero {
        Aero {
            drag: Drag::Constant { cd: 0.0 },
            lift: Lift::Constant { cl: 0.0 },
            ..*self
        }
    }
}

/// The Reynolds number of a ball of radius `r` at speed `v` in air of density `rho`.
#[inline]
pub fn reynolds(rho: f64, v: f64, r: f64) -> f64 {
    rho * v * 2.0 * r / AIR_VISCOSITY
}
