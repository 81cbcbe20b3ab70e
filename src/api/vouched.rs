//! Which outputs of an answer its ball's record vouches for (docs/presets.md, "The calibration
//! record"): each `[[calibration.data]]` set names the outputs it measured; an answer that
//! reports another says so, in its JSON (`uncalibrated_outputs`) and under its text's table.
//! Not a warning: it is true of every answer of the ball, at every speed, and a warning on
//! every run would drown the ones that are about this answer.

use super::Ball;
use crate::preset::{Output, output_words};

impl Ball {
    /// The outputs the ball's record vouches for: those its data sets measured; none when an
    /// override or another parameter set or law took the record away (its `outside
    /// calibration:` warning says so). `None` without a record, or with one that does not say
    /// what its data measured (a user preset without `outputs`): no claim either way.
    pub fn vouched_outputs(&self) -> Option<Vec<Output>> {
        let c = self.calibration.as_ref()?;
        let outputs = c.outputs()?;
        Some(if self.record_taken_away() {
            Vec::new()
        } else {
            outputs
        })
    }

    /// Of `reported` (the outputs an answer gives), those the record does not vouch for: the
    /// model's alone (the JSON's `uncalibrated_outputs`). `None` when the record makes no
    /// claim ([`Ball::vouched_outputs`]).
    ///
    /// ```
    /// use bouncelab::preset::Output;
    /// let t = bouncelab::Ball::from_preset("tennis")?;
    /// let not = t.uncalibrated_outputs(&[Output::Cor, Output::MaxForce]).unwrap();
    /// assert_eq!(not, [Output::MaxForce]);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn uncalibrated_outputs(&self, reported: &[Output]) -> Option<Vec<Output>> {
        let vouched = self.vouched_outputs()?;
        Some(
            (reported.iter().copied())
                .filter(|o| !vouched.contains(o))
                .collect(),
        )
    }

    /// The text's note under its table: "peak force and contact time: the model's, not in
    /// tennis's record, which holds the COR and static deflection". `None` when the record
    /// vouches for all of `reported`, makes no claim, or was taken away (the warning says
    /// that of every output at once).
    pub fn uncalibrated_note(&self, reported: &[Output]) -> Option<String> {
        let not = self.uncalibrated_outputs(reported)?;
        if not.is_empty() || self.record_taken_away() {
            return None;
        }
        let holds = self.vouched_outputs().unwrap_or_default();
        let holds = if holds.is_empty() {
            "which holds no measured output".to_string()
        } else {
            format!("which holds the {}", output_words(&holds))
        };
        let whose = match &self.name {
            Some(name) => format!("{name}'s"),
            None => "the ball's".into(),
        };
        Some(format!(
            "{}: the model's, not in {whose} record, {holds}",
            output_words(&not)
        ))
    }

    /// Whether an override or another parameter set or law changed the ball its record is
    /// of ([`Ball::speeds_warning`] says so for the whole answer).
    fn record_taken_away(&self) -> bool {
        let other = (self.calibration.as_ref()).is_some_and(|c| c.other_model.is_some());
        !self.overrides.is_empty() || other
    }
}
