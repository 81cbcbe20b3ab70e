//! "Copy as command" (`y`): the `bouncelab run …` line of the screen in a box, wrapped, to
//! select with the mouse and copy.

use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

/// The command box, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct CommandBox<'a> {
    pub line: &'a str,
    pub theme: Theme,
}

impl Widget for &CommandBox<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let w = 76.min(area.width);
        let inner_w = usize::from(w.saturating_sub(2)).max(1);
        // the line's rows once wrapped (at most), a blank row, the hint
        let rows = self.line.chars().count().div_ceil(inner_w) as u16 + 2;
        let h = (rows + 2).min(area.height);
        let popup = Rect::new(
            area.x + (area.width - w) / 2,
            area.y + (area.height - h) / 2,
            w,
            h,
        );
        Clear.render(popup, buf);
        let lines = vec![
            Line::raw(self.line.to_string()),
            Line::raw(""),
            Line::styled("runs what the screen shows · Esc closes", self.theme.dim()),
        ];
        let title = Line::styled(" Command · select it to copy ", self.theme.title());
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(Block::bordered().title(title))
            .render(popup, buf);
    }
}
