//! The terminal explorer's charts as [`Figure`]s: the paper's figures ([`paper`]) built from
//! what the explorer holds, with the pinned curves and this run on top. The explorer draws
//! these figures and its export (`e`) writes the very same ones as SVG and CSV, so what is
//! exported is what is on screen.
//!
//! Built from a [`Scene`] — results and display choices, plain data — never from the
//! explorer's state, so a chart can be built (and tested) without a terminal.

use super::history;
use super::paper::{self, Ball};
use super::{Figure, GREY, Kind, Look, Marker, Series, Style, Tone};
use crate::analysis::sweep::{VelocityPoint, ZetaPoint};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::ImpactResponse;
use crate::text::short;

pub use super::overlay::{MeasuredOverlay, same_speed};

/// Palette index of this run's marker: orange, which no model curve of these figures uses.
const THIS_RUN_COLOR: usize = 4;

/// The ball's parameter set's name once λ or ζ moved off the preset's.
pub const MODIFIED: &str = "modified";

/// The explorer's charts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Chart {
    ForceTime,
    Hysteresis,
    CorZeta,
    ForceZeta,
    CorSpeed,
}

impl Chart {
    /// The chart's name in file names: the `bouncelab figure` name of the same figure.
    pub fn file_name(self) -> &'static str {
        match self {
            Chart::ForceTime => "force-time",
            Chart::Hysteresis => "force-displacement",
            Chart::CorZeta => "cor-zeta",
            Chart::ForceZeta => "force-zeta",
            Chart::CorSpeed => "cor-velocity",
        }
    }
}

/// COR and F̄_m against ζ for one λ (linear law, no flattening: Figs. 2, 3).
#[derive(Debug, Clone, Copy)]
pub struct ZetaSweep<'a> {
    pub lambda: f64,
    pub points: &'a [ZetaPoint],
}

/// COR against impact speed (Fig. 4), and the speed at which the linear law starts to flatten.
#[derive(Debug, Clone, Copy)]
pub struct SpeedSweep<'a> {
    pub points: &'a [VelocityPoint],
    pub v_flat: Option<f64>,
    /// The sweep runs over (0, v_max] (m/s).
    pub v_max: f64,
    /// Some speeds only, more to come: the title says the curve is being refined.
    pub refining: bool,
}

/// The pinned setting and its results, drawn dimmed behind the live ones.
#[derive(Debug, Clone, Copy)]
pub struct Pinned<'a> {
    pub params: ImpactParams,
    pub law: ContactLaw,
    pub run: Option<&'a ImpactResponse>,
    pub zeta: Option<ZetaSweep<'a>>,
    pub speed: Option<SpeedSweep<'a>>,
}

/// What the explorer shows: the results it holds and how they are to be drawn.
#[derive(Debug, Clone)]
pub struct Scene<'a> {
    /// The ball with the parameters and law the explorer runs on; its `source` is
    /// [`MODIFIED`] once λ or ζ left the preset's.
    pub ball: Ball,
    /// Every ball with what was measured: the markers of the ζ charts.
    pub balls: Vec<Ball>,
    pub run: Option<&'a ImpactResponse>,
    /// The fixed curves of Fig. 2 (λ = 0, 0.4, 1).
    pub references: Vec<ZetaSweep<'a>>,
    /// The current λ's curve.
    pub zeta: Option<ZetaSweep<'a>>,
    pub speed: Option<SpeedSweep<'a>>,
    /// While COR-vs-speed sweeps are out: the highest speed they reach (the axis spans it).
    pub speed_pending: Option<f64>,
    pub pinned: Option<Pinned<'a>>,
    /// The user's measured data, drawn on the charts they belong to.
    pub measured: &'a [MeasuredOverlay],
}

/// What a chart lacks to be exported (its computation failed, or a sweep is still out), as
/// "no … to export" names it.
pub fn missing(chart: Chart, scene: &Scene) -> Option<&'static str> {
    match chart {
        Chart::ForceTime | Chart::Hysteresis => scene.run.is_none().then_some("impact"),
        Chart::CorZeta | Chart::ForceZeta => scene.zeta.is_none().then_some("COR-vs-ζ curve"),
        Chart::CorSpeed => {
            (scene.speed.is_none() || scene.speed_pending.is_some()).then_some("COR-vs-speed sweep")
        }
    }
}

/// One chart's figure.
pub fn figure(chart: Chart, scene: &Scene) -> Figure {
    let mut fig = match chart {
        Chart::ForceTime | Chart::Hysteresis => history_figure(chart, scene),
        Chart::CorZeta | Chart::ForceZeta => zeta_figure(chart, scene),
        Chart::CorSpeed => speed_figure(scene),
    };
    let v0 = scene.ball.params.v0;
    for m in scene.measured.iter().filter(|m| m.chart == chart) {
        match m.v0 {
            // measured at another speed: neither drawn nor stretching the axes; said instead
            Some(at) if !same_speed(at, v0) => {
                let at = short(at, 4);
                fig.screen_title.push_str(&format!(" · data at {at} m/s"));
                fig.subtitle
                    .push_str(&format!("; measured {} (at {at} m/s) not shown", m.label));
            }
            _ => fig.series.push(m.series()),
        }
    }
    fig
}

