//! `s` in the explorer: save the current ball, λ, ζ, v0 and contact law as a user preset,
//! `<name>.toml` in the user presets folder (`catalog::user_presets_dir()`).
//!
//! As with the export, `App::update` stays free of side effects: on Enter in the name prompt it
//! checks the name ([`check_name`]), builds a [`SaveRequest`] with the file's text
//! ([`request`], pure) and returns it as an effect; the event loop hands the request to
//! [`write()`], the only part that touches the file system, which answers with an action: saved,
//! failed, or "that file exists" — then the explorer asks `overwrite <file>? y/n` and only `y`
//! returns the request again, now allowed to replace that one file.
//!
//! What is saved: the preset's ball (mass, radius, material data) with the parameters the
//! explorer runs on, written as the `[adopted]` set — K_r = λ K_p and c = √(m K_p)/(2ζ) with
//! the ball's own m and K_p (`ImpactParams::with_lambda_zeta`), z_p and K_p as they were — and
//! `[measured] v0` = the current speed, so loading it back gives the same λ, ζ, v0 and law
//! bit for bit.

mod header;

use super::action::Action;
use super::export::{file_name_char, file_stem_part, short_dir};
use super::setting::Setting;
use crate::catalog::{self, Catalog, Origin};
use crate::preset::{Adopted, EMBEDDED, Measured, ParamSource, Preset};
use crate::text::{io_text, sig_trim};
use std::io;
use std::path::{Path, PathBuf};

/// Longest preset name accepted in the prompt.
pub const NAME_MAX: usize = 40;

/// Where a description says it came from; a preset saved again replaces this part.
const SAVED_TAG: &str = "; saved from the explorer at";

/// A preset file to write.
#[derive(Debug, Clone, PartialEq)]
pub struct SaveRequest {
    /// The preset's name; the file is `<name>.toml` unless `replace` says otherwise.
    pub name: String,
    /// The whole file.
    pub text: String,
    /// The file the user agreed to overwrite; `None`: write a new file, never replacing one.
    pub replace: Option<PathBuf>,
}

/// The name the prompt starts with: `<preset>-custom` (once, not `-custom-custom`).
pub fn default_name(preset: &str) -> String {
    let stem = file_stem_part(preset);
    let name = if stem.ends_with("-custom") {
        stem
    } else {
        format!("{stem}-custom")
    };
    name.chars().take(NAME_MAX).collect()
}

/// A name that makes a safe file name and a valid, new preset name, or why not (one line).
pub fn check_name(name: &str) -> Result<(), String> {
    let Some(first) = name.chars().next() else {
        return Err("type a name for the preset".into());
    };
    if name.chars().count() > NAME_MAX {
        return Err(format!("a preset name has at most {NAME_MAX} characters"));
    }
    if let Some(bad) = name.chars().find(|&c| !file_name_char(c)) {
        return Err(format!(
            "'{bad}' cannot be in a name: use letters, digits, - and _"
        ));
    }
    if !first.is_ascii_alphanumeric() {
        return Err("a preset name starts with a letter or a digit".into());
    }
    if EMBEDDED.iter().any(|(n, _)| *n == name) {
        return Err(format!("{name} is an embedded preset: choose another name"));
    }
    Ok(())
}

