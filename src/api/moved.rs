//! What an answer's ball moved from its preset and its record, in the few words a picture's
//! subtitle has room for: the one note every figure names its ball's changes by (`figure`,
//! `map --format svg`, `mc --svg-out`, `shot --svg-out`). Its words are those the text header
//! and the warnings already use — [`Ball::overrides_words`] (the header's `overrides:`),
//! [`Ball::conditions_moved`] (the conditions' warning), [`SurfaceUsed::label`] (the header's
//! surface line) and the calibration warning's speeds — so a picture says nothing a report
//! words otherwise.

use super::calibration::{fitted_words, speeds_words};
use super::{Ball, SurfaceUsed};

impl Ball {
    /// The notes of what moved, each a part of a subtitle ("; " between them, where the SVG
    /// may break it): the overrides ("overrides: k_p"), another parameter set or law than
    /// the record's ("the hertz law, not the record's"), conditions away from the record's
    /// ("the ball at 20 °C, 60 kPa gauge; its record at 20 °C, 80 kPa gauge" as two parts),
    /// a `surface` other than the plain rigid plate (its header label), and impact `speeds`
    /// (lowest, highest) outside the record's ("outside calibration: impact speed 40 m/s,
    /// the ball was fitted at 1.47 m/s only"). Empty when nothing moved: the preset's own
    /// ball, at its record, on the default plate.
    ///
    /// ```
    /// let b = bouncelab::Ball::from_preset("golf")?;
    /// assert!(b.moved_notes(None, Some((1.47, 1.47))).is_empty());
    /// let fast = b.with_v0(40.0)?;
    /// assert_eq!(
    ///     fast.moved_notes(None, Some((40.0, 40.0))),
    ///     ["outside calibration: impact speed 40 m/s, the ball was fitted at 1.47 m/s only"]
    /// );
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn moved_notes(
        &self,
        surface: Option<&SurfaceUsed>,
        speeds: Option<(f64, f64)>,
    ) -> Vec<String> {
        let mut notes: Vec<String> = self.overrides_words().into_iter().collect();
        let record = self.calibration.as_ref();
        if let Some(other) = record.and_then(|c| c.other_model.as_ref()) {
            notes.push(format!("{other}, not the record's"));
        }
        if let Some(moved) = self.conditions_moved() {
            notes.extend(moved.split("; ").map(String::from));
        }
        if let Some(s) = surface.filter(|s| moved_surface(s)) {
            notes.push(s.label());
        }
        if let (Some(c), Some((lo, hi))) = (record, speeds)
            && !(c.holds_at(lo) && c.holds_at(hi))
        {
            notes.push(format!(
                "outside calibration: {}, {}",
                speeds_words(lo, hi),
                fitted_words(c)
            ));
        }
        notes
    }
}

/// Whether `s` is not the default rigid plate as it is: another surface, or its normal
/// numbers given (μ and the tangential ones are each command's own words: a shot's title
/// names its μ).
fn moved_surface(s: &SurfaceUsed) -> bool {
    let normal = s
        .overrides
        .iter()
        .any(|o| !SurfaceUsed::TANGENTIAL.contains(&o.as_str()));
    s.name != crate::target::surface::DEFAULT || normal
}
