//! One axis of a design map: `n` values of λ or ζ from `from` to `to`, evenly spaced in log10
//! (the paper's ζ axes, Figs. 2–3) or linearly, parsed from the command line's `FROM:TO:N`.

use super::MapError;
use crate::model::params::{LAMBDA_MAX, ZETA_MAX};
use serde::Serialize;

/// Most values along one axis: a 4096 × 4096 map would be 16.8 million impacts, far past any
/// work limit; a caller that wants more than a screen's width has made a typo.
pub const MAX_AXIS_POINTS: usize = 4096;

/// Most cells in one map (λ values × ζ values): one million linear-law impacts, the command
/// line's work limit (`cli::budget::LIMIT`).
pub const MAX_CELLS: usize = 1_000_000;

/// How the values of an axis are spaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Scale {
    /// Evenly in log10 (both ends positive).
    Log,
    /// Evenly.
    Linear,
}

/// Which parameter an axis carries; it names the axis in messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Param {
    /// λ = K_r/K_p.
    Lambda,
    /// ζ = √(m K_p)/(2c).
    Zeta,
}

impl Param {
    /// `lambda` or `zeta`, as the command line's flags.
    pub fn name(self) -> &'static str {
        match self {
            Param::Lambda => "lambda",
            Param::Zeta => "zeta",
        }
    }
    fn max(self) -> f64 {
        match self {
            Param::Lambda => LAMBDA_MAX,
            Param::Zeta => ZETA_MAX,
        }
    }
}

/// `n` values of one parameter from `from` to `to` (both included), checked by [`Axis::new`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Axis {
    /// Which parameter the axis varies.
    pub param: Param,
    /// The first value.
    pub from: f64,
    /// The last value (included).
    pub to: f64,
    /// How many values, both ends included.
    pub n: usize,
    /// Evenly spaced in the value (linear) or in its logarithm.
    pub scale: Scale,
}

impl Axis {
    /// An axis, checked: finite ends in the parameter's domain (0 … 1e6; above 0 on a log
    /// axis), `from < to` (or equal with `n = 1`), 1 ≤ n ≤ [`MAX_AXIS_POINTS`].
    pub fn new(param: Param, from: f64, to: f64, n: usize, scale: Scale) -> Result<Axis, MapError> {
        let text = format!(
            "{}:{}:{n}",
            crate::text::number(from),
            crate::text::number(to)
        );
        let bad = |reason: String| MapError::Axis {
            axis: param.name(),
            text: text.clone(),
            reason,
        };
        for (end, v) in [("FROM", from), ("TO", to)] {
            if !v.is_finite() {
                return Err(bad(format!("{end} must be a finite number")));
            }
            if v < 0.0 || v > param.max() {
                return Err(bad(format!("{end} must lie in 0 … 1e6")));
            }
            if scale == Scale::Log && v <= 0.0 {
                return Err(bad(format!(
                    "{end} must be above 0 on a log axis; --linear-axes for a range from 0"
                )));
            }
        }
        if n == 0 || n > MAX_AXIS_POINTS {
            return Err(bad(format!("N must lie in 1 … {MAX_AXIS_POINTS}")));
        }
        if !(from < to || (from == to && n == 1)) {
            return Err(bad(
                "FROM must be below TO (or equal to it with N = 1)".into()
            ));
        }
        Ok(Axis {
            param,
            from,
            to,
            n,
            scale,
        })
    }

    /// `FROM:TO:N` as the command line takes it (each number as `cli::number` reads them:
    /// plain decimals or exponent form).
    pub fn parse(param: Param, text: &str, scale: Scale) -> Result<Axis, MapError> {
        let bad = |reason: &str| MapError::Axis {
            axis: param.name(),
            text: text.to_string(),
            reason: reason.to_string(),
        };
        let parts: Vec<&str> = text.split(':').collect();
        let [from, to, n] = parts[..] else {
            return Err(bad("expected FROM:TO:N, e.g. 0.01:100:200"));
        };
        // `-0` reads as 0, so that no `-0` reaches an output
        let num = |s: &str, what: &str| {
            s.trim()
                .parse::<f64>()
                .map(|x| x + 0.0)
                .map_err(|_| bad(&format!("{what} '{s}' is not a number")))
        };
        let (from, to) = (num(from, "FROM")?, num(to, "TO")?);
        let n: usize = n
            .trim()
            .parse()
            .map_err(|_| bad(&format!("N '{n}' is not a whole number of points")))?;
        Axis::new(param, from, to, n, scale).map_err(|e| match e {
            MapError::Axis { axis, reason, .. } => MapError::Axis {
                axis,
                text: text.to_string(),
                reason,
            },
            e => e,
        })
    }

