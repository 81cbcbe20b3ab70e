//! A panel's text kept to the rows it has, and marked where it is cut: lines broken between
//! their fields and at spaces ([`crate::tui::format::fit_lines`], never inside a word that
//! fits a row), and, when they take more rows than there are, the last row shown ends in
//! "…" — a panel never drops text without saying so (docs/explorer.md, "Numbers";
//! tests/tui/tui_small.rs).

use ratatui::style::Style;
use ratatui::text::Line;

/// `lines` fitted to `width` columns and to `rows` rows: all of them when they fit, else the
/// first rows with the last one's end replaced by "…" (its words that fit before it).
pub fn kept(lines: Vec<Line<'static>>, width: usize, rows: usize) -> Vec<Line<'static>> {
    let lines = crate::tui::format::fit_lines(lines, width);
    if self::rows(&lines, width) <= rows {
        return lines;
    }
    let mut out = Vec::new();
    let mut used = 0;
    for line in lines {
        let n = self::rows(std::slice::from_ref(&line), width);
        if used + n >= rows {
            if rows > used {
                out.push(marked(&line, width));
            }
            break;
        }
        used += n;
        out.push(line);
    }
    out
}

/// The rows `lines` take in a paragraph `width` columns wide that wraps them (an empty line
/// one row).
pub fn rows(lines: &[Line], width: usize) -> usize {
    lines
        .iter()
        .map(|l| l.width().max(1).div_ceil(width.max(1)))
        .sum()
}

/// `line` ended by "…" within `width` columns: its words that fit before " …", their styles
/// kept.
fn marked(line: &Line<'static>, width: usize) -> Line<'static> {
    let mut cells = crate::tui::format::cells_of(line);
    let text: String = cells.iter().map(|c| c.0).collect();
    let text = text.trim_end();
    if text.ends_with('…') {
        // cut at a word already (a short readout's own)
        return line.clone();
    }
    let shown: Vec<char> = crate::tui::format::clip(&format!("{text} …"), width)
        .chars()
        .collect();
    // what `clip` kept of the text, styled as it was, then the rest of what it wrote (" …"
    // or "…") in the style of the last kept character
    cells.truncate(shown.len().saturating_sub(1).min(text.chars().count()));
    let style = cells.last().map_or(Style::default(), |c| c.1);
    let rest: Vec<char> = shown[cells.len()..].to_vec();
    cells.extend(rest.into_iter().map(|c| (c, style)));
    crate::tui::format::spans_of(&cells)
}

#[cfg(test)]
mod tests {
    use super::kept;
    use ratatui::text::Line;

    fn texts(lines: &[Line]) -> Vec<String> {
        lines.iter().map(ToString::to_string).collect()
    }

    #[test]
    fn a_cut_panel_ends_in_an_ellipsis_after_whole_words() {
        let lines = vec![
            Line::raw("first line"),
            Line::raw("a line wider than its panel"),
            Line::raw("never shown"),
        ];
        assert_eq!(
            texts(&kept(lines.clone(), 16, 3)),
            ["first line", "a line wider", "  than its…"]
        );
        assert_eq!(
            texts(&kept(lines.clone(), 16, 2)),
            ["first line", "a line wider …"]
        );
        assert_eq!(texts(&kept(lines.clone(), 13, 1)), ["first line …"]);
        assert_eq!(texts(&kept(lines.clone(), 10, 1)), ["first…"]);
        assert_eq!(kept(lines.clone(), 16, 4).len(), 4, "all of it fits");
        assert!(kept(lines, 16, 0).is_empty());
        let cut_already = vec![Line::raw("outside calibration:…"), Line::raw("e 0.7506")];
        assert_eq!(texts(&kept(cut_already, 28, 1)), ["outside calibration:…"]);
    }
}
