//! The help overlay (`?`): every key.

use crate::tui::keys::{KEYS, help_max_scroll};
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
    // section headings (rows without text) span the line: they do not widen the key column
    let key_w = KEYS
        .iter()
        .filter(|k| !k.1.is_empty())
        .map(|k| k.0.chars().count())
        .max()
        .unwrap_or(0);
    let text_w = KEYS.iter().map(|k| k.1.chars().count()).max().unwrap_or(0);
    let w = ((key_w + text_w + 5) as u16).min(area.width);
    let h = (KEYS.len() as u16 + 2).min(area.height);
    let popup = Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    );
    let lines: Vec<Line> = KEYS
        .iter()
        .map(|(k, t)| {
            if t.is_empty() {
                Line::styled(format!(" {k}"), theme.title())
            } else {
                Line::from(vec![
                    Span::styled(format!(" {k:<key_w$}  "), theme.key()),
                    Span::raw(*t),
                ])
            }
        })
        .collect();
    // `update` keeps the scroll within the screen it knows; a smaller area still shows the end
    let scroll = scroll.min(help_max_scroll(area.height));
    let more = if scroll < help_max_scroll(area.height) {
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
