//! `fit --save NAME`: the fitted ball as a user preset `<presets>/NAME.toml`, staged with the
//! fit's other outputs and published with them ([`crate::cli::outputs`]), never over an
//! existing preset without `--force`. Its comments say what it was fitted to, when, and how well.

use super::FitArgs;
use super::Loaded;
use crate::analysis::fit::MultiFit;
use crate::api::Ball;
use crate::atomic::Outputs;
use crate::catalog::{self, Catalog, Origin};
use crate::model::params::ImpactParams;
use crate::preset::{
    Adopted, Calibration, CalibrationData, FitAir, Measured, Output, ParamSource, Preset,
};
use std::path::{Path, PathBuf};

fn dir() -> anyhow::Result<PathBuf> {
    catalog::user_presets_dir().ok_or_else(|| {
        anyhow::anyhow!("--save: no folder for user presets (set XDG_CONFIG_HOME or HOME)")
    })
}

/// Where `name` goes: the file of the user preset already called so, or `<dir>/name.toml`;
/// and whether it exists.
fn target(name: &str) -> anyhow::Result<(PathBuf, bool)> {
    let dir = dir()?;
    let cat = Catalog::load(Some(&dir), None)?;
    if let Some(e) = cat.may_hold(name).and_then(|bad| bad.error.clone()) {
        return Err(e.into());
    }
    if let Some(e) = cat.entries().iter().find(|e| e.preset.name == name)
        && let Origin::File(f) = &e.origin
    {
        return Ok((f.clone(), true));
    }
    let path = dir.join(format!("{name}.toml"));
    let exists = std::fs::symlink_metadata(&path).is_ok();
    Ok((path, exists))
}

/// Where `name` goes ([`target`]), refused when a preset is there already and `force` is not
/// given: a user's preset is never replaced unasked.
fn target_free(name: &str, force: bool) -> anyhow::Result<PathBuf> {
    let (path, exists) = target(name)?;
    if exists && !force {
        anyhow::bail!(
            "preset '{name}' exists ({}): use --force to replace it",
            path.display()
        );
    }
    Ok(path)
}

/// A name the catalog can take, and no preset replaced without `force` (checked before the
/// fit runs, and again when writing).
pub fn check(name: &str, force: bool) -> anyhow::Result<()> {
    crate::tui::save::check_name(name)
        .map_err(|e| anyhow::anyhow!("invalid --save name '{name}': {e}"))?;
    let path = target_free(name, force)?;
    // a folder that takes no new file is found now, not after the fit (cli::outputs)
    if let Some(dir) = path
        .parent()
        .and_then(|d| d.ancestors().find(|d| d.exists()))
    {
        crate::atomic::probe(&dir.join(path.file_name().unwrap_or_default()))?;
    }
    Ok(())
}

/// Now, UTC, as "2026-11-23 18:55 UTC" (days to a civil date: H. Hinnant's algorithm).
pub fn now_utc() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs()) as i64;
    let (days, rem) = (secs.div_euclid(86_400), secs.rem_euclid(86_400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + (month <= 2) as i64;
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02} UTC",
        rem / 3600,
        rem % 3600 / 60
    )
}

fn header(ball: &Ball, data: &Loaded, f: &MultiFit, when: &str) -> Vec<String> {
    let short = |x: f64| crate::text::short(x, 4);
    let what = match &data.file {
        Some(file) => format!("the {} {file}", data.kind),
        None => format!("the {} given on the command line", data.kind),
    };
    let mut h = vec![
        format!(
            "Fitted by `bouncelab fit` on {when} to {what} ({}), {} law,",
            super::report_text::points(f.points),
            ball.law
        ),
        format!(
            "starting from the preset '{}' ({} parameters); what was not fitted is that preset's.",
            ball.name.as_deref().unwrap_or("ball"),
            ball.source
        ),
    ];
    let exact = f.exact();
    for e in f.fitted.iter().filter(|_| exact) {
        let (name, unit) = (e.name, e.unit);
        let value = short(e.value);
        h.push(format!(
            "{name} = {value} {unit} ({})",
            super::report_text::exact_text(f)
        ));
    }
    for e in f.fitted.iter().filter(|_| !exact) {
        h.push(format!(
            "{} = {} {} ± {} (95 %: {} … {})",
            e.name,
            short(e.value),
            e.unit,
            short(e.std_error),
            short(e.ci95[0]),
            short(e.ci95[1])
        ));
    }
    h.push(format!(
        "rms residual {}{}, {} iterations{}.",
        short(f.rms_residual),
        if data.trace.is_some() { " N" } else { "" },
        f.iterations,
        if f.converged { "" } else { ", not converged" }
    ));
    h.extend(f.warnings.iter().map(|w| format!("warning: {w}")));
    h
}