fn lambda_zeta_text(p: &ImpactParams) -> String {
    let n = p.normalized();
    format!("λ = {}, ζ = {}", short(n.lambda, 3), short(n.zeta, 3))
}

/// A dimmed curve on screen: a grey dotted line in the picture.
fn pinned(label: String, id: &str, points: Vec<(f64, f64)>) -> Series {
    Series::new(&label, id, Kind::Pinned, Style::Dotted, GREY)
        .with_points(points)
        .with_look(Look::new(Tone::Ghost, Some("pinned"), None))
}

/// One run's point on a sweep's chart: the current run's ◆, or the pinned run's dimmed ◇.
fn run_marker(label: String, pinned: bool, at: (f64, f64)) -> Series {
    let (id, role, color, look) = if pinned {
        let look = Look::new(Tone::Ghost, Some("pinned"), Some("◇"));
        ("pinned run", Kind::Pinned, GREY, look)
    } else {
        let look = Look::new(Tone::Highlight, Some("this run"), Some("◆"));
        ("this run", Kind::ThisRun, THIS_RUN_COLOR, look)
    };
    Series::new(&label, id, role, Style::Markers(Marker::Diamond), color)
        .with_points(vec![at])
        .with_look(look)
}

/// Figs. 5–8 of the current run, with the pinned run's curve.
fn history_figure(chart: Chart, scene: &Scene) -> Figure {
    let build = match chart {
        Chart::ForceTime => paper::force_time,
        _ => paper::force_displacement,
    };
    let Some(run) = scene.run else {
        return history::frame(chart == Chart::Hysteresis, &scene.ball);
    };
    let mut fig = build(&scene.ball, run);
    // the subtitle names the parameter set; a modified one by its λ and ζ
    let from = format!("{MODIFIED} parameters");
    let to = format!("{from} ({})", lambda_zeta_text(&scene.ball.params));
    fig.subtitle = fig.subtitle.replacen(&from, &to, 1);
    if let Some(p) = &scene.pinned
        && let Some(r) = p.run
    {
        let h = &r.history;
        let label = format!(
            "pinned ({}, v0 = {} m/s)",
            lambda_zeta_text(&p.params),
            short(p.params.v0, 3)
        );
        let (id, xs) = if chart == Chart::ForceTime {
            ("pinned model", &h.t)
        } else {
            ("pinned displacement", &h.displacement)
        };
        let pts = xs.iter().copied().zip(h.force.iter().copied()).collect();
        let mut s = pinned(label, id, pts);
        if chart == Chart::Hysteresis {
            s.look.key = Some("pinned α".into());
        }
        fig.insert_before_measured(s);
    }
    fig
}

/// The decades of ζ shown: 0.01 … 100, widened to take in the current and pinned ζ.
pub fn decades(scene: &Scene) -> (i32, i32) {
    let pinned = scene.pinned.map(|p| p.params.normalized().zeta);
    super::ticks::covering(
        (-2, 2),
        pinned
            .into_iter()
            .chain([scene.ball.params.normalized().zeta]),
    )
}

/// The points of a ζ sweep inside the decades shown.
fn shown(c: &ZetaSweep, scene: &Scene) -> Vec<ZetaPoint> {
    let (lo, hi) = decades(scene);
    let inside = (10f64.powi(lo) * (1.0 - 1e-9))..=(10f64.powi(hi) * (1.0 + 1e-9));
    c.points
        .iter()
        .filter(|p| inside.contains(&p.zeta))
        .cloned()
        .collect()
}

/// The pinned λ's curve and the pinned run's ◇ on Fig. 2 (`cor`) or 3.
fn add_pinned_zeta(fig: &mut Figure, scene: &Scene, cor: bool) {
    let value = |p: &ZetaPoint| if cor { p.cor } else { p.max_force_normalized };
    let of_run = |r: &ImpactResponse| if cor { r.cor } else { r.max_force_normalized };
    if let Some(p) = &scene.pinned {
        if let Some(c) = &p.zeta {
            let label = format!("pinned, λ = {}", short(c.lambda, 3));
            let id = format!("pinned lambda={}", short(c.lambda, 6));
            let pts = shown(c, scene).iter().map(|p| (p.zeta, value(p))).collect();
            fig.insert_before_measured(pinned(label, &id, pts));
        }
        if let Some(r) = p.run {
            let at = (p.params.normalized().zeta, of_run(r));
            let label = format!("pinned run ({})", lambda_zeta_text(&p.params));
            fig.insert_before_measured(run_marker(label, true, at));
        }
    }
}

