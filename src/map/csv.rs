//! The design map as CSV (`bouncelab map --format csv` and the explorer's map export): one row
//! per cell, the numbers as [`crate::text::number`] writes them.

use super::{Cell, Map, Targets};

/// The CSV header of a map: normalized or SI columns, `feasible` with targets.
pub fn header(normalized: bool, targets: bool) -> String {
    let mut h = String::from("lambda,zeta,cor,");
    h.push_str(if normalized {
        "max_force_normalized,contact_time_normalized"
    } else {
        "max_force,contact_time"
    });
    if targets {
        h.push_str(",feasible");
    }
    h.push('\n');
    h
}

/// One row per cell, λ outer, ζ inner (as `sweep zeta`); empty fields where a value does not
/// exist (no rebound: no contact time; no answer: nothing). Each number as `text::number`
/// writes it (shortest round-trip) without a String of its own; the λ rows are formatted on
/// all cores (rayon) and joined in order, the same bytes as one after the other.
pub fn csv(map: &Map, targets: Option<&Targets>) -> String {
    use rayon::prelude::*;
    let n = map.zetas.len().max(1);
    let rows: Vec<String> = map
        .cells()
        .par_chunks(n)
        .zip(&map.lambdas)
        .map(|(row, &lambda)| csv_row(map, targets, lambda, row))
        .collect();
    let mut s = header(map.spec.normalized, targets.is_some());
    s.reserve(rows.iter().map(String::len).sum());
    for row in rows {
        s.push_str(&row);
    }
    s
}

/// The CSV lines of one λ across the ζ axis.
fn csv_row(map: &Map, targets: Option<&Targets>, lambda: f64, row: &[Option<Cell>]) -> String {
    let mut s = String::with_capacity(row.len() * 80);
    for (c, &zeta) in row.iter().zip(&map.zetas) {
        let c = c.unwrap_or(Cell::UNRESOLVED);
        push_num(&mut s, lambda);
        s.push(',');
        push_num(&mut s, zeta);
        for x in [c.cor, c.max_force, c.contact_time.unwrap_or(f64::NAN)] {
            s.push(',');
            if !x.is_nan() {
                push_num(&mut s, x);
            }
        }
        if let Some(t) = targets {
            s.push_str(if t.holds(&c) { ",true" } else { ",false" });
        }
        s.push('\n');
    }
    s
}

/// `text::number(x)` appended to `s`: plain decimals in [1e-4, 1e7) and zero, exponent form
/// outside, `inf`/`-inf` spelled out (a NaN never reaches here).
fn push_num(s: &mut String, x: f64) {
    use std::fmt::Write;
    let _ = if x.is_infinite() || x == 0.0 || (1e-4..1e7).contains(&x.abs()) {
        write!(s, "{x}")
    } else {
        write!(s, "{x:e}")
    };
}

#[cfg(test)]
mod tests {
    /// The CSV's numbers are `text::number`'s, character for character.
    #[test]
    fn push_num_is_number() {
        for x in [
            0.0,
            1e-4,
            9.99e-5,
            1e7,
            9999999.5,
            0.1 + 0.2,
            -3.5e-12,
            1e300,
            f64::INFINITY,
        ] {
            let mut s = String::new();
            super::push_num(&mut s, x);
            assert_eq!(s, crate::text::number(x), "{x}");
        }
    }
}
