//! Numbers, CSV fields and I/O errors as text: the one place every output (command line,
//! figures, explorer) takes them from.
//!
//! Numbers come in two kinds. [`number`] is exact: the shortest form that reads back to the
//! same `f64`, for CSV, JSON-adjacent text and messages. The rest round to significant digits
//! through one engine, [`digits`], in the styles the outputs have always used: [`human`] and
//! [`given`] for the command line's text, [`short`] for figure labels, [`sig`] and
//! [`sig_trim`] for the explorer's screen (which never shows NaN or inf). Reading a number
//! typed by a user (command line, explorer) is [`parse::number`].

use std::io;

pub mod parse;

/// A number for messages and CSV: plain decimals in [1e-4, 1e7), exponent notation outside
/// it (so 1e300 is not 301 digits), `inf`/`-inf`/`NaN` spelled out; shortest round-trip form.
pub fn number(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf".into() } else { "-inf".into() }
    } else if x == 0.0 {
        // −0 (a velocity at rest, a rounded trajectory) is written as 0: a zero has no sign
        "0".into()
    } else if (1e-4..1e7).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Which trailing zeros a rounded number drops.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Trim {
    /// None: "3.120", "1.050e6".
    Keep,
    /// Those of plain decimals only: "3.12", "1.050e6".
    Plain,
    /// Those of plain decimals and of an exponent form's mantissa: "3.12", "1.05e6".
    All,
}

/// How [`digits`] writes a number.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// The decimal exponents (of the leading digit) written as plain decimals, `lo..hi`;
    /// exponent form outside.
    pub plain: (i32, i32),
    /// Which trailing zeros are dropped.
    pub trim: Trim,
    /// What a NaN or an infinity reads as; `None`: its [`number`] form ("NaN", "inf").
    pub not_finite: Option<&'static str>,
}

/// The command line's text output: plain from 1e-3 up to 1e6.
pub const HUMAN: Style = Style {
    plain: (-3, 6),
    trim: Trim::Keep,
    not_finite: None,
};
/// Values the user gave, as [`HUMAN`] without trailing zeros.
pub const GIVEN: Style = Style {
    trim: Trim::All,
    ..HUMAN
};
/// Figure labels: plain from 1e-4 up to 1e6, no trailing zeros.
pub const LABEL: Style = Style {
    plain: (-4, 6),
    trim: Trim::All,
    not_finite: None,
};
/// The explorer's screen: plain from 1e-4 up to 1e5, "—" for what is not finite.
pub const SCREEN: Style = Style {
    plain: (-4, 5),
    trim: Trim::Keep,
    not_finite: Some("—"),
};

/// `x` to `sig` significant digits (at least one) in `style`: 0.7502, 121.3, 54500, 1.2e-7.
pub fn digits(x: f64, sig: usize, style: Style) -> String {
    if !x.is_finite() {
        return style.not_finite.map_or_else(|| number(x), str::to_string);
    }
    if x == 0.0 {
        return "0".into();
    }
    let sig = sig.max(1);
    let mag = x.abs().log10().floor() as i32;
    let (lo, hi) = style.plain;
    if !(lo..hi).contains(&mag) {
        let s = format!("{:.*e}", sig - 1, x);
        if style.trim != Trim::All {
            return s;
        }
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        return format!("{}e{exp}", trim_zeros(mantissa));
    }
    let decimals = (sig as i32 - 1 - mag).max(0) as usize;
    let s = format!("{x:.decimals$}");
    match style.trim {
        Trim::Keep => s,
        Trim::Plain | Trim::All => trim_zeros(&s),
    }
}

/// A decimal without the zeros after its last significant digit ("3.000" → "3").
fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// [`digits`] in the [`HUMAN`] style: 0.750, 121.3, 54500, 1.20e7.
pub fn human(x: f64, sig: usize) -> String {
    digits(x, sig, HUMAN)
}

/// [`digits`] in the [`GIVEN`] style: 3.12 m/s, not 3.120.
pub fn given(x: f64, sig: usize) -> String {
    digits(x, sig, GIVEN)
}

