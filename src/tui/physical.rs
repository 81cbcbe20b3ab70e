//! The physical inputs the form (`m`) edits — m, R, K_p, K_r, c, z_p, E besides λ, ζ, v0 —
//! their checks, and whether a run stays inside the model's validity (indentation and ball
//! displacement below the radius).
//!
//! E is the contact modulus as the model ties it to K_p for an elastomer ball: flattening at
//! the mean pressure p0 = E z_p/R (Eq. 20) gives K_p = 2π E z_p (Eqs. 15–17; docs/model.md
//! §3). The form shows E = K_p/(2π z_p) of the current values, and a typed E sets K_p = 2π E
//! z_p, z_p kept: what `run --k-p` with that K_p runs. A metal ball's K_p follows its yield
//! strength instead (p0 = 2.2 S_y), and its E is not offered.
//!
//! Each value is checked by the command line's own path: K_p, c, K_r, z_p by
//! [`crate::api::Overrides::apply`] (as `run --k-p/--damping/--k-r/--z-p`, K_h following K_p
//! and z_p by Eq. 16), m by `check_positive`, λ, ζ, v0 by [`Param::check`]; then the whole set
//! by [`ImpactParams::validate`]. Refused, never clamped: the message names the range.

use super::format::{screen_unit, value};
use super::param::Param;
use super::setting::Setting;
use crate::api::Overrides;
use crate::model::params::{self, ImpactParams, MEANINGFUL_MAX, MEANINGFUL_MIN};
use crate::text::short;

pub mod conditions;
mod refusal;
mod surface;
mod target;
mod validity;
use refusal::ball_refusal;
pub use refusal::refusal;
pub use target::closing_check;
use target::{closing, target_set};
pub use validity::validity;

/// A field of the form, in the order shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    Mass,
    Radius,
    KP,
    KR,
    C,
    ZP,
    /// The contact modulus E, tied to K_p by K_p = 2π E z_p (elastomers, Eq. 20).
    E,
    Lambda,
    Zeta,
    V0,
    /// The inflation (gauge) pressure p, as `--pressure` (inflated balls; issue 56).
    Pressure,
    /// The ball's temperature T, °C, as `--temperature`.
    Temperature,
    /// The target's mass M (∞: the wall; docs/targets.md).
    TargetMass,
    /// The target's speed toward the ball v_t.
    TargetSpeed,
    /// The target surface's stiffness K_s (∞: rigid).
    TargetStiffness,
    /// The damping c_s in parallel with K_s.
    TargetDamping,
    /// The surface's Coulomb friction μ (issue 53 item 1): the oblique view's, which the
    /// surface picker sets and the court pace is rated at; the flight view's bounce too.
    Friction,
    /// The surface's tangential stiffness K_t (N/m; the ball's Mindlin value until set): the
    /// oblique view's, as `oblique --tangential-stiffness`.
    TangentialStiffness,
    /// The tangential dashpot c_t beside K_t (the surface's; `oblique --tangential-damping`).
    TangentialDamping,
}

impl Field {
    pub const ALL: [Field; 19] = [
        Field::Mass,
        Field::Radius,
        Field::KP,
        Field::KR,
        Field::C,
        Field::ZP,
        Field::E,
        Field::Lambda,
        Field::Zeta,
        Field::V0,
        Field::Pressure,
        Field::Temperature,
        Field::TargetMass,
        Field::TargetSpeed,
        Field::TargetStiffness,
        Field::TargetDamping,
        Field::Friction,
        Field::TangentialStiffness,
        Field::TangentialDamping,
    ];