/// The current setting as a preset called `name`, and the comment lines for the top of its
/// file.
pub fn preset_for(source: &Preset, setting: &Setting, name: &str) -> (Preset, Vec<String>) {
    let p = setting.params;
    let n = p.normalized();
    let (lambda, zeta, v0) = (
        sig_trim(n.lambda, 6),
        sig_trim(n.zeta, 6),
        sig_trim(p.v0, 6),
    );
    let why = header::elsewhere(source, setting);
    let here = why.is_none();
    let had_results = [
        source.measured.cor,
        source.measured.max_force,
        source.measured.contact_time,
    ]
    .iter()
    .any(Option::is_some);
    // A measurement belongs to the speed and conditions it was taken at: keep cor, max_force
    // and contact_time only there (they are then still this ball's, whatever λ and ζ are now;
    // the explorer shows the difference). Elsewhere they would be shown, and read, as
    // measured there, so they are left out; mass and radius stay, they hold at any speed.
    let why = why.filter(|_| had_results);
    let header = header::lines(source, setting.law, [&lambda, &zeta, &v0], why);
    let keep = |x: Option<f64>| x.filter(|_| here);
    let base = source
        .description
        .split(SAVED_TAG)
        .next()
        .filter(|d| !d.trim().is_empty())
        .unwrap_or(&source.name);
    let preset = Preset {
        name: name.to_string(),
        description: format!(
            "{base}{SAVED_TAG} λ = {lambda}, ζ = {zeta}, v0 = {v0} m/s, {} law",
            setting.law
        ),
        law: setting.law,
        parameters: ParamSource::Adopted,
        // the same ball in the air under its new name: the model is written, not left to
        // the name
        aerodynamics: source.flight_model(),
        measured: Measured {
            // the form (`m`) may have changed them: the preset runs as the screen does
            mass: p.mass,
            radius: setting.radius,
            v0: p.v0,
            cor: keep(source.measured.cor),
            max_force: keep(source.measured.max_force),
            contact_time: keep(source.measured.contact_time),
            inertia_factor: source.measured.inertia_factor,
            // the air of the drops the values came from goes with them
            drops: source.measured.drops.filter(|_| here),
        },
        material: source.material.clone(),
        adopted: Adopted {
            damping: Some(p.damping),
            z_p: Some(p.z_p),
            k_p: Some(p.k_p),
            k_r: p.k_r,
        },
        // the explorer's setting is not the fit's ball: no interval is claimed for it
        fit: None,
        // the record is the source's ball's: kept only while the ball is that ball (its own
        // parameters, on its own law, at whatever speed: the range says where it holds)
        calibration: source.calibration.clone().filter(|_| {
            setting.law == source.law && crate::api::changed_params(&source.params(), &p).is_empty()
        }),
    };
    (preset, header)
}

/// The save of `setting` (from the preset `source`) as `name` (checked with [`check_name`]
/// first): the file's text, checked to read back as a valid preset.
pub fn request(source: &Preset, setting: &Setting, name: &str) -> Result<SaveRequest, String> {
    check_name(name)?;
    let (preset, header) = preset_for(source, setting, name);
    let text = preset.to_toml(&header);
    // the schema has no infinity or NaN: refuse here rather than write a file that breaks
    // the catalog
    Preset::parse(&text, name).map_err(|e| format!("cannot be saved as a preset: {e}"))?;
    Ok(SaveRequest {
        name: name.to_string(),
        text,
        replace: None,
    })
}

/// Carry the save out in `dir` (the user presets folder; `None` when there is none) and say
/// how it went, as the action `App::update` takes next:
///
/// - `replace` set: the user said yes; that file is replaced atomically → `Saved`;
/// - a user preset of that name in the folder (whatever its file is called), or a file
///   `<name>.toml`, and no `replace`: nothing is written → `SaveExists` (ask first);
/// - otherwise a new `<name>.toml` (the folder created when missing) → `Saved`, or, when the
///   name is taken in the meantime (the no-clobber link fails), `SaveExists`.
pub fn write(request: &SaveRequest, dir: Option<&Path>) -> Action {
    match try_write(request, dir) {
        Ok(action) => action,
        Err(msg) => Action::SaveFailed { msg },
    }
}

fn try_write(request: &SaveRequest, dir: Option<&Path>) -> Result<Action, String> {
    if let Some(path) = &request.replace {
        catalog::write::replace(path, &request.text)
            .map_err(|e| format!("cannot write {}: {}", path.display(), io_text(&e)))?;
        return Ok(Action::Saved {
            path: path.clone(),
            replaced: true,
        });
    }
    let dir = dir.ok_or("no folder for user presets: set XDG_CONFIG_HOME or HOME")?;
    // names are unique across the catalog: the preset of this name, in whichever file, is
    // the one a save would replace (a second file with the same name would break the catalog)
    let catalog = Catalog::load(Some(dir), None)
        .map_err(|e| format!("cannot read the user presets ({e}); nothing saved"))?;
    if let Some(bad) = catalog.may_hold(&request.name) {
        return Err(format!(
            "cannot read the user presets ({}); nothing saved",
            bad.why
        ));
    }
    let in_file = |want: &dyn Fn(&catalog::Entry) -> bool| {
        catalog
            .entries()
            .iter()
            .find(|e| want(e))
            .map(|e| e.origin.clone())
    };
    if let Some(Origin::File(path)) = in_file(&|e| e.preset.name == request.name) {
        return Ok(exists(&catalog, path));
    }
    let path = dir.join(format!("{}.toml", request.name));
    if std::fs::symlink_metadata(&path).is_ok() {
        return Ok(exists(&catalog, path));
    }
    create(&catalog, dir, path, &request.text)
}

