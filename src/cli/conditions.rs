//! `--pressure`, `--temperature`, `--inflated-at`, `--after`, `--half-life`: the conditions a
//! ball runs at, on every command that runs a ball (flattened into [`super::ball::BallArgs`],
//! and into `map`'s options), resolved by the library's one resolver
//! ([`crate::api::Ball::at_conditions`], docs/model.md §10).

use clap::Args;

/// The conditions asked on the command line; each `None` keeps the ball's record's.
#[derive(Debug, Clone, Copy, Default, Args)]
pub struct ConditionsArgs {
    /// Inflation (gauge) pressure, at --inflated-at: Pa, or with a unit (0.8bar, 8psi, 55kPa);
    /// inflated balls only [default: the preset's nominal]
    #[arg(long, value_name = "P", value_parser = pressure, allow_hyphen_values = true)]
    pub pressure: Option<f64>,
    /// The ball's temperature, °C [default: the preset's calibration temperature]
    #[arg(long, value_name = "°C", value_parser = super::number::number, allow_hyphen_values = true)]
    pub temperature: Option<f64>,
    /// The temperature the ball was inflated at, °C (the gas law carries its pressure to
    /// --temperature) [default: the preset's calibration temperature]
    #[arg(long = "inflated-at", value_name = "°C", value_parser = super::number::number, allow_hyphen_values = true)]
    pub inflated_at: Option<f64>,
    /// Time since inflation (72h, 30d, 90min, or seconds): the pressure lost by permeation
    /// [leak: --half-life, or the limit of the ball's pressure-loss standard]
    #[arg(long, value_name = "DURATION", value_parser = after, allow_hyphen_values = true)]
    pub after: Option<f64>,
    /// The leak's half-life for --after (72h, 30d, or seconds; fit one with
    /// `fit --pressure-loss`) [default: the limit of the ball's pressure-loss standard]
    #[arg(long = "half-life", value_name = "DURATION", value_parser = half_life, allow_hyphen_values = true)]
    pub half_life: Option<f64>,
}

impl ConditionsArgs {
    /// The library's form of what was asked.
    pub fn spec(&self) -> crate::api::ConditionsSpec {
        crate::api::ConditionsSpec {
            pressure: self.pressure,
            temperature: self.temperature,
            inflated_at: self.inflated_at,
            after: self.after,
            half_life: self.half_life,
        }
    }
}

/// `--pressure`'s reader: pascals, or a number with its unit.
pub(super) fn pressure(text: &str) -> Result<f64, String> {
    crate::conditions::pressure::parse("pressure", text)
}

/// `--after`'s reader: seconds, or a number with its unit.
fn after(text: &str) -> Result<f64, String> {
    crate::conditions::duration::parse("after", text)
}

/// `--half-life`'s reader: seconds, or a number with its unit.
fn half_life(text: &str) -> Result<f64, String> {
    crate::conditions::duration::parse("half-life", text)
}
