//! The readout's short forms: lines beside a chart at 80 × 24 (`narrow`) and the four lines
//! below the charts on narrow terminals (`compact`).

use super::{Readout, Row, results};
use crate::tui::format::{percent_diff, value};
use crate::tui::param::Param;
use crate::tui::widgets::pins;
use ratatui::text::{Line, Span};

impl Readout<'_> {
    /// λ, ζ and v0, each styled as selected or not, the selected one marked ▶ as in the tall
    /// panel (without colour the style alone showed none: issue 51 item 6).
    fn knobs(&self) -> [Span<'static>; 3] {
        let p = |param: Param, text: String| {
            let mark = if self.selected == param { "▶" } else { "" };
            Span::styled(format!("{mark}{text}"), self.param_style(param))
        };
        [
            p(Param::Lambda, format!("λ {}", self.knob(Param::Lambda))),
            p(Param::Zeta, format!("ζ {}", self.knob(Param::Zeta))),
            p(Param::V0, format!("v0 {} m/s", self.knob(Param::V0))),
        ]
    }

    /// "K_p … N/m  K_r … N/m": the setting's two stiffnesses, in the readout's format.
    fn stiffnesses(&self) -> String {
        let p = &self.setting.params;
        format!("K_p {} N/m  K_r {} N/m", value(p.k_p), value(p.k_r))
    }

    /// "c … kg/s": the setting's damping, in the readout's format.
    fn damping(&self) -> String {
        format!("c {} kg/s", value(self.setting.params.damping))
    }

    /// Short lines, one or two quantities each, for a pane beside a chart (80×24).
    pub(super) fn narrow(&self, inner_w: usize) -> Vec<Line<'static>> {
        let s = self.setting;
        let [lambda, zeta, v0] = self.knobs();
        let mut lines = vec![
            Line::from(vec![Span::raw(" "), lambda, Span::raw("  "), zeta]),
            Line::from(vec![
                Span::raw(" "),
                v0,
                Span::raw(format!("  {} law", s.law)),
            ]),
            Line::raw(format!(" {}", self.stiffnesses())),
            Line::raw(format!(
                " {}  {}",
                self.damping(),
                if self.coarse { "[coarse]" } else { "[fine]" }
            )),
        ];
        // the calibration warning before the results: below them the pane's height cuts it at
        // 80 × 24 (tests/tui/tui_calibration.rs)
        lines.extend(self.calibration_line(inner_w));
        lines.extend(self.surface_line(inner_w));
        let rows = results(self.preset, self.run, s);
        if rows.len() < 5 {
            lines.push(Line::styled(" no result", self.theme.error()));
            return lines;
        }
        for (row, unit) in rows[..3].iter().zip(["", " N", " ms"]) {
            lines.push(Line::raw(format!(" {}{unit}", compact_row(row))));
        }
        // the pins' Δe before the indentations, which the pane's height may cut
        // (tests/tui/tui_pins.rs: `pins_at_80x24_show_their_delta_e`)
        lines.extend(pins::compact(self.pins, &self.now()));
        lines.push(Line::raw(format!(
            " {} mm  {} mm",
            compact_row(&rows[3]),
            compact_row(&rows[4])
        )));
        lines.extend(self.validity_line());
        lines
    }

    /// The validity warning as a line (it wraps), if the run leaves the model.
    pub(super) fn validity_line(&self) -> Option<Line<'static>> {
        let w = self.validity.as_ref()?;
        Some(Line::styled(format!(" {w}"), self.theme.warning()))
    }

    /// The calibration warning on one line of `width` columns, cut at a word with "…" (the
    /// message line gives it whole), if v0 lies outside the ball's record.
    fn calibration_line(&self, width: usize) -> Option<Line<'static>> {
        let w = self.calibration.as_ref()?;
        crate::tui::widgets::warning::warning_lines(w, width, 1, &self.theme).pop()
    }

    /// The surface's warning (its rigidity assumed) on one line of `width` columns, cut at a
    /// word with "…" (the message line gives it whole when the surface is picked).
    fn surface_line(&self, width: usize) -> Option<Line<'static>> {
        let w = self.surface_warnings.first()?;
        crate::tui::widgets::warning::warning_lines(w, width, 1, &self.theme).pop()
    }

    /// Four lines for narrow terminals.
    pub(super) fn compact(&self, inner_w: usize) -> Vec<Line<'static>> {
        let s = self.setting;
        let [lambda, zeta, v0] = self.knobs();
        let mut lines = vec![
            Line::from(vec![
                Span::raw(" "),
                lambda,
                Span::raw("  "),
                zeta,
                Span::raw("  "),
                v0,
                Span::raw(format!("  {}", s.law)),
            ]),
            Line::raw(format!(" {}  {}", self.stiffnesses(), self.damping())),
        ];
        let rows = results(self.preset, self.run, self.setting);
        let fmt = compact_row;
        if rows.len() == 5 {
            lines.push(Line::raw(format!(
                " {}  {} N",
                fmt(&rows[0]),
                fmt(&rows[1])
            )));
            lines.push(Line::raw(format!(
                " {} ms  {} mm  {} mm",
                fmt(&rows[2]),
                fmt(&rows[3]),
                fmt(&rows[4])
            )));
        } else {
            lines.push(Line::styled(" no result", self.theme.error()));
        }
        lines.extend(self.validity_line());
        lines.extend(self.calibration_line(inner_w));
        lines.extend(self.surface_line(inner_w));
        lines.extend(pins::compact(self.pins, &self.now()));
        lines
    }
}

/// "e 0.7506 (0.7500, +0.1%)": a result with its measured value and the difference, if any.
fn compact_row(row: &Row) -> String {
    let name = row.name.split(' ').next().unwrap_or("");
    match row.measured {
        Some(m) => format!(
            "{name} {} ({}, {})",
            row.model,
            value(m),
            percent_diff(row.model_value, m)
        ),
        None => format!("{name} {}", row.model),
    }
}
