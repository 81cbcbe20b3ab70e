//! Number formatting for the screen: never prints NaN or inf.

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
    fn percentages() {
        assert_eq!(percent_diff(0.7506, 0.75), "+0.1%");
        assert_eq!(percent_diff(117.3, 121.8), "-3.7%");
        assert_eq!(percent_diff(376.1, 121.8), "+209%");
        assert_eq!(percent_diff(1.0, 0.0), "—");
        assert_eq!(percent_diff(0.9999999, 1.0), "+0.0%");
    }
}
