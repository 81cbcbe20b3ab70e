//! Number formatting for the screen (never prints NaN or inf), and text fitted to a width:
//! names cut with an ellipsis, readout lines broken between their fields, never inside a
//! value.
//!
//! One number format for the whole explorer (docs/explorer.md, "Numbers"): [`value`] writes
//! [`DIGITS`] significant digits, plain from 0.0001 up to 99 999 (the integer part rounded
//! too) and in exponent form outside; a parameter being stepped gets the digits its step
//! needs ([`stepped`]); an uncertainty [`UNCERTAIN`] digits, an interval's
//! two ends in one form ([`interval`]); every quantity in one unit ([`screen_unit`]: mm, g,
//! ms).

use ratatui::style::Style;
use ratatui::text::{Line, Span};

/// Significant digits of a value on screen.
pub const DIGITS: usize = 4;
/// Significant digits of an uncertainty (a standard error, an interval's ends).
pub const UNCERTAIN: usize = 3;

/// `x` to `digits` significant digits, the integer part of a plain number rounded too
/// (78094 to 3 digits is 78100).
fn rounded(x: f64, digits: usize) -> String {
    crate::text::sig(crate::text::rounded(x, digits), digits)
}

/// A value on screen: [`DIGITS`] significant digits, "—" when not finite.
pub fn value(x: f64) -> String {
    rounded(x, DIGITS)
}

/// An uncertainty on screen (a standard error): [`UNCERTAIN`] significant digits.
pub fn uncertainty(x: f64) -> String {
    rounded(x, UNCERTAIN)
}

/// A value being stepped by `step`: the digits needed to see one step (λ 1000.01 one fine
/// step above 1000), at least [`DIGITS`].
pub fn stepped(x: f64, step: f64) -> String {
    let mag = |v: f64| v.abs().log10().floor() as i32;
    let digits = if x.is_finite() && x != 0.0 && step.is_finite() && step > 0.0 {
        (mag(x) - mag(step) + 1).clamp(DIGITS as i32, 15) as usize
    } else {
        DIGITS
    };
    rounded(x, digits)
}

/// An interval "[7.81e4, 1.17e5]": both ends in one form (exponent form for both when
/// either needs it), to [`UNCERTAIN`] digits, or more where the interval is narrow: as many
/// as show its width to two digits, and a value's [`DIGITS`] for a zero width. Three digits
/// made [70447.5, 70447.5] read "[70400, 70400]" beside its value "70450".
pub fn interval(lo: f64, hi: f64) -> String {
    let digits = interval_digits(lo, hi);
    let (a, b) = (rounded(lo, digits), rounded(hi, digits));
    if a.contains('e') == b.contains('e') || !lo.is_finite() || !hi.is_finite() {
        return format!("[{a}, {b}]");
    }
    let e = |x: f64| format!("{:.*e}", digits - 1, x);
    format!("[{}, {}]", e(lo), e(hi))
}

/// The significant digits of [`interval`]'s ends.
fn interval_digits(lo: f64, hi: f64) -> usize {
    let mag = |v: f64| v.abs().log10().floor() as i32;
    let (top, width) = (lo.abs().max(hi.abs()), hi - lo);
    if !top.is_finite() || !width.is_finite() || top == 0.0 {
        return UNCERTAIN;
    }
    if width <= 0.0 {
        return DIGITS;
    }
    (mag(top) - mag(width) + 2).clamp(UNCERTAIN as i32, 15) as usize
}

/// The unit a quantity in `si` units is shown in, and the factor to it: lengths in mm,
/// masses in g, times in ms (as the readout and the charts show them); others as they are.
pub fn screen_unit(si: &str) -> (&str, f64) {
    match si {
        "m" => ("mm", 1e3),
        "kg" => ("g", 1e3),
        "s" => ("ms", 1e3),
        "J" => ("mJ", 1e3),
        other => (other, 1.0),
    }
}

/// How far `model` is from `measured`, in percent of `measured`: "+0.1%", "-3.7%", "+209%".
pub fn percent_diff(model: f64, measured: f64) -> String {
    let p = 100.0 * (model - measured) / measured;
    if !p.is_finite() {
        return "—".into();
    }
    let s = if p.abs() < 9.95 {
        format!("{p:+.1}%")
    } else {
        format!("{p:+.0}%")
    };
    if s == "-0.0%" { "+0.0%".into() } else { s }
}

