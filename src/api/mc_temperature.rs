//! What a temperature spread (`mc --vary temperature=…`) carries a ball's samples to that
//! its conditions' model does not vouch for (docs/model.md §10), as `run` says it of one
//! temperature: a solid ball's shift beyond the span it was fitted over, and past the COR's
//! turn, which `run` refuses (`Ball::past_turn`); an inflated ball's gas moved by the gas law
//! alone. The shares are the spread's own distribution (`Dist::below`), not a count of the
//! samples drawn: the samples keep no temperature.

use super::Ball;
use super::shift::{span, span_words};
use crate::analysis::mc::{McSpec, Varied};
use crate::conditions::ZERO_CELSIUS;
use crate::text::short;

impl Ball {
    /// The warnings of `spec`'s temperature spread on this ball at its temperature; `[]`
    /// without one, or where fewer than half a sample is expected outside what the model
    /// vouches for.
    pub(super) fn temperature_spread_warnings(&self, spec: &McSpec) -> Vec<String> {
        let spread = spec.vary.iter().find(|v| v.what == Varied::Temperature);
        let (Some(spread), Some(t0)) = (spread, self.conditions.temperature_c) else {
            return Vec::new();
        };
        let below = |t: f64| {
            spec.dist
                .below(spread.spread, (t + ZERO_CELSIUS) / (t0 + ZERO_CELSIUS))
        };
        let what = format!(
            "the temperature spread ({} % of {} K, {})",
            short(100.0 * spread.spread, 4),
            short(t0 + ZERO_CELSIUS, 5),
            spec.dist.name()
        );
        let n = spec.samples as f64;
        let share = |p: f64| {
            format!(
                "about {} % of the samples (≈ {} of {})",
                short(100.0 * p, 3),
                (p * n).round(),
                spec.samples
            )
        };
        if let Some(shift) = self.temperature_shift() {
            let [lo, hi] = span(shift);
            let outside = below(lo) + (1.0 - below(hi));
            if outside * n < 0.5 {
                return Vec::new();
            }
            let at = (self.params.damping, t0);
            let cold = self
                .turn(shift, at, true)
                .map(|(_, t)| (below(t), t, "colder"));
            let warm = self
                .turn(shift, at, false)
                .map(|(_, t)| (1.0 - below(t), t, "warmer"));
            let past: Vec<String> = [cold, warm]
                .into_iter()
                .flatten()
                .filter(|(p, ..)| p * n >= 0.5)
                .map(|(p, t, side)| format!("{} {side} than {} °C", share(p), short(t, 5)))
                .collect();
            let turn = match past.is_empty() {
                true => String::new(),
                false => format!(
                    "; {}, past the nominal ball's COR minimum, where the model turns the COR \
                     back (`run` refuses such a temperature)",
                    past.join(" and ")
                ),
            };
            return vec![format!(
                "outside calibration: {what} takes {} outside the temperature shift's fitted \
                 span {}, where its Arrhenius law is extrapolated{turn}",
                share(outside),
                span_words([lo, hi])
            )];
        }
        // a ball away from its record's temperature says so in its own warning already
        if !self.is_inflated() || !self.conditions_caveat().is_empty() {
            return Vec::new();
        }
        let record = match self.calibration.as_ref().and_then(|c| c.temperature) {
            Some(r) => format!("the record's {} °C", short(r, 4)),
            None => "the record's temperature, which the record does not state".into(),
        };
        vec![format!(
            "outside calibration: {what} moves each sample's gas by the gas law alone: its \
             rubber is taken as at {record} (its own change with temperature is not modelled, \
             docs/model.md §10.2)"
        )]
    }
}