    pub fn symbol(self) -> &'static str {
        match self {
            Field::Mass => "m",
            Field::Radius => "R",
            Field::KP => "K_p",
            Field::KR => "K_r",
            Field::C => "c",
            Field::ZP => "z_p",
            Field::E => "E",
            Field::Lambda => "λ",
            Field::Zeta => "ζ",
            Field::V0 => "v0",
            Field::Pressure => "p",
            Field::Temperature => "T",
            Field::TargetMass => "M",
            Field::TargetSpeed => "v_t",
            Field::TargetStiffness => "K_s",
            Field::TargetDamping => "c_s",
            Field::Friction => "μ",
            Field::TangentialStiffness => "K_t",
            Field::TangentialDamping => "c_t",
        }
    }

    /// The SI unit values are typed in (as the command line's overrides take them).
    pub fn unit(self) -> &'static str {
        match self {
            Field::Mass | Field::TargetMass => "kg",
            Field::Radius | Field::ZP => "m",
            Field::KP | Field::KR | Field::TargetStiffness | Field::TangentialStiffness => "N/m",
            Field::C | Field::TargetDamping | Field::TangentialDamping => "kg/s",
            Field::E | Field::Pressure => "Pa",
            Field::Temperature => "°C",
            Field::V0 | Field::TargetSpeed => "m/s",
            Field::Lambda | Field::Zeta | Field::Friction => "",
        }
    }

    /// The unit the form shows and takes the field in — the readout's (m in g, R and z_p in
    /// mm: [`screen_unit`]) — and the factor from SI to it (issue 51 item 4: the form wrote
    /// m in kg to six digits beside a readout in g).
    pub fn screen(self) -> (&'static str, f64) {
        // a pressure reads in kPa, as the readout's conditions line states it
        if self == Field::Pressure {
            return ("kPa", 1e-3);
        }
        screen_unit(self.unit())
    }

    /// `v` (SI) as the form writes it: four significant digits ([`value`]) in the field's
    /// screen unit, "∞" (the wall's M, a rigid K_s), "—" for none (a metal ball's E).
    pub fn show(self, v: f64) -> String {
        let (unit, k) = self.screen();
        let n = if v.is_nan() {
            "—".to_string()
        } else if v == f64::INFINITY {
            "∞".to_string()
        } else {
            value(v * k)
        };
        if unit.is_empty() {
            n
        } else {
            format!("{n} {unit}")
        }
    }

    /// The live parameter this field is, if it is one.
    fn live(self) -> Option<Param> {
        match self {
            Field::Lambda => Some(Param::Lambda),
            Field::Zeta => Some(Param::Zeta),
            Field::V0 => Some(Param::V0),
            _ => None,
        }
    }

    /// The field's value in `s` (SI).
    pub fn get(self, s: &Setting) -> f64 {
        let p = &s.params;
        match self {
            Field::Mass => p.mass,
            Field::Radius => s.radius,
            Field::KP => p.k_p,
            Field::KR => p.k_r,
            Field::C => p.damping,
            Field::ZP => p.z_p,
            Field::E if s.elastomer => modulus(p),
            Field::E => f64::NAN,
            Field::TargetMass => s.target.mass,
            Field::TargetSpeed => s.target.speed,
            Field::TargetStiffness => s.target.stiffness,
            Field::TargetDamping => s.target.damping,
            Field::TangentialDamping => s.tangential_damping.unwrap_or(0.0),
            // the oblique view holds μ and K_t: `App::form_value` reads them there
            Field::Friction | Field::TangentialStiffness => f64::NAN,
            // as typed, else the record's; NaN ("—") where the ball has none
            Field::Pressure => s
                .conditions
                .pressure
                .or(s.record.pressure)
                .unwrap_or(f64::NAN),
            Field::Temperature => s
                .conditions
                .temperature
                .or(s.record.temperature)
                .unwrap_or(f64::NAN),
            Field::Lambda | Field::Zeta | Field::V0 => self.live().map_or(f64::NAN, |q| s.get(q)),
        }
    }

    /// The range the command line holds a positive input to, e.g. "1e-15 … 1e15 N/m".
    pub fn range_text(self) -> String {
        if let Some(p) = self.surface_param() {
            return p.range_text().into();
        }
        match self.live() {
            Some(p) => p.range_text(),
            None if self == Field::TargetMass => format!(
                "{} … {} {}, or inf (the wall)",
                short(MEANINGFUL_MIN * self.screen().1, 4),
                short(MEANINGFUL_MAX * self.screen().1, 4),
                self.screen().0
            ),
            None if self == Field::TargetSpeed => "v0 + v_t > 0 m/s".into(),
            None if self == Field::TargetStiffness => format!(
                "{} … {} N/m, or inf (rigid)",
                short(MEANINGFUL_MIN, 4),
                short(MEANINGFUL_MAX, 4)
            ),
            None if self == Field::TangentialDamping => {
                format!("0 … {} kg/s (0: none)", short(MEANINGFUL_MAX, 4))
            }
            None if self == Field::TargetDamping => {
                format!("0 … {} kg/s, with K_s", short(MEANINGFUL_MAX, 4))
            }
            None if self == Field::Pressure => {
                "a gauge pressure in kPa, or with its unit (0.8bar, 8psi); inflated balls".into()
            }
            None if self == Field::Temperature => "above −273.15 °C".into(),
            None => format!(
                "{} … {} {}",
                short(MEANINGFUL_MIN * self.screen().1, 4),
                short(MEANINGFUL_MAX * self.screen().1, 4),
                self.screen().0
            ),
        }
    }

    /// `s` with this field set to `value`, if the command line takes it; or why not, with the
    /// range. K_p, K_r, c, z_p go through [`Overrides::apply`]; m keeps λ and ζ's meaning only
    /// through K_p and c, as `run` does (ζ moves with m).
    pub fn check(self, value: f64, s: &Setting) -> Result<Setting, String> {
        if let Some(p) = self.live() {
            let params = p.check(value, &s.params)?;
            let next = Setting {
                params,
                ..s.clone()
            };
            closing(&next).map_err(|e| format!("{e}; {} kept", self.symbol()))?;
            return Ok(next);
        }
        let refuse =
            |e: String| format!("{e}; {} kept (range {})", self.symbol(), self.range_text());
        let mut next = s.clone();
        match self {
            Field::Mass => {
                params::check_positive(params::Field::Mass, value)
                    .map_err(|e| refuse(refusal(&e)))?;
                next.params.mass = value;
            }
            Field::Radius => {
                if !(MEANINGFUL_MIN..=MEANINGFUL_MAX).contains(&value) {
                    return Err(refuse(format!("invalid R: {}", self.shown(value))));
                }
                next.radius = value;
            }
            Field::TargetMass
            | Field::TargetSpeed
            | Field::TargetStiffness
            | Field::TargetDamping => next = target_set(self, value, s).map_err(refuse)?,
            // as `oblique --tangential-damping` takes it: finite, ≥ 0 (0: none)
            Field::TangentialDamping => {
                if !(0.0..=MEANINGFUL_MAX).contains(&value) {
                    return Err(refuse(format!(
                        "invalid tangential_damping: {}",
                        self.shown(value)
                    )));
                }
                next.tangential_damping = (value > 0.0).then_some(value);
            }
            // the preset's record is needed: App::submit_physical takes these
            // (physical::conditions::set)
            Field::Pressure | Field::Temperature => {
                return Err(format!("{} is set with its ball's record", self.symbol()));
            }
            // the oblique view's values: App::submit_physical sets them (physical/surface.rs)
            Field::Friction | Field::TangentialStiffness => {
                return Err(format!("{} is the oblique view's", self.symbol()));
            }
            Field::KP | Field::E if conditions::k_p_refused(s).is_some() => {
                let why = conditions::k_p_refused(s).unwrap_or_default();
                return Err(refuse(why));
            }
            Field::E => {
                if !s.elastomer {
                    return Err(
                        "E sets K_p = 2π E z_p for an elastomer ball only (Eq. 20); this \
                         ball's material is a metal, whose K_p follows its yield strength: \
                         type K_p"
                            .into(),
                    );
                }
                params::check_positive(params::Field::KP, value)
                    .map_err(|_| refuse(format!("invalid E: {}", self.shown(value))))?;
                Field::KP
                    .overrides(k_p_of(value, s.params.z_p))
                    .apply(&mut next.params)
                    .map_err(|e| refuse(ball_refusal(&e)))?;
            }
            _ => {
                let o = self.overrides(value);
                o.apply(&mut next.params)
                    .map_err(|e| refuse(ball_refusal(&e)))?;
            }
        }
        next.params.validate().map_err(|e| refuse(refusal(&e)))?;
        closing(&next).map_err(refuse)?;
        Ok(next)
    }

    fn overrides(self, v: f64) -> Overrides {
        let mut o = Overrides::default();
        match self {
            Field::KP => o.k_p = Some(v),
            Field::KR => o.k_r = Some(v),
            Field::C => o.damping = Some(v),
            Field::ZP => o.z_p = Some(v),
            _ => {}
        }
        o
    }

    /// The field after this one (↓), wrapping.
    pub fn next(self) -> Field {
        let i = Field::ALL.iter().position(|&f| f == self).unwrap_or(0);
        Field::ALL[(i + 1) % Field::ALL.len()]
    }

    /// The field before this one (↑), wrapping.
    pub fn prev(self) -> Field {
        let n = Field::ALL.len();
        let i = Field::ALL.iter().position(|&f| f == self).unwrap_or(0);
        Field::ALL[(i + n - 1) % n]
    }
}

/// The contact modulus the values imply for an elastomer ball: E = K_p/(2π z_p) (Eq. 20 with
/// Eqs. 15–17).
pub fn modulus(p: &ImpactParams) -> f64 {
    p.k_p / (2.0 * std::f64::consts::PI * p.z_p)
}

/// K_p = 2π E z_p.
fn k_p_of(e: f64, z_p: f64) -> f64 {
    2.0 * std::f64::consts::PI * e * z_p
}

/// The form's state: which field is highlighted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Form {
    pub selected: Field,
}

/// The derived quantities the form shows: ω0 = √(K_p/m) (rad/s), z̄_p = z_p ω0/v0, λ, ζ.
pub fn derived(p: &ImpactParams) -> [(&'static str, f64); 4] {
    let n = p.normalized();
    [
        ("ω0 rad/s", p.omega0()),
        ("z̄_p", n.zp_bar),
        ("λ", n.lambda),
        ("ζ", n.zeta),
    ]
}
