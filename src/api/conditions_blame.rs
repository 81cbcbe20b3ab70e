//! Which condition a refusal names: a ball its conditions leave flat (or a parameter past its
//! range) is refused naming the flag whose step did it, not the pressure it was worked to
//! (docs/cli.md "Conditions").

use super::conditions::{ConditionsSpec, invalid};
use super::{Ball, BallError};
use crate::conditions::gas;

/// Seconds in an hour.
const HOUR: f64 = 3_600.0;

impl Ball {
    /// The refusal of a ball its conditions left out of range (flat, or a parameter past its
    /// range), named by the flag whose step did it: the inflation pressure, then the leak over
    /// `--after` at the inflation temperature `t0`, then the gas law to the run's temperature
    /// (`--temperature`, or `--inflated-at` where only it was given). `--after 1e30d` said
    /// "invalid pressure: 0 (… flat)" and `--pressure 1e308` "invalid k_p: 2.1e307" (issue
    /// 52's trial; tests/cli/issue52_trial.rs): quantities the user never typed.
    pub(super) fn blame(
        &self,
        e: BallError,
        spec: &ConditionsSpec,
        p0: f64,
        t0: Option<f64>,
    ) -> BallError {
        let fails = |p: f64| self.pressure_params(p0, p).is_err();
        let inflated = spec.pressure.unwrap_or(p0);
        if fails(inflated) {
            return match spec.pressure {
                Some(given) => blamed(e, "pressure", given, None, "gives"),
                None => e,
            };
        }
        if let Some(after) = spec.after
            && let Ok((leak, _)) = self.leak(spec)
            && let Ok(leaked) = leak.gauge_after(inflated, after)
        {
            let atm = self.conditions.atmosphere_pa;
            // at the inflation temperature, as the run's pressure is worked (the gas law's
            // sum with the atmosphere rounds a pressure leaked to 1e-26 Pa to 0)
            let at_t0 = t0.map_or(Ok(leaked), |t0| gas::gauge_at(leaked, t0, t0, atm));
            if at_t0.is_ok_and(fails) {
                let h = |s: f64| crate::text::short(s / HOUR, 4);
                let flat = format!(
                    "the ball has leaked flat: no contact stiffness left after {} h at a \
                     half-life of {} h",
                    h(after),
                    h(leak.half_life())
                );
                return blamed(e, "after", after, Some(flat), "the leak leaves");
            }
        }
        let (field, value) = match (spec.temperature, spec.inflated_at) {
            (Some(t), _) => ("temperature", t),
            (None, Some(t0)) => ("inflated-at", t0),
            _ => return e,
        };
        let flat = match &e {
            BallError::Invalid { value: p, .. } => format!(
                "the gas law takes the ball to {} kPa gauge: it is flat, no contact stiffness \
                 left",
                crate::text::short(p / 1e3, 4)
            ),
            _ => String::new(),
        };
        blamed(e, field, value, Some(flat), "the gas law gives")
    }
}

/// `e`, a parameter out of range (`gives` introduces it) or the ball flat (`flat` says so;
/// `None`: `e`'s own words), as the refusal of `field` = `value`; any other error as it is.
fn blamed(
    e: BallError,
    field: &'static str,
    value: f64,
    flat: Option<String>,
    gives: &str,
) -> BallError {
    let why = match e {
        BallError::Param(p) => {
            let derived = crate::text::human(p.value, 4);
            format!("{gives} {} = {derived}: {}", p.field.as_str(), p.reason)
        }
        BallError::Invalid { reason, .. } => flat.unwrap_or(reason),
        e => return e,
    };
    invalid(field, value, why)
}
