//! One file per panel, each a widget over the few things it shows (a figure, a view struct),
//! never the whole state: [`plot`] draws any figure, the others the readout, the header and
//! status line, and the dialogs. Nothing here changes the state or runs the model.

pub mod command;
pub mod confirm;
pub mod cut;
pub mod form;
pub mod help;
pub mod input;
pub mod marks;
pub mod picker;
pub mod pins;
pub mod plot;
pub mod quit;
pub mod readout;
pub mod status;
pub mod strokes;
pub mod surfaces;
pub mod tags;
pub mod title;
pub mod warning;

use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::text::Line;
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

/// A `w` × `h` rectangle centred on `area` (`w`, `h` no larger than it): where every dialog
/// and picker sits.
pub fn centred(area: Rect, w: u16, h: u16) -> Rect {
    Rect::new(
        area.x + (area.width - w) / 2,
        area.y + (area.height - h) / 2,
        w,
        h,
    )
}

/// The rows `lines` take wrapped inside a dialog `w` columns wide (its border excluded), an
/// empty line one row: counted by ratatui's own word wrapper, the one [`dialog`] draws with
/// (a count by characters misses the rows a word moved whole to the next line leaves:
/// tui_save_overwrite::the_overwrite_question_shows_its_answers_when_its_lines_wrap).
pub fn wrapped_rows(lines: &[Line], w: u16) -> usize {
    Paragraph::new(lines.to_vec())
        .wrap(Wrap { trim: false })
        .line_count(w.saturating_sub(2).max(1))
}

/// A dialog (the questions, the command box): `lines` wrapped in a bordered box `w` columns
/// wide and `rows` rows inside (as much as `area` has), titled, centred on `area` and cleared.
pub fn dialog(
    area: Rect,
    buf: &mut Buffer,
    w: u16,
    rows: usize,
    title: &str,
    lines: Vec<Line>,
    theme: &Theme,
) {
    let h = (rows as u16 + 2).min(area.height);
    let popup = centred(area, w, h);
    Clear.render(popup, buf);
    Paragraph::new(lines)
        .wrap(Wrap { trim: false })
        .block(Block::bordered().title(Line::styled(title, theme.title())))
        .render(popup, buf);
}

/// A [`dialog`] `width` columns wide (as much as `area` has) and as tall as `lines` wrapped
/// in it ([`wrapped_rows`]): the y/n questions.
pub fn wrapped_dialog(
    area: Rect,
    buf: &mut Buffer,
    width: u16,
    title: &str,
    lines: Vec<Line>,
    theme: &Theme,
) {
    let w = width.min(area.width);
    let rows = wrapped_rows(&lines, w);
    dialog(area, buf, w, rows, title, lines, theme);
}

/// A readout in one bordered column (wide screens): `lines` broken between fields, never
/// inside a value (`+0.225` and its `m` on two lines), to the width inside the border, and
/// the last row ending in "…" when they do not all fit ([`cut::kept`]).
pub fn readout_column(lines: Vec<Line<'static>>, area: Rect, buf: &mut Buffer) {
    let block = Block::bordered();
    let inner = block.inner(area);
    let lines = cut::kept(lines, usize::from(inner.width), usize::from(inner.height));
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .block(block)
        .render(area, buf);
}

/// A readout under the charts (narrow screens): its border drawn on `area` with `title` on
/// it if any, and the two columns inside it, as wide as `columns` says, for [`fitted`] lines.
pub fn readout_columns(
    area: Rect,
    buf: &mut Buffer,
    title: Option<Line<'static>>,
    columns: [Constraint; 2],
) -> [Rect; 2] {
    let block = title.map_or_else(Block::bordered, |t| Block::bordered().title(t));
    let inner = block.inner(area);
    block.render(area, buf);
    Layout::horizontal(columns).areas(inner)
}

/// `lines` broken between fields to `area`'s width and wrapped there, without a border; the
/// last row ending in "…" when they do not all fit ([`cut::kept`]).
pub fn fitted(lines: Vec<Line<'static>>, area: Rect, buf: &mut Buffer) {
    let lines = cut::kept(lines, usize::from(area.width), usize::from(area.height));
    Paragraph::new(lines)
        .wrap(Wrap { trim: true })
        .render(area, buf);
}
