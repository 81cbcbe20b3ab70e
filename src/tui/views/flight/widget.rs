//! The flight view (`h`, src/tui/views/flight/state.rs): the shot's path — the height of the
//! ball's centre against x, the bounce marked, the surface — in braille by the explorer's
//! one plot widget (so its ticks are the other charts', each label at its value's place:
//! tests/tui/tui_ticks.rs), and a readout with the launch, the landing, the bounce, the end
//! and the shot's warnings.
//! Reads the state only.

use crate::figure::{Look, Marker as Glyph, Role, Tone};
use crate::text::sig;
use crate::tui::layout::charts_and_readout;
use crate::tui::theme::Theme;
use crate::tui::views::flight::export::{net_words, path_figure};
use crate::tui::views::flight::param::FlightParam;
use crate::tui::views::flight::state::FlightView;
use crate::tui::widgets::plot::Plot;
use crate::tui::widgets::warning::warning_lines;
use crate::tui::widgets::{fitted, readout_column, readout_columns};
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Rect};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// Width of the readout on wide screens.
const READOUT_WIDTH: u16 = 40;

/// Rows each of the shot's warnings may take in the wide readout (a calibration warning
/// names its sources in some 250 characters; cut at a word with "…" past them).
const WARNING_ROWS: usize = 4;

/// The flight view in its area (between the header and the status line).
#[derive(Debug, Clone, Copy)]
pub struct FlightPanel<'a> {
    pub view: &'a FlightView,
    /// The ball's name, for the readout's title.
    pub ball: &'a str,
    /// The ball's radius (m): the centre's height at a bounce.
    pub radius: f64,
    pub theme: Theme,
}

impl Widget for FlightPanel<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let wide = area.width >= 100;
        let rows = (area.height * 45 / 100).clamp(7, 11);
        let (chart, readout) = charts_and_readout(area, wide, READOUT_WIDTH, rows);
        self.render_chart(chart, buf);
        if wide {
            let mut lines = self.launch_lines();
            lines.push(Line::raw(""));
            lines.extend(self.shot_lines());
            // the border's two columns off the readout's width
            let width = usize::from(readout.width.saturating_sub(2));
            lines.extend(self.warning_lines(width, WARNING_ROWS));
            lines.push(Line::raw(""));
            lines.push(Line::styled(
                "←→ select · ↑↓ step (Shift coarse) · a/w/k · y line · e export · h back",
                self.theme.key(),
            ));
            readout_column(lines, readout, buf);
        } else {
            self.render_strip(readout, buf);
        }
    }
}

/// The rows `lines` take broken to `width` (as [`fitted`] breaks them).
fn rows_of(lines: Vec<Line<'static>>, width: u16) -> usize {
    let w = usize::from(width);
    crate::tui::widgets::cut::rows(&crate::tui::format::fit_lines(lines, w), w)
}

