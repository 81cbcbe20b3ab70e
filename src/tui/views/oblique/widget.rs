//! The oblique view's panel (`i`): on the charts page F_n and F_t, v_c and ω against time and
//! the paths; on the map page the (angle, μ) map; on both a readout of θ, ω, μ (the selected
//! one marked) and the outgoing motion, and the ITF court pace for the tennis ball. Reads the
//! view's state only.

use crate::api::CourtPace;
use crate::figure::Figure;
use crate::oblique::ObliqueResponse;
use crate::tui::format::{stepped, value};
use crate::tui::theme::Theme;
use crate::tui::views::oblique::charts;
use crate::tui::views::oblique::map_widget::MapRaster;
use crate::tui::views::oblique::param::ObliqueParam;
use crate::tui::views::oblique::state::{ObliqueView, Page};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// Width of the readout column.
const READOUT_WIDTH: u16 = 36;
/// Narrowest chart column with three charts in its bottom row (v_c, ω and the paths).
const NARROW: u16 = 60;

/// The oblique view in its area (between the header and the message line).
#[derive(Debug, Clone, Copy)]
pub struct ObliquePanel<'a> {
    pub view: &'a ObliqueView,
    /// The ball's name, for the readout's title.
    pub ball: &'a str,
    /// The incoming speed (m/s), the explorer's v0.
    pub v0: f64,
    /// K_t (N/m) and κ the impact runs on (the view's, or the ball's where it sets none).
    pub tangential: [f64; 2],
    /// The surface the ball bounces on: its name (the steel plate's when none was picked)
    /// and K_s, c_s, M, c_t (issue 53 item 6; `App::oblique_surface_line`), and whether it is
    /// the default plate, said last so that a short readout loses it first (60×20).
    pub surface: (&'a str, bool),
    /// The library's "outside calibration: …" warning when the impact's normal speed lies
    /// outside the ball's record (`App::calibration`, issue 52 item 2).
    pub calibration: Option<&'a str>,
    /// The library's warnings of the surface (its rigidity assumed): the impact's, as
    /// `bouncelab oblique` prints them, and the court rating's, as `bouncelab court` does
    /// (`App::oblique_surface_warnings`): each cut to the rows left, under the calibration
    /// warning and under the court pace.
    pub surface_warnings: &'a [Vec<String>; 2],
    /// The time charts as drawn (`charts::time_figures` with their normalize, zoom and
    /// crosshair: src/tui/app/charts.rs), once the impact is computed.
    pub time: Option<&'a [Figure; 3]>,
    pub theme: Theme,
}

impl Widget for ObliquePanel<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let w = READOUT_WIDTH.min(area.width / 2);
        let [main, side] =
            Layout::horizontal([Constraint::Fill(1), Constraint::Length(w)]).areas(area);
        match self.view.page {
            Page::Charts => self.render_charts(main, side, buf),
            Page::Map => {
                MapRaster {
                    view: self.view,
                    theme: self.theme,
                }
                .render(main, buf);
                self.render_readout(side, buf);
            }
        }
    }
}