/// The fitted ball as a preset: the base preset's ball and material data, the fit as the
/// adopted set (K_h then follows Eq. 16 from K_p and z_p), `[measured] v0` the data's speed,
/// m and R the fitted ball's (`--mass`, `--radius`).
fn preset(
    base: &Preset,
    name: &str,
    ball: &Ball,
    data: &Loaded,
    f: &MultiFit,
    p: &ImpactParams,
    when: &str,
) -> Preset {
    let single = (data.trace.is_none() && data.points.len() == 1).then(|| data.points[0].cor);
    Preset {
        name: name.into(),
        // a description holds no control character (preset::check): a file name's are shown
        description: format!(
            "fitted to {} ({}) on {when}",
            crate::sanitize::line(&data.label),
            data.kind
        ),
        law: ball.law,
        parameters: ParamSource::Adopted,
        // the base's ball in the air under its new name: the model is written, not left to
        // the name
        aerodynamics: base.flight_model(),
        measured: Measured {
            // the fitted ball's: --mass and --radius replace the base preset's
            mass: p.mass,
            radius: ball
                .measured
                .as_ref()
                .map_or(base.measured.radius, |m| m.radius),
            v0: p.v0,
            cor: single,
            max_force: None,
            contact_time: None,
            inertia_factor: base.measured.inertia_factor,
            // the drops' air, so that `bouncelab drop` can say when it falls through another
            drops: (!data.drops.is_empty()).then(|| fit_air(data.air)),
        },
        material: base.material.clone(),
        adopted: Adopted {
            damping: Some(p.damping),
            z_p: Some(p.z_p),
            k_p: Some(p.k_p),
            k_r: p.k_r,
        },
        fit: crate::api::fit_table(f),
        calibration: Some(at_conditions(calibration(data, p, when), &ball.conditions)),
    }
}

/// The record `c` at the conditions the ball was fitted at: its gauge pressure and
/// temperature (the base preset's record's, or `--pressure`, `--temperature`). A tennis ball
/// fitted and saved lost its 12 psi from the record (issue 52; tests/cli/issue52_trial.rs,
/// `fit_save_keeps_the_balls_pressure`).
fn at_conditions(mut c: Calibration, conditions: &crate::conditions::Conditions) -> Calibration {
    c.pressure = conditions.pressure_gauge_pa;
    c.temperature = conditions.temperature_c;
    c
}

/// The record of what the ball was fitted to: the data's file (or what was typed), their
/// impact speeds (a trace's: the fit's v0) and drop heights; the range is their speeds'.
fn calibration(data: &Loaded, p: &ImpactParams, when: &str) -> Calibration {
    if !data.joint.is_empty() {
        return joint_calibration(data, p, when);
    }
    let speeds: Vec<f64> = if data.trace.is_some() || data.points.is_empty() {
        vec![p.v0]
    } else {
        data.points.iter().map(|q| q.v0).collect()
    };
    let source = match &data.file {
        Some(file) => format!("{file} (fitted by `bouncelab fit` on {when})"),
        None => format!(
            "{} given on the command line (fitted by `bouncelab fit` on {when})",
            data.label
        ),
    };
    let set = CalibrationData {
        // a description, a file's name: shown escaped, never as a control character
        source: crate::sanitize::line(&source).to_string(),
        quantities: data.kind.to_string(),
        speeds: speeds.clone(),
        heights: data.drops.iter().map(|d| d.0).collect(),
        loads: Vec::new(),
        outputs: Some(measured_outputs(data)),
    };
    Calibration::over(set, &speeds)
}

/// What one data set measured, by the answers' keys (docs/presets.md, "The calibration
/// record"): a COR table, drops and a COR typed in the COR (a table's peak forces and contact
/// times too, where its rows give them: the fit weighs them); a force–time trace its peak
/// force and contact time. A trace's impulse gives the COR only through the impact speed and
/// mass it is told, which the trace does not measure: no COR.
pub(super) fn measured_outputs(data: &Loaded) -> Vec<Output> {
    if data.trace.is_some() {
        return vec![Output::MaxForce, Output::ContactTime];
    }
    let mut o = vec![Output::Cor];
    if data.points.iter().any(|q| q.max_force.is_some()) {
        o.push(Output::MaxForce);
    }
    if data.points.iter().any(|q| q.contact_time.is_some()) {
        o.push(Output::ContactTime);
    }
    o
}

