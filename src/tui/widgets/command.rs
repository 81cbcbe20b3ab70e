//! "Copy as command" (`y`): the explorer's line of the screen (`bouncelab --preset … --v0 …`)
//! in a box as wide as the line (the terminal's width at most), so that it stays one row a
//! mouse can select; copied with OSC 52 where the terminal takes it (issue 29 item 2). A line
//! wider than the terminal is wrapped here and printed whole on the main screen when the
//! explorer ends (src/tui/mod.rs), as fzf prints its choice: lazygit and htop keep no such
//! line, and a modal can only cut or wrap what the terminal is too narrow for.

use crate::tui::theme::Theme;
use crate::tui::widgets::dialog;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Widget;

/// The command box, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct CommandBox<'a> {
    pub line: &'a str,
    /// Whether the line went to the clipboard (OSC 52: `App::osc52`).
    pub copied: bool,
    pub theme: Theme,
}

impl Widget for &CommandBox<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let len = self.line.chars().count();
        // one row for the line where the terminal is wide enough: no wrap to break a selection
        let w = (len.max(40) as u16).saturating_add(2).min(area.width);
        let inner_w = usize::from(w.saturating_sub(2)).max(1);
        let hint = hint(
            self.copied,
            len > inner_w,
            self.line.starts_with("bouncelab oblique "),
        );
        let hint = hint.as_str();
        // the line's rows once wrapped (at most), a blank row, the hint's rows
        let rows = len.div_ceil(inner_w) + 1 + hint.chars().count().div_ceil(inner_w);
        let lines = vec![
            Line::raw(self.line.to_string()),
            Line::raw(""),
            Line::styled(hint, self.theme.dim()),
        ];
        let title = " Command · select it to copy ";
        dialog(area, buf, w, rows, title, lines, &self.theme);
    }
}

/// What the box says under the line: what it does (the oblique view's `bouncelab oblique`
/// line computes the impact shown, the explorer's line reopens the state), whether it was
/// copied, and where a line too wide for the terminal is to be found whole.
fn hint(copied: bool, wrapped: bool, oblique: bool) -> String {
    let copy = if copied {
        "copied (OSC 52)"
    } else {
        "select it with the mouse (BOUNCELAB_OSC52=1 copies)"
    };
    let whole = if wrapped {
        " · wider than the terminal: printed whole when you quit"
    } else {
        ""
    };
    let does = if oblique {
        "computes this impact"
    } else {
        "reopens this state"
    };
    format!("{does} · {copy}{whole} · Esc closes")
}
