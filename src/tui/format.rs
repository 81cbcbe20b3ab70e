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

/// A tick label for a value on an axis whose ticks are `step` apart.
pub fn tick(x: f64, step: f64) -> String {
    if !(x.is_finite() && step.is_finite() && step > 0.0) {
        return "—".into();
    }
    let decimals = (-step.log10().floor()).max(0.0) as usize;
    // the step may need one more digit (0.25)
    let decimals = if ((step * 10f64.powi(decimals as i32)).round()
        - step * 10f64.powi(decimals as i32))
    .abs()
        > 1e-9
    {
        decimals + 1
    } else {
        decimals
    };
    let s = format!("{x:.decimals$}");
    if s.starts_with('-') && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s[1..].to_string()
    } else {
        s
    }
}

/// Smallest of 1, 2, 2.5, 5 × 10^k not below `x`; 1 for a non-positive or non-finite `x`.
pub fn nice_ceil(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let p = 10f64.powf(x.log10().floor());
    [1.0, 2.0, 2.5, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&v| v >= x * (1.0 - 1e-12))
        .unwrap_or(10.0 * p)
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

    #[test]
    fn nice_ceilings() {
        assert_eq!(nice_ceil(1.3), 2.0);
        assert_eq!(nice_ceil(2.2), 2.5);
        assert_eq!(nice_ceil(14.5), 20.0);
        assert_eq!(nice_ceil(50.0), 50.0);
        assert_eq!(nice_ceil(0.0), 1.0);
    }

    #[test]
    fn ticks() {
        assert_eq!(tick(0.5, 0.25), "0.50");
        assert_eq!(tick(0.75, 0.25), "0.75");
        assert_eq!(tick(40.0, 20.0), "40");
        assert_eq!(tick(1.0, 0.2), "1.0");
        assert_eq!(tick(-0.0, 0.5), "0.0");
    }
}
