//! The ball standards of the sports' governing bodies and a verdict against them
//! (docs/drop.md, "Standards", where each entry's source is cited).
//!
//! Two kinds of test: a drop onto a rigid plate with a window on the rebound height, and a
//! COR test (a ball fired at a rigid wall, ASTM F1887 style) with a window on the COR. Each
//! drop test states where its heights are measured to, the bottom or the top of the ball
//! (FIBA drops from 1.80 m to the bottom and reads the rebound at the top); the verdict
//! converts explicitly: the model's heights are of the bottom of the ball.

use super::{Air, DropBall, DropError, DropSetup, impact};
use serde::Serialize;

/// The point of the ball a height is measured to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Reference {
    /// The lowest point of the ball (the model's heights are of this point).
    Bottom,
    /// The highest point, one diameter above the bottom.
    Top,
}

impl Reference {
    /// Height of this point above the bottom of the ball (m).
    pub fn offset(self, radius: f64) -> f64 {
        match self {
            Reference::Bottom => 0.0,
            Reference::Top => 2.0 * radius,
        }
    }

    /// `"bottom"` or `"top"`, as the output writes it.
    pub fn name(self) -> &'static str {
        match self {
            Reference::Bottom => "bottom",
            Reference::Top => "top",
        }
    }
}

/// What a standard measures.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Test {
    /// Release from rest at `height` (to `drop_ref` of the ball); the rebound's apex (to
    /// `rebound_ref`) is the measured value (m).
    Drop {
        /// Release height, m, measured to `drop_ref`.
        height: f64,
        /// The point of the ball the release height is measured to.
        drop_ref: Reference,
        /// The point of the ball the rebound height is read at.
        rebound_ref: Reference,
    },
    /// A ball fired at a rigid wall at `speed` (m/s); the COR from the speeds just before and
    /// after impact is the measured value.
    Cor {
        /// Impact speed, m/s.
        speed: f64,
    },
}

/// One governing body's test and its window: a ball standard's ([`Test`]), or a bat
/// standard's (`T` = [`crate::target::bat::BatTest`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Standard<T = Test> {
    /// Short name (`--standard NAME` for a ball standard).
    pub name: &'static str,
    /// The governing body and the test, as the text output heads it.
    pub title: &'static str,
    /// The test and its conditions.
    pub test: T,
    /// Surface the ball hits.
    pub surface: &'static str,
    /// [lo, hi] of the measured value; `None` where the standard sets no bound.
    pub window: [Option<f64>; 2],
    /// Where the numbers come from (docs/drop.md and docs/targets.md cite each in full).
    pub source: &'static str,
    /// What could not be confirmed from a public source, if anything.
    pub unconfirmed: Option<&'static str>,
    /// The embedded presets it is the ball of; a ball standard's pass it (`bouncelab drop
    /// --preset BALL --standard NAME`: tests/physics/standards.rs,
    /// `every_standard_names_a_ball_that_passes_it`).
    pub balls: &'static [&'static str],
}

/// 60 mph in m/s, the speed of the ASTM F1887 COR tests (NCAA baseball, softball; exact: 1 mph
/// = 0.44704 m/s).
pub const MPH_60: f64 = 60.0 * 0.44704;
/// 85 ft/s in m/s, the speed of MLB's COR test (exact: 1 ft = 0.3048 m).
pub const FPS_85: f64 = 85.0 * 0.3048;

/// 100 in in m, the WSF rebound test's drop (exact: 1 in = 0.0254 m).
const WSF_DROP: f64 = 100.0 * 0.0254;
const WSF_SOURCE: &str = "World Squash Federation, Specifications for Squash Balls (the \
     championship, double yellow dot ball): rebound resilience from 100 in, at 23 °C 12 % \
     minimum, at 45 °C 26–33 % (docs/presets.md, squash)";
const WSF_UNCONFIRMED: &str = "the windows' percentages (recalled from the WSF specification; \
     no stored copy of it could be read in the session that added them: the test's 100 in and \
     23/45 °C are confirmed by S. Edgar's account of it), the plate's material and that both \
     heights are of the bottom of the ball";

const fn drop_test(height: f64, rebound_ref: Reference) -> Test {
    Test::Drop {
        height,
        drop_ref: Reference::Bottom,
        rebound_ref,
    }
}

/// A FIFA Quality Programme rebound test of a football: dropped from 2 m (to its bottom) onto
/// a steel plate, its rebound within `lo` … 1.65 m.
const fn fifa_rebound(name: &'static str, title: &'static str, lo: f64) -> Standard {
    Standard {
        name,
        title,
        test: drop_test(2.0, Reference::Bottom),
        surface: "steel plate",
        window: [Some(lo), Some(1.65)],
        source: "FIFA Quality Programme for Footballs, rebound test (as published by licensees)",
        unconfirmed: Some(
            "the window in FIFA's own current test manual (a retailer quotes 1.35–1.55 m for \
             its Quality Pro ball) and the bottom-of-ball reading",
        ),
        balls: &["football"],
    }
}

