//! The 95 % intervals of an answer on a fitted preset, as text lines
//! (`COR 0.4610 (95 %: 0.444 … 0.478)`; docs/fitting.md, "Prediction intervals").

use super::output::human;
use crate::api::Intervals;
use std::io::{self, Write};

/// `name value (95 %: lo … hi) unit`, the value to 4 significant digits and the bounds to 3,
/// after scaling SI by `scale`.
pub fn line(name: &str, value: f64, ci: [f64; 2], scale: f64, unit: &str) -> String {
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    format!(
        "{name} {}{unit} (95 %: {} … {}{unit})",
        human(value * scale, 4),
        human(ci[0] * scale, 3),
        human(ci[1] * scale, 3)
    )
}

/// The intervals of one run (COR, peak force in N, contact time in ms), indented, after a
/// line naming where they come from.
pub fn write(out: &mut dyn Write, i: &Intervals, values: [f64; 3], dof: u32) -> io::Result<()> {
    writeln!(
        out,
        "  95 % intervals from the preset's fit (delta method, Student t, {dof} dof):"
    )?;
    writeln!(out, "  {}", line("COR", values[0], i.cor_ci95, 1.0, ""))?;
    writeln!(
        out,
        "  {}",
        line("peak force", values[1], i.max_force_ci95, 1.0, "N")
    )?;
    if let Some(ci) = i.contact_time_ci95 {
        writeln!(out, "  {}", line("contact time", values[2], ci, 1e3, "ms"))?;
    }
    Ok(())
}

/// The CSV columns of one answer's intervals (`sweep velocity`'s rows, `run`'s row), each
/// JSON `…_ci95` pair as `…_ci95_lo`, `…_ci95_hi`.
pub const CSV_COLUMNS: [&str; 6] = [
    "cor_ci95_lo",
    "cor_ci95_hi",
    "max_force_ci95_lo",
    "max_force_ci95_hi",
    "contact_time_ci95_lo",
    "contact_time_ci95_hi",
];

/// The cells of [`CSV_COLUMNS`] (the contact time's empty without a rebound).
pub fn csv_cells(i: &Intervals) -> [String; 6] {
    use super::output::{num, opt_num};
    let ct = i.contact_time_ci95;
    [
        num(i.cor_ci95[0]),
        num(i.cor_ci95[1]),
        num(i.max_force_ci95[0]),
        num(i.max_force_ci95[1]),
        opt_num(ct.map(|c| c[0])),
        opt_num(ct.map(|c| c[1])),
    ]
}