/// The record of a joint fit: every set it was fitted to, the range their impact speeds'
/// (a trace's the fit's v0; static deflections have none: the joint fit refuses `--save` with
/// static deflections alone, `cli::fit::joint`).
fn joint_calibration(data: &Loaded, p: &ImpactParams, when: &str) -> Calibration {
    let mut sets = data.joint.clone();
    for s in &mut sets {
        s.source = crate::sanitize::line(&format!(
            "{} (fitted jointly by `bouncelab fit` on {when})",
            s.source
        ))
        .to_string();
        if s.speeds.is_empty() && s.quantities == "force-time trace" {
            s.speeds = vec![p.v0];
        }
    }
    let speeds: Vec<f64> = sets.iter().flat_map(|s| s.speeds.iter().copied()).collect();
    let mut c = Calibration::over(sets[0].clone(), &speeds);
    c.data = sets;
    c
}

/// The preset staged in `files`, to be published with the fit's other outputs
/// (`cli::outputs`); returns its path and the presets folder when this call created it (to be
/// removed again if nothing is published).
pub fn stage(
    name: &str,
    a: &FitArgs,
    ball: &Ball,
    data: &Loaded,
    f: &MultiFit,
    p: &ImpactParams,
    files: &mut Outputs,
) -> anyhow::Result<(PathBuf, Option<PathBuf>)> {
    let base = crate::cli::ball::select(
        a.ball.choice.preset.as_deref(),
        a.ball.choice.config.as_deref(),
    )?
    .preset;
    let when = now_utc();
    let preset = preset(&base, name, ball, data, f, p, &when);
    stage_preset(&preset, &header(ball, data, f, &when), a.force, files)
}

/// `preset` as the user preset of its name, its comments `header`, staged in `files` (checked
/// as a preset first); its path and the presets folder when this call created it.
pub fn stage_preset(
    preset: &Preset,
    header: &[String],
    force: bool,
    files: &mut Outputs,
) -> anyhow::Result<(PathBuf, Option<PathBuf>)> {
    let name = preset.name.as_str();
    let text = preset.to_toml(header);
    Preset::parse(&text, name)
        .map_err(|e| anyhow::anyhow!("the fitted ball is not a valid preset: {e}"))?;
    let path = target_free(name, force)?;
    let folder = path.parent().unwrap_or(Path::new("."));
    let created = first_missing(folder);
    std::fs::create_dir_all(folder).map_err(|e| {
        anyhow::Error::new(e).context(format!("cannot create {}", folder.display()))
    })?;
    // the TOML as built: its own quoting holds whatever a name or path contains
    if let Err(e) = files.bytes(&path, text.as_bytes()) {
        remove_created(created.as_deref(), folder);
        return Err(e.into());
    }
    Ok((path, created))
}

/// The outermost folder of `dir` (itself or a parent) that does not exist yet.
fn first_missing(dir: &Path) -> Option<PathBuf> {
    dir.ancestors()
        .take_while(|d| !d.as_os_str().is_empty() && !d.exists())
        .last()
        .map(Path::to_path_buf)
}

/// Remove the folders from `inner` up to `created` that this run made, while empty.
pub fn remove_created(created: Option<&Path>, inner: &Path) {
    let Some(top) = created else {
        return;
    };
    for d in inner.ancestors() {
        if std::fs::remove_dir(d).is_err() || d == top {
            break;
        }
    }
}

/// The air of a drop fit as the preset keeps it (C_d 0 for vacuum).
fn fit_air(air: Option<crate::measured::Air>) -> FitAir {
    let a = air.unwrap_or(crate::measured::Air {
        drag_coefficient: 0.0,
        ..crate::measured::Air::default()
    });
    FitAir {
        drag_coefficient: a.drag_coefficient,
        air_density: a.density,
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn utc_date_format() {
        let s = super::now_utc();
        assert_eq!(s.len(), "2026-11-23 18:55 UTC".len(), "{s}");
        assert!(s.starts_with("20") && s.ends_with(" UTC"), "{s}");
    }
}