/// An ASA/USA Softball COR class: a maximum COR at 60 mph against a rigid wall (ASTM F1887).
const fn softball_class(
    name: &'static str,
    title: &'static str,
    max: f64,
    unconfirmed: &'static str,
    balls: &'static [&'static str],
) -> Standard {
    Standard {
        name,
        title,
        test: Test::Cor { speed: MPH_60 },
        surface: "rigid wall (ASTM F1887)",
        window: [None, Some(max)],
        source: "ASA/USA Softball ball classes (COR maximum); ASTM F1887 at 60 mph",
        unconfirmed: Some(unconfirmed),
        balls,
    }
}

/// What the softball classes leave unconfirmed.
const MAXIMA_ONLY: &str = "any lower limit: the classes are published as maxima";

/// Every standard, in the order `bouncelab standards` lists them.
pub const STANDARDS: [Standard; 14] = [
    Standard {
        name: "itf",
        title: "ITF tennis ball (Type 2), rebound test",
        test: drop_test(2.54, Reference::Bottom),
        surface: "smooth, rigid, horizontal block (concrete or granite)",
        window: [Some(1.35), Some(1.47)],
        source: "ITF Rules of Tennis, Appendix I; ITF ball rebound test page",
        unconfirmed: Some("that both heights are read at the bottom of the ball"),
        balls: &["tennis"],
    },
    fifa_rebound("fifa-quality", "FIFA Quality football, rebound test", 1.15),
    fifa_rebound(
        "fifa-quality-pro",
        "FIFA Quality Pro football, rebound test",
        1.20,
    ),
    Standard {
        name: "fiba",
        title: "FIBA basketball, rebound test",
        test: drop_test(1.80, Reference::Top),
        surface: "playing floor",
        window: [Some(1.20), Some(1.40)],
        source: "FIBA Official Basketball Rules, Basketball Equipment, section 2 (Basketballs)",
        unconfirmed: Some("the floor's stiffness: the model's plate is rigid"),
        balls: &["basketball"],
    },
    Standard {
        name: "ittf",
        title: "ITTF table tennis ball (celluloid), bounce",
        test: drop_test(0.305, Reference::Bottom),
        surface: "standard steel block",
        window: [Some(0.240), Some(0.260)],
        source: "ITTF Technical Leaflet T3 (The Ball), B.7 Bounce conformity",
        unconfirmed: None,
        balls: &["table-tennis"],
    },
    Standard {
        name: "ittf-plastic",
        title: "ITTF table tennis ball (non-celluloid), bounce",
        test: drop_test(0.305, Reference::Bottom),
        surface: "standard steel block",
        window: [Some(0.240), Some(0.265)],
        source: "ITTF Technical Leaflet T3 (The Ball), B.7 Bounce conformity",
        unconfirmed: None,
        balls: &["table-tennis"],
    },
    Standard {
        name: "mlb",
        title: "MLB baseball, COR against a wall of northern white ash",
        test: Test::Cor { speed: FPS_85 },
        surface: "northern white ash wall (the model's wall is rigid)",
        window: [Some(0.514), Some(0.578)],
        source: "MLB Official Baseball Rules (COR 0.546 ± 0.032 at 85 ft/s), as quoted by \
                 Kagan & Atkinson, The Physics Teacher (2004)",
        unconfirmed: None,
        balls: &["baseball-mlb"],
    },
    Standard {
        name: "ncaa-baseball",
        title: "NCAA baseball, COR maximum",
        test: Test::Cor { speed: MPH_60 },
        surface: "rigid wall (ASTM F1887)",
        window: [None, Some(0.555)],
        source: "NCAA maximum COR 0.555 (ABCA, 2013); speed per ASTM F1887",
        unconfirmed: Some("the test speed (ASTM F1887's 60 mph assumed) and any lower limit"),
        balls: &["baseball-mlb"],
    },
    softball_class(
        "softball-44",
        "Softball, .44 COR class",
        0.44,
        MAXIMA_ONLY,
        &["softball-44"],
    ),
    softball_class(
        "softball-47",
        "Softball, .47 COR class (fastpitch)",
        0.47,
        MAXIMA_ONLY,
        &["softball"],
    ),
    softball_class(
        "softball-50",
        "Softball, .50 COR class",
        0.50,
        "the class itself (named in the issue, not found in a public rule book) and any \
             lower limit",
        &["softball"],
    ),
    softball_class(
        "softball-52",
        "Softball, .52 COR class (slow pitch)",
        0.52,
        MAXIMA_ONLY,
        &["softball"],
    ),
    Standard {
        name: "wsf-23",
        title: "WSF squash ball (double yellow dot), rebound resilience at 23 °C",
        test: drop_test(WSF_DROP, Reference::Bottom),
        surface: "steel plate",
        // 12 % of 100 in, minimum
        window: [Some(0.12 * WSF_DROP), None],
        source: WSF_SOURCE,
        unconfirmed: Some(WSF_UNCONFIRMED),
        balls: &["squash"],
    },
    Standard {
        name: "wsf-45",
        title: "WSF squash ball (double yellow dot), rebound resilience at 45 °C",
        test: drop_test(WSF_DROP, Reference::Bottom),
        surface: "steel plate",
        // 26–33 % of 100 in
        window: [Some(0.26 * WSF_DROP), Some(0.33 * WSF_DROP)],
        source: WSF_SOURCE,
        unconfirmed: Some(WSF_UNCONFIRMED),
        balls: &["squash"],
    },
];

