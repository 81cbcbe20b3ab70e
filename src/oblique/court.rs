//! The ITF Court Pace Rating as a standard (`bouncelab standards` lists it; docs/oblique.md §6).

use serde::Serialize;

/// A surface test: the ball fired at a speed and angle, the rating read from its bounce.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CourtStandard {
    /// Short name.
    pub name: &'static str,
    /// The governing body and the test.
    pub title: &'static str,
    /// `{"kind": "court-pace", "speed": 30, "angle_deg": 16}`.
    pub test: CourtTest,
    /// What the ball hits.
    pub surface: &'static str,
    /// The categories' lower bounds of the rounded rating, 2 … 5 (1 below the first).
    pub categories: [f64; 4],
    /// Where the numbers come from.
    pub source: &'static str,
    /// What could not be confirmed from a public source, if anything.
    pub unconfirmed: Option<&'static str>,
    /// The embedded presets it is the ball of.
    pub balls: &'static [&'static str],
}

/// The court test's conditions.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum CourtTest {
    /// The ball at `speed` (m/s) and `angle_deg` to the surface, without spin.
    CourtPace {
        /// m/s.
        speed: f64,
        /// Degrees to the surface.
        angle_deg: f64,
    },
}

/// The ITF's court pace test.
pub const ITF_COURT_PACE: CourtStandard = CourtStandard {
    name: "itf-court-pace",
    title: "ITF Court Pace Rating of a tennis surface",
    test: CourtTest::CourtPace {
        speed: 30.0,
        angle_deg: 16.0,
    },
    surface: "the court, rigid in the model, with the friction μ given (`bouncelab court`)",
    categories: [30.0, 35.0, 40.0, 45.0],
    source: "ITF CS 01/02 (Initial ITF Study on Performance Standards for Tennis Court \
             Surfaces): CPR = 100(1 − μ) + 150(0.81 − e), μ and e from a ball fired at 30 m/s \
             and 16°",
    unconfirmed: Some(
        "the test ball's spin at the surface (the model fires it without) and any embedded \
         court's own give: none was found published, so the embedded surfaces are rigid and a \
         court's give comes from its measured e (`court --surface-cor`, `--fit`; \
         docs/surfaces.md)",
    ),
    balls: &["tennis"],
};

/// The ITF's pace category of a rating: (number, name), the rating rounded to the nearest
/// integer first (1 slow ≤ 29, 2 medium-slow 30–34, 3 medium 35–39, 4 medium-fast 40–44,
/// 5 fast ≥ 45).
pub fn pace_category(cpr: f64) -> (u8, &'static str) {
    const NAMES: [&str; 5] = ["slow", "medium-slow", "medium", "medium-fast", "fast"];
    let r = cpr.round();
    let above = ITF_COURT_PACE
        .categories
        .iter()
        .filter(|&&lo| r >= lo)
        .count();
    (above as u8 + 1, NAMES[above])
}

#[cfg(test)]
mod tests {
    use super::pace_category;

    #[test]
    fn categories_follow_the_rounded_rating() {
        assert_eq!(pace_category(29.49), (1, "slow"));
        assert_eq!(pace_category(29.5), (2, "medium-slow"));
        assert_eq!(pace_category(34.4), (2, "medium-slow"));
        assert_eq!(pace_category(35.0), (3, "medium"));
        assert_eq!(pace_category(44.49), (4, "medium-fast"));
        assert_eq!(pace_category(44.5), (5, "fast"));
        assert_eq!(pace_category(-10.0), (1, "slow"));
    }
}