/// Figs. 2 and 3 as on screen: the λ = 0, 0.4, 1 curves and the current λ over the decades
/// shown, the pinned λ and run, this run and every ball's measured value.
fn zeta_figure(chart: Chart, scene: &Scene) -> Figure {
    let (lo, hi) = decades(scene);
    let (z_lo, z_hi) = (10f64.powi(lo), 10f64.powi(hi));
    let shown = |c: &ZetaSweep| shown(c, scene);
    let mut rows: Vec<ZetaPoint> = scene.references.iter().flat_map(shown).collect();
    // a current λ that is one of the references is already there
    if let Some(c) = &scene.zeta
        && !scene.references.iter().any(|r| r.lambda == c.lambda)
    {
        rows.extend(shown(c));
    }
    let cor = chart == Chart::CorZeta;
    let build = if cor {
        paper::cor_zeta
    } else {
        paper::force_zeta
    };
    let mut fig = build(&rows, &scene.balls, ContactLaw::Linear);
    fig.x.range = Some((z_lo, z_hi));
    // told apart without colour (NO_COLOR, greyscale print): the current λ solid, the fixed
    // ones dashed, dotted, dashed, each named at its right end
    const REFERENCE_STYLES: [Style; 3] = [Style::Dashed, Style::Dotted, Style::Dashed];
    let now = scene
        .zeta
        .as_ref()
        .map(|c| format!("model lambda={}", short(c.lambda, 6)));
    for s in fig
        .series
        .iter_mut()
        .filter(|s| s.id.starts_with("model lambda="))
    {
        let lambda = s.look.key.clone().unwrap_or_default();
        if Some(&s.id) == now.as_ref() {
            s.style = Style::Solid;
            s.look = Look::new(Tone::Current, Some(&format!("{lambda} now")), Some("now"));
        } else if let Tone::Reference(i) = s.look.tone {
            s.style = REFERENCE_STYLES[i % REFERENCE_STYLES.len()];
            s.look.text = Some(lambda);
        }
    }
    add_pinned_zeta(&mut fig, scene, cor);
    if let Some(r) = scene.run {
        let (y, what) = if cor {
            (r.cor, "e")
        } else {
            (r.max_force_normalized, "F̄m")
        };
        let label = format!(
            "this run ({}, {what} = {})",
            lambda_zeta_text(&scene.ball.params),
            short(y, 3)
        );
        fig.insert_before_measured(run_marker(
            label,
            false,
            (scene.ball.params.normalized().zeta, y),
        ));
    }
    fig
}

/// Where a sweep starts to flatten: midway between its last speed without a permanent
/// indentation and its first with one (to the sweep's spacing); `None` when it never does,
/// or already does at its first speed.
pub fn first_flattened(rows: &[VelocityPoint]) -> Option<f64> {
    let i = rows.iter().position(|r| r.permanent_indentation > 0.0)?;
    let before = rows.get(i.checked_sub(1)?)?;
    Some(0.5 * (before.v0 + rows[i].v0))
}

/// Fig. 4 for the current ball, with the pinned sweep and this run; the axis reaches as far
/// as the sweeps still out.
fn speed_figure(scene: &Scene) -> Figure {
    let ball = &scene.ball;
    let (rows, onset) = match &scene.speed {
        Some(s) => (s.points, s.v_flat),
        None => (&[][..], None),
    };
    // the onset computed for the sweep is the linear law's; the elastic–plastic law's is
    // where its sweep first leaves a permanent indentation; Hertz never flattens
    let onset = match ball.law {
        ContactLaw::Linear => onset,
        ContactLaw::ElasticPlastic => first_flattened(rows),
        ContactLaw::Hertz => None,
    };
    let mut fig = paper::cor_velocity(ball, rows, onset);
    // the ball's mark as on the ζ charts, where it must differ from the other balls'
    let names: Vec<&str> = scene.balls.iter().map(|b| b.name.as_str()).collect();
    if let Some(i) = names.iter().position(|n| *n == ball.name)
        && let Some(s) = fig.series.iter_mut().find(|s| s.id == "measured cor")
    {
        s.look.text = Some(paper::initials(&names)[i].clone());
    }
    let v_hi = [
        scene.speed.map(|s| s.v_max),
        scene.pinned.and_then(|p| p.speed).map(|s| s.v_max),
        scene.speed_pending,
        Some(ball.params.v0),
    ]
    .into_iter()
    .flatten()
    .fold(0.0, f64::max);
    let left = fig.x.range.map_or(0.0, |r| r.0);
    fig.x.range = Some((left, v_hi));
    if scene.speed.is_some_and(|s| s.refining) {
        fig.screen_title.push_str(" · refining…");
    } else if scene.speed_pending.is_some() {
        fig.screen_title.push_str(" · updating…");
    }
    if let Some(p) = &scene.pinned
        && let Some(c) = &p.speed
    {
        let label = format!("pinned ({}, {} law)", lambda_zeta_text(&p.params), p.law);
        let pts = c.points.iter().map(|p| (p.v0, p.cor)).collect();
        fig.insert_before_measured(pinned(label, "pinned model", pts));
    }
    if let Some(r) = scene.run {
        let v0 = ball.params.v0;
        let label = format!(
            "this run (v0 = {} m/s, e = {})",
            short(v0, 3),
            short(r.cor, 3)
        );
        fig.insert_before_measured(run_marker(label, false, (v0, r.cor)));
    }
    fig
}

#[cfg(test)]
#[path = "explorer_tests.rs"]
mod tests;
