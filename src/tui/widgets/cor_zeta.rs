//! COR against ζ on a decade axis (Fig. 2) — and, sharing this code, the normalized peak force
//! (Fig. 3, force_zeta.rs): the λ = 0, 0.4, 1 curves, the current λ, a marker at the current
//! run, and each ball's measured value at its adopted ζ.

use super::axis::AxisSpec;
use super::log_axis::covering;
use super::plot::{Corner, Mark, Plot, Series};
use super::{initial, legend};
use crate::analysis::sweep::ZetaPoint;
use crate::solver::ImpactResponse;
use crate::text::sig_trim;
use crate::tui::app::App;
use crate::tui::compute::{ZetaCurve, reference_curves};
use crate::tui::param::Param;
use crate::tui::theme::Theme;
use ratatui::style::Style;

/// Which result goes up the y axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// e (Fig. 2)
    Cor,
    /// F̄_m = F_m / (m v0 ω0) (Fig. 3)
    PeakForce,
}

impl Quantity {
    fn of_point(self, p: &ZetaPoint) -> f64 {
        match self {
            Quantity::Cor => p.cor,
            Quantity::PeakForce => p.max_force_normalized,
        }
    }
    fn of_run(self, r: &ImpactResponse) -> f64 {
        match self {
            Quantity::Cor => r.cor,
            Quantity::PeakForce => r.max_force_normalized,
        }
    }
}

/// The decades shown: 0.01 … 100, widened to take in the current and pinned ζ.
pub fn decades(app: &App) -> (i32, i32) {
    let ghost = app.ghost().map(|g| g.setting.get(Param::Zeta));
    covering(
        (-2, 2),
        ghost.into_iter().chain([app.setting().get(Param::Zeta)]),
    )
}

fn curve(c: &ZetaCurve, q: Quantity) -> Vec<(f64, f64)> {
    c.points
        .iter()
        .map(|p| (p.zeta.log10(), q.of_point(p)))
        .collect()
}

pub fn plot(app: &App) -> Plot {
    zeta_plot(app, Quantity::Cor)
}

pub fn zeta_plot(app: &App, q: Quantity) -> Plot {
    let theme = Theme::new(app.color());
    let (lo, hi) = decades(app);
    let mut series = Vec::new();
    let mut legend_lines = Vec::new();
    let mut marks = Vec::new();
    let mut y_hi = 1.0f64;
    for (i, c) in reference_curves().iter().enumerate() {
        let color = theme.reference(i);
        series.push(Series::live(curve(c, q), color));
        legend_lines.push(legend(
            "━",
            Style::default().fg(color),
            format!("λ={}", c.lambda),
        ));
    }
    if let Some(g) = app.ghost() {
        if let Some(c) = &g.zeta {
            series.push(Series::ghost(curve(c, q)));
        }
        if let Some(r) = &g.run {
            let at = (g.setting.get(Param::Zeta).log10(), q.of_run(r));
            marks.push(Mark {
                x: at.0,
                y: at.1,
                text: "◇".into(),
                style: theme.ghost(),
            });
        }
    }
    if let Some(c) = app.zeta_curve() {
        series.push(Series::live(curve(c, q), theme.current()));
        let text = format!("λ={} now", sig_trim(c.lambda, 4));
        legend_lines.push(legend("━", Style::default().fg(theme.current()), text));
    }
    if app.ghost().is_some() {
        legend_lines.push(legend("━", theme.ghost(), "pinned"));
    }
    // the current run's marker first: a measured letter in the same cell stays visible
    if let Some(r) = app.run() {
        let v = q.of_run(r);
        y_hi = y_hi.max(v);
        let at = (app.setting().get(Param::Zeta).log10(), v);
        marks.push(Mark {
            x: at.0,
            y: at.1,
            text: "◆".into(),
            style: theme.warning(),
        });
        legend_lines.push(legend("◆", theme.warning(), "this run"));
    }
    let mut letters = Vec::new();
    for p in app.presets() {
        let params = p.params();
        let value = match q {
            Quantity::Cor => p.measured.cor,
            Quantity::PeakForce => p
                .measured
                .max_force
                .map(|f| f / (params.mass * p.measured.v0 * params.omega0())),
        };
        if let Some(v) = value.filter(|v| v.is_finite()) {
            let text = initial(&p.name);
            y_hi = y_hi.max(v);
            marks.push(Mark {
                x: params.normalized().zeta.log10(),
                y: v,
                text: text.clone(),
                style: theme.measured(),
            });
            letters.push(text);
        }
    }
    if !letters.is_empty() {
        legend_lines.push(legend(
            "",
            theme.measured(),
            format!("{} measured", letters.join(" ")),
        ));
    }
    let (title, short_title) = match q {
        Quantity::Cor => (
            "COR e vs ζ (log) · linear law, no flattening",
            "e vs ζ (log)",
        ),
        Quantity::PeakForce => (
            "Normalized peak force Fm/(m v0 ω0) vs ζ (log) · linear law",
            "Fm/(m v0 ω0) vs ζ",
        ),
    };
    Plot {
        title: title.into(),
        short_title: short_title.into(),
        x: AxisSpec::Log { lo, hi },
        y: AxisSpec::Linear { lo: 0.0, hi: y_hi },
        series,
        rules: Vec::new(),
        marks,
        legend: legend_lines,
        legend_at: match q {
            Quantity::Cor => Corner::BottomRight,
            Quantity::PeakForce => Corner::BottomLeft,
        },
        theme,
    }
}
