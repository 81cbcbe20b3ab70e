//! The question before quitting loses work (`q` with pins, measured data or a fit).

use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

/// "Quit and lose …?", centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct QuitDialog<'a> {
    /// What would be lost: "2 pins, measured data, the fit".
    pub lost: &'a str,
    pub theme: Theme,
}

impl Widget for &QuitDialog<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let lines = vec![
            Line::styled(
                format!(" Quit and lose {}?", self.lost),
                self.theme.warning(),
            ),
            Line::styled(" q or y quits · n or Esc stays", self.theme.dim()),
        ];
        let w = 50.min(area.width);
        let inner = usize::from(w.saturating_sub(2));
        let rows: usize = lines.iter().map(|l| l.width().div_ceil(inner.max(1))).sum();
        let h = (rows as u16 + 2).min(area.height);
        let popup = Rect::new(
            area.x + (area.width - w) / 2,
            area.y + (area.height - h) / 2,
            w,
            h,
        );
        Clear.render(popup, buf);
        Paragraph::new(lines)
            .wrap(Wrap { trim: false })
            .block(Block::bordered().title(Line::styled(" Quit ", self.theme.title())))
            .render(popup, buf);
    }
}
