//! The explorer's models view as [`Figure`]s: the field's contact models (crate::peers)
//! calibrated exactly to the explorer's ball — its Christoforou–Yigit COR at its v0 — drawn
//! over the Christoforou–Yigit impact: COR against impact speed (log axis), force against time
//! and force against the ball's displacement toward the wall. Built from [`ModelsData`], computed beforehand
//! (src/tui/views/models/state.rs, on the background worker); nothing here solves anything.
//!
//! Without colour the curves are told apart by a letter each ([`letter`]), printed on the
//! curve and in front of its legend key; the SVG writes the same letters beside the markers.

use super::Scene;
use crate::figure::{Axis, Corner, Figure, GREY, Kind, Look, Marker, Series, Style, Tone};
use crate::peers::PeerModel;
use crate::peers::calibrate::Calibrated;
use crate::peers::rules::Rule;
use crate::solver::{History, ImpactResponse};
use crate::text::short;

/// The calibrations and sweeps the models view draws, for one ball.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelsData {
    /// The COR calibrated to: the Christoforou–Yigit model's at v0.
    pub target: f64,
    /// The speed of the calibration (m/s).
    pub v0: f64,
    /// Every model under every rule published for it (`calibrate::compare`), with histories.
    pub rows: Vec<Calibrated>,
    /// The Christoforou–Yigit COR at log-spaced speeds: (v0, e).
    pub cy_speed: Vec<(f64, f64)>,
    /// Hunt–Crossley's damping kept as the material constant α = χ/v0 (s/m) of its exact
    /// calibration, and the COR that gives at the same speeds (it falls with speed).
    pub hc_alpha: f64,
    /// The COR Hunt–Crossley gives with α held at `hc_alpha`: (v0, e).
    pub hc_fixed: Vec<(f64, f64)>,
}

impl ModelsData {
    /// The exact calibration of `model`.
    pub fn exact(&self, model: PeerModel) -> Option<&Calibrated> {
        self.rows
            .iter()
            .find(|c| c.model == model && c.rule == Rule::Exact)
    }
}

/// The letter that marks a model's curves on screen and in the SVG (and heads its legend key
/// and table row), so the curves stay distinct without colour.
pub fn letter(model: Option<PeerModel>) -> &'static str {
    match model {
        None => "C",
        Some(PeerModel::KelvinVoigt) => "K",
        Some(PeerModel::KelvinVoigtNoTension) => "N",
        Some(PeerModel::Tsuji) => "T",
        Some(PeerModel::HuntCrossley) => "H",
    }
}

/// A model's short name on screen; `None` is the Christoforou–Yigit model.
pub fn short_name(model: Option<PeerModel>) -> &'static str {
    match model {
        None => "C–Y",
        Some(PeerModel::KelvinVoigt) => "KV",
        Some(PeerModel::KelvinVoigtNoTension) => "KV F≥0",
        Some(PeerModel::Tsuji) => "Tsuji",
        Some(PeerModel::HuntCrossley) => "H–C",
    }
}

/// A rule's short name on screen.
pub fn short_rule(rule: Rule) -> &'static str {
    match rule {
        Rule::Exact => "exact",
        Rule::LogDecrement => "log-dec",
        Rule::HuntCrossley => "H–C",
        Rule::LankaraniNikravesh => "L–N",
        Rule::Flores => "Flores",
        Rule::Gonthier => "Gonthier",
    }
}

/// The letter for Hunt–Crossley with α fixed.
const FIXED_ALPHA: &str = "h";

/// The k-th curve's tone and palette colour: the Christoforou–Yigit model the live colour,
/// each peer its own.
fn colors(k: usize) -> (Tone, usize) {
    match k {
        0 => (Tone::Current, 0),
        k => (Tone::Reference(k - 1), k),
    }
}

