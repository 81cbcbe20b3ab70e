//! Where a chart's texts go: a marker's text clear of the others, and a legend stacked or
//! in one line (src/tui/widgets/plot.rs draws them).

use ratatui::text::{Line, Span};

/// Where a marker's text starts on its row, and the text: from the marker's column when it
/// fits before the plot's right edge; a labelled marker ("▲t_f 2.6 ms", its glyph first) that
/// does not is written mirrored, "t_f 2.6 ms▲", so that it ends on its column and the glyph
/// stays on its point; other texts end at the edge.
pub fn marker_text_at(text: &str, col: u16, (left, right): (u16, u16)) -> (u16, String) {
    let w = text.chars().count() as u16;
    if col + w <= right {
        return (col, text.to_string());
    }
    let mut chars = text.chars();
    match chars.next() {
        Some(glyph @ ('●' | '▲')) if col + 1 >= left + w => {
            (col + 1 - w, format!("{}{glyph}", chars.as_str()))
        }
        _ => (right.saturating_sub(w).max(left), text.to_string()),
    }
}

/// Where a marker's text goes, as pieces (x, y, text), clear of the `taken` cells: where
/// [`marker_text_at`] puts it; else, for a labelled marker ("▲t_f 2.7 ms"), its glyph on the
/// point and the label on the row above or below; else the glyph alone. A marker without a
/// label ("S", "◆") whose cell is taken moves right, so both show.
pub fn marker_place(
    text: &str,
    (col, row): (u16, u16),
    (left, right, top, bottom): (u16, u16, u16, u16),
    taken: &[(u16, u16)],
) -> Vec<(u16, u16, String)> {
    // a text and a blank cell either side of it: two texts never run together ("◆nowS",
    // tests/tui/tui_marks.rs: `marker_texts_never_run_together`)
    let clear = |x: u16, y: u16, t: &str| {
        let w = t.chars().count() as u16;
        x >= left
            && x + w <= right
            && (x.saturating_sub(1)..x + w + 1).all(|c| !taken.contains(&(c, y)))
    };
    let mut chars = text.chars();
    let glyph = chars.next().unwrap_or('●');
    let label = chars.as_str();
    if !matches!(glyph, '●' | '▲' | '◆') || label.is_empty() {
        let mut x = col;
        // off taken cells, a blank cell either side: never run together ("So1", "nowS")
        let w = text.chars().count() as u16;
        let blocked = |x: u16| {
            (x..x + w).any(|c| taken.contains(&(c, row)))
                || (x > left && taken.contains(&(x - 1, row)))
                || taken.contains(&(x + w, row))
        };
        while blocked(x) && x + w < right {
            x += 1;
        }
        let (x, t) = marker_text_at(text, x, (left, right));
        return vec![(x, row, t)];
    }
    let (x, t) = marker_text_at(text, col, (left, right));
    if clear(x, row, &t) {
        return vec![(x, row, t)];
    }
    let g = glyph.to_string();
    let w = label.chars().count() as u16;
    for y in [row.checked_sub(1), Some(row + 1)].into_iter().flatten() {
        if y < top || y >= bottom {
            continue;
        }
        let starts = [col, (col + 1).saturating_sub(w)];
        if let Some(&x) = starts.iter().find(|&&x| clear(x, y, label)) {
            return vec![(col, row, g), (x, y, label.to_string())];
        }
    }
    vec![(col, row, g)]
}

/// `lines` one under the other when they fit, else on one line when that fits.
pub fn stacked_or_in_one(
    lines: Vec<Line<'static>>,
    fits: &dyn Fn(u16, u16) -> bool,
) -> Option<Vec<Line<'static>>> {
    if lines.is_empty() {
        return None;
    }
    let width = lines.iter().map(Line::width).max().unwrap_or(0) as u16;
    if fits(lines.len() as u16, width) {
        return Some(lines);
    }
    let mut spans = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        if i > 0 {
            spans.push(Span::raw("  "));
        }
        spans.extend(line.spans.iter().cloned());
    }
    let one = Line::from(spans);
    fits(1, one.width() as u16).then(|| vec![one])
}
