//! Bats: the batted-ball speed (BBS) of a game impact and the NCAA BBCOR test, with the bat
//! standards `bouncelab standards` lists (docs/targets.md §5).
//!
//! BBCOR ("ball–bat coefficient of restitution"): a ball fired at 136 mph onto a bat at rest;
//! with the bat's effective mass M_eff at the impact point, BBCOR is the COR of the pair e
//! (separation speed over closing speed). NCAA's certification allows at most 0.50.

use super::{Collision, Target, collide};
use crate::drop::standards::{Standard, Verdict};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::SolveError;
use serde::Serialize;

/// 136 mph in m/s, the BBCOR test's ball speed (exact: 1 mph = 0.44704 m/s).
pub const MPH_136: f64 = 136.0 * 0.44704;

/// What a bat standard measures.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum BatTest {
    /// A ball fired at `speed` (m/s) onto the bat at rest; the pair's COR is the measured value.
    Bbcor {
        /// Ball speed, m/s.
        speed: f64,
    },
}

/// One body's bat test and its window.
pub type BatStandard = Standard<BatTest>;

/// The bat standards, as `bouncelab standards` lists them after the ball standards.
pub const BAT_STANDARDS: [BatStandard; 1] = [BatStandard {
    name: "ncaa-bbcor",
    title: "NCAA baseball bat, BBCOR maximum",
    test: BatTest::Bbcor { speed: MPH_136 },
    surface: "the bat at rest, effective mass at the impact point (`bouncelab bat`)",
    window: [None, Some(0.50)],
    source: "NCAA BBCOR bat certification (BBCOR ≤ 0.50), ball fired at 136 mph onto a \
             stationary bat",
    unconfirmed: Some(
        "the pivoted bat's moment of inertia, which the test reads the effective mass from: \
         the model takes M_eff as given",
    ),
    // the ball the test fires is a regulation (NCAA) baseball: the MLB rules' ball is the
    // closest embedded (docs/presets.md, `baseball-mlb`); the paper's baseball, COR 0.485 at
    // 85 ft/s, passes any rigid bat (issue 52)
    balls: &["baseball-mlb"],
}];

/// A bat's game impact and its BBCOR test, with the verdict.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BatRun {
    /// BBCOR: the pair's COR at 136 mph onto the bat at rest.
    pub bbcor: f64,
    /// Batted-ball speed at the game speeds (m/s, away from the bat).
    pub bbs: f64,
    /// Apparent COR e_A = (e − m/M)/(1 + m/M) of the game impact.
    pub apparent_cor: f64,
    /// `"PASS"` (BBCOR within the window) or `"FAIL"`.
    pub verdict: &'static str,
    /// Whether BBCOR lies within the window.
    pub pass: bool,
    /// The limit BBCOR is held to (0.50).
    pub limit: f64,
    /// The game impact in full.
    pub game: Collision,
    /// The BBCOR impact in full.
    pub test: Collision,
    /// The bat as the game's target (the test's is the same at rest): what the warnings read
    /// the ball's compression against (`Ball::bat_warnings`).
    #[serde(skip)]
    pub bat: Target,
}

/// The game impact (`speeds` = (ball, bat) in m/s, toward each other) and the BBCOR test of a
/// bat of effective mass `bat_mass` (kg) with surface (K_s, c_s).
pub fn run(
    params: &ImpactParams,
    law: ContactLaw,
    bat_mass: f64,
    (ball_speed, bat_speed): (f64, f64),
    (stiffness, damping): (f64, f64),
) -> Result<BatRun, SolveError> {
    let bat = Target {
        mass: bat_mass,
        speed: bat_speed,
        stiffness,
        damping,
    };
    let game = collide(params, law, &bat, ball_speed, None)?;
    let at_rest = Target { speed: 0.0, ..bat };
    let BatTest::Bbcor { speed } = BAT_STANDARDS[0].test;
    let test = collide(params, law, &at_rest, speed, None)?;
    let standard = &BAT_STANDARDS[0];
    let limit = standard.window[1].unwrap_or(f64::INFINITY);
    // the window's verdict, as a ball standard's (`Verdict::of`)
    let pass = Verdict::of(standard.name, standard.window, test.cor).pass;
    Ok(BatRun {
        bbcor: test.cor,
        bbs: game.ball_speed_out,
        apparent_cor: game.apparent_cor,
        verdict: if pass { "PASS" } else { "FAIL" },
        pass,
        limit,
        game,
        test,
        bat,
    })
}
