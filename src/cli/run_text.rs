//! `bouncelab run --format text`: a readable table, units converted at the edge (N, ms, mm),
//! the measured values beside the model's for a preset.

use super::output::{self, difference, given, human, table};
use crate::api::{Ball, Intervals};
use crate::preset::Measured;
use crate::solver::{EnergyBudget, ImpactResponse, Method};
use std::io::{self, Write};

/// Rows of a downsampled history printed in text mode.
const HISTORY_ROWS: usize = 40;

/// How one quantity is shown: scale from SI and unit (none for the normalized ball).
struct Unit {
    scale: f64,
    name: &'static str,
}

impl Unit {
    fn show(&self, x: f64, sig: usize) -> String {
        self.with(human(x * self.scale, sig))
    }

    /// A value the user gave, without trailing zeros.
    fn given(&self, x: f64) -> String {
        self.with(given(x * self.scale, 6))
    }

    fn with(&self, v: String) -> String {
        if self.name.is_empty() {
            v
        } else {
            format!("{v} {}", self.name)
        }
    }
}

/// The units a run is shown in: N, ms, mm for a preset; none for the normalized ball.
struct Units {
    dimensional: bool,
    force: Unit,
    time: Unit,
    length: Unit,
}

impl Units {
    fn of(b: &Ball) -> Units {
        let dimensional = b.name.is_some();
        let unit = |scale, name| Unit::of(dimensional, scale, name);
        Units {
            dimensional,
            force: unit(1.0, "N"),
            time: unit(1e3, "ms"),
            length: unit(1e3, "mm"),
        }
    }

    fn unit(&self, scale: f64, name: &'static str) -> Unit {
        Unit::of(self.dimensional, scale, name)
    }
}

impl Unit {
    /// `name` at `scale` from SI when `dimensional`, else a bare number.
    fn of(dimensional: bool, scale: f64, name: &'static str) -> Unit {
        if dimensional {
            Unit { scale, name }
        } else {
            Unit::NONE
        }
    }

    const NONE: Unit = Unit {
        scale: 1.0,
        name: "",
    };
}

pub fn write(
    out: &mut dyn Write,
    b: &Ball,
    r: &ImpactResponse,
    surface: &crate::api::SurfaceUsed,
    intervals: Option<&Intervals>,
    history: bool,
) -> io::Result<()> {
    let units = Units::of(b);
    let method = match r.method {
        Method::Exact => "exact solver",
        Method::Numeric => "adaptive numerical solver",
    };
    match b.name.as_deref() {
        Some(_) if !b.description.is_empty() => writeln!(out, "{}: {}", b.label(), b.description)?,
        _ => writeln!(out, "{}", b.label())?,
    }
    writeln!(out, "{} law, {method}", r.law)?;
    output::ball_lines(out, b, output::Met::Surface(surface))?;
    writeln!(out)?;
    write_parameters(out, b, r, &units)?;
    writeln!(out)?;
    write_comparison(out, b, r, &units)?;
    if let (Some(i), Some(fit)) = (intervals, &b.fit) {
        writeln!(out)?;
        let values = [r.cor, r.max_force, r.contact_time.unwrap_or(f64::NAN)];
        super::intervals_text::write(out, i, values, fit.dof)?;
    }
    if let Some(e) = &r.energy {
        writeln!(out)?;
        write_energy(out, e, &units)?;
    }
    if history {
        write_history(out, r, &units.force, &units.time, &units.length)?;
    }
    super::output::warning_lines(out, &b.warnings_on(r, surface))
}

/// The parameters the run used (SI ones for a preset), and λ, ζ, z̄_p.
fn write_parameters(
    out: &mut dyn Write,
    b: &Ball,
    r: &ImpactResponse,
    units: &Units,
) -> io::Result<()> {
    let (p, n) = (&b.params, &r.normalized);
    let mut rows: Vec<Vec<String>> = Vec::new();
    let mut row = |k: &str, v: String| rows.push(vec![k.to_string(), v]);
    if units.dimensional {
        row("mass m", units.unit(1e3, "g").given(p.mass));
        row("impact speed v0", units.unit(1.0, "m/s").given(p.v0));
        row("contact stiffness K_p", units.unit(1.0, "N/m").given(p.k_p));
        row("recoil spring K_r", units.unit(1.0, "N/m").given(p.k_r));
        row("dashpot c", units.unit(1.0, "kg/s").given(p.damping));
        row("flattening at z_p", units.length.given(p.z_p));
    }
    row("λ = K_r/K_p", human(n.lambda, 4));
    row("ζ = √(m K_p)/(2c)", human(n.zeta, 4));
    let zp = if n.zp_bar.is_finite() {
        human(n.zp_bar, 4)
    } else {
        "∞ (no flattening)".into()
    };
    row("z̄_p = z_p ω0/v0", zp);
    table(out, "  ", &rows)
}

