//! Force–displacement (Figs. 6, 8): F (N) against the ball's displacement α (mm) — the
//! loading/unloading loop, whose area is the energy lost — and against the contact indentation
//! z (mm), which ends at the permanent indentation z_f once the ball flattens (z_m > z_p).

use super::axis::AxisSpec;
use super::legend;
use super::plot::{Corner, Mark, Plot, Rule, Series};
use crate::solver::ImpactResponse;
use crate::text::sig_trim;
use crate::tui::app::App;
use crate::tui::theme::Theme;
use ratatui::style::Style;

fn against(r: &ImpactResponse, x: &[f64]) -> Vec<(f64, f64)> {
    x.iter()
        .zip(&r.history.force)
        .map(|(x, f)| (x * 1e3, *f))
        .collect()
}

fn max(v: &[f64]) -> f64 {
    v.iter()
        .copied()
        .filter(|x| x.is_finite())
        .fold(0.0, f64::max)
}

pub fn plot(app: &App) -> Plot {
    let theme = Theme::new(app.color());
    let ghost = app.ghost().and_then(|g| g.run.as_ref());
    let (mut x_hi, mut f_hi) = (0.0f64, 0.0f64);
    for r in ghost.into_iter().chain(app.run()) {
        x_hi = x_hi
            .max(max(&r.history.displacement) * 1e3)
            .max(max(&r.history.indentation) * 1e3);
        f_hi = f_hi.max(r.max_force);
    }
    let mut series = Vec::new();
    let mut legend_lines = Vec::new();
    let mut marks = Vec::new();
    let mut rules = Vec::new();
    if let Some(g) = ghost {
        series.push(Series::ghost(against(g, &g.history.displacement)));
    }
    if let Some(r) = app.run() {
        series.push(Series::live(
            against(r, &r.history.indentation),
            theme.secondary(),
        ));
        series.push(Series::live(
            against(r, &r.history.displacement),
            theme.current(),
        ));
        legend_lines.push(legend("━", Style::default().fg(theme.current()), "ball α"));
        legend_lines.push(legend(
            "━",
            Style::default().fg(theme.secondary()),
            "contact z",
        ));
        let z_p = app.setting().params.z_p;
        if z_p.is_finite() && z_p * 1e3 <= x_hi * 1.05 {
            let label = Some("z_p".to_string());
            rules.push(Rule {
                at: z_p * 1e3,
                vertical: true,
                color: theme.axis().fg.unwrap_or_default(),
                label,
            });
        }
        if r.permanent_indentation > 0.0 {
            marks.push(Mark {
                x: r.permanent_indentation * 1e3,
                y: 0.0,
                text: format!("▲z_f {} mm", sig_trim(r.permanent_indentation * 1e3, 3)),
                style: theme.warning(),
            });
        }
    }
    if ghost.is_some() {
        legend_lines.push(legend("━", theme.ghost(), "pinned α"));
    }
    Plot {
        title: "Force–displacement · F [N] vs α, z [mm]".into(),
        short_title: "F–α,z · N, mm".into(),
        x: AxisSpec::Linear { lo: 0.0, hi: x_hi },
        y: AxisSpec::Linear { lo: 0.0, hi: f_hi },
        series,
        rules,
        marks,
        legend: legend_lines,
        legend_at: Corner::TopLeft,
        theme,
    }
}
