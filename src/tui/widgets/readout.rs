//! The readout: the live parameters (λ, ζ, v0, law, K_p, K_r, c) and the results (e, F_m, t_f,
//! z_m, z_f) next to the preset's measured values and the difference. A tall panel beside the
//! charts, or four compact lines below them on narrow terminals. Pinned runs add the pin table
//! (`pins`).

use crate::preset::Preset;
use crate::solver::ImpactResponse;
use crate::tui::format::{percent_diff, stepped, value};
use crate::tui::param::{Dir, Param};
use crate::tui::setting::Setting;
use crate::tui::theme::Theme;
use crate::tui::widgets::pins::{self, Now, PinView};
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

#[path = "readout_notes.rs"]
mod notes;
#[path = "readout_short.rs"]
mod short;

/// Rows the tall panel needs, border included.
pub const PANEL_HEIGHT: u16 = 22;
/// Rows the compact form needs, border included.
pub const COMPACT_HEIGHT: u16 = 6;
/// Most rows of the calibration warning in the tall panel (tests/tui/tui_calibration.rs).
const CALIBRATION_ROWS: usize = 4;
/// Most rows of the line of the measured values where the library says why they are not
/// compared (tests/tui/tui_surface_said.rs).
const MEASURED_ROWS: usize = 3;
/// Most rows of the surface's warnings in the tall panel (tests/tui/tui_surface_said.rs).
const SURFACE_ROWS: usize = 3;
/// Rows of the energy budget in the tall panel, shown only when they fit.
const ENERGY_ROWS: usize = 3;

/// Rows the compact form needs with `pins` pinned runs: one more line for their COR.
pub fn compact_height(pins: usize) -> u16 {
    COMPACT_HEIGHT + u16::from(pins > 0)
}

/// What the readout shows.
#[derive(Debug, Clone)]
pub struct Readout<'a> {
    pub preset: &'a Preset,
    pub setting: &'a Setting,
    pub selected: Param,
    pub coarse: bool,
    pub run: Option<&'a ImpactResponse>,
    /// Why the run is outside the model's validity (z_m or α_max beyond R), if it is.
    pub validity: Option<String>,
    /// The library's "outside calibration: …" warning when v0 lies outside the ball's record
    /// (`App::calibration`): whole in the tall panel, one line cut at a word in the short
    /// forms, whose full text the message line gives (issue 52 item 2).
    pub calibration: Option<String>,
    /// The library's warnings of the surface the ball meets (`App::surface_warnings`: its
    /// rigidity assumed), as `bouncelab run --surface NAME` prints them: at most
    /// `SURFACE_ROWS` rows under the surface's line in the tall panel, a line cut at a word
    /// in the short forms; the message line says them whole when the surface is picked.
    pub surface_warnings: Vec<String>,
    /// The pinned runs, oldest first: the pin table compares them with this run.
    pub pins: &'a [PinView<'a>],
    /// The tall panel beside the charts, or four compact lines below them.
    pub tall: bool,
    pub theme: Theme,
}

/// The narrowest pane (inner columns) that takes the four compact lines, whose results line
/// holds e and F_m with their measured values (about 52 columns): the full-width pane at
/// 60 × 20 shows the results (tests/tui/tui_render.rs: `the_sweeps_readout_keeps_its_results_at_60x20`).
const COMPACT_FROM: usize = 52;

impl Widget for &Readout<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let inner_w = usize::from(area.width.saturating_sub(2));
        let lines = if self.tall {
            let inner = Block::bordered().inner(area);
            self.panel(usize::from(inner.width), usize::from(inner.height))
        } else if inner_w < COMPACT_FROM {
            self.narrow(inner_w)
        } else {
            self.compact(inner_w)
        };
        // a long line breaks between its fields, never inside a value (tests/tui/tui_render.rs:
        // `readout_values_never_wrap`); a last row cut short ends in "…"
        let rows = usize::from(area.height.saturating_sub(2));
        let lines = crate::tui::widgets::cut::kept(lines, inner_w, rows);
        Paragraph::new(lines)
            .block(self.block())
            .wrap(Wrap { trim: false })
            .render(area, buf);
    }
}

/// One result row: name with unit, model value, measured value (same unit).
struct Row {
    name: &'static str,
    model: String,
    measured: Option<f64>,
    model_value: f64,
}

/// Whether the preset's measured values were taken at `v0`, against the wall and at the
/// record's conditions (none typed in the form; `run` withholds them at others): only then
/// are they compared.
fn measured_here(preset: &Preset, setting: &Setting) -> bool {
    crate::figure::explorer::same_speed(preset.measured.v0, setting.params.v0)
        && setting.target == crate::target::Target::wall()
        && setting.conditions.is_empty()
}

