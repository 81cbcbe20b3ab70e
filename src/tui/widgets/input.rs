//! The text-entry dialog: an exact value (`=` or Enter), or the name to save a preset under
//! (`s`).

use crate::text::sig_trim;
use crate::tui::param::Param;
use crate::tui::setting::Setting;
use crate::tui::state::{Input, Purpose};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget};

/// The entry dialog over the area it is given; `setting` is what the values are now.
#[derive(Debug, Clone, Copy)]
pub struct InputDialog<'a> {
    pub input: &'a Input,
    pub setting: &'a Setting,
    pub theme: Theme,
}

impl Widget for &InputDialog<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        render(self.input, self.setting, &self.theme, area, buf);
    }
}

fn render(input: &Input, s: &Setting, theme: &Theme, area: Rect, buf: &mut Buffer) {
    let (title, about, label, keys, width) = entry(input.purpose, s);
    let w = width.min(area.width);
    // border, label and cursor take the rest of the row: a longer text shows its end
    let room = (w as usize).saturating_sub(label.chars().count() + 3);
    let mut lines = vec![
        Line::styled(about, theme.dim()),
        Line::from(
            std::iter::once(Span::styled(label, theme.title()))
                .chain(with_cursor(input, room, theme))
                .collect::<Vec<_>>(),
        ),
    ];
    // the reason is wrapped at spaces, never cut mid-word: the dialog grows for it
    let reason = match &input.error {
        Some(e) => crate::tui::format::wrap(e, (w as usize).saturating_sub(3)),
        None => vec![String::new()],
    };
    let h = (5 + reason.len() as u16).min(area.height);
    lines.extend(
        reason
            .into_iter()
            .map(|r| Line::styled(format!(" {r}"), theme.warning())),
    );
    lines.push(Line::styled(keys, theme.dim()));
    let popup = crate::tui::widgets::centred(area, w, h);
    Clear.render(popup, buf);
    Paragraph::new(lines)
        .block(Block::bordered().title(Line::styled(title, theme.title())))
        .render(popup, buf);
}

/// What the dialog for `purpose` says, with `s` the values now.
fn entry(purpose: Purpose, s: &Setting) -> Entry {
    match purpose {
        Purpose::Value(p) => {
            // four digits, as the readout shows it (issue 51 item 4: "now 1.29908")
            let current = sig_trim(s.get(p), 4);
            let about = format!(" range {}, now {current}{}", p.range_text(), p.unit());
            number_entry(p.symbol(), about, " Enter accepts · Esc cancels", 44)
        }
        Purpose::MeasuredPath => (
            " Load measured data ".to_string(),
            " force–time CSV, COR table or drop test".to_string(),
            " file: ".to_string(),
            " Enter loads · Esc cancels",
            62,
        ),
        Purpose::PresetName => {
            let v = |p: Param| sig_trim(s.get(p), 4);
            (
                " Save as a user preset ".to_string(),
                format!(
                    " λ = {}, ζ = {}, v0 = {} m/s, {} law",
                    v(Param::Lambda),
                    v(Param::Zeta),
                    v(Param::V0),
                    s.law
                ),
                " name: ".to_string(),
                " Enter saves · Esc cancels",
                // room for the longest name (save::NAME_MAX) after " name: ", and for the
                // parameters with the longest law's name
                62,
            )
        }
        Purpose::Physical(f) => number_entry(
            f.symbol(),
            format!(" range {}, now {}", f.range_text(), f.show(f.get(s))),
            " Enter accepts · Esc back to the form",
            50,
        ),
        Purpose::SessionPath => (
            " Save the session ".to_string(),
            " ball, law, v0, target, pins, measured file, view".to_string(),
            " file: ".to_string(),
            " Enter saves · Esc cancels",
            62,
        ),
        Purpose::Oblique(p) => number_entry(
            p.symbol(),
            format!(" {}: range {}", p.name(), p.range_text()),
            " Enter accepts · Esc cancels",
            50,
        ),
        Purpose::Targets => (
            " Map targets ".to_string(),
            " e.g. cor>=0.8,contact_time>=2 (N, ms); empty clears".to_string(),
            " where ".to_string(),
            " Enter accepts · Esc cancels",
            60,
        ),
    }
}

/// What an entry dialog says: its title, the line about the value, the entry's label, the
/// keys, and its width.
type Entry = (String, String, String, &'static str, u16);

/// The entry of one number named by its `symbol` (λ, m, θ, …): "Set λ", "λ = ".
fn number_entry(symbol: &str, about: String, keys: &'static str, width: u16) -> Entry {
    let title = format!(" Set {symbol} ");
    (title, about, format!(" {symbol} = "), keys, width)
}

/// The entry's text with the cursor shown, in `room` cells plus one: the character under the
/// cursor reversed, or "█" after the end. A longer text shows the cells around the cursor,
/// "…" where it goes on.
fn with_cursor(input: &Input, room: usize, theme: &Theme) -> Vec<Span<'static>> {
    let chars: Vec<char> = input.text.chars().collect();
    let n = chars.len();
    let at = input.cursor.min(n);
    let cells = room.max(3) + 1;
    let to = (at + 1).max(cells).min(n + 1);
    let from = to.saturating_sub(cells);
    (from..to)
        .map(|i| {
            if i == at {
                let c = chars.get(i).map_or("█".to_string(), char::to_string);
                let style = if i < n { theme.selected() } else { theme.dim() };
                Span::styled(c, style)
            } else if (i == from && from > 0) || (i + 1 == to && to <= n) {
                Span::styled("…", theme.dim())
            } else {
                // the cell after the end, when the cursor is elsewhere, is blank
                Span::raw(chars.get(i).map_or(" ".to_string(), char::to_string))
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every text length, cursor place and width: no panic, the cursor's cell always shown, the
    /// line never wider than the room given.
    #[test]
    fn the_cursor_is_always_shown_within_the_room() {
        let theme = Theme::new(false);
        for n in 0..12 {
            let text: String = "0123456789ab".chars().take(n).collect();
            for cursor in 0..=n {
                for room in 0..9 {
                    let mut input = Input::new(Purpose::PresetName, text.clone());
                    input.cursor = cursor;
                    let spans = with_cursor(&input, room, &theme);
                    assert_eq!(
                        spans.len(),
                        (n + 1).min(room.max(3) + 1),
                        "{n} {cursor} {room}"
                    );
                    let shown = |s: &Span| s.style == theme.selected() || s.content == "█";
                    assert_eq!(spans.iter().filter(|s| shown(s)).count(), 1);
                }
            }
        }
    }
}
