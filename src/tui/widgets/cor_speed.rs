//! COR against impact speed for the current ball (Fig. 4): flat while the ball does not
//! flatten, falling after. A dotted rule marks where flattening starts (linear law).

use super::axis::AxisSpec;
use super::plot::{Corner, Mark, Plot, Rule, Series};
use super::{initial, legend};
use crate::analysis::sweep::VelocityPoint;
use crate::model::contact::ContactLaw;
use crate::tui::app::App;
use crate::tui::theme::Theme;
use ratatui::style::Style;

fn curve(points: &[VelocityPoint]) -> Vec<(f64, f64)> {
    points.iter().map(|p| (p.v0, p.cor)).collect()
}

pub fn plot(app: &App) -> Plot {
    let theme = Theme::new(app.color());
    let s = app.setting();
    let mut series = Vec::new();
    let mut legend_lines = Vec::new();
    let mut marks = Vec::new();
    let mut rules = Vec::new();
    // while a sweep is out, the axis already spans it
    let mut v_hi = app
        .speed_requests()
        .iter()
        .map(|r| r.v_max)
        .fold(s.params.v0, f64::max);
    let ghost = app.ghost().and_then(|g| g.speed.as_ref());
    if let Some(c) = ghost {
        v_hi = v_hi.max(c.request.v_max);
        series.push(Series::ghost(curve(&c.points)));
    }
    if let Some(c) = app.speed_curve() {
        v_hi = v_hi.max(c.request.v_max);
        series.push(Series::live(curve(&c.points), theme.current()));
        legend_lines.push(legend(
            "━",
            Style::default().fg(theme.current()),
            format!("e(v0), {} law", s.law),
        ));
        if let Some(v) = c.request.v_flat.filter(|_| s.law == ContactLaw::Linear) {
            let color = theme.axis().fg.unwrap_or_default();
            rules.push(Rule {
                at: v,
                vertical: true,
                color,
                label: Some("flattens".into()),
            });
        }
    }
    if let Some(r) = app.run() {
        marks.push(Mark {
            x: s.params.v0,
            y: r.cor,
            text: "◆".into(),
            style: theme.warning(),
        });
        legend_lines.push(legend("◆", theme.warning(), "this run"));
    }
    let preset = app.preset();
    if let Some(e) = preset.measured.cor {
        let text = initial(&preset.name);
        marks.push(Mark {
            x: preset.measured.v0,
            y: e,
            text: text.clone(),
            style: theme.measured(),
        });
        legend_lines.push(legend("", theme.measured(), format!("{text} measured")));
    }
    if ghost.is_some() {
        legend_lines.push(legend("━", theme.ghost(), "pinned"));
    }
    let updating = if app.speed_requests().is_empty() {
        ""
    } else {
        " · updating…"
    };
    Plot {
        title: format!("COR e vs impact speed v0 [m/s] · {}{updating}", preset.name),
        short_title: format!("e vs v0 · {}{updating}", preset.name),
        x: AxisSpec::Linear { lo: 0.0, hi: v_hi },
        y: AxisSpec::Linear { lo: 0.0, hi: 1.0 },
        series,
        rules,
        marks,
        legend: legend_lines,
        legend_at: Corner::BottomLeft,
        theme,
    }
}
