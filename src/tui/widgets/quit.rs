//! The question before quitting loses work (`q` with pins, measured data or a fit).

use crate::tui::theme::Theme;
use crate::tui::widgets::wrapped_dialog;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Widget;

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
        wrapped_dialog(area, buf, 50, " Quit ", lines, &self.theme);
    }
}