/// `text` in lines of at most `width` characters, broken at spaces; a word longer than a line
/// (a path) is broken where the line ends, so nothing is cut off.
pub fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.last_mut().expect("one line at least");
        let n = last.chars().count();
        if n > 0 && n + 1 + word.chars().count() <= width {
            last.push(' ');
            last.push_str(word);
            continue;
        }
        if n > 0 {
            lines.push(String::new());
        }
        let chars: Vec<char> = word.chars().collect();
        for (i, piece) in chars.chunks(width).enumerate() {
            if i > 0 {
                lines.push(String::new());
            }
            lines.last_mut().expect("a line").extend(piece);
        }
    }
    lines
}

/// `text` in at most `width` characters (a terminal cell each): whole, or its whole words
/// from the left and "…" — never cut inside a word (issue 51 item 6): words end at a space or
/// after a hyphen ("table-…"), and a bracketed unit is part of its word, so "[ms" never shows.
/// Only "…" when not even the first word fits; nothing at width 0. The one place the
/// explorer shortens a text: chart titles ([`crate::tui::widgets::title::fit`]), the picker,
/// the pin table.
pub fn clip(text: &str, width: usize) -> String {
    if text.chars().count() <= width {
        return text.to_string();
    }
    if width == 0 {
        return String::new();
    }
    // the ends of words: before each space, after each hyphen
    let chars: Vec<char> = text.chars().collect();
    let ends = (1..chars.len()).filter(|&i| chars[i] == ' ' || chars[i - 1] == '-');
    // room for the ellipsis after the words
    let end = ends.take_while(|&i| i < width).last().unwrap_or(0);
    let mut out: String = chars[..end].iter().collect();
    out.truncate(out.trim_end().len());
    out + "…"
}

