//! `bouncelab drop --format json`'s document (src/cli/drop.rs): the bounces with their
//! intervals on a fitted preset, and the standard's verdict.

use crate::api::Ball;
use crate::drop::standards::Verdict;
use crate::drop::{DropRun, DropSetup};
use serde::Serialize;

#[derive(Serialize)]
pub(super) struct StandardJson {
    name: &'static str,
    window: [Option<f64>; 2],
    measured: f64,
    verdict: &'static str,
    margin: f64,
    /// The release height (m, bottom of the ball) the verdict was judged at: the standard's
    /// own drop, whatever `--height` gave the bounces above (`height`); `null` for a COR
    /// test. tests/cli/cli_drop.rs.
    judged_at_height_m: Option<f64>,
    /// A static standard's test (src/drop/deformation.rs): only for one.
    #[serde(rename = "static", skip_serializing_if = "Option::is_none")]
    pub(super) static_test: Option<crate::api::StaticTestReport>,
}

/// One bounce's 95 % intervals on a fitted preset (docs/fitting.md, "Prediction intervals").
#[derive(Debug, Clone, Copy, Serialize)]
pub(super) struct BounceIntervals {
    pub(super) cor_ci95: [f64; 2],
    pub(super) max_force_ci95: [f64; 2],
    pub(super) contact_time_ci95: [f64; 2],
    pub(super) rebound_height_ci95: [f64; 2],
}

/// A bounce, with its intervals when the ball carries a fit.
#[derive(Serialize)]
struct BounceRow<'a> {
    #[serde(flatten)]
    bounce: &'a crate::drop::Bounce,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    intervals: Option<BounceIntervals>,
}

/// A fitted preset's bounce intervals ([`Ball::drop_intervals`]); empty without a fit or when
/// an override moved it.
pub(super) fn bounce_intervals(
    b: &Ball,
    setup: &DropSetup,
    watch: &super::budget::Watcher,
) -> anyhow::Result<Vec<BounceIntervals>> {
    // a watch that said stop leaves the signal flag set: any error then exits 130
    // (`cli::exit_code`)
    let Some(bands) = b.drop_intervals_watched(setup, watch).transpose()? else {
        return Ok(Vec::new());
    };
    Ok(bands
        .iter()
        .map(|c| BounceIntervals {
            cor_ci95: c[0],
            max_force_ci95: c[1],
            contact_time_ci95: c[2],
            rebound_height_ci95: c[3],
        })
        .collect())
}

/// The JSON document of the issue, SI: `standard` only with `--standard`.
#[derive(Serialize)]
pub(super) struct Report<'a> {
    height: f64,
    drag: bool,
    bounces: Vec<BounceRow<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) standard: Option<StandardJson>,
    /// What the caller should know (the first, fastest impact's [`Ball::warnings`]).
    pub(super) warnings: Vec<String>,
    /// The ball dropped (docs/cli.md, "The ball object").
    pub(super) ball: Option<crate::api::BallRecord>,
    /// The bounces' outputs its record does not vouch for (`Ball::uncalibrated_outputs`).
    pub(super) uncalibrated_outputs: Option<Vec<crate::preset::Output>>,
    /// The surface it bounced on (docs/surfaces.md).
    pub(super) surface: Option<super::surface::SurfaceUsed>,
    /// `--standard fifa-pressure-loss`'s verdict on the ball's leak.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) pressure_loss: Option<super::drop_leak::LeakVerdict>,
}

pub(super) fn report<'a>(
    run: &'a DropRun,
    bands: &[BounceIntervals],
    v: Option<&Verdict>,
    judged_at: Option<f64>,
) -> Report<'a> {
    let bands = bands
        .iter()
        .copied()
        .map(Some)
        .chain(std::iter::repeat(None));
    Report {
        height: run.setup.height,
        drag: run.drag(),
        bounces: run
            .bounces
            .iter()
            .zip(bands)
            .map(|(bounce, intervals)| BounceRow { bounce, intervals })
            .collect(),
        standard: v.map(|v| StandardJson {
            name: v.name,
            window: v.window,
            measured: v.measured,
            verdict: if v.pass { "pass" } else { "fail" },
            margin: v.margin,
            judged_at_height_m: judged_at,
            static_test: None,
        }),
        warnings: Vec::new(),
        ball: None,
        uncalibrated_outputs: None,
        surface: None,
        pressure_loss: None,
    }
}
