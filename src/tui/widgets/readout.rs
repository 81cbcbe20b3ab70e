//! The readout: the live parameters (λ, ζ, v0, law, K_p, K_r, c) and the results (e, F_m, t_f,
//! z_m, z_f) next to the preset's measured values and the difference. A tall panel beside the
//! charts, or four compact lines below them on narrow terminals.

use crate::solver::ImpactResponse;
use crate::text::{sig, sig_trim};
use crate::tui::app::App;
use crate::tui::format::percent_diff;
use crate::tui::param::Param;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Style;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

/// Rows the tall panel needs, border included.
pub const PANEL_HEIGHT: u16 = 22;
/// Rows the compact form needs, border included.
pub const COMPACT_HEIGHT: u16 = 6;

/// One result row: name with unit, model value, measured value (same unit).
struct Row {
    name: &'static str,
    model: String,
    measured: Option<f64>,
    model_value: f64,
}

fn results(app: &App, r: Option<&ImpactResponse>) -> Vec<Row> {
    let m = &app.preset().measured;
    let Some(r) = r else {
        return Vec::new();
    };
    let t_f = r.contact_time.map(|t| t * 1e3);
    vec![
        Row {
            name: "e",
            model: sig(r.cor, 4),
            measured: m.cor,
            model_value: r.cor,
        },
        Row {
            name: "F_m N",
            model: sig(r.max_force, 4),
            measured: m.max_force,
            model_value: r.max_force,
        },
        Row {
            name: "t_f ms",
            model: t_f.map_or("none".into(), |t| sig(t, 4)),
            measured: m.contact_time.map(|t| t * 1e3),
            model_value: t_f.unwrap_or(f64::NAN),
        },
        Row {
            name: "z_m mm",
            model: sig(r.max_indentation * 1e3, 4),
            measured: None,
            model_value: f64::NAN,
        },
        Row {
            name: "z_f mm",
            model: sig(r.permanent_indentation * 1e3, 3),
            measured: None,
            model_value: f64::NAN,
        },
    ]
}

fn param_line(app: &App, theme: &Theme, p: Param, text: String) -> Line<'static> {
    let marker = if app.selected() == p { "▶" } else { " " };
    let style = if app.selected() == p {
        theme.selected()
    } else {
        Style::default()
    };
    Line::from(vec![Span::raw(marker), Span::styled(text, style)])
}

fn block(app: &App, theme: &Theme) -> Block<'static> {
    let p = app.preset();
    Block::bordered()
        .border_style(theme.dim())
        .title(Line::styled(
            format!(" {} · {} ", p.name, p.parameters.name()),
            theme.title(),
        ))
}

