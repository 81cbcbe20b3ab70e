//! A solid ball's temperature by its record's dashpot shift (docs/model.md §10.4), and where
//! the conditions' model holds: the shift within the span of the data it was fitted to,
//! refused where, beyond that span, it would turn the COR back; the gas law of an inflated
//! ball said to carry the gas alone.

use super::conditions::invalid;
use super::{Ball, BallError};
use crate::analysis::fit::cor_temperature::{cor_turn, damping_temperature, shifted_damping};
use crate::analysis::fit::{Param, apply};
use crate::preset::TemperatureShift;
use crate::text::short;

/// How far past an end of a span (K) a temperature may lie and still be inside it: a record
/// states temperatures to 0.01 K (as `conditions_words`'s `at_record`).
const SPAN_SLACK: f64 = 0.01;

/// The span a shift holds over, °C: its data's, or its reference alone where its record
/// (written before spans were kept) states none.
pub(super) fn span(shift: &TemperatureShift) -> [f64; 2] {
    shift.span.unwrap_or([shift.reference; 2])
}

/// "36.11–45 °C", or "45 °C" for one temperature.
pub(super) fn span_words([lo, hi]: [f64; 2]) -> String {
    if lo == hi {
        format!("{} °C", short(lo, 4))
    } else {
        format!("{}–{} °C", short(lo, 4), short(hi, 4))
    }
}

/// The end of `span` that `t` lies beyond, `None` inside it.
fn beyond([lo, hi]: [f64; 2], t: f64) -> Option<f64> {
    if t < lo - SPAN_SLACK {
        Some(lo)
    } else if t > hi + SPAN_SLACK {
        Some(hi)
    } else {
        None
    }
}

impl Ball {
    /// The dashpot's temperature shift of the ball's record, if it holds one
    /// (`[calibration.temperature_shift]`).
    pub fn temperature_shift(&self) -> Option<&TemperatureShift> {
        self.calibration.as_ref()?.temperature_shift.as_ref()
    }

