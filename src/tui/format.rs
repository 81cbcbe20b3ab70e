//! Number formatting for the screen: never prints NaN or inf.

/// `x` to `n` significant digits; scientific (`5.45e5`) outside 1e-4 … 1e5; "—" when not finite.
pub fn sig(x: f64, n: usize) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let n = n.max(1);
    let e = x.abs().log10().floor() as i32;
    if !(-4..5).contains(&e) {
        return format!("{:.*e}", n - 1, x);
    }
    let decimals = (n as i32 - 1 - e).max(0) as usize;
    format!("{x:.decimals$}")
}

/// Like [`sig`], without trailing zeros after the decimal point ("3.000" → "3").
pub fn sig_trim(x: f64, n: usize) -> String {
    let s = sig(x, n);
    if s.contains('e') || !s.contains('.') {
        return s;
    }
    s.trim_end_matches('0').trim_end_matches('.').to_string()
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(sig(0.75056, 4), "0.7506");
        assert_eq!(sig(117.34, 4), "117.3");
        assert_eq!(sig(54500.0, 3), "54500");
        assert_eq!(sig(5.6e5, 3), "5.60e5");
        assert_eq!(sig(f64::NAN, 3), "—");
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig_trim(3.0, 4), "3");
        assert_eq!(sig_trim(0.75, 4), "0.75");
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
