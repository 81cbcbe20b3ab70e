//! What values an impact parameter takes and the checks that hold them (docs/model.md §5,
//! docs/guarantees.md): the [`Field`] an error names, [`ParamError`], the meaningful range
//! 1e-15 … 1e15 and λ's and ζ's [`Range`]s. Re-exported from `model::params`, where callers
//! name them.

use crate::text::number;
use std::fmt;

/// The quantity a [`ParamError`] names; it displays as the name messages give it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    /// Mass m, kg.
    Mass,
    /// Radius R, m (a ball's, where a command takes it: `--radius`).
    Radius,
    /// Contact stiffness K_p, N/m.
    KP,
    /// Dashpot c, kg/s.
    Damping,
    /// Recoil spring K_r, N/m.
    KR,
    /// Flattening (yield) indentation z_p, m.
    ZP,
    /// Hertz stiffness K_h, N/m^{3/2}.
    KH,
    /// Impact speed v0, m/s.
    V0,
    /// λ = K_r/K_p.
    Lambda,
    /// ζ = √(m K_p)/(2c).
    Zeta,
    /// z̄_p = z_p ω0/v0.
    ZpBar,
    /// The solver's relative tolerance.
    Rtol,
    /// The solver asked for (the exact one runs the linear law only).
    Method,
    /// The first value of a sweep's range.
    From,
    /// The last value of a sweep's range.
    To,
    /// A target's mass M, kg (docs/targets.md).
    TargetMass,
    /// A target's speed v_t toward the ball, m/s.
    TargetSpeed,
    /// A target's stiffness K_s, N/m.
    TargetStiffness,
    /// A target's damping c_s, kg/s.
    TargetDamping,
}