/// `x` rounded to `sig` significant digits before it is written, the integer part of a plain
/// number too (13268 to four digits is 13270): the explorer's one number format (its readout
/// and its charts' labels agree; tui::format::value, issue 51 item 4).
pub fn rounded(x: f64, sig: usize) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    let mag = x.abs().log10().floor() as i32;
    let spare = mag + 1 - sig as i32;
    if spare > 0 && mag < 5 {
        let unit = 10f64.powi(spare);
        (x / unit).round() * unit
    } else {
        x
    }
}

/// [`digits`] in the [`LABEL`] style: 0.4, 121.8, 1.05e6.
pub fn short(x: f64, sig: usize) -> String {
    digits(x, sig, LABEL)
}

/// [`digits`] in the [`SCREEN`] style: 0.7506, 5.60e5, "—".
pub fn sig(x: f64, sig: usize) -> String {
    digits(x, sig, SCREEN)
}

/// [`sig`] without trailing zeros after the decimal point ("3.000" → "3").
pub fn sig_trim(x: f64, sig: usize) -> String {
    digits(
        x,
        sig,
        Style {
            trim: Trim::Plain,
            ..SCREEN
        },
    )
}

/// `n` and its noun, singular for one: `counted(1, "ball")` is "1 ball", else "N balls".
///
/// ```
/// assert_eq!(bouncelab::text::counted(1, "ball"), "1 ball");
/// assert_eq!(bouncelab::text::counted(3, "ball"), "3 balls");
/// ```
pub fn counted(n: usize, noun: &str) -> String {
    if n == 1 {
        format!("1 {noun}")
    } else {
        format!("{n} {noun}s")
    }
}

/// One CSV field (RFC 4180): quoted when it holds a comma, quote or line break (a user
/// preset's name could).
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// An I/O error without the "(os error N)" tail.
pub fn io_text(e: &io::Error) -> String {
    let s = e.to_string();
    match s.find(" (os error") {
        Some(i) => s[..i].to_string(),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers() {
        assert_eq!(number(0.75), "0.75");
        assert_eq!(number(1e300), "1e300");
        assert_eq!(number(1.5e-7), "1.5e-7");
        assert_eq!(number(f64::INFINITY), "inf");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(-2.0), "-2");
        assert_eq!(number(-0.0), "0");
    }

    #[test]
    fn command_line_digits() {
        assert_eq!(human(0.750_123, 3), "0.750");
        assert_eq!(human(121.34, 4), "121.3");
        assert_eq!(human(54500.0, 3), "54500");
        assert_eq!(human(1.2e7, 3), "1.20e7");
        assert_eq!(given(3.120, 4), "3.12");
        assert_eq!(given(3e-3 * 1e3, 4), "3");
        assert_eq!(given(1.05e6, 4), "1.05e6");
        assert_eq!(given(54500.0, 4), "54500");
    }

    #[test]
    fn label_digits() {
        assert_eq!(short(0.4, 3), "0.4");
        assert_eq!(short(121.8, 4), "121.8");
        assert_eq!(short(1.05e6, 4), "1.05e6");
        assert_eq!(short(1.2e7, 4), "1.2e7");
        assert_eq!(short(54500.0, 4), "54500");
        assert_eq!(short(3e-3 * 1e3, 3), "3");
        assert_eq!(short(0.0, 3), "0");
    }

    #[test]
    fn screen_digits() {
        assert_eq!(sig(0.75056, 4), "0.7506");
        assert_eq!(sig(117.34, 4), "117.3");
        assert_eq!(sig(54500.0, 3), "54500");
        assert_eq!(sig(5.6e5, 3), "5.60e5");
        assert_eq!(sig(f64::NAN, 3), "—");
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig_trim(3.0, 4), "3");
        assert_eq!(sig_trim(0.75, 4), "0.75");
        // the mantissa of an exponent form keeps its zeros on screen
        assert_eq!(sig_trim(5.6e5, 3), "5.60e5");
    }

    #[test]
    fn csv_quoting() {
        assert_eq!(csv_field("plain"), "plain");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
        assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    }

    #[test]
    fn io_errors_lose_the_os_number() {
        let e = io::Error::from_raw_os_error(2);
        let full = e.to_string();
        let cut = full
            .find(" (os error")
            .expect("an OS error names its number");
        assert_eq!(io_text(&e), full[..cut]);
        assert_eq!(io_text(&io::Error::other("disk full")), "disk full");
    }
}
