//! `bouncelab run --format text`: a readable table, units converted at the edge (N, ms, mm),
//! the measured values beside the model's for a preset.

use super::ball::ChosenBall;
use super::output::{difference, given, human, table};
use crate::solver::{ImpactResponse, Method};
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

pub fn write(
    out: &mut dyn Write,
    b: &ChosenBall,
    r: &ImpactResponse,
    history: bool,
) -> io::Result<()> {
    let dimensional = b.preset().is_some();
    let unit = |scale, name| {
        if dimensional {
            Unit { scale, name }
        } else {
            Unit {
                scale: 1.0,
                name: "",
            }
        }
    };
    let (force, time, length) = (unit(1.0, "N"), unit(1e3, "ms"), unit(1e3, "mm"));
    let p = &b.ball.params;
    let n = &r.normalized;
    let method = match r.method {
        Method::Exact => "exact solver",
        Method::Numeric => "adaptive numerical solver",
    };
    match b.preset() {
        Some(_) if !b.description.is_empty() => writeln!(out, "{}: {}", b.label(), b.description)?,
        _ => writeln!(out, "{}", b.label())?,
    }
    writeln!(out, "{} law, {method}", r.law)?;
    writeln!(out)?;

    let mut rows: Vec<Vec<String>> = Vec::new();
    let mut row = |k: &str, v: String| rows.push(vec![k.to_string(), v]);
    if dimensional {
        row("mass m", unit(1e3, "g").given(p.mass));
        row("impact speed v0", unit(1.0, "m/s").given(p.v0));
        row("contact stiffness K_p", unit(1.0, "N/m").given(p.k_p));
        row("recoil spring K_r", unit(1.0, "N/m").given(p.k_r));
        row("dashpot c", unit(1.0, "kg/s").given(p.damping));
        row("flattening at z_p", length.given(p.z_p));
    }
    row("λ = K_r/K_p", human(n.lambda, 4));
    row("ζ = √(m K_p)/(2c)", human(n.zeta, 4));
    let zp = if n.zp_bar.is_finite() {
        human(n.zp_bar, 4)
    } else {
        "∞ (no flattening)".into()
    };
    row("z̄_p = z_p ω0/v0", zp);
    table(out, "  ", &rows)?;
    writeln!(out)?;

    // the measured values are comparable only at the measured speed
    let measured = b
        .ball
        .measured
        .as_ref()
        .filter(|m| m.v0 == p.v0 && (m.cor.is_some() || m.max_force.is_some()));
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
    let m = measured.cloned();
    let meas = |v: Option<f64>, model: f64, u: &Unit| v.map(|v| (model, v, u.given(v)));
    let none = Unit {
        scale: 1.0,
        name: "",
    };
    compare(
        "COR",
        cor,
        m.as_ref().and_then(|m| meas(m.cor, r.cor, &none)),
    );
    compare(
        "peak force",
        force.show(r.max_force, 4),
        m.as_ref()
            .and_then(|m| meas(m.max_force, r.max_force, &force)),
    );
    let tf = r
        .contact_time
        .map_or("— (no rebound)".into(), |t| time.show(t, 4));
    compare(
        "contact time",
        tf,
        m.as_ref()
            .and_then(|m| r.contact_time.and_then(|t| meas(m.contact_time, t, &time))),
    );
    compare("peak indentation", length.show(r.max_indentation, 4), None);
    compare(
        "permanent indentation",
        length.show(r.permanent_indentation, 4),
        None,
    );
    table(out, "  ", &rows)?;
    if let Some(m) = b.ball.measured.as_ref().filter(|m| m.v0 != p.v0) {
        writeln!(
            out,
            "  (measured values are at v0 = {} m/s; not compared)",
            given(m.v0, 6)
        )?;
    }

    if let Some(e) = r.energy {
        writeln!(out)?;
        let energy = unit(1e3, "mJ");
        // round-off (|x| < 1e-12 of the initial energy) shows as 0
        let clean = |x: f64| {
            if x.abs() < 1e-12 * e.initial_kinetic {
                0.0
            } else {
                x
            }
        };
        let rows = vec![
            vec![
                "kinetic energy before".into(),
                energy.show(clean(e.initial_kinetic), 4),
            ],
            vec![
                "kinetic energy after".into(),
                energy.show(clean(e.final_kinetic), 4),
            ],
            vec![
                "lost in the dashpot".into(),
                energy.show(clean(e.dashpot), 4),
            ],
            vec![
                "left in the contact".into(),
                energy.show(clean(e.contact), 4),
            ],
            vec![
                "left in the recoil spring".into(),
                energy.show(clean(e.spring), 4),
            ],
            vec![
                "balance residual".into(),
                format!("{:.1e} of the initial", e.relative_residual()),
            ],
        ];
        table(out, "  ", &rows)?;
    }
    if history {
        write_history(out, r, &force, &time, &length)?;
    }
    Ok(())
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