impl ObliquePanel<'_> {
    /// The forces above v_c and ω; the paths above the readout beside them (on a short
    /// screen the paths go in the bottom row, beside v_c and ω).
    fn render_charts(self, main: Rect, side: Rect, buf: &mut Buffer) {
        let theme = self.theme;
        let Some((r, [forces, slip_fig, spin_fig])) = self.view.response().zip(self.time) else {
            self.render_readout(main.union(side), buf);
            return;
        };
        let [top, bottom] = Layout::vertical([Constraint::Fill(1); 2]).areas(main);
        charts::render_time(forces, theme, top, buf);
        let tall = side.height >= 30;
        if tall {
            let [paths, readout] =
                Layout::vertical([Constraint::Length(side.height / 3), Constraint::Fill(1)])
                    .areas(side);
            charts::render_paths(r, theme, paths, buf);
            self.render_readout(readout, buf);
            let [slip, spin] = Layout::horizontal([Constraint::Fill(1); 2]).areas(bottom);
            charts::render_time(slip_fig, theme, slip, buf);
            charts::render_time(spin_fig, theme, spin, buf);
        } else if main.width >= NARROW {
            self.render_readout(side, buf);
            let [slip, spin, paths] = Layout::horizontal([Constraint::Fill(1); 3]).areas(bottom);
            charts::render_time(slip_fig, theme, slip, buf);
            charts::render_time(spin_fig, theme, spin, buf);
            charts::render_paths(r, theme, paths, buf);
        } else {
            // two charts a row at most: the paths give way (the readout has both angles)
            self.render_readout(side, buf);
            let [slip, spin] = Layout::horizontal([Constraint::Fill(1); 2]).areas(bottom);
            charts::render_time(slip_fig, theme, slip, buf);
            charts::render_time(spin_fig, theme, spin, buf);
        }
    }

    fn render_readout(self, area: Rect, buf: &mut Buffer) {
        let theme = self.theme;
        let mut lines = vec![Line::styled(
            format!("{} · oblique", self.ball),
            theme.title(),
        )];
        lines.extend(self.parameter_lines());
        let (surface, default) = self.surface;
        let surface = Line::styled(surface.to_string(), theme.dim());
        if !default {
            lines.push(surface.clone());
        }
        match &self.view.impact {
            Some(Ok(r)) => lines.extend(result_lines(r, theme)),
            Some(Err(e)) => lines.push(Line::styled(e.clone(), theme.error())),
            None => {}
        }
        let mut pace = Vec::new();
        match &self.view.pace {
            Some(Ok(p)) => pace.extend(pace_lines(p, self.view.values.friction, theme)),
            Some(Err(e)) => pace.push(Line::styled(format!("ITF pace: {e}"), theme.error())),
            None => {}
        }
        let inner = Block::bordered().inner(area);
        let last = usize::from(default);
        let room = usize::from(inner.height).saturating_sub(lines.len() + pace.len() + last);
        let [answer, court] = self.surface_warnings;
        // the rows left shared among the warnings, one each at least, the first ones taking
        // what does not divide: the calibration's, the impact's surface's, the rating's
        let texts: Vec<&str> = (self.calibration.into_iter())
            .chain(answer.iter().chain(court).map(String::as_str))
            .collect();
        let mut warned = texts.iter().enumerate().map(|(i, w)| {
            let rows = room / texts.len() + usize::from(i < room % texts.len());
            let theme = &self.theme;
            crate::tui::widgets::warning::warning_lines(
                w,
                usize::from(inner.width),
                rows.max(1),
                theme,
            )
        });
        let before = usize::from(self.calibration.is_some()) + answer.len();
        lines.extend(warned.by_ref().take(before).flatten());
        lines.extend(pace);
        lines.extend(warned.flatten());
        if default {
            lines.push(surface);
        }
        Paragraph::new(lines)
            .wrap(Wrap { trim: true })
            .block(Block::bordered())
            .render(area, buf);
    }

    /// θ, ω and μ a line each, K_t and κ on one (the ball's Mindlin K_t and preset κ until
    /// set in the view), the selected one marked ▶, and the speed — in the explorer's one
    /// number format, with the digits a step needs (docs/explorer.md, "Numbers").
    fn parameter_lines(self) -> Vec<Line<'static>> {
        let v = self.view;
        let style = |p: ObliqueParam| {
            if p == v.selected {
                self.theme.selected()
            } else {
                ratatui::style::Style::default()
            }
        };
        let span = |p: ObliqueParam, x: f64| {
            let mark = if p == v.selected { "▶" } else { " " };
            let x = stepped(x, p.fine_step(x));
            Span::styled(format!("{mark}{} {x}{}", p.symbol(), p.unit()), style(p))
        };
        let [k_t, kappa] = self.tangential;
        vec![
            Line::from(span(ObliqueParam::Angle, v.values.angle)),
            Line::from(span(ObliqueParam::Spin, v.values.spin)),
            Line::from(span(ObliqueParam::Friction, v.values.friction)),
            Line::from(vec![
                span(ObliqueParam::TangentialStiffness, k_t),
                Span::raw(" "),
                span(ObliqueParam::InertiaFactor, kappa),
            ]),
            Line::raw(format!(" v0 {} m/s", value(self.v0))),
        ]
    }
}

/// The outgoing motion and the contact's figures.
fn result_lines(r: &ObliqueResponse, theme: Theme) -> Vec<Line<'static>> {
    let ex = r.cor_tangential.map_or("— (rolls in)".into(), value);
    let grip = if r.slid_throughout {
        "slid throughout".to_string()
    } else {
        format!("gripped {} ms", value(r.grip_time * 1e3))
    };
    vec![
        Line::from(vec![
            Span::styled(" out", theme.dim()),
            Span::raw(format!(
                " {} m/s at {}°",
                value(r.v_out),
                value(r.angle_out_deg)
            )),
        ]),
        Line::raw(format!(" spin  {} rad/s", value(r.spin_out))),
        Line::raw(format!(" e_y {}  e_x {ex}", value(r.cor_normal))),
        Line::raw(format!(" μ_app {}", value(r.apparent_friction))),
        Line::raw(format!(" contact {} ms", value(r.contact_time * 1e3))),
        Line::raw(format!(" {grip}")),
    ]
}

/// The ITF court pace at μ: its rating and category.
fn pace_lines(p: &CourtPace, mu: f64, theme: Theme) -> Vec<Line<'static>> {
    vec![
        Line::styled(
            format!(
                "ITF court pace at μ {}",
                stepped(mu, ObliqueParam::Friction.fine_step(mu))
            ),
            theme.dim(),
        ),
        Line::from(vec![
            Span::raw(format!(" CPR {} · ", value(p.cpr))),
            Span::styled(format!("{} {}", p.category, p.category_name), theme.title()),
        ]),
        // what it is computed from, e on the court included (CPR = 100(1 − μ_app) +
        // 150(0.81 − e); issue 53): a name and its number never parted by the wrap
        Line::raw(format!(
            " e\u{a0}{}  μ_app\u{a0}{}",
            value(p.cor_normal),
            value(p.apparent_friction)
        )),
    ]
}
