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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percentages() {
        assert_eq!(percent_diff(0.7506, 0.75), "+0.1%");
        assert_eq!(percent_diff(117.3, 121.8), "-3.7%");
        assert_eq!(percent_diff(376.1, 121.8), "+209%");
        assert_eq!(percent_diff(1.0, 0.0), "—");
        assert_eq!(percent_diff(0.9999999, 1.0), "+0.0%");
    }
}