/// The tall panel.
pub fn render_panel(app: &App, area: Rect, buf: &mut Buffer) {
    let theme = Theme::new(app.color());
    let s = app.setting();
    let (params, n) = (&s.params, s.params.normalized());
    let inner_w = usize::from(area.width.saturating_sub(2));
    let mut lines = vec![
        Line::from(vec![
            Span::styled(" parameters", theme.title()),
            Span::styled(
                if app.coarse() {
                    "  [coarse]"
                } else {
                    "  [fine]"
                },
                theme.dim(),
            ),
        ]),
        param_line(
            app,
            &theme,
            Param::Lambda,
            format!("λ   {:<9}", sig(n.lambda, 4)),
        ),
        param_line(
            app,
            &theme,
            Param::Zeta,
            format!("ζ   {:<9}", sig(n.zeta, 4)),
        ),
        param_line(
            app,
            &theme,
            Param::V0,
            format!("v0  {} m/s", sig_trim(params.v0, 4)),
        ),
        Line::raw(format!(" law {}", s.law)),
        Line::raw(format!(" K_p {} N/m", sig(params.k_p, 3))),
        Line::raw(format!(" K_r {} N/m", sig(params.k_r, 3))),
        Line::raw(format!(" c   {} kg/s", sig(params.damping, 4))),
        Line::raw(format!(
            " z_p {} mm   m {} g",
            sig_trim(params.z_p * 1e3, 3),
            sig_trim(params.mass * 1e3, 4)
        )),
        Line::raw(""),
    ];
    let col = inner_w.saturating_sub(8) / 3;
    let cell = |s: &str| format!("{s:>w$} ", w = col.saturating_sub(1));
    lines.push(Line::styled(
        format!(
            " {:<7}{}{}{}",
            "result",
            cell("model"),
            cell("meas."),
            cell("diff")
        ),
        theme.title(),
    ));
    let rows = results(app, app.run());
    if rows.is_empty() {
        lines.push(Line::styled(" no result", theme.error()));
    }
    for row in rows {
        let (measured, diff) = match row.measured {
            Some(m) => (sig_trim(m, 4), percent_diff(row.model_value, m)),
            None => (String::new(), String::new()),
        };
        lines.push(Line::from(vec![
            Span::raw(format!(" {:<7}", row.name)),
            Span::styled(cell(&row.model), Style::default().fg(theme.current())),
            Span::styled(cell(&measured), theme.measured()),
            Span::raw(cell(&diff)),
        ]));
    }
    if let Some(r) = app.run() {
        let note = match (r.rebound, r.permanent_indentation > 0.0) {
            (false, _) => " no rebound: the ball sinks into the dashpot",
            (true, true) => " flattened: z_f > 0",
            (true, false) => " no flattening (z_m < z_p)",
        };
        lines.push(Line::styled(note, theme.dim()));
    }
    // a preset saved at another speed keeps no measurements, and its `[measured] v0` is only
    // the speed it runs at: claim no measurement then
    let m = &app.preset().measured;
    if m.cor.is_some() || m.max_force.is_some() || m.contact_time.is_some() {
        lines.push(Line::styled(
            format!(" measured at v0 = {} m/s", sig_trim(m.v0, 4)),
            theme.dim(),
        ));
    }
    if let Some(g) = app.ghost() {
        let gs = &g.setting;
        let name = &app.presets()[gs.preset].name;
        lines.push(Line::styled(
            format!(" pinned: {name}, {} law", gs.law),
            theme.ghost(),
        ));
        lines.push(Line::styled(
            format!(
                "   λ {}  ζ {}  v0 {} m/s",
                sig_trim(gs.get(Param::Lambda), 3),
                sig_trim(gs.get(Param::Zeta), 3),
                sig_trim(gs.get(Param::V0), 3),
            ),
            theme.ghost(),
        ));
    }
    Paragraph::new(lines)
        .block(block(app, &theme))
        .render(area, buf);
}

/// Four lines for narrow terminals.
pub fn render_compact(app: &App, area: Rect, buf: &mut Buffer) {
    let theme = Theme::new(app.color());
    let s = app.setting();
    let n = s.params.normalized();
    let p = |param: Param, text: String| {
        let style = if app.selected() == param {
            theme.selected()
        } else {
            Style::default()
        };
        Span::styled(text, style)
    };
    let mut lines = vec![
        Line::from(vec![
            Span::raw(" "),
            p(Param::Lambda, format!("λ {}", sig(n.lambda, 4))),
            Span::raw("  "),
            p(Param::Zeta, format!("ζ {}", sig(n.zeta, 4))),
            Span::raw("  "),
            p(Param::V0, format!("v0 {} m/s", sig_trim(s.params.v0, 4))),
            Span::raw(format!("  {}", s.law)),
        ]),
        Line::raw(format!(
            " K_p {} N/m  K_r {} N/m  c {} kg/s",
            sig(s.params.k_p, 3),
            sig(s.params.k_r, 3),
            sig(s.params.damping, 3)
        )),
    ];
    let rows = results(app, app.run());
    let fmt = |row: &Row| match row.measured {
        Some(m) => format!(
            "{} {} ({}, {})",
            row.name.split(' ').next().unwrap_or(""),
            row.model,
            sig_trim(m, 4),
            percent_diff(row.model_value, m)
        ),
        None => format!("{} {}", row.name.split(' ').next().unwrap_or(""), row.model),
    };
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
        lines.push(Line::styled(" no result", theme.error()));
    }
    Paragraph::new(lines)
        .block(block(app, &theme))
        .render(area, buf);
}
