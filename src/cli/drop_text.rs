//! `bouncelab drop`'s text report (src/cli/drop.rs): the bounces' table, how the drop ended,
//! and the verdicts of an impact standard and of a static one.

use super::output::{given, human, table};
use crate::analysis::statics::StaticDeflection;
use crate::drop::deformation::DeformationStandard;
use crate::drop::standards::{Reference, Standard, Test, Verdict};
use crate::drop::{DropRun, End, G};
use std::io::Write;

/// "standard itf-deformation: …" with the forward verdict and the return reading.
pub(super) fn static_verdict_text(
    out: &mut dyn Write,
    d: &DeformationStandard,
    s: &StaticDeflection,
    v: &Verdict,
) -> std::io::Result<()> {
    let mm = |x: f64| human(x * 1e3, 4);
    let window = |lo: Option<f64>, hi: Option<f64>| {
        format!(
            "{} … {} mm",
            lo.map_or("–".into(), |x| human(x * 1e3, 4)),
            hi.map_or("–".into(), |x| human(x * 1e3, 4))
        )
    };
    writeln!(out)?;
    writeln!(out, "standard {}: {}", d.name, d.title)?;
    writeln!(
        out,
        "  {} kg between {}, the model's static chain (not the drop above)",
        given(d.test.load_kg, 6),
        d.surface
    )?;
    writeln!(
        out,
        "  forward deflection: window {}, predicted {} mm: {}, margin {}{} mm",
        window(v.window[0], v.window[1]),
        mm(v.measured),
        if v.pass { "PASS" } else { "FAIL" },
        if v.margin >= 0.0 { "+" } else { "" },
        human(v.margin * 1e3, 3),
    )?;
    let ret = match &s.return_ {
        Ok(r) => format!("{} mm", mm(r.diameter())),
        Err(why) => format!("none ({why})"),
    };
    match d.return_window {
        Some([lo, hi]) => writeln!(
            out,
            "  return deflection after a {} mm compression: {ret}; the rules' window {} \
             (reported, not judged: docs/drop.md)",
            mm(d.test.peak_m),
            window(Some(lo), Some(hi))
        ),
        None => writeln!(out, "  return deflection: {ret}"),
    }
}

pub(super) fn text(
    out: &mut dyn Write,
    label: &str,
    run: &DropRun,
    judged: Option<(&Standard, Verdict)>,
    radius: f64,
    note: Option<String>,
) -> std::io::Result<()> {
    writeln!(out, "{label}")?;
    writeln!(
        out,
        "released from rest at {} m (bottom of the ball), g = {G} m/s², {}",
        given(run.setup.height, 6),
        run.drag_model()
    )?;
    writeln!(out)?;
    let mut rows = vec![
        [
            "#",
            "t_start s",
            "v_in m/s",
            "v_out m/s",
            "COR",
            "rebound m",
            "contact ms",
            "peak force N",
        ]
        .map(String::from)
        .to_vec(),
    ];
    for (i, b) in run.bounces.iter().enumerate() {
        rows.push(vec![
            (i + 1).to_string(),
            human(b.t_start, 4),
            human(b.v_in, 4),
            human(b.v_out, 4),
            format!("{:.4}", b.cor),
            human(b.rebound_height, 4),
            human(b.contact_time * 1e3, 4),
            human(b.max_force, 4),
        ]);
    }
    table(out, "  ", &rows)?;
    // the columns the ball's record does not vouch for (`Ball::uncalibrated_note`)
    if let Some(note) = note {
        writeln!(out, "  ({note})")?;
    }
    writeln!(out)?;
    let why = match run.end {
        End::Count => format!(
            "after {} (--bounces)",
            crate::text::counted(run.bounces.len(), "bounce")
        ),
        End::MinRebound => format!(
            "a rebound below {} m (--min-rebound)",
            given(run.setup.min_rebound, 4)
        ),
        End::NoRebound => "the ball stayed on the plate (e = 0)".into(),
    };
    writeln!(out, "ended: {why}")?;
    if let Some((s, v)) = judged {
        writeln!(out)?;
        verdict_text(out, s, &v, radius)?;
        if s.release_height(radius)
            .is_some_and(|h| h != run.setup.height)
        {
            writeln!(
                out,
                "  (judged on the standard's own drop, not on the {} m above)",
                given(run.setup.height, 6)
            )?;
        }
    }
    Ok(())
}

/// "standard itf (…): window 1.35 … 1.47 m, measured 1.410 m → pass, margin +0.060 m".
fn verdict_text(
    out: &mut dyn Write,
    s: &Standard,
    v: &Verdict,
    radius: f64,
) -> std::io::Result<()> {
    let (unit, conditions) = match s.test {
        Test::Drop {
            height,
            drop_ref,
            rebound_ref,
        } => (
            " m",
            format!(
                "drop from {} m to the {} of the ball, rebound read at the {}{}",
                given(height, 4),
                drop_ref.name(),
                rebound_ref.name(),
                match rebound_ref {
                    Reference::Top => format!(" (+{} m, the diameter)", given(2.0 * radius, 4)),
                    Reference::Bottom => String::new(),
                }
            ),
        ),
        Test::Cor { speed } => ("", format!("COR at {} m/s", given(speed, 4))),
    };
    writeln!(out, "standard {}: {}", s.name, s.title)?;
    writeln!(out, "  {conditions}, {}", s.surface)?;
    writeln!(
        out,
        "  window {}, predicted {}{unit}: {}, margin {}{}{unit}",
        super::standards::window_cell(s),
        human(v.measured, 4),
        if v.pass { "PASS" } else { "FAIL" },
        if v.margin >= 0.0 { "+" } else { "" },
        human(v.margin, 3),
    )
}
