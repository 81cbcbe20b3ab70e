//! The `[fit]` table a fitted preset carries (`fit … --save`, docs/fitting.md "Prediction
//! intervals"): which parameters the fit moved, their values, their covariance (SI units, the
//! fit's cov = s² (JᵀJ)⁻¹ carried from ln p to p by the delta method), the degrees of freedom
//! of its residual variance and that residual's standard deviation. With it every answer on
//! the preset can carry a 95 % interval (`crate::api::intervals`).

use super::error::Bad;
use super::{Adopted, Preset};
use crate::analysis::fit::Param;
use crate::text::number;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// A fit's uncertainty, as the preset stores it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitTable {
    /// The free parameters' names, as `--free` takes them: `k_p`, `c`, `k_r`, `z_p`, `k_h`.
    pub free: Vec<String>,
    /// Their fitted values, SI, in the order of `free` (the `[adopted]` values they set).
    pub values: Vec<f64>,
    /// Their covariance matrix, SI², one row per parameter of `free`.
    pub covariance: Vec<Vec<f64>>,
    /// Degrees of freedom of the residual variance (data points − quantities fitted).
    pub dof: u32,
    /// The residual standard deviation s of the fit (N for a trace, COR for a table).
    pub residual_sd: f64,
}

impl FitTable {
    /// The free parameters, parsed (the check has made sure they parse).
    pub fn params(&self) -> Vec<Param> {
        self.free.iter().filter_map(|n| Param::parse(n)).collect()
    }

    /// `[fit]` as TOML, numbers in their round-trip form.
    pub(super) fn write(&self, out: &mut String) {
        let list = |v: &[f64]| {
            let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
            format!("[{}]", items.join(", "))
        };
        let names: Vec<String> = self.free.iter().map(|n| format!("{n:?}")).collect();
        out.push_str("\n[fit]\n");
        let _ = writeln!(out, "free = [{}]", names.join(", "));
        let _ = writeln!(out, "values = {}", list(&self.values));
        out.push_str("covariance = [\n");
        for row in &self.covariance {
            let _ = writeln!(out, "    {},", list(row));
        }
        out.push_str("]\n");
        let _ = writeln!(out, "dof = {}", self.dof);
        let _ = writeln!(out, "residual_sd = {:?}", self.residual_sd);
    }
}

fn bad(key: &'static str, message: String) -> Bad {
    Bad {
        table: "fit",
        layer: None,
        key,
        message,
    }
}

/// Known and distinct names, one value and one covariance row each, the values those of
/// `[adopted]` (to 1e-12: the table describes this ball), a symmetric covariance with a
/// non-negative diagonal, at least one degree of freedom, a finite residual sd.
pub(super) fn check(p: &Preset) -> Result<(), Bad> {
    let Some(f) = &p.fit else { return Ok(()) };
    let n = f.free.len();
    let mut seen = Vec::new();
    for name in &f.free {
        match Param::parse(name) {
            // the impact speed a trace's fit can free is the measurement's, not the ball's
            Some(Param::V0) => {
                return Err(bad(
                    "free",
                    "v0 is a measurement's speed, not the ball's: not in a preset's fit".into(),
                ));
            }
            Some(q) if !seen.contains(&q) => seen.push(q),
            Some(_) => return Err(bad("free", format!("names {name} twice"))),
            None => {
                return Err(bad(
                    "free",
                    format!("unknown parameter {name:?}, expected k_p, c, k_r, z_p or k_h"),
                ));
            }
        }
    }
    if n == 0 {
        return Err(bad("free", "names no parameter".into()));
    }
    if f.values.len() != n {
        let msg = format!("holds {} values for {n} free parameters", f.values.len());
        return Err(bad("values", msg));
    }
    for (q, &v) in seen.iter().zip(&f.values) {
        let own = adopted(&p.adopted, *q);
        if !(v.is_finite() && v > 0.0 && (v - own).abs() <= 1e-12 * own.abs()) {
            let msg = format!(
                "{} = {} is not the preset's {} ({})",
                q.name(),
                number(v),
                q.name(),
                number(own)
            );
            return Err(bad("values", msg));
        }
    }
    covariance(&f.covariance, n)?;
    widths(&f.covariance, &seen, &f.values)?;
    if f.dof == 0 {
        return Err(bad("dof", "must be at least 1".into()));
    }
    if !(f.residual_sd.is_finite() && f.residual_sd >= 0.0) {
        let msg = format!(
            "must be finite and not negative, got {}",
            number(f.residual_sd)
        );
        return Err(bad("residual_sd", msg));
    }
    Ok(())
}