/// The results against the preset's measured values; no measured values away from the speed
/// they were taken at (a peak force at 3.12 m/s says nothing of one at 12 m/s), nor on a
/// target other than the wall they were measured on.
fn results(preset: &Preset, r: Option<&ImpactResponse>, setting: &Setting) -> Vec<Row> {
    let Some(r) = r else {
        return Vec::new();
    };
    let none = crate::preset::Measured {
        cor: None,
        max_force: None,
        contact_time: None,
        ..preset.measured.clone()
    };
    let m = if measured_here(preset, setting) {
        &preset.measured
    } else {
        &none
    };
    let t_f = r.contact_time.map(|t| t * 1e3);
    vec![
        Row {
            name: "e",
            model: value(r.cor),
            measured: m.cor,
            model_value: r.cor,
        },
        Row {
            name: "F_m N",
            model: value(r.max_force),
            measured: m.max_force,
            model_value: r.max_force,
        },
        Row {
            name: "t_f ms",
            model: t_f.map_or("none".into(), value),
            measured: m.contact_time.map(|t| t * 1e3),
            model_value: t_f.unwrap_or(f64::NAN),
        },
        Row {
            name: "z_m mm",
            model: value(r.max_indentation * 1e3),
            measured: None,
            model_value: f64::NAN,
        },
        Row {
            name: "z_f mm",
            model: value(r.permanent_indentation * 1e3),
            measured: None,
            model_value: f64::NAN,
        },
    ]
}

impl Readout<'_> {
    /// λ, ζ or v0 as the readouts show it: with the digits its step needs when it is
    /// stepped by a fixed amount (λ, v0), else [`value`]'s.
    pub(super) fn knob(&self, p: Param) -> String {
        let x = self.setting.get(p);
        match p {
            Param::Lambda | Param::V0 => {
                let step = (p.step(x, Dir::Up, self.coarse) - x).abs();
                stepped(x, step)
            }
            _ => value(x),
        }
    }

    fn param_line(&self, p: Param, text: String) -> Line<'static> {
        let marker = if self.selected == p { "▶" } else { " " };
        Line::from(vec![
            Span::raw(marker),
            Span::styled(text, self.param_style(p)),
        ])
    }

    fn param_style(&self, p: Param) -> Style {
        if self.selected == p {
            self.theme.selected()
        } else {
            Style::default()
        }
    }

    fn block(&self) -> Block<'static> {
        let p = self.preset;
        let mut title = vec![Span::styled(
            format!(" {} · {} ", p.name, p.parameters.name()),
            self.theme.title(),
        )];
        // the short readouts may have no row left for the warning: the title says it
        if !self.tall && self.validity.is_some() {
            title.push(Span::styled("beyond R ", self.theme.warning()));
        }
        Block::bordered()
            .border_style(self.theme.dim())
            .title(Line::from(title))
    }

    /// The tall panel: parameters, results against the measured values, notes.
    fn panel(&self, inner_w: usize, inner_h: usize) -> Vec<Line<'static>> {
        let mut lines = self.parameter_lines();
        lines.push(Line::raw(""));
        lines.extend(self.result_lines(inner_w));
        lines.extend(self.notes(inner_w));
        let energy = self.energy_lines();
        if inner_h >= lines.len() + energy.len().max(ENERGY_ROWS) {
            lines.extend(energy);
        }
        let left = inner_h.saturating_sub(lines.len());
        lines.extend(pins::table(
            self.pins,
            &self.now(),
            (inner_w, left),
            &self.theme,
        ));
        lines
    }

    pub(super) fn now(&self) -> Now<'_> {
        Now {
            setting: self.setting,
            run: self.run,
        }
    }

    fn parameter_lines(&self) -> Vec<Line<'static>> {
        let (theme, s) = (&self.theme, self.setting);
        let params = &s.params;
        let step = if self.coarse {
            "  [coarse]"
        } else {
            "  [fine]"
        };
        vec![
            Line::from(vec![
                Span::styled(" parameters", theme.title()),
                Span::styled(step, theme.dim()),
            ]),
            self.param_line(
                Param::Lambda,
                format!("λ   {:<9}", self.knob(Param::Lambda)),
            ),
            self.param_line(Param::Zeta, format!("ζ   {:<9}", self.knob(Param::Zeta))),
            self.param_line(Param::V0, format!("v0  {} m/s", self.knob(Param::V0))),
            Line::raw(format!(" law {}", s.law)),
            Line::raw(format!(" K_p {} N/m", value(params.k_p))),
            Line::raw(format!(" K_r {} N/m", value(params.k_r))),
            Line::raw(format!(" c   {} kg/s", value(params.damping))),
            Line::raw(format!(
                " z_p {} mm   m {} g",
                value(params.z_p * 1e3),
                value(params.mass * 1e3)
            )),
        ]
    }

    /// The results table: model, measured, difference.
    fn result_lines(&self, inner_w: usize) -> Vec<Line<'static>> {
        let theme = &self.theme;
        let col = inner_w.saturating_sub(8) / 3;
        let cell = |s: &str| format!("{s:>w$} ", w = col.saturating_sub(1));
        let mut lines = vec![Line::styled(
            format!(
                " {:<7}{}{}{}",
                "result",
                cell("model"),
                cell("meas."),
                cell("diff")
            ),
            theme.title(),
        )];
        let rows = results(self.preset, self.run, self.setting);
        if rows.is_empty() {
            lines.push(Line::styled(" no result", theme.error()));
        }
        for row in rows {
            let (measured, diff) = match row.measured {
                Some(m) => (value(m), percent_diff(row.model_value, m)),
                None => (String::new(), String::new()),
            };
            lines.push(Line::from(vec![
                Span::raw(format!(" {:<7}", row.name)),
                Span::styled(cell(&row.model), Style::default().fg(theme.current())),
                Span::styled(cell(&measured), theme.measured()),
                Span::raw(cell(&diff)),
            ]));
        }
        lines
    }
}
