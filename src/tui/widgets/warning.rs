//! A long warning in a panel's few rows: the ball's calibration warning (some 250 characters,
//! its sources named) in the readouts, whose message line says it whole (issue 52 item 2).

use crate::tui::format::{clip, wrap};
use crate::tui::theme::Theme;
use ratatui::style::Style;
use ratatui::text::Line;

/// `text` wrapped at spaces to `width` columns (each line indented one), in at most `rows`
/// lines: the last one cut at a word with "…" ([`clip`]) when it does not all fit.
pub fn warning_lines(text: &str, width: usize, rows: usize, theme: &Theme) -> Vec<Line<'static>> {
    cut_lines(text, width, rows, theme.warning())
}

/// [`warning_lines`] in `style`: a long note (why the measured values are not compared) in
/// the readout's few rows.
pub fn cut_lines(text: &str, width: usize, rows: usize, style: Style) -> Vec<Line<'static>> {
    let width = width.saturating_sub(1);
    let mut lines = wrap(text, width);
    if rows > 0 && lines.len() > rows {
        let rest = lines.split_off(rows - 1).join(" ");
        lines.push(clip(&rest, width));
    }
    lines.truncate(rows);
    lines
        .into_iter()
        .map(|l| Line::styled(format!(" {l}"), style))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(lines: &[Line]) -> Vec<String> {
        lines.iter().map(|l| l.to_string()).collect()
    }

    #[test]
    fn a_warning_that_fits_is_whole_and_one_that_does_not_ends_at_a_word() {
        let t = Theme::new(false);
        let w = "outside calibration: impact speed 20 m/s, the ball was fitted at 6.906 m/s";
        assert_eq!(
            texts(&warning_lines(w, 41, 3, &t)),
            [
                " outside calibration: impact speed 20",
                " m/s, the ball was fitted at 6.906 m/s"
            ]
        );
        assert_eq!(
            texts(&warning_lines(w, 41, 1, &t)),
            [" outside calibration: impact speed 20…"]
        );
        assert!(warning_lines(w, 41, 0, &t).is_empty());
    }
}
