//! `bouncelab peers`' text and CSV (the JSON is the report's serde form, `output::json`): the
//! columns and the table of docs/cli.md, written from the report `run` built.

use super::{Report, Row};
use crate::api::Ball;
use crate::cli::output::{Met, ball_lines, csv_row, given, human, num, opt_num, table};
use crate::peers::PeerBall;
use std::io::Write;

/// The CSV: a header, then one row a model.
pub(super) fn csv(out: &mut dyn Write, rows: &[Row]) -> std::io::Result<()> {
    csv_row(
        out,
        &[
            "model",
            "rule",
            "stiffness",
            "damping",
            "cor",
            "max_force",
            "contact_time",
            "k_r",
        ],
    )?;
    for r in rows {
        csv_row(
            out,
            &[
                r.model.to_string(),
                r.rule.to_string(),
                num(r.stiffness),
                num(r.damping),
                num(r.cor),
                num(r.max_force),
                opt_num(r.contact_time),
                opt_num(r.k_r),
            ],
        )?;
    }
    Ok(())
}

/// The text: the ball, the target COR, then a table of the models.
pub(super) fn text(
    out: &mut dyn Write,
    b: &Ball,
    ball: &PeerBall,
    r: &Report,
) -> std::io::Result<()> {
    writeln!(
        out,
        "{}: m = {} kg, R = {} m, v0 = {} m/s",
        b.label(),
        given(ball.mass, 6),
        given(ball.radius, 6),
        given(ball.v0, 6)
    )?;
    // the pair met no surface (the JSON's `surface: null`), a single ball the rigid plate
    let met_pair = r.pair.as_ref().map(|p| p.met_words());
    let met = match &met_pair {
        Some(what) => Met::NoSurface(what),
        None => Met::RigidPlate,
    };
    ball_lines(out, b, met)?;
    if let Some(p) = &r.pair {
        writeln!(
            out,
            "pair with {}: m_eff = {} kg, R_eff = {} m (the partner at rest, v0 the closing speed)",
            p.preset,
            given(p.effective_mass, 6),
            given(p.effective_radius.unwrap_or(f64::NAN), 6)
        )?;
    }
    writeln!(
        out,
        "target COR {} ({}); k = K_p = {} N/m, K_h = {} N/m^1.5",
        // a target typed is shown as typed, every digit (0.9999999, never a rounded 1)
        if r.target_source == "given" {
            crate::text::number(r.target_cor)
        } else {
            given(r.target_cor, 6)
        },
        r.target_source,
        human(ball.k, 4),
        human(ball.k_h, 4)
    )?;
    writeln!(out)?;
    let mut rows = vec![vec![
        "model".into(),
        "rule".into(),
        "damping".into(),
        "COR at v0".into(),
        "peak force".into(),
        "contact time".into(),
    ]];
    for row in r.models {
        let damping = match row.model {
            "hunt-crossley" => format!("χ = {}", human(row.damping, 5)),
            "tsuji" => format!("η = {} kg/(s·m^¼)", human(row.damping, 5)),
            _ => format!("η = {} kg/s", human(row.damping, 5)),
        };
        rows.push(vec![
            row.model.into(),
            row.rule.into(),
            damping,
            human(row.cor, 6),
            format!("{} N", human(row.max_force, 4)),
            row.contact_time
                .map_or("no rebound".into(), |t| format!("{} ms", human(t * 1e3, 4))),
        ]);
    }
    table(out, "  ", &rows)?;
    writeln!(out)?;
    writeln!(
        out,
        "The peers' COR does not depend on v0 at this damping (η for Kelvin–Voigt and Tsuji, χ for \
         Hunt–Crossley, whose force is normalized by v0); docs/peers.md."
    )
}
