//! The surface picker (`G`, issue 53 item 6): every surface with its numbers (K_s, c_s, M, μ,
//! K_t, c_t where it gives them, src/tui/surface.rs) and where it comes from, the highlighted
//! one marked ▶, scrolled as the preset picker is (src/tui/widgets/picker.rs).

use crate::tui::format::clip;
use crate::tui::surface::{SurfacePicker, numbers, origin};
use crate::tui::theme::Theme;
use crate::tui::widgets::picker::Popup;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Paragraph, Widget};

/// The surface picker, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct SurfacesBox<'a> {
    pub picker: &'a SurfacePicker,
    pub theme: Theme,
}

impl Widget for &SurfacesBox<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let p = self.picker;
        // two rows an entry: name and origin, its numbers
        let Popup {
            popup,
            rows,
            first,
            inner,
        } = Popup::cleared(area, buf, p.entries.len(), p.selected, p.error.is_some());
        let mut lines = Vec::new();
        if let Some(e) = &p.error {
            lines.push(Line::styled(clip(e, inner), self.theme.error()));
        }
        for (i, e) in p.entries.iter().enumerate().skip(first).take(rows) {
            let here = i == p.selected;
            let style = if here {
                self.theme.selected()
            } else {
                self.theme.title()
            };
            let name = clip(&e.surface.name, inner.saturating_sub(1));
            let from = clip(
                &format!("  {}", origin(&e.origin)),
                inner.saturating_sub(1 + name.chars().count()),
            );
            lines.push(Line::from(vec![
                Span::raw(if here { "▶" } else { " " }),
                Span::styled(name, style),
                Span::styled(from, self.theme.dim()),
            ]));
            lines.push(Line::raw(format!(
                "   {}",
                clip(&numbers(&e.surface), inner.saturating_sub(3))
            )));
        }
        let more = if p.entries.len() > rows {
            format!(" · {}/{}", p.selected + 1, p.entries.len())
        } else {
            String::new()
        };
        lines.push(Line::styled(
            clip(
                &format!("↑↓ choose · Enter puts the ball on it · Esc closes{more}"),
                inner,
            ),
            self.theme.dim(),
        ));
        let title = Line::styled(" Surfaces ", self.theme.title());
        Paragraph::new(lines)
            .block(Block::bordered().title(title))
            .render(popup, buf);
    }
}