/// The model's answer, beside what was measured when the run is at the measured speed.
fn write_comparison(
    out: &mut dyn Write,
    b: &Ball,
    r: &ImpactResponse,
    units: &Units,
) -> io::Result<()> {
    let v0 = b.params.v0;
    // the measured values are comparable only at the measured speed
    let measured = b
        .measured
        .as_ref()
        .filter(|m| m.v0 == v0 && (m.cor.is_some() || m.max_force.is_some()))
        // nor where the JSON's `comparison_withheld` withholds them (an override changed the
        // ball, or it runs away from its record's conditions): one rule for both outputs
        .filter(|_| b.measurement_withheld().is_none());
    let mut rows = vec![if measured.is_some() {
        vec![
            "".into(),
            "model".into(),
            "measured".into(),
            "difference".into(),
        ]
    } else {
        vec!["".into(), "model".into()]
    }];
    rows.extend(comparison_rows(r, measured, units));
    table(out, "  ", &rows)?;
    if let Some(m) = b.measured.as_ref().filter(|m| m.v0 != v0) {
        writeln!(
            out,
            "  (measured values are at v0 = {} m/s; not compared)",
            given(m.v0, 6)
        )?;
    } else if let Some(why) = b.measurement_withheld().filter(|_| b.measured.is_some()) {
        writeln!(out, "  (measured values not compared: {why})")?;
    }
    if let Some(note) = b.uncalibrated_note(&crate::preset::Output::IMPACT) {
        writeln!(out, "  ({note})")?;
    }
    Ok(())
}

/// COR, peak force, contact time and indentations: the model's, and where `measured` has one,
/// the measured value and the difference.
fn comparison_rows(
    r: &ImpactResponse,
    measured: Option<&Measured>,
    units: &Units,
) -> Vec<Vec<String>> {
    let (force, time, length) = (&units.force, &units.time, &units.length);
    let mut rows = Vec::new();
    let mut compare = |name: &str, model: String, meas: Option<(f64, f64, String)>| {
        let mut r = vec![name.to_string(), model];
        if let (Some(_), Some((mo, me, shown))) = (measured, meas) {
            r.push(shown);
            r.push(match name {
                "COR" => difference(mo, me, 1.0, ""),
                "peak force" => difference(mo, me, force.scale, force.name),
                _ => difference(mo, me, time.scale, time.name),
            });
        }
        rows.push(r);
    };
    let cor = if r.rebound {
        human(r.cor, 4)
    } else {
        "0 (no rebound)".into()
    };
    let meas = |v: Option<f64>, model: f64, u: &Unit| v.map(|v| (model, v, u.given(v)));
    compare(
        "COR",
        cor,
        measured.and_then(|m| meas(m.cor, r.cor, &Unit::NONE)),
    );
    compare(
        "peak force",
        force.show(r.max_force, 4),
        measured.and_then(|m| meas(m.max_force, r.max_force, force)),
    );
    let tf = r
        .contact_time
        .map_or("— (no rebound)".into(), |t| time.show(t, 4));
    compare(
        "contact time",
        tf,
        measured.and_then(|m| r.contact_time.and_then(|t| meas(m.contact_time, t, time))),
    );
    compare("peak indentation", length.show(r.max_indentation, 4), None);
    compare(
        "permanent indentation",
        length.show(r.permanent_indentation, 4),
        None,
    );
    rows
}

/// Where the energy went (mJ for a preset).
fn write_energy(out: &mut dyn Write, e: &EnergyBudget, units: &Units) -> io::Result<()> {
    let energy = units.unit(1e3, "mJ");
    // round-off shows as 0
    let clean = |x: f64| e.shown(x);
    let mut rows: Vec<Vec<String>> = [
        ("kinetic energy before", e.initial_kinetic),
        ("kinetic energy after", e.final_kinetic),
        ("lost in the dashpot", e.dashpot),
        ("left in the contact", e.contact),
        ("left in the recoil spring", e.spring),
    ]
    .into_iter()
    .map(|(name, x)| vec![name.into(), energy.show(clean(x), 4)])
    .collect();
    rows.push(vec![
        "balance residual".into(),
        format!("{} of the initial", output::residual(e.relative_residual())),
    ]);
    table(out, "  ", &rows)
}

fn write_history(
    out: &mut dyn Write,
    r: &ImpactResponse,
    force: &Unit,
    time: &Unit,
    length: &Unit,
) -> io::Result<()> {
    let h = &r.history;
    let step = h.t.len().div_ceil(HISTORY_ROWS).max(1);
    writeln!(out)?;
    let head = |s: &str, u: &Unit| {
        if u.name.is_empty() {
            s.to_string()
        } else {
            format!("{s} ({})", u.name)
        }
    };
    let mut rows = vec![vec![
        head("t", time),
        head("F", force),
        head("z", length),
        head("α", length),
    ]];
    let mut idx: Vec<usize> = (0..h.t.len()).step_by(step).collect();
    if idx.last() != Some(&(h.t.len().saturating_sub(1))) && !h.t.is_empty() {
        idx.push(h.t.len() - 1);
    }
    // round-off (|x| < 1e-12 of the peak) shows as 0
    let clean = |x: f64, peak: f64| if x.abs() < 1e-12 * peak { 0.0 } else { x };
    let zmax = h
        .displacement
        .iter()
        .fold(r.max_indentation, |a, &b| a.max(b.abs()));
    for i in idx {
        rows.push(vec![
            human(h.t[i] * time.scale, 4),
            human(clean(h.force[i], r.max_force) * force.scale, 4),
            human(clean(h.indentation[i], zmax) * length.scale, 4),
            human(clean(h.displacement[i], zmax) * length.scale, 4),
        ]);
    }
    table(out, "  ", &rows)?;
    if step > 1 {
        writeln!(
            out,
            "  (one row in {step} of {} samples; --format csv prints them all)",
            h.t.len()
        )?;
    }
    Ok(())
}
