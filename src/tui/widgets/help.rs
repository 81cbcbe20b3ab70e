//! The help overlay (`?`): every key.

use crate::tui::keys::{help_max_scroll, help_rows, help_width};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// The help overlay, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct Help {
    pub theme: Theme,
    /// The first line shown (`App::help_scroll`).
    pub scroll: u16,
}

impl Widget for &Help {
    fn render(self, area: Rect, buf: &mut Buffer) {
        render(&self.theme, self.scroll, area, buf);
    }
}

fn render(theme: &Theme, scroll: u16, area: Rect, buf: &mut Buffer) {
    let rows = help_rows(area.width);
    let w = help_width(area.width);
    let h = (rows.len() as u16 + 2).min(area.height);
    let popup = crate::tui::widgets::centred(area, w, h);
    let lines: Vec<Line> = rows
        .into_iter()
        .map(|r| {
            if r.heading {
                Line::styled(format!(" {}", r.text), theme.title())
            } else {
                Line::from(vec![
                    Span::styled(format!(" {}  ", r.key), theme.key()),
                    Span::raw(r.text),
                ])
            }
        })
        .collect();
    // `update` keeps the scroll within the screen it knows; a smaller area still shows the end
    let last = help_max_scroll(area.width, area.height);
    let scroll = scroll.min(last);
    let more = if scroll < last {
        " ↓ more "
    } else if scroll > 0 {
        " ↑ more "
    } else {
        ""
    };
    Clear.render(popup, buf);
    Paragraph::new(lines)
        .scroll((scroll, 0))
        .block(
            Block::bordered()
                .title(Line::styled(" Keys · Esc or ? closes ", theme.title()))
                .title_bottom(Line::styled(more, theme.dim()).right_aligned()),
        )
        .render(popup, buf);
}