/// The standard called `name`, or an error listing the names.
pub fn find(name: &str) -> Result<&'static Standard, String> {
    STANDARDS.iter().find(|s| s.name == name).ok_or_else(|| {
        let names: Vec<&str> = STANDARDS.iter().map(|s| s.name).collect();
        format!(
            "unknown standard '{name}' (available: {})",
            names.join(", ")
        )
    })
}

/// Each embedded ball's own standard: the one its damping was fitted to (its TOML file says
/// so). A ball may pass several (`balls` of each lists them all: the football passes both FIFA
/// windows, the .47 softball every class above .47).
const OWN: [(&str, &str); 8] = [
    ("tennis", "itf"),
    ("football", "fifa-quality-pro"),
    ("basketball", "fiba"),
    ("table-tennis", "ittf"),
    ("softball", "softball-47"),
    ("baseball-mlb", "mlb"),
    ("softball-44", "softball-44"),
    ("squash", "wsf-45"),
];

/// The standard an embedded preset is made to pass, if any: its own (the one it was fitted
/// to), else the first that names it.
pub fn for_ball(preset: &str) -> Option<&'static Standard> {
    let own = OWN.iter().find(|(b, _)| *b == preset).map(|(_, s)| *s);
    own.and_then(|name| STANDARDS.iter().find(|s| s.name == name))
        .or_else(|| STANDARDS.iter().find(|s| s.balls.contains(&preset)))
}

/// A ball measured against a standard.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Verdict {
    /// The standard's short name.
    pub name: &'static str,
    /// Its window, [lo, hi] (m or COR; `None` where unbounded).
    pub window: [Option<f64>; 2],
    /// The rebound height in the standard's convention (m), or the COR.
    pub measured: f64,
    /// Whether `measured` lies in the window (bounds included).
    pub pass: bool,
    /// Distance to the nearer bound, positive inside the window, negative outside (m or COR).
    pub margin: f64,
}

impl Verdict {
    /// The verdict of the standard `name` on `measured` against its `window`: the margin is
    /// the distance to the nearer bound.
    pub fn of(name: &'static str, window: [Option<f64>; 2], measured: f64) -> Verdict {
        let [lo, hi] = window;
        let margin = [lo.map(|l| measured - l), hi.map(|h| h - measured)]
            .into_iter()
            .flatten()
            .fold(f64::INFINITY, f64::min);
        Verdict {
            name,
            window,
            measured,
            pass: margin >= 0.0,
            margin,
        }
    }
}

impl Standard {
    /// Release height of the bottom of the ball (m) for a drop test.
    pub fn release_height(&self, radius: f64) -> Option<f64> {
        match self.test {
            Test::Drop {
                height, drop_ref, ..
            } => Some(height - drop_ref.offset(radius)),
            Test::Cor { .. } => None,
        }
    }

    /// The verdict on a measured value: the margin is the distance to the nearer bound.
    pub fn judge_value(&self, measured: f64) -> Verdict {
        Verdict::of(self.name, self.window, measured)
    }

    /// Run this standard's test on `ball` in `air` (`None`: vacuum; a COR test reads the speeds
    /// at the wall, so air plays no part) and judge it.
    pub fn judge(&self, ball: &DropBall, air: Option<Air>) -> Result<Verdict, DropError> {
        self.judge_on(ball, air, &crate::target::Target::wall())
    }

    /// [`Standard::judge`] with the test run on `surface` (at rest) instead of the rigid plate
    /// the standard names (docs/surfaces.md): what the ball would do on that floor.
    pub fn judge_on(
        &self,
        ball: &DropBall,
        air: Option<Air>,
        surface: &crate::target::Target,
    ) -> Result<Verdict, DropError> {
        let measured = match self.test {
            Test::Drop { rebound_ref, .. } => {
                let height = self.release_height(ball.radius).unwrap_or(f64::NAN);
                let setup = DropSetup {
                    bounces: 1,
                    air,
                    ..DropSetup::new(height)
                };
                let watch = crate::analysis::work::Unwatched;
                let run = super::drop_on_watched(ball, &setup, surface, &watch)?
                    .expect("an unwatched drop is never stopped");
                run.bounces[0].rebound_height + rebound_ref.offset(ball.radius)
            }
            Test::Cor { speed } if surface == &crate::target::Target::wall() => {
                impact(ball, speed)?.cor
            }
            Test::Cor { speed } => {
                crate::target::collide(&ball.params, ball.law, surface, speed, None)
                    .map_err(super::DropError::Solve)?
                    .apparent_cor
            }
        };
        Ok(self.judge_value(measured))
    }
}