/// A curve and its letter: the line (legend label `"<letter>: <name>"` in the SVG), and one
/// marker printing the letter at fraction `0.1 + 0.16 k` along it, so that the letters of
/// different curves sit apart. The marker comes first: the terminal legend then shows the
/// letter in front of the key. The line's CSV id is the model's name, as in
/// `bouncelab figure peers-*` (`name` without " (exact)"); the marker's `"<id> letter"`.
fn lettered(k: usize, letter: &str, name: &str, key: &str, pts: Vec<(f64, f64)>) -> [Series; 2] {
    let id = name.strip_suffix(" (exact)").unwrap_or(name);
    let (tone, color) = colors(k);
    let style = [Style::Solid, Style::Dashed, Style::Dotted][k % 3];
    let at = ((0.1 + 0.16 * k as f64) * pts.len() as f64) as usize;
    let mark_at: Vec<(f64, f64)> = pts
        .get(at.min(pts.len().saturating_sub(1)))
        .into_iter()
        .copied()
        .collect();
    let mut mark = Series::new(
        "",
        &format!("{id} letter"),
        Kind::Model,
        Style::Markers(Marker::Square),
        color,
    )
    .with_points(mark_at)
    .with_look(Look::new(tone, Some(key), Some(letter)));
    mark.annotations = vec![letter.to_string()];
    let line = Series::new(&format!("{letter}: {name}"), id, Kind::Model, style, color)
        .with_points(pts)
        .with_look(Look::new(tone, Some(key), None));
    [mark, line]
}

/// The curves of one chart: the Christoforou–Yigit one, then each peer's exact calibration.
fn curves(
    scene: &Scene,
    data: Option<&ModelsData>,
    pick: impl Fn(&ImpactResponse) -> Vec<(f64, f64)>,
) -> Vec<Series> {
    let mut out = Vec::new();
    if let Some(r) = scene.run {
        out.extend(lettered(
            0,
            letter(None),
            "christoforou-yigit",
            "C–Y model",
            pick(r),
        ));
    }
    for (k, model) in PeerModel::ALL.into_iter().enumerate() {
        if let Some(c) = data.and_then(|d| d.exact(model)) {
            let name = format!("{model} (exact)");
            let key = format!("{} exact", short_name(Some(model)));
            out.extend(lettered(
                k + 1,
                letter(Some(model)),
                &name,
                &key,
                pick(&c.response),
            ));
        }
    }
    out
}

/// The subtitle (the SVG's): ball, speed and COR of the calibration. Without one (still out,
/// failed, or its worker stopped) it says that the peers are not calibrated, not that a result
/// is coming (the export refuses such a figure, `super::missing`: tests/tui/tui_models_export.rs).
fn subtitle(scene: &Scene, data: Option<&ModelsData>) -> String {
    let ball = &scene.ball;
    match data {
        Some(d) => format!(
            "{}, {} law; peers calibrated exactly to the model's e = {} at v0 = {} m/s",
            ball.name,
            ball.law,
            short(d.target, 4),
            short(d.v0, 3)
        ),
        None => format!("{}, {} law; peers not calibrated", ball.name, ball.law),
    }
}

/// The screen title, with "calibrating…" while the worker is at it.
fn screen_title(title: &str, scene: &Scene) -> String {
    if scene.models_pending {
        format!("{title} · calibrating…")
    } else {
        title.to_string()
    }
}

