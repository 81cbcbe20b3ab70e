//! Reading a number typed by a user (the command line, the explorer's fields): what
//! `str::parse::<f64>` does, with three differences that keep the outputs honest
//! (tests/cli/cli_guarantees.rs, `numbers_are_read_as_typed`):
//!
//! - `-0` is read as `0`: a negative zero would otherwise reach the CSV and JSON as `-0`;
//! - a literal that is not zero but rounds to zero (`1e-400`) is refused, and so is one that
//!   rounds to a subnormal (`1e-320`, held to fewer digits than typed): neither is silently
//!   replaced, also where no range check would catch it (`--spin`, `--friction`, a spread;
//!   issue 54 item 7, tests/cli/numbers_as_typed.rs);
//! - `inf`, `-inf` and `nan` are numbers (the range checks then refuse them, naming the
//!   field); the arguments that use this parser also set `allow_hyphen_values`, so clap does
//!   not take `-inf` for an option.

/// Why a text is not read as a number ([`read`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refused {
    /// Not a decimal literal (nor `inf`, `nan`).
    NotANumber,
    /// A literal that is not zero but rounds to zero (`1e-400`).
    RoundsToZero,
    /// A literal that rounds to a subnormal (`1e-320`): below f64::MIN_POSITIVE ≈ 2.2e-308
    /// a number keeps fewer than 16 digits.
    Subnormal,
}

/// The number `text` (trimmed) holds, by the rules of this module: one reader for the command
/// line, the explorer and measured-data files (`measured::table`), so that `1e-400` is refused
/// alike everywhere (tests/analysis/measured_readers.rs, `numbers_in_files_are_read_as_arguments_are`).
pub fn read(text: &str) -> Result<f64, Refused> {
    let t = text.trim();
    let x: f64 = t.parse().map_err(|_| Refused::NotANumber)?;
    if x == 0.0 && !x.is_nan() {
        if has_nonzero_digit(t) {
            return Err(Refused::RoundsToZero);
        }
        return Ok(0.0);
    }
    if x.is_subnormal() {
        return Err(Refused::Subnormal);
    }
    Ok(x)
}

/// What is wrong with `shown` (the text as the message shows it) when [`read`] refused it.
pub fn refusal(shown: &str, why: Refused) -> String {
    match why {
        Refused::NotANumber => format!("'{shown}' is not a number"),
        Refused::RoundsToZero => format!(
            "{shown} is too small: it rounds to 0 (numbers below about 1e-308 cannot be held)"
        ),
        Refused::Subnormal => format!(
            "{shown} is too small: below about 2.2e-308 a number is not held to the digits typed"
        ),
    }
}

/// A value parser for clap: `#[arg(value_parser = number, allow_hyphen_values = true)]`.
pub fn number(text: &str) -> Result<f64, String> {
    read(text).map_err(|why| match why {
        Refused::NotANumber => refusal(&crate::sanitize::line(text), why),
        Refused::RoundsToZero | Refused::Subnormal => refusal(text.trim(), why),
    })
}

/// Largest count [`count`] reads: 2^53, the last whole number every larger one is not exactly
/// held as (a command's own cap, e.g. `mc`'s samples, is far below and named by the command).
const MAX_COUNT: f64 = 9_007_199_254_740_992.0;

/// A value parser for a count (`--samples`): a whole number, written plainly or in scientific
/// notation (`10000`, `1e7`, `2.5e3`: a scientific tool's counts are typed so; docs/guarantees.md
/// runs `mc --samples 1e7`). Refused, saying what a count is: a fraction (`1.5e0`), a negative
/// number, inf, nan, text. `--samples -inf` and `1e2` said "invalid digit found in string"
/// (issue 52's trial; tests/cli/issue52_trial.rs).
pub fn count(text: &str) -> Result<usize, String> {
    let shown = crate::sanitize::line(text);
    let what = "a whole number ≥ 0, e.g. 10000 or 1e4";
    let x = read(text).map_err(|why| format!("{}; a count is {what}", refusal(&shown, why)))?;
    if !x.is_finite() || x < 0.0 || x.fract() != 0.0 {
        return Err(format!("{shown} is not a count ({what})"));
    }
    if x > MAX_COUNT {
        return Err(format!("{shown} is too large to count (at most 2^53)"));
    }
    Ok(x as usize)
}

/// Whether the mantissa of a decimal literal (before any exponent) has a digit other than 0.
fn has_nonzero_digit(t: &str) -> bool {
    t.chars()
        .take_while(|c| !matches!(c, 'e' | 'E'))
        .any(|c| c.is_ascii_digit() && c != '0')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_take_whole_numbers_plain_or_scientific() {
        assert_eq!(count("10000"), Ok(10_000));
        assert_eq!(count("1e7"), Ok(10_000_000));
        assert_eq!(count("2.5e3"), Ok(2_500));
        assert_eq!(count("0"), Ok(0));
        for bad in [
            "1.5e0", "-1", "-inf", "inf", "nan", "1e300", "ten", "1e-400",
        ] {
            let e = count(bad).unwrap_err();
            assert!(e.starts_with(&format!("{bad} ")) || e.starts_with(&format!("'{bad}'")));
        }
        assert!(count("1.5e0").unwrap_err().contains("whole number"));
        assert!(count("1e300").unwrap_err().contains("too large"));
    }

    #[test]
    fn zeros_underflow_and_infinities() {
        assert_eq!(number("-0").unwrap().to_bits(), 0f64.to_bits());
        assert_eq!(number("-0.0e5").unwrap().to_bits(), 0f64.to_bits());
        assert_eq!(number("0").unwrap(), 0.0);
        assert!(number("1e-400").unwrap_err().contains("rounds to 0"));
        assert!(number("-5e-999").unwrap_err().contains("rounds to 0"));
        assert!(number("1e-320").unwrap_err().contains("too small"));
        assert!(number("-2.2e-308").unwrap_err().contains("too small"));
        assert_eq!(number("2.3e-308").unwrap(), 2.3e-308);
        assert_eq!(number("-inf").unwrap(), f64::NEG_INFINITY);
        assert!(number("nan").unwrap().is_nan());
        assert!(number("abc").is_err());
    }
}
