//! The terminal explorer's charts as [`Figure`]s: the paper's figures ([`paper`]) built from
//! what the explorer holds, with the pinned curves and this run on top. The explorer draws
//! these figures and its export (`e`) writes the very same ones as SVG and CSV, so what is
//! exported is what is on screen.
//!
//! Built from a [`Scene`] — results and display choices, plain data — never from the
//! explorer's state, so a chart can be built (and tested) without a terminal.

use super::history;
use super::paper::{self, Ball};
use super::{Figure, Kind, Look, Marker, Series, Style, Tone};
use crate::analysis::sweep::{VelocityPoint, ZetaPoint};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::ImpactResponse;
use crate::text::short;

pub use super::chart::Chart;
pub use super::overlay::{MeasuredOverlay, same_speed};

/// Palette index of this run's marker: orange, which no model curve of these figures uses.
const THIS_RUN_COLOR: usize = 4;

/// The ball's parameter set's name once λ or ζ moved off the preset's.
pub const MODIFIED: &str = "modified";

/// COR and F̄_m against ζ for one λ (linear law, no flattening: Figs. 2, 3).
#[derive(Debug, Clone, Copy)]
pub struct ZetaSweep<'a> {
    /// The λ of the curve.
    pub lambda: f64,
    /// Its points, ζ increasing.
    pub points: &'a [ZetaPoint],
}

/// COR against impact speed (Fig. 4), and the speed at which the linear law starts to flatten.
#[derive(Debug, Clone, Copy)]
pub struct SpeedSweep<'a> {
    /// Its points, speed increasing.
    pub points: &'a [VelocityPoint],
    /// The speed (m/s) above which the peak indentation passes z_p, when within the sweep.
    pub v_flat: Option<f64>,
    /// The sweep runs over (0, v_max] (m/s).
    pub v_max: f64,
    /// Some speeds only, more to come: the title says the curve is being refined.
    pub refining: bool,
}

/// A pinned setting and its results, drawn dimmed behind the live ones.
#[derive(Debug, Clone)]
pub struct Pinned<'a> {
    /// 1, 2, …: the pin's tag on screen and in the series ids (`pinned 2 model`).
    pub number: usize,
    /// The ball's name.
    pub ball: String,
    /// The pinned parameters, SI.
    pub params: ImpactParams,
    /// The pinned contact law.
    pub law: ContactLaw,
    /// Its impact, once computed.
    pub run: Option<&'a ImpactResponse>,
    /// Its ζ curve, once computed.
    pub zeta: Option<ZetaSweep<'a>>,
    /// Its COR-against-speed curve, once computed.
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
    /// The current impact, once computed (with its history).
    pub run: Option<&'a ImpactResponse>,
    /// The fixed curves of Fig. 2 (λ = 0, 0.4, 1).
    pub references: Vec<ZetaSweep<'a>>,
    /// The current λ's curve.
    pub zeta: Option<ZetaSweep<'a>>,
    /// The current ball's COR-against-speed curve, once computed.
    pub speed: Option<SpeedSweep<'a>>,
    /// While COR-vs-speed sweeps are out: the highest speed they reach (the axis spans it).
    pub speed_pending: Option<f64>,
    /// Why the sweeps' worker stopped, when it did (the chart's title says so).
    pub speed_stopped: Option<&'a str>,
    /// The pins, oldest first.
    pub pinned: Vec<Pinned<'a>>,
    /// The user's measured data, drawn on the charts they belong to.
    pub measured: &'a [MeasuredOverlay],
    /// The models view's calibrations, once computed for this ball.
    pub models: Option<&'a models::ModelsData>,
    /// Whether the calibrations for this ball are still out (`models` may be a stale ball's,
    /// and is then not drawn).
    pub models_pending: bool,
    /// The target's motion in the current run, when the ball meets a moving or compliant
    /// target (the force–displacement chart draws it).
    pub target: Option<&'a TargetMotion>,
}

/// What a chart lacks to be exported (its computation failed, or a sweep is still out), as
/// "no … to export" names it.
pub fn missing(chart: Chart, scene: &Scene) -> Option<&'static str> {
    match chart {
        Chart::ForceTime | Chart::Hysteresis => scene.run.is_none().then_some("impact"),
        Chart::CorZeta | Chart::ForceZeta => scene.zeta.is_none().then_some("COR-vs-ζ curve"),
        Chart::CorSpeed => {
            let out = scene.speed_pending.is_some() || scene.speed_stopped.is_some();
            (scene.speed.is_none() || out).then_some("COR-vs-speed sweep")
        }
        Chart::ModelsCorSpeed | Chart::ModelsForceTime | Chart::ModelsForceDisplacement => {
            (scene.models.is_none() || scene.models_pending).then_some("calibration of the models")
        }
    }
}

/// One chart's figure.
pub fn figure(chart: Chart, scene: &Scene) -> Figure {
    let mut fig = match chart {
        Chart::ForceTime | Chart::Hysteresis => history_figure(chart, scene),
        Chart::CorZeta | Chart::ForceZeta => zeta_figure(chart, scene),
        Chart::CorSpeed => speed_figure(scene),
        Chart::ModelsCorSpeed => models::cor_speed(scene),
        Chart::ModelsForceTime => models::force_time(scene),
        Chart::ModelsForceDisplacement => models::force_displacement(scene),
    };
    let v0 = scene.ball.params.v0;
    for (i, m) in scene
        .measured
        .iter()
        .filter(|m| m.chart == chart)
        .enumerate()
    {
        match m.v0 {
            // measured at another speed: neither drawn nor stretching the axes; said instead
            Some(at) if !same_speed(at, v0) => {
                let at = short(at, 4);
                fig.screen_title.push_str(&format!(" · data at {at} m/s"));
                fig.subtitle
                    .push_str(&format!("; measured {} (at {at} m/s) not shown", m.label));
            }
            _ => fig.series.push(m.series(i)),
        }
    }
    fig
}

