//! The preset picker (`g`): every preset with its description and where it comes from, the
//! highlighted one marked ▶, scrolled so it stays in view at any size.

use crate::tui::format::clip;
use crate::tui::picker::{PickEntry, Picker};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// A picker, centred on the area it is given: the preset picker's by default, the surface
/// picker's as [`crate::tui::widgets::surfaces::SurfacesBox`].
#[derive(Debug, Clone, Copy)]
pub struct PickerBox<'a, E = PickEntry> {
    pub picker: &'a Picker<E>,
    pub theme: Theme,
}

/// An entry as its picker writes it, in two rows: `▶` (when highlighted), its name and where
/// it comes from; then its detail, indented.
pub trait Listed {
    /// The popup's title.
    const TITLE: &'static str;
    /// What Enter does, in the hint.
    const ENTER: &'static str;
    /// Whether a reading error too long for the popup is cut with "…" (the surface picker's),
    /// or by the border (the preset picker's, as it always was).
    const CUT_ERROR: bool;
    fn name(&self) -> &str;
    /// Where it comes from: "embedded", or its file.
    fn origin(&self) -> String;
    /// The second row.
    fn detail(&self) -> String;
}

impl Listed for PickEntry {
    const TITLE: &'static str = " Presets ";
    const ENTER: &'static str = "Enter loads";
    const CUT_ERROR: bool = false;
    fn name(&self) -> &str {
        &self.preset.name
    }
    fn origin(&self) -> String {
        self.origin.clone()
    }
    fn detail(&self) -> String {
        if self.preset.description.is_empty() {
            "(no description)".into()
        } else {
            self.preset.description.clone()
        }
    }
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

impl<E: Listed> Widget for &PickerBox<'_, E> {
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
            let e = if E::CUT_ERROR {
                clip(e, inner)
            } else {
                e.clone()
            };
            lines.push(Line::styled(e, self.theme.error()));
        }
        for (i, e) in p.entries.iter().enumerate().skip(first).take(rows) {
            let here = i == p.selected;
            let style = if here {
                self.theme.selected()
            } else {
                self.theme.title()
            };
            let name = clip(e.name(), inner.saturating_sub(1));
            let origin = clip(
                &format!("  {}", e.origin()),
                inner.saturating_sub(1 + name.chars().count()),
            );
            lines.push(Line::from(vec![
                Span::raw(if here { "▶" } else { " " }),
                Span::styled(name, style),
                Span::styled(origin, self.theme.dim()),
            ]));
            lines.push(Line::raw(format!(
                "   {}",
                clip(&e.detail(), inner.saturating_sub(3))
            )));
        }
        let more = if p.entries.len() > rows {
            format!(" · {}/{}", p.selected + 1, p.entries.len())
        } else {
            String::new()
        };
        // the presets' hint (46 columns at most) fits the narrowest popup (MIN_WIDTH less the
        // borders): only the surfaces' is ever cut
        let hint = format!("↑↓ choose · {} · Esc closes{more}", E::ENTER);
        lines.push(Line::styled(clip(&hint, inner), self.theme.dim()));
        let title = Line::styled(E::TITLE, self.theme.title());
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