    /// [`Ball::with_lambda_zeta`] on the ball [`Ball::at_conditions`] gave, `temperature` the
    /// one its caller gave (°C; `None`: none): ζ sets c as `--damping` does, and a temperature
    /// moves the c of a ball whose record holds a shift, so the two together are refused
    /// naming the temperature, as `at_conditions` refuses `--damping` there (ζ comes after the
    /// conditions, so here). A temperature given at the record's own is refused too: it is
    /// still two settings of c. Neither λ nor ζ: the ball as it is. One rule for the command
    /// line's `--zeta` (`BallArgs::resolve_tuned`) and Python's `run(zeta=…)`, which ran the
    /// pair that the command line refused.
    ///
    /// ```
    /// use bouncelab::{Ball, api::ConditionsSpec};
    /// let at = ConditionsSpec { temperature: Some(30.0), ..Default::default() };
    /// let squash = Ball::from_preset("squash")?.at_conditions(&at)?;
    /// let e = squash.with_lambda_zeta_at(Some(30.0), None, Some(0.2)).unwrap_err();
    /// assert_eq!(
    ///     e.to_string(),
    ///     "invalid temperature: 30 (--zeta sets c too, which the temperature shifts: give one \
    ///      of them)"
    /// );
    /// let ball = Ball::from_preset("squash")?.with_lambda_zeta_at(None, None, Some(0.2))?;
    /// assert!((ball.zeta() - 0.2).abs() < 1e-12);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn with_lambda_zeta_at(
        self,
        temperature: Option<f64>,
        lambda: Option<f64>,
        zeta: Option<f64>,
    ) -> Result<Ball, BallError> {
        if let (Some(t), Some(_)) = (temperature, zeta)
            && self.temperature_shift().is_some()
        {
            let why = "--zeta sets c too, which the temperature shifts: give one of them";
            return Err(invalid("temperature", t, why.into()));
        }
        if lambda.is_none() && zeta.is_none() {
            return Ok(self);
        }
        self.with_lambda_zeta(lambda, zeta)
    }

    /// A solid ball at `t` °C by its record's shift: c(T) = c · exp[(E_a/R)(1/T − 1/T_ref)]
    /// (docs/model.md §10.4), the springs kept. Refused beyond the shift's span where the COR
    /// turns back between the span's end and `t` ([`Ball::past_turn`]).
    pub(super) fn shifted(mut self, shift: &TemperatureShift, t: f64) -> Result<Ball, BallError> {
        let (c_ref, e_a, t_ref) = (
            self.params.damping,
            shift.activation_energy,
            shift.reference,
        );
        if let Some(why) = self.past_turn(shift, t) {
            return Err(invalid("temperature", t, why));
        }
        let c = shifted_damping(c_ref, e_a, t_ref, t);
        self.params = apply(&self.params, &[Param::C], &[c]);
        self.params.validate()?;
        self.conditions.temperature_c = Some(t);
        Ok(self)
    }

    /// Why the shift is refused at `t`: beyond its span, the shifted c passes the dashpot at
    /// which this ball's COR (its other parameters and speed kept) has its minimum, so that
    /// the model would turn the COR back with temperature — a colder ball bouncing higher
    /// where the data had it lower, or the reverse — a turn no data of the shift show
    /// (Arrhenius's form has no pole: the turn is the model's COR against c, §5). `None`
    /// inside the span and where the COR does not turn.
    fn past_turn(&self, shift: &TemperatureShift, t: f64) -> Option<String> {
        let edge = beyond(span(shift), t)?;
        let cold = t < edge;
        let (turn, at) = self.turn(shift, (self.params.damping, shift.reference), cold)?;
        if (cold && t >= at) || (!cold && t <= at) {
            return None;
        }
        let (side, going) = if cold {
            ("below", "cools")
        } else {
            ("above", "warms")
        };
        Some(format!(
            "{}'s temperature shift, fitted over {}, carries its dashpot past the COR's minimum \
             (c = {} kg/s at {} m/s): beyond it the model has the ball's COR turn back as it \
             {going}, which no data of the shift show; refused {side} {} °C",
            self.name.as_deref().unwrap_or("the ball"),
            span_words(span(shift)),
            short(turn, 4),
            short(self.params.v0, 4),
            short(at, 5),
        ))
    }

    /// Where, beyond the shift's span on its `cold` side (else its warm one), the shifted
    /// dashpot reaches the one at which this ball's COR has its minimum: that dashpot (kg/s)
    /// and its temperature (°C), past which [`Ball::past_turn`] refuses. `(c_at, t_at)`: the
    /// ball's dashpot and the temperature (°C) it holds at, on the shift's curve. The whole
    /// path's turn, one bound for every temperature past it; `None` where the COR does not
    /// turn on that side.
    pub(super) fn turn(
        &self,
        shift: &TemperatureShift,
        (c_at, t_at): (f64, f64),
        cold: bool,
    ) -> Option<(f64, f64)> {
        let e_a = shift.activation_energy;
        let [lo, hi] = span(shift);
        let from = shifted_damping(c_at, e_a, t_at, if cold { lo } else { hi });
        // c(T) = c_at exp[(E_a/R)(1/T − 1/T_at)] grows as the ball cools where E_a > 0
        let rising = cold == (e_a > 0.0);
        let turn = cor_turn(&self.params, self.law, from, rising)?;
        let at = damping_temperature(c_at, e_a, t_at, turn);
        at.is_finite().then_some((turn, at))
    }

    /// What the conditions' model cannot vouch for at the ball's temperature, for the
    /// `outside calibration:` warning (", …", or empty): a solid ball's shift beyond the span
    /// it was fitted over, an inflated ball away from its record's temperature, where the gas
    /// law moves the gas alone and the rubber is taken as at the record's (docs/model.md §10.2:
    /// no bound is set; the answer says so instead).
    pub(super) fn conditions_caveat(&self) -> String {
        let Some(t) = self.conditions.temperature_c else {
            return String::new();
        };
        if let Some(shift) = self.temperature_shift() {
            let fitted = match shift.span {
                Some(s) => format!("fitted span {}", span_words(s)),
                None => format!(
                    "fitted span, which its record does not state (its reference is {} °C)",
                    short(shift.reference, 4)
                ),
            };
            return beyond(span(shift), t).map_or(String::new(), |_| {
                format!(
                    ", outside the temperature shift's {fitted} (its Arrhenius law \
                     extrapolated to {} °C)",
                    short(t, 4)
                )
            });
        }
        if !self.is_inflated() {
            return String::new();
        }
        let record = self.calibration.as_ref().and_then(|c| c.temperature);
        let at = match record {
            Some(r) if (r - t).abs() <= SPAN_SLACK => return String::new(),
            Some(r) => format!("its record's {} °C", short(r, 4)),
            None => "its record's temperature, which the record does not state".into(),
        };
        format!(
            ", by the gas law alone: its rubber is taken as at {at} (its own change with \
             temperature is not modelled)"
        )
    }
}
