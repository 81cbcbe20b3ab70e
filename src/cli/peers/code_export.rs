//! `bouncelab peers --export CODE`: the ball's contact parameters for another code, with the
//! bounce asked and bouncelab's answer for it; the ball's warnings on stderr (docs/peers.md).

use super::{ExportArg, Peered, PeersArgs, ball_warnings, case};
use crate::cli::output;
use crate::peers::calibrate;
use crate::peers::export::{self, Code, ExportSet};
use std::io::Write;

/// The export of the ball `p` for `code`.
pub(super) fn write(
    a: &PeersArgs,
    out: &mut dyn Write,
    code: ExportArg,
    p: &Peered,
) -> anyhow::Result<()> {
    let (b, pair) = (&p.b, p.pair.as_ref());
    let mut set = ExportSet::new(&p.ball, p.target, b.name.as_deref().unwrap_or("ball"))?;
    set.tangential = case::tangential(a, b, code)?;
    // bouncelab's answer for the bounce is its model's, whatever the export's target
    let model_cor = match pair {
        Some(p) => p.cor,
        None => calibrate::christoforou_yigit_cor(&b.params, b.law, b.params.v0)?,
    };
    set.case = Some(case::case(
        &p.whole,
        p.bounce,
        pair,
        set.tangential.as_ref(),
        model_cor,
    )?);
    // the exported file is another code's input: the ball's warnings on stderr
    output::warnings_to_stderr(&warnings(a, p)?);
    let code = match code {
        ExportArg::Json => return Ok(output::json(out, &set)?),
        ExportArg::Lammps => Code::Lammps,
        ExportArg::Liggghts => Code::Liggghts,
        ExportArg::Chrono => Code::Chrono,
        ExportArg::Yade => Code::Yade,
        ExportArg::Mujoco => Code::Mujoco,
    };
    out.write_all(export::snippet(code, &set).as_bytes())?;
    Ok(())
}

/// The ball's warnings ([`ball_warnings`]), and a pair's calibrated at the preset's own speed.
fn warnings(a: &PeersArgs, p: &Peered) -> anyhow::Result<Vec<String>> {
    let mut w = ball_warnings(&p.b, p.pair.as_ref(), p.source)?;
    // a pair's COR falls with its closing speed (tennis on tennis 0.772 at 6.9 m/s, 0.690
    // at 30): the preset's own speed is nothing of the pair's (issue 52 item 8)
    if let (Some(pair), None) = (&p.pair, a.v0) {
        w.push(format!(
            "the pair export is calibrated at the closing speed {} m/s, the preset's v0: give --v0 with the pair's closing speed against {} (its COR changes with it)",
            crate::text::number(p.whole.params.v0),
            pair.preset
        ));
    }
    Ok(w)
}
