//! The question before a preset file is overwritten: `overwrite <file>? y/n`.

use crate::tui::save::{question, short_path};
use crate::tui::state::Confirm;
use crate::tui::theme::Theme;
use crate::tui::widgets::wrapped_dialog;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::Widget;

/// The question, centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct ConfirmDialog<'a> {
    pub confirm: &'a Confirm,
    pub theme: Theme,
}

impl Widget for &ConfirmDialog<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        render(self.confirm, &self.theme, area, buf);
    }
}

fn render(confirm: &Confirm, theme: &Theme, area: Rect, buf: &mut Buffer) {
    let Some(path) = &confirm.request.replace else {
        return;
    };
    let mut lines = vec![
        Line::raw(" This preset file exists:"),
        Line::styled(format!(" {}", short_path(path)), theme.title()),
    ];
    // the file may hold a preset under another name: say which one is about to go
    if let Some(holds) = confirm
        .holds
        .as_ref()
        .filter(|h| **h != confirm.request.name)
    {
        lines.push(Line::raw(format!(" It holds the preset {holds}.")));
    }
    lines.push(Line::raw(""));
    lines.push(Line::styled(
        format!(" {}", question(path)),
        theme.warning(),
    ));
    lines.push(Line::styled(
        " y replaces it · n or Esc keeps it",
        theme.dim(),
    ));
    let title = format!(" Save preset {} ", confirm.request.name);
    // as tall as its lines wrapped: a long file name must not push the answers out
    // (tui_save_overwrite::the_overwrite_question_shows_its_answers_when_its_lines_wrap)
    wrapped_dialog(area, buf, 60, &title, lines, theme);
}

/// A y/n question of [`crate::tui::state::Ask`], centred on the area it is given.
#[derive(Debug, Clone, Copy)]
pub struct AskDialog<'a> {
    pub ask: &'a crate::tui::state::Ask,
    pub theme: Theme,
}

impl Widget for &AskDialog<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        use crate::tui::state::Ask;
        let theme = self.theme;
        let (title, lines) = match self.ask {
            Ask::PutAway(what) => (
                " Put away ",
                vec![
                    Line::styled(format!(" Put away the {what}?"), theme.warning()),
                    Line::styled(" y puts away (u puts back) · n or Esc keeps", theme.dim()),
                ],
            ),
            Ask::Session { path, .. } => (
                " Save session ",
                vec![
                    Line::raw(" This file exists:"),
                    Line::styled(format!(" {}", short_path(path)), theme.title()),
                    Line::raw(""),
                    Line::styled(" overwrite it with this session? y/n", theme.warning()),
                    Line::styled(" y replaces it · n or Esc keeps it", theme.dim()),
                ],
            ),
        };
        wrapped_dialog(area, buf, 60, title, lines, &theme);
    }
}