impl Field {
    /// The name messages give the field: `k_p`, `zp_bar`, `lambda`, …
    pub const fn as_str(self) -> &'static str {
        match self {
            Field::Mass => "mass",
            Field::Radius => "radius",
            Field::KP => "k_p",
            Field::Damping => "damping",
            Field::KR => "k_r",
            Field::ZP => "z_p",
            Field::KH => "k_h",
            Field::V0 => "v0",
            Field::Lambda => "lambda",
            Field::Zeta => "zeta",
            Field::ZpBar => "zp_bar",
            Field::Rtol => "rtol",
            Field::Method => "method",
            Field::From => "from",
            Field::To => "to",
            Field::TargetMass => "target_mass",
            Field::TargetSpeed => "target_speed",
            Field::TargetStiffness => "target_stiffness",
            Field::TargetDamping => "target_damping",
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A parameter that cannot be used, named by field: "invalid v0: 1e300 (out of the physically
/// meaningful range 1e-15 … 1e15)".
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid {field}: {} ({reason})", number(*.value))]
pub struct ParamError {
    /// The quantity at fault.
    pub field: Field,
    /// The value given.
    pub value: f64,
    /// Why it is refused ("must not be negative", "out of the physically meaningful range
    /// 1e-15 … 1e15", …).
    pub reason: &'static str,
}

/// A finite, positive value in the meaningful range 1e-15 … 1e15, or an error naming `field`.
pub fn check_positive(field: Field, value: f64) -> Result<(), ParamError> {
    check(field, value, false, false)
}

/// The largest λ and ζ accepted. Beyond them the limits of docs/model.md §5 hold to the precision
/// of the arithmetic (ζ = 1e6 is within 1e-6 of the ζ → ∞ limit), while the exact solver's
/// modes span more than twelve decades and its sums lose their digits.
pub const LAMBDA_MAX: f64 = 1e6;
/// The largest ζ accepted (see [`LAMBDA_MAX`]).
pub const ZETA_MAX: f64 = 1e6;

/// The values a parameter takes, as one source for every check, prompt and message: zero
/// (when `zero`) and the closed interval `lo … hi`. `text` is how users read it; the test
/// `each_range_reads_as_its_bounds` holds it to the numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Whether 0 is taken besides `lo … hi`.
    pub zero: bool,
    /// The smallest positive value taken.
    pub lo: f64,
    /// The largest value taken.
    pub hi: f64,
    /// The range as users read it, e.g. "0 or 1e-15 … 1e6".
    pub text: &'static str,
}

impl Range {
    /// Whether `value` is in the range (never NaN or ±∞).
    pub fn contains(&self, value: f64) -> bool {
        (self.zero && value == 0.0) || (self.lo..=self.hi).contains(&value)
    }
}

/// λ's values: 0 (Maxwell), or 1e-15 … 1e6 ([`LAMBDA_MAX`]); between them K_r leaves the
/// meaningful range of [`check_positive`].
pub const LAMBDA_RANGE: Range = Range {
    zero: true,
    lo: MEANINGFUL_MIN,
    hi: LAMBDA_MAX,
    text: "0 or 1e-15 … 1e6",
};
/// ζ's values: 0 (a rigid dashpot), or 1e-15 … 1e6 ([`ZETA_MAX`]).
pub const ZETA_RANGE: Range = Range {
    zero: true,
    lo: MEANINGFUL_MIN,
    hi: ZETA_MAX,
    text: "0 or 1e-15 … 1e6",
};
/// A positive parameter's values (v0, m, K_p, …): 1e-15 … 1e15.
pub const POSITIVE_RANGE: Range = Range {
    zero: false,
    lo: MEANINGFUL_MIN,
    hi: MEANINGFUL_MAX,
    text: "1e-15 … 1e15",
};
/// The smallest z̄_p = z_p ω0/v0 accepted, as `--zp-bar` already requires. Each of z_p, K_p,
/// m, v0 may lie anywhere in 1e-15 … 1e15, but together they reached z̄_p = 4e-35: the ball
/// then flattens to z_m with z_r = z_p √(2 z_m/z_p − 1) below the rounding of z_m, z_f = z_m,
/// and the unloading slope F_m/(z_m − z_f) is infinite. At 1e-15 the run still closes its
/// energy balance (to ~4e-8); the solver_inputs fuzz target's regressions
/// (tests/physics/fuzz_regressions.rs, `solver_inputs_regressions`) hold the refusal below it.
pub const ZP_BAR_MIN: f64 = 1e-15;

/// Largest magnitude accepted for any parameter: beyond it products overflow or lose meaning.
const ABSURD: f64 = 1e15;
/// The physically meaningful range of a positive parameter (v0, m, K_p, …): 1e-15 … 1e15, the
/// bounds [`check_positive`] holds. The explorer's v0 range is this one (`tui::param`).
pub const MEANINGFUL_MIN: f64 = 1.0 / ABSURD;
/// The upper end of that range (see [`MEANINGFUL_MIN`]).
pub const MEANINGFUL_MAX: f64 = ABSURD;

/// A value in the meaningful range 1e-15 … 1e15, zero too when `allow_zero`, +∞ too when
/// `allow_inf`; NaN and negative values never: else an error naming `field`.
pub fn check_range(
    field: Field,
    value: f64,
    allow_zero: bool,
    allow_inf: bool,
) -> Result<(), ParamError> {
    check(field, value, allow_zero, allow_inf)
}

pub(super) fn check(
    field: Field,
    value: f64,
    allow_zero: bool,
    allow_inf: bool,
) -> Result<(), ParamError> {
    let err = |reason| {
        Err(ParamError {
            field,
            value,
            reason,
        })
    };
    if value.is_nan() {
        return err("not a number");
    }
    if value.is_infinite() {
        return if allow_inf && value > 0.0 {
            Ok(())
        } else {
            err("must be finite")
        };
    }
    if value < 0.0 {
        return err("must not be negative");
    }
    if value == 0.0 && !allow_zero {
        return err("must be positive");
    }
    if value > ABSURD || (value > 0.0 && value < 1.0 / ABSURD) {
        return err("out of the physically meaningful range 1e-15 … 1e15");
    }
    Ok(())
}