/// The value of `q` in the adopted set (K_h by Eq. 16).
fn adopted(a: &Adopted, q: Param) -> f64 {
    let nan = f64::NAN;
    match q {
        Param::KP => a.k_p.unwrap_or(nan),
        Param::C => a.damping.unwrap_or(nan),
        Param::KR => a.k_r,
        Param::ZP => a.z_p.unwrap_or(nan),
        Param::KH => crate::model::params::ImpactParams::k_h_matching(
            a.k_p.unwrap_or(nan),
            a.z_p.unwrap_or(nan),
        ),
        // refused by `check` before it asks
        Param::V0 => nan,
    }
}

/// The widest a parameter's standard deviation may be in a `[fit]` table, as a multiple of its
/// value. A fit exits 0, and `--save` writes its table, only when each 95 % interval spans at
/// most a factor 100 (`fit::verdict::PIN_RATIO`): 2·t·se ≤ ln 100 in ln p, so se ≤ 1.17 and
/// the saved relative standard deviation (p·se, the delta method) is at most 1.17. A table
/// wider than 100 was not written by a fit, and its intervals mean nothing (a COR of ±7e144
/// once: issue 54 item 8, tests/analysis/intervals_physical.rs).
pub const MAX_RELATIVE_SD: f64 = 100.0;

/// Each parameter's standard deviation within [`MAX_RELATIVE_SD`] of its value.
fn widths(c: &[Vec<f64>], names: &[Param], values: &[f64]) -> Result<(), Bad> {
    for (i, (q, &v)) in names.iter().zip(values).enumerate() {
        let sd = c[i][i].sqrt();
        if sd > MAX_RELATIVE_SD * v {
            let msg = format!(
                "diagonal {}: the standard deviation {} of {} = {} is more than {} times its \
                 value: no interval drawn from it means anything (fit --save writes none this \
                 wide)",
                i + 1,
                number(sd),
                q.name(),
                number(v),
                MAX_RELATIVE_SD
            );
            return Err(bad("covariance", msg));
        }
    }
    Ok(())
}

fn covariance(c: &[Vec<f64>], n: usize) -> Result<(), Bad> {
    if c.len() != n || c.iter().any(|row| row.len() != n) {
        return Err(bad(
            "covariance",
            format!("must be {n} rows of {n} numbers"),
        ));
    }
    for i in 0..n {
        if !(c[i][i].is_finite() && c[i][i] >= 0.0) {
            let msg = format!("diagonal {} is {}: a variance", i + 1, number(c[i][i]));
            return Err(bad("covariance", msg));
        }
        for j in 0..i {
            let (a, b) = (c[i][j], c[j][i]);
            let scale = (c[i][i] * c[j][j]).sqrt();
            if !(a.is_finite() && (a - b).abs() <= 1e-9 * scale && a.abs() <= scale * (1.0 + 1e-9))
            {
                let msg = format!(
                    "row {}, column {}: {} must equal its mirror {} and lie within ±√(var·var)",
                    i + 1,
                    j + 1,
                    number(a),
                    number(b)
                );
                return Err(bad("covariance", msg));
            }
        }
    }
    Ok(())
}
