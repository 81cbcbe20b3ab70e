//! The fit pane under the charts (`f`): "fitting…" while the fit worker runs, then each
//! fitted parameter with its standard error and 95 % interval, the residual RMS, and whether
//! `F` applies it — or that it is stale, the ball having changed since `f`.

use crate::analysis::fit::Estimate;
use crate::text::sig;
use crate::tui::theme::Theme;
use crate::tui::views::fit::state::{FitOutcome, FitPane, FitStatus, Standing};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// The pane's view: the fit and how it stands to the ball on screen.
#[derive(Debug, Clone, Copy)]
pub struct FitView<'a> {
    pub pane: &'a FitPane,
    pub standing: Standing,
    pub theme: Theme,
}

impl FitView<'_> {
    /// Rows the pane wants, borders included.
    pub fn height(&self) -> u16 {
        let rows = match &self.pane.status {
            FitStatus::Done(Ok(o)) => {
                o.fitted.len() + usize::from(o.time_offset.is_some()) + o.warnings.len().min(1) + 2
            }
            _ => 2,
        };
        rows as u16 + 2
    }
}

impl Widget for &FitView<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let t = self.theme;
        let stale = self.standing == Standing::Stale;
        // the stale mark takes the legend's place: a narrow pane keeps it whole
        let legend = if stale {
            ""
        } else {
            "· value ± std error [95 % interval] "
        };
        let mut title = vec![Span::styled(
            format!(" fit to {} {legend}", self.pane.label),
            t.title(),
        )];
        let lines = match &self.pane.status {
            FitStatus::Running => vec![
                Line::raw(format!(
                    " fitting {}…{} (the keys keep working)",
                    free_names(self.pane),
                    progress(self.pane.progress)
                )),
                Line::styled(" f fits again · O puts the data away", t.dim()),
            ],
            FitStatus::Done(Err(e)) => vec![
                Line::styled(format!(" failed: {e}"), t.error()),
                Line::styled(" f fits again · O puts the data away", t.dim()),
            ],
            FitStatus::Done(Ok(o)) => outcome(o, self.standing, &t),
        };
        if stale {
            title.push(Span::styled(
                " stale: the ball changed since f ",
                t.warning(),
            ));
        }
        Clear.render(area, buf);
        Paragraph::new(lines)
            .block(Block::bordered().title(Line::from(title)))
            .render(area, buf);
    }
}

/// ` 1234 model runs, 3.2 s`: the work budget's progress, as `bouncelab fit` shows it on a
/// terminal (src/cli/budget.rs); nothing before the worker's first word.
fn progress(p: Option<crate::tui::views::fit::state::FitProgress>) -> String {
    p.map_or(String::new(), |p| {
        format!(" {} model runs, {:.1} s", p.runs, p.seconds)
    })
}

fn free_names(p: &FitPane) -> String {
    p.free
        .iter()
        .map(|f| f.name())
        .collect::<Vec<_>>()
        .join(", ")
}

/// "k_r = 1.234e5 ± 2.10e3 N/m  [1.19e5, 1.27e5]": value ± standard error, 95 % interval
/// (the title says so); an interval without finite ends is "not pinned by the data", as
/// `bouncelab fit` says.
fn estimate(e: &Estimate) -> Line<'static> {
    let interval = if e.ci95.iter().all(|v| v.is_finite()) {
        format!("[{}, {}]", sig(e.ci95[0], 3), sig(e.ci95[1], 3))
    } else {
        "not pinned by the data".into()
    };
    Line::raw(format!(
        " {:<4}= {} ± {} {}  {interval}",
        e.name,
        sig(e.value, 4),
        sig(e.std_error, 3),
        e.unit,
    ))
}

fn outcome(o: &FitOutcome, standing: Standing, t: &Theme) -> Vec<Line<'static>> {
    let mut lines: Vec<Line> = o.fitted.iter().map(estimate).collect();
    if let Some(e) = &o.time_offset {
        lines.push(estimate(&Estimate {
            name: "t0",
            ..e.clone()
        }));
    }
    let mut rms = format!(
        " residual RMS {} {} · {} points",
        sig(o.rms_residual, 3),
        o.rms_unit,
        o.points
    );
    if !o.converged {
        rms.push_str(" · not converged");
    }
    if !o.not_pinned.is_empty() {
        rms.push_str(&format!(" · {} not pinned", o.not_pinned.join(", ")));
    }
    lines.push(Line::raw(rms));
    if let Some(w) = o.warnings.first() {
        lines.push(Line::styled(format!(" {w}"), t.warning()));
    }
    let (keys, style) = match standing {
        Standing::Ready if !o.identified => {
            (" no answer: F twice applies it · f fits again", t.warning())
        }
        Standing::Ready => (" F applies it (u undoes) · f fits again", t.info()),
        Standing::Applied => (" applied: u undoes · f fits again", t.info()),
        Standing::Stale => (" stale: F refuses it · f fits the ball now", t.warning()),
    };
    lines.push(Line::styled(keys, style));
    lines
}