/// `lines` fitted to `width` columns without breaking a value: a line too long breaks
/// between its fields (two spaces apart), else at its last space that fits; the rest goes
/// on the next line, indented two columns past the line's own indent. A single word wider
/// than `width` is left to the paragraph's wrap.
pub fn fit_lines(lines: Vec<Line<'static>>, width: usize) -> Vec<Line<'static>> {
    let mut out = Vec::new();
    for line in lines {
        let mut cells = cells_of(&line);
        let indent = cells.iter().take_while(|c| c.0 == ' ').count();
        while cells.len() > width {
            let Some(cut) = break_at(&cells, width, indent) else {
                break;
            };
            let rest: Vec<(char, Style)> = cells[cut..]
                .iter()
                .skip_while(|c| c.0 == ' ')
                .copied()
                .collect();
            cells.truncate(cut);
            while cells.last().is_some_and(|c| c.0 == ' ') {
                cells.pop();
            }
            out.push(spans_of(&cells));
            let pad = (' ', Style::default());
            cells = std::iter::repeat_n(pad, indent + 2).chain(rest).collect();
        }
        out.push(spans_of(&cells));
    }
    out
}

/// Where to break `cells` to fit `width`: the last field gap ("  ") that fits, else the last
/// space after a comma (between list items: "c_s 5 kg/s" stays whole), else the last space;
/// never inside the indent.
fn break_at(cells: &[(char, Style)], width: usize, indent: usize) -> Option<usize> {
    let is = |i: usize, ch: char| cells.get(i).is_some_and(|c| c.0 == ch);
    let fits = (indent + 1..=width.min(cells.len())).rev();
    let word_end = |i: usize| is(i, ' ') && !is(i - 1, ' ');
    fits.clone()
        .find(|&i| word_end(i) && is(i + 1, ' '))
        .or_else(|| fits.clone().find(|&i| word_end(i) && is(i - 1, ',')))
        .or_else(|| fits.clone().find(|&i| word_end(i)))
}

/// `line`'s characters, each with its style (the line's patched by its span's).
pub(crate) fn cells_of(line: &Line) -> Vec<(char, Style)> {
    line.spans
        .iter()
        .flat_map(|s| {
            s.content
                .chars()
                .map(move |c| (c, line.style.patch(s.style)))
        })
        .collect()
}

/// A line from styled characters, one span per run of one style.
pub(crate) fn spans_of(cells: &[(char, Style)]) -> Line<'static> {
    let mut spans: Vec<Span<'static>> = Vec::new();
    for &(c, style) in cells {
        match spans.last_mut() {
            Some(s) if s.style == style => s.content.to_mut().push(c),
            _ => spans.push(Span::styled(c.to_string(), style)),
        }
    }
    Line::from(spans)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrapping_breaks_at_spaces_and_inside_overlong_words() {
        assert_eq!(wrap("ab cd ef", 5), ["ab cd", "ef"]);
        assert_eq!(
            wrap("a /very/long/path b", 6),
            ["a", "/very/", "long/p", "ath b"]
        );
        assert_eq!(wrap("", 4), [""]);
    }

    #[test]
    fn one_number_format() {
        assert_eq!(value(140.0), "140.0");
        assert_eq!(value(54500.0), "54500");
        assert_eq!(value(78094.0), "78090");
        assert_eq!(value(1.17e5), "1.170e5");
        assert_eq!(value(5e6), "5.000e6");
        assert_eq!(value(f64::NAN), "—");
        assert_eq!(interval(78094.0, 1.17e5), "[7.81e4, 1.17e5]");
        assert_eq!(interval(0.25, 0.5), "[0.250, 0.500]");
        // a narrow interval keeps the digits that tell its ends apart, and a zero-width one
        // (an exact fit with no residual) reads as its value does
        assert_eq!(interval(70350.2, 70546.1), "[70350, 70550]");
        assert_eq!(interval(70447.53, 70447.53), "[70450, 70450]");
        assert_eq!(value(70447.53), "70450");
        assert_eq!(interval(1.23456e6, 1.23466e6), "[1.23456e6, 1.23466e6]");
        assert_eq!(stepped(1000.01, 0.01), "1000.01");
        assert_eq!(stepped(1000.0, 0.01), "1000.00");
        assert_eq!(stepped(3.12, 0.1), "3.120");
        assert_eq!(screen_unit("m"), ("mm", 1e3));
        assert_eq!(screen_unit("N/m"), ("N/m", 1.0));
    }

    #[test]
    fn names_are_cut_with_an_ellipsis() {
        assert_eq!(clip("superball", 9), "superball");
        assert_eq!(clip("golf", 0), "");
        // never inside a word (issue 51 item 6: the picker showed "hollow rubber ba")
        assert_eq!(clip("superball", 8), "…");
        assert_eq!(clip("p1 superball λ 1.3", 14), "p1 superball…");
        assert_eq!(clip("p1 superball λ 1.3", 12), "p1…");
        assert_eq!(clip("table-tennis ball", 10), "table-…");
        assert_eq!(clip("a  b c", 4), "a…");
        for w in 0..20 {
            assert!(clip("p1 superball λ 1.3", w).chars().count() <= w, "{w}");
        }
    }

    fn texts(lines: &[Line]) -> Vec<String> {
        lines.iter().map(|l| l.to_string()).collect()
    }

    #[test]
    fn lines_break_between_fields_never_inside_a_value() {
        let lines = vec![Line::raw(" energy mJ in 1.870e-29  out 1.053e-29")];
        assert_eq!(
            texts(&fit_lines(lines, 32)),
            [" energy mJ in 1.870e-29", "   out 1.053e-29"]
        );
        // no field gap that fits: the last space that does
        let lines = vec![Line::raw(" measured at v0 = 3.12 m/s: not compared")];
        assert_eq!(
            texts(&fit_lines(lines, 34)),
            [" measured at v0 = 3.12 m/s: not", "   compared"]
        );
        // a list breaks after a comma, keeping each item whole
        let lines = vec![Line::raw(" pair: M 0.3 kg, K_s 40000 N/m, c_s 5 kg/s")];
        assert_eq!(
            texts(&fit_lines(lines, 38)),
            [" pair: M 0.3 kg, K_s 40000 N/m,", "   c_s 5 kg/s"]
        );
        // a line that fits is kept as it is, styles and all
        let styled = Line::from(vec![
            Span::raw(" a"),
            Span::styled(" b", Style::new().bold()),
        ]);
        assert_eq!(fit_lines(vec![styled.clone()], 10), [styled]);
        // a word wider than the width is left whole for the paragraph to wrap
        assert_eq!(
            texts(&fit_lines(vec![Line::raw(" 1.053e-29")], 4)),
            [" 1.053e-29"]
        );
    }

    #[test]
    fn percentages() {
        assert_eq!(percent_diff(0.7506, 0.75), "+0.1%");
        assert_eq!(percent_diff(117.3, 121.8), "-3.7%");
        assert_eq!(percent_diff(376.1, 121.8), "+209%");
        assert_eq!(percent_diff(1.0, 0.0), "—");
        assert_eq!(percent_diff(0.9999999, 1.0), "+0.0%");
    }
}
