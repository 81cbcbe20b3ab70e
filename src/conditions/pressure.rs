//! A pressure as users type it: a number and an optional unit, `0.8bar`, `8psi`, `55kPa`,
//! `101325` (pascals when bare). One reader for the command line, the explorer and Python.
//!
//! The units are exact by definition: 1 bar = 10⁵ Pa, 1 atm = 101 325 Pa, 1 psi = one
//! pound-force (0.453 592 37 kg × 9.806 65 m/s²) per square inch (0.0254² m²)
//! = 6 894.757 293 168 361 Pa (NIST SP 811, B.8).

/// Pascals in one pound-force per square inch (NIST SP 811, B.8; exact from the pound's and
/// the inch's definitions and standard gravity).
pub const PSI: f64 = 0.453_592_37 * 9.806_65 / (0.0254 * 0.0254);

/// The units a pressure may carry, with their size in pascals. Matched case-insensitively,
/// longest first (`kpa` before `pa`).
const UNITS: [(&str, f64); 8] = [
    ("mbar", 100.0),
    ("hpa", 100.0),
    ("kpa", 1e3),
    ("mpa", 1e6),
    ("bar", 1e5),
    ("psi", PSI),
    ("atm", super::STANDARD_ATMOSPHERE),
    ("pa", 1.0),
];

/// The pressure `text` holds, in pascals: a number (read as every number a user types is,
/// `text::parse::read`) and an optional unit from `Pa, hPa, kPa, MPa, mbar, bar, psi, atm`,
/// with or without a space between. `field` names the flag in the message.
pub fn parse(field: &str, text: &str) -> Result<f64, String> {
    let (x, scale, shown) = super::with_unit(field, text, &UNITS)?;
    if !x.is_finite() {
        return Err(format!(
            "invalid {field}: {shown} (must be a finite pressure)"
        ));
    }
    Ok(x * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_are_read() {
        assert_eq!(parse("pressure", "0.8bar").unwrap(), 80_000.0);
        assert_eq!(parse("pressure", "55kPa").unwrap(), 55_000.0);
        assert_eq!(parse("pressure", "55 kpa").unwrap(), 55_000.0);
        assert_eq!(parse("pressure", "55000").unwrap(), 55_000.0);
        assert_eq!(parse("pressure", "55000Pa").unwrap(), 55_000.0);
        assert_eq!(parse("pressure", "300mbar").unwrap(), 30_000.0);
        assert_eq!(parse("pressure", "1atm").unwrap(), 101_325.0);
        // 8 psi = 55.158 kPa (NIST SP 811: 1 psi = 6.894 757 kPa)
        let p = parse("pressure", "8psi").unwrap();
        assert!((p - 55_158.058_345_3).abs() < 1e-6, "{p}");
        assert!((PSI - 6_894.757_293_168_361).abs() < 1e-9);
    }

    #[test]
    fn bad_pressures_name_the_field() {
        for bad in [
            "",
            "bar",
            "0.8 bars",
            "x8psi",
            "inf",
            "nan bar",
            "1e-400kPa",
        ] {
            let e = parse("pressure", bad).unwrap_err();
            assert!(e.starts_with("invalid pressure: "), "{bad}: {e}");
        }
        // a negative gauge pressure is a number here; the ball's checks judge it
        assert_eq!(parse("pressure", "-1psi").unwrap(), -PSI);
    }
}