impl FlightPanel<'_> {
    /// The path (the export's figure, `e`), drawn with the current ball's tones.
    fn render_chart(&self, area: Rect, buf: &mut Buffer) {
        let Some(r) = self.view.report() else {
            let text = match &self.view.shot {
                Some(Err(e)) => Line::styled(e.clone(), self.theme.error()),
                _ => Line::raw("no shot yet"),
            };
            Paragraph::new(text)
                .wrap(Wrap { trim: true })
                .block(Block::bordered())
                .render(area, buf);
            return;
        };
        let mut fig = path_figure(r, self.radius, "");
        for s in &mut fig.series {
            match s.kind {
                Role::Model => {
                    s.look = Look::new(Tone::Current, Some("centre of the ball"), None);
                }
                Role::Measured => {
                    s.kind = Role::ThisRun;
                    s.style = crate::figure::Style::Markers(Glyph::Circle);
                    s.look = Look::new(Tone::Current, Some("bounce"), Some("●"));
                }
                _ if s.id == "net" => s.look = Look::new(Tone::Measured, Some("net"), None),
                _ => s.look = Look::new(Tone::Measured, None, None),
            }
        }
        fig.screen_title = "Flight · height [m] vs x [m]".into();
        (&Plot::new(&fig, self.theme)).render(area, buf);
    }

    /// The readout under the chart (narrow screens): the launch and the net on the left (30
    /// characters and a gap), the shot's numbers on the right. Where the rows are too few
    /// (60 × 20), the ball's name goes on the border and the launch two values a row, so
    /// the net's verdict shows, and the shot's numbers come the bounce's way out first; what
    /// still does not fit is marked "…" (tests/tui/tui_small.rs).
    fn render_strip(&self, area: Rect, buf: &mut Buffer) {
        let rows = usize::from(area.height.saturating_sub(2));
        let mut launch = self.launch_lines();
        let title = (launch.len() > rows).then(|| {
            // set off by a space each side, as every panel's title
            let mut title = launch.remove(0);
            title.spans.insert(0, Span::raw(" "));
            title.spans.push(Span::raw(" "));
            let params = launch.drain(..FlightParam::ALL.len()).collect::<Vec<_>>();
            let paired = params.chunks(2).map(|pair| {
                let mut spans = pair[0].spans.clone();
                if let Some(second) = pair.get(1) {
                    spans.push(Span::raw("  "));
                    spans.extend(second.spans.iter().cloned());
                }
                Line::from(spans)
            });
            launch.splice(0..0, paired);
            title
        });
        let [left, right] = readout_columns(
            area,
            buf,
            title,
            [Constraint::Length(32), Constraint::Fill(1)],
        );
        fitted(launch, left, buf);
        let shot = if rows_of(self.shot_lines(), right.width) <= rows {
            self.shot_lines()
        } else {
            self.shot_lines_short()
        };
        fitted(shot, right, buf);
        self.render_strip_warning(area, buf);
    }

    /// The narrow readout's rows hold the numbers: the shot's first warning goes on its
    /// bottom border, cut at a word ("…"; the wide readout gives each whole in its rows).
    fn render_strip_warning(&self, area: Rect, buf: &mut Buffer) {
        let Some(first) = self
            .view
            .report()
            .and_then(|r| r.warnings().first().copied())
        else {
            return;
        };
        if area.height < 2 || area.width < 6 {
            return;
        }
        let width = usize::from(area.width - 4);
        let text = format!(" {} ", crate::tui::format::clip(first, width - 2));
        let line = Line::styled(text, self.theme.warning());
        buf.set_line(area.x + 1, area.bottom() - 1, &line, area.width - 2);
    }

    /// The shot's warnings, as `bouncelab shot` says them once each
    /// ([`crate::api::ShotReport::warnings`]: a bounce outside the ball's record, the net's),
    /// each in at most `rows` rows of `width` columns, cut at a word.
    fn warning_lines(&self, width: usize, rows: usize) -> Vec<Line<'static>> {
        let Some(r) = self.view.report() else {
            return Vec::new();
        };
        r.warnings()
            .into_iter()
            .flat_map(|w| warning_lines(w, width, rows, &self.theme))
            .collect()
    }

    /// The ball and the launch, the selected value marked, then the net's verdict.
    fn launch_lines(&self) -> Vec<Line<'static>> {
        let t = self.theme;
        let v = &self.view.values;
        let mut lines = vec![Line::styled(format!("{} · shot", self.ball), t.title())];
        for p in FlightParam::ALL {
            // marked ▶ as in the other readouts, not by its style alone (NO_COLOR, a copy)
            let chosen = p == self.view.selected.0;
            let mark = if chosen { "▶" } else { "" };
            let text = format!("{mark}{} {}{}", p.symbol(), sig(v.get(p), 4), p.unit());
            let style = if chosen {
                t.selected()
            } else {
                ratatui::style::Style::default()
            };
            lines.push(Line::from(Span::styled(text, style)));
        }
        // the net and whether the ball clears it, under the launch (the one row the narrow
        // readout has spare)
        if let Some(n) = self.view.report().and_then(|r| r.net.as_ref()) {
            let style = if n.cleared {
                ratatui::style::Style::default()
            } else {
                t.error()
            };
            let text = format!("net {} m: {}", sig(n.x, 4), net_words(n));
            lines.push(Line::styled(text, style));
        }
        lines
    }

    /// The bounce's way out first, then the end, the landing and the way in: the narrow
    /// readout's order, whose few rows cut the least telling last.
    fn shot_lines_short(&self) -> Vec<Line<'static>> {
        let t = self.theme;
        let Some(r) = self.view.report() else {
            return self.shot_lines();
        };
        let mut lines = Vec::new();
        if let Some(b) = r.bounces.first() {
            lines.push(Line::styled(format!("leaves · {}", slid_words(b)), t.dim()));
            lines.push(Line::raw(way(b.v_out, b.angle_out, b.spin_out)));
        }
        lines.push(Line::raw(landing(
            "lands again",
            r.end.state.x,
            r.end.state.t,
        )));
        if let Some(b) = r.bounces.first() {
            lines.push(Line::styled(landing("lands", b.x, b.t), t.dim()));
            lines.push(Line::raw(format!(
                "in {}",
                way(b.v_in, b.angle_in, b.spin_in)
            )));
        }
        lines
    }

    /// The landing, the bounce and the end.
    fn shot_lines(&self) -> Vec<Line<'static>> {
        let t = self.theme;
        let Some(r) = self.view.report() else {
            return match &self.view.shot {
                Some(Err(e)) => vec![Line::styled(e.clone(), t.error())],
                _ => Vec::new(),
            };
        };
        let mut lines = Vec::new();
        if let Some(b) = r.bounces.first() {
            lines.push(Line::styled("lands", t.dim()));
            lines.push(Line::raw(landing("", b.x, b.t).trim_start().to_string()));
            lines.push(Line::raw(format!(
                "in {}",
                way(b.v_in, b.angle_in, b.spin_in)
            )));
            lines.push(Line::styled("leaves", t.dim()));
            lines.push(Line::raw(way(b.v_out, b.angle_out, b.spin_out)));
            lines.push(Line::styled(slid_words(b), t.dim()));
        }
        let e = r.end.state;
        lines.push(Line::raw(landing("lands again", e.x, e.t)));
        lines
    }
}

/// "21.96 m/s at 14.27°  ω 215.3 rad/s": a way into or out of the bounce, the spin with its
/// unit and the angle in four digits, as the launch lines write them (issue 51 item 4:
/// "ω 200.0" bare, "11.2°").
fn way(v: f64, angle: f64, spin: f64) -> String {
    format!(
        "{} m/s at {}°  ω {} rad/s",
        sig(v, 4),
        sig(angle, 4),
        sig(spin, 4)
    )
}

/// "lands again x 23.45 m  t 1.234 s".
fn landing(what: &str, x: f64, t: f64) -> String {
    format!("{what} x {} m  t {} s", sig(x, 4), sig(t, 4))
}

/// How the ball met the surface.
fn slid_words(b: &crate::api::ShotBounce) -> &'static str {
    if b.slid_throughout {
        "slid throughout"
    } else {
        "slid, then gripped"
    }
}