    /// The i-th value (i < n); the ends are `from` and `to` exactly.
    pub fn value(&self, i: usize) -> f64 {
        if self.n == 1 || i == 0 {
            return self.from;
        }
        if i + 1 == self.n {
            return self.to;
        }
        self.at(i as f64)
    }

    /// All n values.
    pub fn values(&self) -> Vec<f64> {
        (0..self.n).map(|i| self.value(i)).collect()
    }

    /// The value at a fractional index (linear in the axis's own spacing: in log10 on a log
    /// axis), so that contour vertices found between two grid values map back onto the axis.
    pub fn at(&self, index: f64) -> f64 {
        let t = if self.n > 1 {
            index / (self.n - 1) as f64
        } else {
            0.0
        };
        match self.scale {
            Scale::Linear => self.from + (self.to - self.from) * t,
            Scale::Log => {
                let (a, b) = (self.from.log10(), self.to.log10());
                10f64.powf(a + (b - a) * t)
            }
        }
    }

    /// The fractional index of a value (the inverse of [`Axis::at`]); outside 0 … n−1 when the
    /// value is off the axis.
    pub fn index_of(&self, v: f64) -> f64 {
        if self.n == 1 {
            return 0.0;
        }
        let t = match self.scale {
            Scale::Linear => (v - self.from) / (self.to - self.from),
            Scale::Log => (v.log10() - self.from.log10()) / (self.to.log10() - self.from.log10()),
        };
        t * (self.n - 1) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_spaces() {
        let a = Axis::parse(Param::Zeta, "0.01:100:5", Scale::Log).unwrap();
        let want = [0.01, 0.1, 1.0, 10.0, 100.0];
        for (v, w) in a.values().iter().zip(want) {
            assert!((v - w).abs() <= 1e-14 * w, "{v} vs {w}");
        }
        assert_eq!(a.values()[0], 0.01);
        assert_eq!(a.values()[4], 100.0);
        assert!((a.index_of(1.0) - 2.0).abs() < 1e-12);
        let l = Axis::parse(Param::Lambda, "0:2:5", Scale::Linear).unwrap();
        assert_eq!(l.values(), vec![0.0, 0.5, 1.0, 1.5, 2.0]);
    }

    #[test]
    fn hostile_ranges_are_named() {
        let cases = [
            ("0:1:5", Scale::Log, "above 0 on a log axis"),
            ("1:0.5:5", Scale::Linear, "FROM must be below TO"),
            ("1:1:5", Scale::Linear, "FROM must be below TO"),
            ("nan:1:5", Scale::Linear, "finite"),
            ("0:inf:5", Scale::Linear, "finite"),
            ("0:1e7:5", Scale::Linear, "0 … 1e6"),
            ("-1:1:5", Scale::Linear, "0 … 1e6"),
            ("0:1:0", Scale::Linear, "N must lie in 1 … 4096"),
            ("0:1:4097", Scale::Linear, "N must lie in 1 … 4096"),
            ("0:1:1e3", Scale::Linear, "not a whole number"),
            ("0:1", Scale::Linear, "expected FROM:TO:N"),
            ("a:1:3", Scale::Linear, "FROM 'a' is not a number"),
        ];
        for (text, scale, want) in cases {
            let e = Axis::parse(Param::Lambda, text, scale)
                .unwrap_err()
                .to_string();
            assert!(e.starts_with(&format!("invalid lambda: '{text}'")), "{e}");
            assert!(e.contains(want), "{text}: {e}");
        }
        assert!(Axis::parse(Param::Zeta, "0.5:0.5:1", Scale::Log).is_ok());
    }
}
