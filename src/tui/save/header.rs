//! The comment lines a saved preset's file starts with: where it came from, what its
//! `[adopted]` set holds, and why its source's measurements were left out, if they were.

use crate::model::contact::ContactLaw;
use crate::preset::{ParamSource, Preset};
use crate::text::sig_trim;
use crate::tui::setting::Setting;

/// Why `source`'s measurements are not this setting's, if they are not: taken at another
/// speed, or at the record's conditions while the setting is at others. (Keeping them with
/// the record's conditions would not do: the saved K_p, K_r, c are the ball's at the new
/// ones, and a record beside them would carry them on again from the old.)
pub(super) fn elsewhere(source: &Preset, setting: &Setting) -> Option<LeftOut> {
    let moved = crate::tui::physical::conditions::library_ball(source, setting);
    let at = source.measured.v0;
    let same_speed = (setting.params.v0 - at).abs() <= 1e-9 * at;
    match (moved.conditions_moved(), same_speed) {
        (Some(m), _) => Some(LeftOut::Conditions(m)),
        (None, false) => Some(LeftOut::Speed),
        (None, true) => None,
    }
}

/// Why a saved preset leaves its source's measurements out.
pub(super) enum LeftOut {
    /// They were taken at another speed.
    Speed,
    /// They were taken at the record's conditions, and the ball is at these (the library's
    /// words: "the ball at …; its record at …").
    Conditions(String),
}

/// The comment lines at the top of a saved preset's file: where it came from, what
/// `[adopted]` holds, and why the measurements were left out, if they were.
pub(super) fn lines(
    source: &Preset,
    law: ContactLaw,
    [lambda, zeta, v0]: [&str; 3],
    left_out: Option<LeftOut>,
) -> Vec<String> {
    let mut header = vec![
        format!(
            "Saved from the bouncelab explorer, from the preset '{}'.",
            source.name
        ),
        format!(
            "λ = {lambda}, ζ = {zeta}, v0 = {v0} m/s, {law} law. [adopted] holds the K_r and c"
        ),
        "that give this λ and ζ with the ball's own m and K_p.".into(),
    ];
    if source.parameters == ParamSource::Materials {
        header.push(format!(
            "'{}' ran on the set derived from its material data: that set is written as",
            source.name
        ));
        header.push("[adopted] (K_h now follows Eq. 16 from K_p and z_p).".into());
    }
    match left_out {
        Some(LeftOut::Speed) => {
            header.push(format!(
                "The measured COR, peak force and contact time of '{}' were taken at",
                source.name
            ));
            header.push(format!(
                "{} m/s, not at {v0} m/s: left out. [measured] v0 is the speed this preset runs at.",
                sig_trim(source.measured.v0, 6)
            ));
        }
        Some(LeftOut::Conditions(moved)) => {
            header.push(format!(
                "The measured COR, peak force and contact time of '{}' were taken at its",
                source.name
            ));
            header.push("record's conditions, not at this ball's: left out.".into());
            header.push(format!("({moved})"));
        }
        None => {}
    }
    header
}
