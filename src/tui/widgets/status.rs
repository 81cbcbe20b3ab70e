//! The header (ball, law, view, the last message) and the status line of key hints.

use crate::model::contact::ContactLaw;
use crate::tui::state::{Message, Severity, View};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

/// Key hints in display order, with the rank at which they are dropped when space runs out
/// (lower ranks stay longer).
const HINTS: [(&str, &str, u8); 17] = [
    ("l/L", "λ", 0),
    ("z/Z", "ζ", 0),
    ("v/V", "v0", 0),
    ("↑↓", "change", 2),
    ("←→", "select", 3),
    ("[ ]", "fine/coarse", 4),
    ("=", "type", 2),
    ("1-3", "ball", 1),
    ("c", "law", 1),
    ("p/P", "pin", 3),
    ("u", "undo", 2),
    ("e", "export", 2),
    ("s", "save", 3),
    ("r", "reset", 3),
    ("Tab", "view", 0),
    ("?", "help", 0),
    ("q", "quit", 0),
];

/// The map view's hints in place of `↑↓ change` and `←→ select`: the arrows move the cursor.
const MAP_HINTS: [(&str, &str, u8); 3] = [
    ("←→↑↓", "cursor", 0),
    ("n", "quantity", 1),
    ("t", "targets", 1),
];

/// The header line: ball, law, view, and the last message on the right.
#[derive(Debug, Clone, Copy)]
pub struct Header<'a> {
    pub ball: &'a str,
    pub law: ContactLaw,
    pub view: View,
    pub message: Option<&'a Message>,
    pub theme: Theme,
}

impl Widget for &Header<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let theme = self.theme;
        let left = Line::from(vec![
            Span::styled(" bouncelab ", theme.title()),
            Span::raw(format!(
                "· {} · {} law · view {}",
                self.ball,
                self.law,
                self.view.title()
            )),
        ]);
        left.render(area, buf);
        if let Some(m) = self.message {
            message(m, &theme, area, buf);
        }
    }
}

/// The message, right-aligned; it wins over the left part when they meet.
fn message(m: &Message, theme: &Theme, area: Rect, buf: &mut Buffer) {
    let style = match m.severity {
        Severity::Info => theme.info(),
        Severity::Warning => theme.warning(),
        Severity::Error => theme.error(),
    };
    let text = format!(" {} ", m.text);
    let w = (text.chars().count() as u16).min(area.width);
    let x = area.right() - w;
    let room = usize::from(w);
    buf.set_stringn(x, area.y, text, room, style);
}

/// The status line of key hints, as many as fit.
#[derive(Debug, Clone, Copy)]
pub struct KeyHints {
    pub theme: Theme,
    /// In the map view: its own hints for the arrows.
    pub map: bool,
}

impl Widget for &KeyHints {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let hints_shown: Vec<(&str, &str, u8)> = if self.map {
            let mut v = MAP_HINTS.to_vec();
            v.extend(HINTS.iter().filter(|h| !matches!(h.0, "↑↓" | "←→")));
            v
        } else {
            HINTS.to_vec()
        };
        hints(&self.theme, &hints_shown, area, buf);
    }
}

fn hints(theme: &Theme, all: &[(&str, &str, u8)], area: Rect, buf: &mut Buffer) {
    let width = |h: &(&str, &str, u8)| h.0.chars().count() + h.1.chars().count() + 3;
    let mut budget = usize::from(area.width);
    let mut keep = vec![false; all.len()];
    for rank in 0..=4 {
        for (i, h) in all.iter().enumerate() {
            if h.2 == rank && width(h) <= budget {
                keep[i] = true;
                budget -= width(h);
            }
        }
    }
    let mut spans = vec![Span::raw(" ")];
    for (h, _) in all.iter().zip(keep).filter(|(_, k)| *k) {
        spans.push(Span::styled(h.0, theme.key()));
        spans.push(Span::raw(format!(" {}  ", h.1)));
    }
    Line::from(spans).style(theme.dim()).render(area, buf);
}
