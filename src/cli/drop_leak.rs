//! `drop --standard fifa-pressure-loss`: the FIFA 72-hour pressure-loss test as a standard
//! (docs/drop.md, "Pressure loss"). The test judges the ball's leak, not a bounce: the ball
//! inflated to the test's pressure at its temperature loses, over the test's time, the
//! fraction 1 − e^(−k t) of its gauge pressure (docs/model.md §10.3), judged against the
//! limit. The leak is the caller's `--half-life` (a measured one: `fit --pressure-loss`); the
//! drop shows the ball after the test's time, so that what the leak does to its bounce is
//! seen beside the verdict.

use super::conditions::ConditionsArgs;
pub use crate::api::LeakVerdict;
use crate::drop::conditions::PressureLoss;
use crate::text::short;
use std::io::Write;

/// The pressure-loss test named `name`, if it is one.
pub fn find(name: &str) -> Option<&'static PressureLoss> {
    crate::api::pressure_loss_test(name)
}

/// The conditions the test runs the ball at ([`crate::api::leak_test_conditions`]: the
/// test's pressure, temperature and time, the caller's `--half-life`).
pub fn conditions(test: &PressureLoss, asked: &ConditionsArgs) -> anyhow::Result<ConditionsArgs> {
    let c = crate::api::leak_test_conditions(test, &asked.spec(), |n| format!("--{n}"))
        .map_err(anyhow::Error::msg)?;
    Ok(ConditionsArgs {
        pressure: c.pressure,
        temperature: c.temperature,
        inflated_at: c.inflated_at,
        after: c.after,
        half_life: c.half_life,
    })
}

/// The verdict on a leak of half-life `half_life` s ([`crate::api::judge_leak`]).
pub fn judge(test: &PressureLoss, half_life: f64) -> anyhow::Result<LeakVerdict> {
    crate::api::judge_leak(test, half_life).map_err(anyhow::Error::msg)
}

/// The verdict as the text output's closing lines.
pub fn text(out: &mut dyn Write, test: &PressureLoss, v: &LeakVerdict) -> std::io::Result<()> {
    writeln!(out, "\nstandard {}: {}", test.name, test.title)?;
    writeln!(
        out,
        "  inflated to {} kPa gauge at {} °C, kept {} h; leak half-life {} h",
        short(test.pressure / 1e3, 4),
        short(test.temperature, 4),
        short(test.hours, 4),
        short(v.half_life_h, 4)
    )?;
    writeln!(
        out,
        "  lost {} % of the pressure, limit {} %: {}, margin {:+.2} %",
        short(100.0 * v.lost, 4),
        short(100.0 * v.max_loss, 4),
        v.verdict.to_uppercase(),
        100.0 * v.margin
    )
}
