//! The preset picker (`g`): every preset with its description and where it comes from, the
//! highlighted one marked ▶, scrolled so it stays in view at any size.

use crate::tui::format::clip;
use crate::tui::picker::Picker;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// The picker, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct PickerBox<'a> {
    pub picker: &'a Picker,
    pub theme: Theme,
}

/// The first entry shown so that `selected` is one of `rows` entries shown.
pub fn first_shown(selected: usize, rows: usize) -> usize {
    selected.saturating_sub(rows.saturating_sub(1))
}

/// Where a picker's list sits (the preset picker's and the surface picker's): a popup up to
/// 76 columns wide, centred and cleared, two rows an entry, the hint and the error if any
/// below them; `rows` entries shown from `first`, `inner` columns inside the borders (a text
/// too long for them is cut with "…", docs/explorer.md, Numbers, not by the border).
pub struct Popup {
    pub popup: Rect,
    pub rows: usize,
    pub first: usize,
    pub inner: usize,
}

impl Popup {
    /// The popup for `entries` entries with `selected` shown, cleared in `buf`.
    pub fn cleared(
        area: Rect,
        buf: &mut Buffer,
        entries: usize,
        selected: usize,
        error: bool,
    ) -> Popup {
        let w = 76.min(area.width);
        let extra = 1 + u16::from(error);
        let want = 2 * entries as u16 + extra + 2;
        let h = want.min(area.height);
        let popup = crate::tui::widgets::centred(area, w, h);
        Clear.render(popup, buf);
        let rows = usize::from(h.saturating_sub(2 + extra) / 2).max(1);
        Popup {
            popup,
            rows,
            first: first_shown(selected, rows),
            inner: usize::from(w.saturating_sub(2)),
        }
    }
}

impl Widget for &PickerBox<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let p = self.picker;
        let Popup {
            popup,
            rows,
            first,
            inner,
        } = Popup::cleared(area, buf, p.entries.len(), p.selected, p.error.is_some());
        let mut lines = Vec::new();
        if let Some(e) = &p.error {
            lines.push(Line::styled(e.clone(), self.theme.error()));
        }
        for (i, e) in p.entries.iter().enumerate().skip(first).take(rows) {
            let here = i == p.selected;
            let style = if here {
                self.theme.selected()
            } else {
                self.theme.title()
            };
            let name = clip(&e.preset.name, inner.saturating_sub(1));
            let origin = clip(
                &format!("  {}", e.origin),
                inner.saturating_sub(1 + name.chars().count()),
            );
            lines.push(Line::from(vec![
                Span::raw(if here { "▶" } else { " " }),
                Span::styled(name, style),
                Span::styled(origin, self.theme.dim()),
            ]));
            let text = if e.preset.description.is_empty() {
                "(no description)"
            } else {
                e.preset.description.as_str()
            };
            lines.push(Line::raw(format!(
                "   {}",
                clip(text, inner.saturating_sub(3))
            )));
        }
        let more = if p.entries.len() > rows {
            format!(" · {}/{}", p.selected + 1, p.entries.len())
        } else {
            String::new()
        };
        lines.push(Line::styled(
            format!("↑↓ choose · Enter loads · Esc closes{more}"),
            self.theme.dim(),
        ));
        let title = Line::styled(" Presets ", self.theme.title());
        Paragraph::new(lines)
            .block(Block::bordered().title(title))
            .render(popup, buf);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_highlight_stays_in_view() {
        assert_eq!(first_shown(0, 3), 0);
        assert_eq!(first_shown(2, 3), 0);
        assert_eq!(first_shown(3, 3), 1);
        assert_eq!(first_shown(9, 1), 9);
    }
}
