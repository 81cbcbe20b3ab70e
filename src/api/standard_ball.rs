//! Whether a ball is the one a standard's test is for (the standard's `balls`), and the one
//! warning, in the same words from every command that judges against a standard (`bat`,
//! `drop --standard`, `batch --standard`, `court`, and Python's equivalents), when it is not.

use super::Ball;
use crate::drop::deformation::DeformationStandard;
use crate::drop::standards::{Standard, Test};

/// What follows "this is BALL: " in a ball standard's warning: the verdict is still given.
const ANOTHER_BALL: &str = "the verdict judges another ball by this test";

impl Ball {
    /// Whether this ball is named among `balls` (the embedded presets a standard is for): the
    /// standard's sport's ball, whatever the command line changed in it. A user preset copied
    /// from one under another name is another ball (its name is not the standard's ball's).
    pub fn is_named_among(&self, balls: &[&str]) -> bool {
        self.name.as_deref().is_some_and(|n| balls.contains(&n))
    }

    /// `not the standard's ball: the NAME test VERB BALLS; this is …: JUDGED`, or `None` for
    /// one of `balls` as recorded: a parameter the command line changed, or another law,
    /// makes it another ball (`bat_names_the_standards_ball_unchanged`).
    pub fn not_standards_ball(
        &self,
        name: &str,
        verb: &str,
        balls: &[&str],
        judged: &str,
    ) -> Option<String> {
        let other_law = self
            .calibration
            .as_ref()
            .is_some_and(|c| c.other_model.is_some());
        let changed = (!self.overrides.is_empty() || other_law).then(|| {
            if self.overrides.is_empty() {
                "under another law".to_string()
            } else {
                format!("with {} changed", self.overrides.join(", "))
            }
        });
        let this = match (self.is_named_among(balls), changed) {
            (true, None) => return None,
            (true, Some(how)) => format!("{} {how}", self.name.as_deref().unwrap_or_default()),
            (false, _) => self
                .name
                .as_deref()
                .unwrap_or("a ball that is no preset")
                .to_string(),
        };
        Some(format!(
            "not the standard's ball: the {name} test {verb} {}; this is {this}: {judged}",
            balls.join(", ")
        ))
    }

    /// [`Ball::not_standards_ball`] for a ball standard (a drop or a COR test): another
    /// sport's ball is run at its own conditions, never the test's
    /// ([`Ball::at_standard`]), and the warning says so where the test states conditions.
    pub fn standard_ball_warning(&self, s: &Standard) -> Option<String> {
        let verb = match s.test {
            Test::Drop { .. } => "drops",
            Test::Cor { .. } => "fires",
        };
        let test = crate::drop::conditions::of(s.name);
        let stated = test.temperature_c.is_some() || test.pressure_gauge_pa.is_some();
        let judged = match stated && !self.is_named_among(s.balls) {
            true => format!(
                "{ANOTHER_BALL}, at its own conditions ({}), not the test's ({})",
                super::conditions_words::words(&self.conditions),
                super::test_words(&test)
            ),
            false => ANOTHER_BALL.to_string(),
        };
        self.not_standards_ball(s.name, verb, s.balls, &judged)
    }

    /// [`Ball::not_standards_ball`] for a static (deformation) standard.
    pub fn static_standard_ball_warning(&self, d: &DeformationStandard) -> Option<String> {
        self.not_standards_ball(d.name, "loads", d.balls, ANOTHER_BALL)
    }
}
