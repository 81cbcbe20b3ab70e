//! The help overlay (`?`): every key.

use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// (keys, what they do)
pub const KEYS: [(&str, &str); 27] = [
    ("l / L", "λ up / down (±0.01, coarse ±0.1)"),
    ("z / Z", "ζ up / down (×1.1, coarse ×2)"),
    ("v / V", "v0 up / down (±0.1, coarse ±1 m/s)"),
    ("↑ / ↓", "change the selected parameter"),
    ("Shift+↑↓ PgUp/Dn", "coarse step"),
    ("← / →", "select λ, ζ or v0"),
    ("[ / ]", "fine / coarse steps"),
    ("= or Enter", "type an exact value"),
    ("1 2 3", "load superball, golf, baseball"),
    ("4", "the start preset, if another"),
    ("c", "cycle the contact law"),
    ("r", "reset to the preset"),
    ("p / P", "pin curves as a ghost / clear it"),
    ("u", "undo the last change"),
    ("e", "export this view (SVG + CSV files)"),
    ("s", "save as a user preset (asks a name)"),
    ("Tab / Shift+Tab", "switch view (impact, sweeps)"),
    ("d", "drop test (space pauses, b replays)"),
    ("?", "this help (Esc or ? closes)"),
    ("q  Esc  Ctrl-C", "quit"),
    ("", ""),
    ("In the value or name entry", ""),
    ("Enter / Esc", "accept / cancel"),
    ("Backspace", "delete a character"),
    ("", ""),
    ("At \"overwrite …? y/n\"", ""),
    ("y / n or Esc", "replace the file / keep it"),
];

/// The help overlay, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct Help {
    pub theme: Theme,
}

impl Widget for &Help {
    fn render(self, area: Rect, buf: &mut Buffer) {
        render(&self.theme, area, buf);
    }
}

fn render(theme: &Theme, area: Rect, buf: &mut Buffer) {
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
    Clear.render(popup, buf);
    Paragraph::new(lines)
        .block(Block::bordered().title(Line::styled(" Keys · Esc or ? closes ", theme.title())))
        .render(popup, buf);
}
