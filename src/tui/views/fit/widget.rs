//! The fit pane under the charts (`f`): "fitting…" while the fit worker runs, then each
//! fitted parameter with its standard error and 95 % interval, the residual RMS, for a drop
//! test that its drops were taken in vacuum, and whether `F` applies it — or that it is
//! stale, the ball having changed since `f`.

use crate::analysis::fit::Estimate;
use crate::tui::format::{self, screen_unit, uncertainty, value};
use crate::tui::theme::Theme;
use crate::tui::views::fit::state::{FitOutcome, FitPane, FitStatus, Standing};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

/// The pane's view: the fit and how it stands to the ball on screen.
#[derive(Debug, Clone, Copy)]
pub struct FitView<'a> {
    pub pane: &'a FitPane,
    pub standing: Standing,
    pub theme: Theme,
}

impl FitView<'_> {
    /// Rows the pane wants, borders included, its lines broken to `width` (the pane's, its
    /// border included) as [`Widget::render`] breaks them.
    pub fn height(&self, width: u16) -> u16 {
        let inner = usize::from(width.saturating_sub(2));
        let lines = crate::tui::format::fit_lines(self.lines(), inner);
        crate::tui::widgets::cut::rows(&lines, inner) as u16 + 2
    }

    /// The pane's lines, before they are fitted to its width.
    fn lines(&self) -> Vec<Line<'static>> {
        let t = self.theme;
        match &self.pane.status {
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
            FitStatus::Done(Ok(o)) => outcome(o, self.pane.drops, self.standing, &t),
        }
    }

    /// The title: what was fitted, then the legend of its numbers or, once the ball has
    /// changed, the stale mark in its place; cut at a word with "…" to `width` (the pane's
    /// top border less its corners).
    fn title(&self, width: usize) -> Line<'static> {
        let t = self.theme;
        let name = format!(" fit to {} ", self.pane.label);
        // each in shorter words where the longer do not fit
        let (forms, style): (&[&str], _) = if self.standing == Standing::Stale {
            (
                &[
                    " stale: the ball changed since f ",
                    " stale: ball changed ",
                    " stale ",
                ],
                t.warning(),
            )
        } else {
            (
                &[
                    "· value ± std error [95 % interval] ",
                    "· value ± std error ",
                ],
                t.title(),
            )
        };
        let name = crate::tui::format::clip(&name, width);
        let room = width.saturating_sub(name.chars().count());
        let tail = match forms.iter().find(|f| f.chars().count() <= room) {
            Some(f) => f.to_string(),
            None => crate::tui::format::clip(forms[0].trim_end(), room.saturating_sub(1)) + " ",
        };
        Line::from(vec![
            Span::styled(name, t.title()),
            Span::styled(tail, style),
        ])
    }
}

impl Widget for &FitView<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let block = Block::bordered().title(self.title(usize::from(area.width.saturating_sub(2))));
        let inner = block.inner(area);
        // broken at words; a pane shorter than its lines ends in "…" (80 × 24:
        // tests/tui/tui_small.rs)
        let lines = crate::tui::widgets::cut::kept(
            self.lines(),
            usize::from(inner.width),
            usize::from(inner.height),
        );
        Clear.render(area, buf);
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(block)
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
/// In the units the readout shows (z_p in mm, m in g, t0 in ms: `format::screen_unit`).
fn estimate(e: &Estimate) -> Line<'static> {
    let (unit, k) = screen_unit(e.unit);
    let interval = if e.ci95.iter().all(|v| v.is_finite()) {
        format::interval(k * e.ci95[0], k * e.ci95[1])
    } else {
        "not pinned by the data".into()
    };
    Line::raw(format!(
        " {:<4}= {} ± {} {unit}  {interval}",
        e.name,
        value(k * e.value),
        uncertainty(k * e.std_error),
    ))
}

/// The drops' assumption, as the command line's report says how it weighed them: no air drag
/// (`state::request` takes `Flight::vacuum()`; the explorer has no drag option).
const DROPS: &str =
    " drops taken in vacuum (no drag correction) · weighed by their rebound readings";

fn outcome(o: &FitOutcome, drops: bool, standing: Standing, t: &Theme) -> Vec<Line<'static>> {
    let mut lines: Vec<Line> = o.fitted.iter().map(estimate).collect();
    if let Some(e) = &o.time_offset {
        lines.push(estimate(&Estimate {
            name: "t0",
            ..e.clone()
        }));
    }
    let (unit, k) = screen_unit(o.rms_unit);
    let mut rms = format!(
        " residual RMS {} {unit} · {} points",
        uncertainty(k * o.rms_residual),
        o.points
    );
    if !o.converged {
        rms.push_str(" · not converged");
    }
    if !o.not_pinned.is_empty() {
        rms.push_str(&format!(" · {} not pinned", o.not_pinned.join(", ")));
    }
    lines.push(Line::raw(rms));
    if drops {
        lines.push(Line::raw(DROPS));
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 29 item 6: the fit pane wrote "z_p = 0.001572 ± 0.000122 m" where the readout
    /// reads mm, and "[78094, 1.17e5]" (two forms in one interval). One format, one unit.
    #[test]
    fn estimates_read_in_the_readouts_units_and_one_form() {
        let line = |name, unit, value, std_error, ci95| {
            let e = Estimate {
                name,
                unit,
                value,
                std_error,
                ci95,
            };
            estimate(&e).to_string()
        };
        assert_eq!(
            line("z_p", "m", 0.001572, 0.000122, [0.00133, 0.00181]),
            " z_p = 1.572 ± 0.122 mm  [1.33, 1.81]"
        );
        assert_eq!(
            line("k_r", "N/m", 96000.0, 9700.0, [78094.0, 1.17e5]),
            " k_r = 96000 ± 9700 N/m  [7.81e4, 1.17e5]"
        );
    }
}