/// The COR-vs-speed curves of `d`: Christoforou–Yigit, each peer's exact calibration (flat),
/// Hunt–Crossley with α fixed, and the calibration point.
fn cor_series(d: &ModelsData) -> Vec<Series> {
    let mut series = Vec::new();
    let cy = d.cy_speed.clone();
    series.extend(lettered(
        0,
        letter(None),
        "christoforou-yigit",
        "C–Y model",
        cy,
    ));
    for (k, model) in PeerModel::ALL.into_iter().enumerate() {
        if let Some(c) = d.exact(model) {
            let pts = d.cy_speed.iter().map(|p| (p.0, c.response.cor)).collect();
            let name = format!("{model} (exact)");
            let key = format!("{} exact", short_name(Some(model)));
            series.extend(lettered(k + 1, letter(Some(model)), &name, &key, pts));
        }
    }
    let alpha = short(d.hc_alpha, 3);
    let name = format!("hunt-crossley, fixed α = χ/v0 = {alpha} s/m");
    let [mut mark, mut line] = lettered(5, FIXED_ALPHA, &name, "H–C α fixed", d.hc_fixed.clone());
    for s in [&mut mark, &mut line] {
        s.color = GREY;
        s.look.tone = Tone::Secondary;
    }
    line.id = "hunt-crossley-fixed-alpha".into();
    mark.id = "hunt-crossley-fixed-alpha letter".into();
    series.extend([mark, line]);
    let label = format!(
        "calibration point (v0 = {} m/s, e = {})",
        short(d.v0, 3),
        short(d.target, 4)
    );
    let look = Look::new(Tone::Highlight, Some("calibrated here"), Some("◆"));
    let point = Series::new(
        &label,
        "calibration point",
        Kind::ThisRun,
        Style::Markers(Marker::Diamond),
        4,
    );
    series.push(point.with_points(vec![(d.v0, d.target)]).with_look(look));
    series
}

/// COR against impact speed: the Christoforou–Yigit curve, each peer's exact calibration (flat:
/// their COR does not depend on v0), Hunt–Crossley with α fixed, the calibration point.
pub fn cor_speed(scene: &Scene) -> Figure {
    let data = scene.models;
    let v0 = scene.ball.params.v0;
    let (lo, hi) = crate::figure::peers::default_range(&scene.ball.params);
    let series = data.map(cor_series).unwrap_or_default();
    let mut fig = Figure::new(
        format!(
            "Contact models calibrated to this ball: {}",
            scene.ball.name
        ),
        subtitle(scene, data),
        Axis::log("impact speed v0 (m/s)", "v0", lo.min(v0), hi.max(v0)),
        Axis::linear("coefficient of restitution e", "cor", 1.0).with_range(0.0, 1.05),
        series,
    );
    fig.screen_title = screen_title("models: COR e vs v0 [m/s] (log)", scene);
    fig.legend_corner = Corner::BottomLeft;
    fig
}

/// Force against time at v0: the Christoforou–Yigit impact and each peer's exact calibration.
pub fn force_time(scene: &Scene) -> Figure {
    force_against(
        scene,
        |h| &h.t,
        "time",
        Axis::linear("time t (ms)", "t", 1e3),
        "F [N] vs t [ms]",
    )
}

/// Force against the ball's displacement toward the wall at v0 — the approach δ, the overlap
/// of a DEM code: the peers' δ (rigid flat), the Christoforou–Yigit ball's α = z + the
/// element's displacement — with the loading and unloading loops.
pub fn force_displacement(scene: &Scene) -> Figure {
    let mut fig = force_against(
        scene,
        |h| &h.displacement,
        "the ball's approach",
        Axis::linear("ball displacement (approach) δ (mm)", "displacement", 1e3),
        "F [N] vs δ [mm]",
    );
    fig.legend_corner = Corner::TopLeft;
    fig
}

/// The contact force of every model against the history's column `x` (`what`, on `x_axis`),
/// titled `screen` on the screen.
fn force_against(
    scene: &Scene,
    x: fn(&History) -> &[f64],
    what: &str,
    x_axis: Axis,
    screen: &str,
) -> Figure {
    let series = curves(scene, scene.models, |r| {
        let h = &r.history;
        x(h).iter().copied().zip(h.force.iter().copied()).collect()
    });
    let mut fig = Figure::new(
        format!(
            "Contact force against {what}, models calibrated: {}",
            scene.ball.name
        ),
        subtitle(scene, scene.models),
        x_axis,
        Axis::linear("contact force F (N)", "force", 1.0),
        series,
    );
    fig.screen_title = screen_title(screen, scene);
    fig
}