/// Write the new file `path` in `dir` (created when missing), never replacing one.
fn create(catalog: &Catalog, dir: &Path, path: PathBuf, text: &str) -> Result<Action, String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("cannot create {}: {}", dir.display(), io_text(&e)))?;
    match catalog::write::create_new(&path, text) {
        Ok(()) => Ok(Action::Saved {
            path,
            replaced: false,
        }),
        // someone created it since the checks: ask, as if it had been there
        Err(e) if e.kind() == io::ErrorKind::AlreadyExists => Ok(exists(catalog, path)),
        Err(e) => Err(format!("cannot write {}: {}", path.display(), io_text(&e))),
    }
}

/// The answer for a taken `path`, naming the preset the catalog read from it, if any.
fn exists(catalog: &Catalog, path: PathBuf) -> Action {
    let holds = catalog
        .entries()
        .iter()
        .find(|e| e.origin == Origin::File(path.clone()))
        .map(|e| e.preset.name.clone());
    Action::SaveExists { path, holds }
}

/// A preset file for the header line: its folder shortened as the export does.
pub fn short_path(path: &Path) -> String {
    let file = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    match path.parent().filter(|d| !d.as_os_str().is_empty()) {
        Some(d) => format!("{}/{file}", short_dir(d)),
        None => file,
    }
}

/// What the header says after a save.
pub fn saved_message(name: &str, path: &Path, replaced: bool) -> String {
    let how = if replaced { " (replaced)" } else { "" };
    format!("saved preset {name} to {}{how}", short_path(path))
}

/// The question before replacing `path`.
pub fn question(path: &Path) -> String {
    let file = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    format!("overwrite {file}? y/n")
}

/// What the header says when the user answers `n`.
pub fn declined_message(path: &Path) -> String {
    format!("not saved: {} left as it was", short_path(path))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_names() {
        assert_eq!(default_name("superball"), "superball-custom");
        assert_eq!(default_name("superball-custom"), "superball-custom");
        assert_eq!(default_name("my ball"), "my-ball-custom");
        assert!(check_name(&default_name(&"x".repeat(80))).is_ok());
    }

    #[test]
    fn names_are_checked() {
        for ok in ["superball-custom", "a", "Golf_2", "9iron"] {
            assert_eq!(check_name(ok), Ok(()), "{ok}");
        }
        let err = |n: &str| check_name(n).unwrap_err();
        assert_eq!(err(""), "type a name for the preset");
        assert_eq!(
            err("my ball"),
            "' ' cannot be in a name: use letters, digits, - and _"
        );
        assert!(err("../etc/passwd").starts_with("'.' cannot be"));
        assert!(err("a/b").starts_with("'/' cannot be"));
        assert!(err("bälle").starts_with("'ä' cannot be"));
        assert_eq!(err("-x"), "a preset name starts with a letter or a digit");
        assert_eq!(
            err("golf"),
            "golf is an embedded preset: choose another name"
        );
        assert_eq!(
            err(&"a".repeat(NAME_MAX + 1)),
            "a preset name has at most 40 characters"
        );
    }

    #[test]
    fn a_file_that_appears_after_the_checks_is_not_clobbered() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("mine.toml");
        // the checks in `try_write` found nothing; then another program writes the name
        std::fs::write(&path, "theirs").unwrap();
        let answer = create(&Catalog::embedded(), dir.path(), path.clone(), "ours");
        assert_eq!(
            answer,
            Ok(Action::SaveExists {
                path: path.clone(),
                holds: None
            })
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "theirs");
        let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(left.len(), 1, "no temporary file left behind");
    }

    #[test]
    fn messages() {
        let p = Path::new("/tmp/x/bouncelab/presets/mine.toml");
        assert_eq!(
            saved_message("mine", p, false),
            "saved preset mine to /tmp/x/bouncelab/presets/mine.toml"
        );
        let long = Path::new("/home/someone/.config/bouncelab/presets/mine.toml");
        assert_eq!(
            saved_message("mine", long, true),
            "saved preset mine to …/bouncelab/presets/mine.toml (replaced)"
        );
        assert_eq!(question(long), "overwrite mine.toml? y/n");
        assert_eq!(
            declined_message(long),
            "not saved: …/bouncelab/presets/mine.toml left as it was"
        );
    }
}
