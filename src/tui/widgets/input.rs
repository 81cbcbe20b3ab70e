//! The value-entry dialog (`=` or Enter).

use crate::tui::app::{App, Input};
use crate::tui::format::sig_trim;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

pub fn render(app: &App, input: &Input, area: Rect, buf: &mut Buffer) {
    let theme = Theme::new(app.color());
    let p = input.param;
    let current = sig_trim(app.setting().get(p), 6);
    let mut lines = vec![
        Line::styled(
            format!(" range {}, now {current}{}", p.range_text(), p.unit()),
            theme.dim(),
        ),
        Line::from(vec![
            Span::styled(format!(" {} = ", p.symbol()), theme.title()),
            Span::raw(input.text.clone()),
            Span::styled("█", theme.dim()),
        ]),
    ];
    match &input.error {
        Some(e) => lines.push(Line::styled(format!(" {e}"), theme.warning())),
        None => lines.push(Line::raw("")),
    }
    lines.push(Line::styled(" Enter accepts · Esc cancels", theme.dim()));
    let w = 44.min(area.width);
    let h = 6.min(area.height);
    let popup = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    Clear.render(popup, buf);
    Paragraph::new(lines)
        .block(
            Block::bordered().title(Line::styled(format!(" Set {} ", p.symbol()), theme.title())),
        )
        .render(popup, buf);
}
