//! "Copy as command" (`y`): the `bouncelab run …` line of the screen in a box as wide as the
//! line (the terminal's width at most), so that it stays one row a mouse can select; the loop
//! copies it with OSC 52 too (issue 29).

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
        const HINT: &str =
            "runs what the screen shows · copied where the terminal allows (OSC 52) · Esc closes";
        let len = self.line.chars().count();
        // one row for the line where the terminal is wide enough: no wrap to break a selection
        let w = (len.max(40) as u16).saturating_add(2).min(area.width);
        let inner_w = usize::from(w.saturating_sub(2)).max(1);
        // the line's rows once wrapped (at most), a blank row, the hint's rows
        let rows = (len.div_ceil(inner_w) + 1 + HINT.chars().count().div_ceil(inner_w)) as u16;
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
            Line::styled(HINT, self.theme.dim()),
        ];
        let title = Line::styled(" Command · select it to copy ", self.theme.title());
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(Block::bordered().title(title))
            .render(popup, buf);
    }
}