fn lambda_zeta_text(p: &ImpactParams) -> String {
    let n = p.normalized();
    format!("λ = {}, ζ = {}", short(n.lambda, 3), short(n.zeta, 3))
}

/// The current run's point on a sweep's chart: ◆.
fn run_marker(label: String, at: (f64, f64)) -> Series {
    let look = Look::new(Tone::Highlight, Some("this run"), Some("◆"));
    let diamond = Style::Markers(Marker::Diamond);
    Series::new(&label, "this run", Kind::ThisRun, diamond, THIS_RUN_COLOR)
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
    for p in &scene.pinned {
        let Some(r) = p.run else { continue };
        let h = &r.history;
        let (what, xs) = if chart == Chart::ForceTime {
            ("model", &h.t)
        } else {
            ("displacement", &h.displacement)
        };
        let pts = xs.iter().copied().zip(h.force.iter().copied()).collect();
        let mut s = p.curve(what, pts);
        if chart == Chart::Hysteresis {
            s.look.key = Some(format!("{} α", p.key()));
        }
        fig.insert_before_measured(s);
    }
    if chart == Chart::Hysteresis {
        target::add(&mut fig, scene);
    }
    if chart == Chart::ForceTime {
        for s in labels::result_labels(run) {
            fig.insert_before_measured(s);
        }
    } else if let Some(s) = labels::open_loop_label(run) {
        fig.insert_before_measured(s);
    }
    fig
}

/// The decades of ζ shown: 0.01 … 100, widened to take in the current and pinned ζ.
pub fn decades(scene: &Scene) -> (i32, i32) {
    let pinned = scene.pinned.iter().map(|p| p.params.normalized().zeta);
    super::ticks::covering((-2, 2), pinned.chain([scene.ball.params.normalized().zeta]))
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

/// Each pin's λ curve (tagged `p1`, …) and run (its number) on Fig. 2 (`cor`) or 3, one
/// legend entry for all.
fn add_pinned_zeta(fig: &mut Figure, scene: &Scene, cor: bool) {
    let value = |p: &ZetaPoint| if cor { p.cor } else { p.max_force_normalized };
    let of_run = |r: &ImpactResponse| if cor { r.cor } else { r.max_force_normalized };
    for p in &scene.pinned {
        if let Some(c) = &p.zeta {
            let what = format!("lambda={}", short(c.lambda, 6));
            let pts = shown(c, scene).iter().map(|p| (p.zeta, value(p))).collect();
            let mut s = p.curve(&what, pts);
            s.look.key = Some("pinned".into());
            fig.insert_before_measured(s);
        }
        if let Some(r) = p.run {
            let at = (p.params.normalized().zeta, of_run(r));
            fig.insert_before_measured(p.marker(at));
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
    // ones dashed, dotted, in long dashes, each named at its right end: four lines, four
    // patterns (tests/tui/tui_render.rs: `no_color_cor_zeta_lines_each_have_their_own_glyph`)
    const REFERENCE_STYLES: [Style; 3] = [Style::Dashed, Style::Dotted, Style::LongDashed];
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
        let mut marker = run_marker(label, (scene.ball.params.normalized().zeta, y));
        // the curves are the linear law's without flattening: a run under another law, or
        // one that flattened, lies off them and says so, hollow
        // (`a_run_off_the_linear_curves_is_drawn_hollow_and_says_so`)
        let flattened = r.permanent_indentation > 0.0;
        if scene.ball.law != ContactLaw::Linear || flattened {
            let why = if flattened {
                "flattened".to_string()
            } else {
                format!("{} law", scene.ball.law)
            };
            let key = format!("this run: {why}, off curves");
            marker.look = Look::new(Tone::Highlight, Some(&key), Some("◇"));
        }
        fig.insert_before_measured(marker);
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
        s.look.text = Some(paper::marks(&names)[i].clone());
    }
    let v_hi = [
        scene.speed.map(|s| s.v_max),
        scene.speed_pending,
        Some(ball.params.v0),
    ]
    .into_iter()
    .flatten()
    .chain(scene.pinned.iter().filter_map(|p| p.speed).map(|s| s.v_max))
    .fold(0.0, f64::max);
    let left = fig.x.range.map_or(0.0, |r| r.0);
    fig.x.range = Some((left, v_hi));
    if let Some(why) = scene.speed_stopped {
        fig.screen_title
            .push_str(&format!(" · stopped: {why} (R retries)"));
    } else if scene.speed.is_some_and(|s| s.refining) {
        fig.screen_title.push_str(" · refining…");
    } else if scene.speed_pending.is_some() {
        fig.screen_title.push_str(" · updating…");
    }
    for p in &scene.pinned {
        let Some(c) = &p.speed else { continue };
        let pts = c.points.iter().map(|p| (p.v0, p.cor)).collect();
        fig.insert_before_measured(p.curve("model", pts));
    }
    if let Some(r) = scene.run {
        let v0 = ball.params.v0;
        let label = format!(
            "this run (v0 = {} m/s, e = {})",
            short(v0, 3),
            short(r.cor, 3)
        );
        fig.insert_before_measured(run_marker(label, (v0, r.cor)));
    }
    fig
}

mod labels;
pub mod models;
pub use labels::result_labels;

mod pins;
mod target;
pub use target::TargetMotion;

#[cfg(test)]
mod tests;
