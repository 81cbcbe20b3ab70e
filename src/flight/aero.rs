//! The air's forces on a spinning ball in the vertical plane (docs/flight.md §1–2): drag
//! C_D against the Reynolds number, Magnus lift C_L against the spin parameter S = R|ω|/|v|,
//! and the spin's decay. Each preset's published model is [`Aero::for_ball`]'s, with its
//! source in docs/flight.md §2; a ball with none takes the smooth sphere's C_D, no lift and
//! no decay, and says so ([`Aero::assumed`]).

use serde::Serialize;

/// Dynamic viscosity of air at 20 °C (Pa s), the Reynolds number's μ (docs/flight.md §2).
pub const AIR_VISCOSITY: f64 = 1.81e-5;
/// 1 mph in m/s (exact: 0.44704).
const MPH: f64 = 0.44704;

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
    /// linear in ln Re between (docs/flight.md §2: the shape between is assumed).
    Crisis {
        /// Below this Re, `cd_low`.
        re_low: f64,
        /// C_D below the crisis.
        cd_low: f64,
        /// Above this Re, `cd_high`.
        re_high: f64,
        /// C_D above the crisis.
        cd_high: f64,
    },
}

impl Drag {
    /// C_D at Reynolds number `re`.
    #[inline]
    pub fn cd(&self, re: f64) -> f64 {
        match *self {
            Drag::Constant { cd } => cd,
            Drag::Crisis {
                re_low,
                cd_low,
                re_high,
                cd_high,
            } => {
                if re <= re_low {
                    cd_low
                } else if re >= re_high {
                    cd_high
                } else {
                    let f = (re / re_low).ln() / (re_high / re_low).ln();
                    cd_low + f * (cd_high - cd_low)
                }
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
}

impl Lift {
    /// C_L at spin parameter `s` ≥ 0.
    #[inline]
    pub fn cl(&self, s: f64) -> f64 {
        match *self {
            Lift::Constant { cl } => cl,
            Lift::Rational { c0, c1, c2 } => c2 * s / (c0 + c1 * s),
        }
    }
}

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
    /// The published model of a preset `name` in air of density `rho` (docs/flight.md §2),
    /// or [`Aero::assumed`] for a ball with none.
    pub fn for_ball(name: Option<&str>, rho: f64) -> Aero {
        let published = |drag, lift, decay, source| Aero {
            air_density: rho,
            drag,
            lift,
            decay,
            assumed: false,
            source,
        };
        match name {
            // Cross & Lindsey (2014): C_D = 0.507 ± 0.024 in free flight, independent of speed
            // and spin (15–30 m/s); Štěpánek (1988): C_L = 1/(2.022 + 0.981/S)
            Some("tennis") => published(
                Drag::Constant { cd: 0.507 },
                Lift::Rational {
                    c0: 0.981,
                    c1: 2.022,
                    c2: 1.0,
                },
                Decay::None,
                "C_D Cross & Lindsey 2014; C_L Stepanek 1988; no spin decay (none published found)",
            ),
            // Nathan's trajectory calculator: C_L = 1.120 S/(0.583 + 2.333 S), spin decaying
            // as exp(−(t/30 s)(|v|/100 mph)); C_D: none found, the smooth sphere's assumed
            Some("baseball") => published(
                Drag::Constant { cd: SMOOTH_CD },
                Lift::Rational {
                    c0: 0.583,
                    c1: 2.333,
                    c2: 1.120,
                },
                Decay::PerMetre {
                    k: 1.0 / (30.0 * 100.0 * MPH),
                },
                "C_L and spin decay Nathan's calculator; C_D assumed 0.47 (smooth sphere)",
            ),
            // Jenkins et al. (2018): 0.24 < C_D < 0.7 over 3·10⁴ < Re < 1.08·10⁵ (the dimpled
            // ball's crisis); Smits & Smith (1994): spin loss 0.0004 (1/mph/s) × speed × spin;
            // C_L: none found, no lift assumed
            Some("golf") => published(
                Drag::Crisis {
                    re_low: 3.0e4,
                    cd_low: 0.7,
                    re_high: 1.08e5,
                    cd_high: 0.24,
                },
                Lift::Constant { cl: 0.0 },
                Decay::PerMetre { k: 0.0004 / MPH },
                "C_D Jenkins et al. 2018 (crisis); spin decay Smits & Smith 1994; no lift (none found)",
            ),
            _ => Aero::assumed(rho),
        }
    }

    /// A ball with no published model: the smooth sphere's C_D = 0.47, no lift, no decay.
    pub fn assumed(rho: f64) -> Aero {
        Aero {
            air_density: rho,
            drag: Drag::Constant { cd: SMOOTH_CD },
            lift: Lift::Constant { cl: 0.0 },
            decay: Decay::None,
            assumed: true,
            source: "assumed: C_D 0.47 (smooth sphere), no lift, no spin decay",
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
