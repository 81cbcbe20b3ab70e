//! A time as users type it: a number and an optional unit, `72h`, `30d`, `90min`, `3600`
//! (seconds when bare). The twin of [`super::pressure::parse`], read by the same number
//! reader; written by hand because the crates that read durations (humantime) take whole
//! numbers only ("1.5h" is refused) and would be a new dependency for four suffixes.

/// The units a time may carry, with their size in seconds, longest first so that `min` is
/// matched before `s`'s neighbours. 1 d = 86 400 s, 1 h = 3 600 s, 1 min = 60 s (SI Brochure,
/// 9th ed., Table 8: non-SI units accepted for use with the SI).
const UNITS: [(&str, f64); 9] = [
    ("days", 86_400.0),
    ("day", 86_400.0),
    ("min", 60.0),
    ("h", 3_600.0),
    ("d", 86_400.0),
    ("w", 604_800.0),
    ("m", 60.0),
    ("s", 1.0),
    ("", 1.0),
];

/// The time `text` holds, in seconds: a number and an optional unit (`s`, `m`/`min`, `h`,
/// `d`/`day`/`days`, `w`), with or without a space between. Refused, naming `field`: no
/// number, a negative or non-finite time.
pub fn parse(field: &str, text: &str) -> Result<f64, String> {
    let (x, scale, shown) = super::with_unit(field, text, &UNITS)?;
    let seconds = x * scale;
    if !seconds.is_finite() || seconds < 0.0 {
        return Err(format!(
            "invalid {field}: {shown} (must be a finite time ≥ 0: 72h, 30d, 90min, or seconds)"
        ));
    }
    Ok(seconds)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_read() {
        assert_eq!(parse("after", "72h").unwrap(), 259_200.0);
        assert_eq!(parse("after", "72 h").unwrap(), 259_200.0);
        assert_eq!(parse("after", "30d").unwrap(), 2_592_000.0);
        assert_eq!(parse("after", "2days").unwrap(), 172_800.0);
        assert_eq!(parse("after", "90min").unwrap(), 5_400.0);
        assert_eq!(parse("after", "1.5h").unwrap(), 5_400.0);
        assert_eq!(parse("after", "3600").unwrap(), 3_600.0);
        assert_eq!(parse("after", "3600s").unwrap(), 3_600.0);
        assert_eq!(parse("after", "1w").unwrap(), 604_800.0);
        assert_eq!(parse("after", "0").unwrap(), 0.0);
    }

    #[test]
    fn bad_times_name_the_field() {
        for bad in ["", "h", "72hours", "x72h", "-1h", "inf", "nan d", "1e400s"] {
            let e = parse("after", bad).unwrap_err();
            assert!(e.starts_with("invalid after: "), "{bad}: {e}");
        }
    }
}
