//! Force–time (Figs. 5, 7): F (N) against t (ms), with the measured peak force and contact
//! time as dotted rules.

use super::axis::AxisSpec;
use super::legend;
use super::plot::{Corner, Plot, Rule, Series};
use crate::solver::ImpactResponse;
use crate::tui::app::App;
use crate::tui::theme::Theme;
use ratatui::style::Style;

fn curve(r: &ImpactResponse) -> Vec<(f64, f64)> {
    r.history
        .t
        .iter()
        .zip(&r.history.force)
        .map(|(t, f)| (t * 1e3, *f))
        .collect()
}

pub fn plot(app: &App) -> Plot {
    let theme = Theme::new(app.color());
    let measured = &app.preset().measured;
    let mut series = Vec::new();
    let mut legend_lines = Vec::new();
    let runs = app
        .ghost()
        .and_then(|g| g.run.as_ref())
        .into_iter()
        .chain(app.run());
    let (mut t_hi, mut f_hi) = (0.0f64, 0.0f64);
    for r in runs {
        t_hi = t_hi.max(r.duration * 1e3);
        f_hi = f_hi.max(r.max_force);
    }
    if let Some(r) = app.ghost().and_then(|g| g.run.as_ref()) {
        series.push(Series::ghost(curve(r)));
    }
    if let Some(r) = app.run() {
        series.push(Series::live(curve(r), theme.current()));
        legend_lines.push(legend("━", Style::default().fg(theme.current()), "model"));
    }
    let mut rules = Vec::new();
    let meas = theme.measured().fg.unwrap_or_default();
    if let Some(f) = measured.max_force {
        f_hi = f_hi.max(f);
        rules.push(Rule {
            at: f,
            vertical: false,
            color: meas,
            label: None,
        });
    }
    if let Some(t) = measured.contact_time {
        t_hi = t_hi.max(t * 1e3);
        rules.push(Rule {
            at: t * 1e3,
            vertical: true,
            color: meas,
            label: None,
        });
    }
    if !rules.is_empty() {
        legend_lines.push(legend("┄", theme.measured(), "measured"));
    }
    if app.ghost().is_some() {
        legend_lines.push(legend("━", theme.ghost(), "pinned"));
    }
    Plot {
        title: "Force–time · F [N] vs t [ms]".into(),
        short_title: "F–t · N, ms".into(),
        x: AxisSpec::Linear { lo: 0.0, hi: t_hi },
        y: AxisSpec::Linear { lo: 0.0, hi: f_hi },
        series,
        rules,
        marks: Vec::new(),
        legend: legend_lines,
        legend_at: Corner::TopRight,
        theme,
    }
}
