//! `bouncelab reproduce [--out DIR] [--force]`: every figure of the paper for the three
//! embedded balls, their data as CSV, and a Markdown report of model against experiment.
//!
//! Overwrite policy: DIR is created when missing; if any file this command writes already
//! exists in DIR, nothing is written unless `--force` (which replaces exactly those files and
//! leaves anything else in DIR alone). Everything is computed before the first file is written,
//! so a failure leaves no half-written set.

use super::figure::{
    HISTORY_SAMPLES, VELOCITY_POINTS, ZETA_POINTS, embedded_ball, history_figures, velocity_figure,
    zeta_figures,
};
use super::output::given;
use crate::atomic::Outputs;
use crate::figure::report::{self, FigureRef};
use crate::figure::{Figure, csv, paper, svg};
use crate::preset::Preset;
use clap::Args;
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Peak indentation, in units of z_p, of the extra force–displacement figure of each ball: far
/// enough past flattening that the permanent indentation z_f is plain to see.
const FLATTENING_ZP: f64 = 2.0;

pub const REPORT: &str = "report.md";

#[derive(Debug, Clone, Args)]
pub struct ReproduceArgs {
    /// Folder to write into, created when missing
    #[arg(long, value_name = "DIR", default_value = "figures")]
    pub out: PathBuf,
    /// Replace the files of an earlier run (other files in DIR are left alone)
    #[arg(long)]
    pub force: bool,
}

/// One figure to write: file stem and caption; `ball` for the per-ball ones.
struct Planned {
    stem: String,
    caption: String,
    ball: Option<String>,
    figure: Figure,
}

/// The stems of the figure files, in writing order, known before anything is computed.
fn stems(presets: &[Preset]) -> Vec<String> {
    let mut v = vec!["cor-zeta".to_string(), "force-zeta".to_string()];
    for p in presets {
        for kind in ["cor-velocity", "force-time", "force-displacement"] {
            v.push(format!("{kind}-{}", p.name));
        }
        v.push(format!("force-displacement-{}-flattening", p.name));
    }
    v
}

fn plan(presets: &[Preset]) -> anyhow::Result<Vec<Planned>> {
    let balls: Vec<paper::Ball> = presets
        .iter()
        .map(|p| embedded_ball(p, None, p.law))
        .collect();
    let law = presets.first().map_or(crate::ContactLaw::Linear, |p| p.law);
    let (cor, force) = zeta_figures(&[0.0, 0.4, 1.0], ZETA_POINTS, law, &balls)?;
    let mut out = vec![
        Planned {
            stem: "cor-zeta".into(),
            caption: "Fig. 2: coefficient of restitution against the damping factor ζ".into(),
            ball: None,
            figure: cor,
        },
        Planned {
            stem: "force-zeta".into(),
            caption: "Fig. 3: normalized peak force against the damping factor ζ".into(),
            ball: None,
            figure: force,
        },
    ];
    for b in &balls {
        let one = |stem: &str, caption: String, figure: Figure| Planned {
            stem: format!("{stem}-{}", b.name),
            caption,
            ball: Some(b.name.clone()),
            figure,
        };
        let velocity = velocity_figure(b, None, None, VELOCITY_POINTS)?;
        out.push(one(
            "cor-velocity",
            "Fig. 4: COR against impact speed".into(),
            velocity,
        ));
        let (time, disp) = history_figures(b, HISTORY_SAMPLES)?;
        out.push(one(
            "force-time",
            "Figs. 5, 7: force against time at the measured speed".into(),
            time,
        ));
        out.push(one(
            "force-displacement",
            "Figs. 6, 8: force against indentation and displacement at the measured speed".into(),
            disp,
        ));
        let v = paper::speed_for_indentation(&b.params, b.law, FLATTENING_ZP)?
            .unwrap_or(3.0 * b.params.v0);
        let fast = paper::Ball {
            params: crate::ImpactParams { v0: v, ..b.params },
            ..b.clone()
        };
        let (_, flat) = history_figures(&fast, HISTORY_SAMPLES)?;
        let caption = format!(
            "force against displacement at v0 = {} m/s, where z_m = {FLATTENING_ZP} z_p: the \
             ball leaves flattened",
            given(v, 3)
        );
        let mut p = one("force-displacement", caption, flat);
        p.stem.push_str("-flattening");
        out.push(p);
    }
    Ok(out)
}

/// `--out` must be a folder or nothing yet: a file, or a symbolic link that leads nowhere
/// (dangling or looping), is refused naming it (exit 2), never met by "File exists" from
/// creating the folder (tests/cli/cli_outputs.rs, `reproduce_refuses_a_dangling_link`).
fn check_folder(dir: &Path) -> anyhow::Result<()> {
    let Ok(entry) = fs::symlink_metadata(dir) else {
        return Ok(());
    };
    if entry.file_type().is_symlink() && !dir.exists() {
        let to = fs::read_link(dir).map_or_else(|_| "?".into(), |t| t.display().to_string());
        anyhow::bail!(
            "--out {} is a symbolic link to {to}, which does not lead to a folder: remove it or \
             give another --out",
            dir.display()
        );
    }
    if !dir.is_dir() {
        anyhow::bail!("{} exists and is not a directory", dir.display());
    }
    Ok(())
}

pub fn run(a: &ReproduceArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    let presets = Preset::embedded();
    let dir = &a.out;
    check_folder(dir)?;
    let mut files: Vec<String> = stems(&presets)
        .iter()
        .flat_map(|s| [format!("{s}.svg"), format!("{s}.csv")])
        .collect();
    files.push(REPORT.into());
    let taken: Vec<PathBuf> = files
        .iter()
        .map(|f| dir.join(f))
        .filter(|p| p.exists())
        .collect();
    if let Some(first) = taken.first()
        && !a.force
    {
        let more = match taken.len() - 1 {
            0 => String::new(),
            n => format!(" (and {n} more of the files reproduce writes)"),
        };
        anyhow::bail!(
            "{} exists{more}; use --force to replace them, or another --out",
            first.display()
        );
    }
    let planned = plan(&presets)?;
    let mut texts: Vec<(String, String)> = Vec::new();
    let mut refs = Vec::new();
    for p in &planned {
        let picture = svg::render(&p.figure)?;
        texts.push((format!("{}.svg", p.stem), picture));
        texts.push((format!("{}.csv", p.stem), csv::to_string(&p.figure)));
        refs.push(FigureRef {
            file: format!("{}.svg", p.stem),
            caption: p.caption.clone(),
            ball: p.ball.clone(),
        });
    }
    let mut comparisons = Vec::new();
    for p in &presets {
        comparisons.push(report::compare(p, p.law)?);
    }
    texts.push((REPORT.into(), report::markdown(&comparisons, &refs)));
    debug_assert_eq!(
        texts.iter().map(|t| &t.0).collect::<Vec<_>>(),
        files.iter().collect::<Vec<_>>()
    );
    let created = !dir.exists();
    fs::create_dir_all(dir)
        .map_err(|e| anyhow::Error::new(e).context(format!("cannot create {}", dir.display())))?;
    // every file or none (crate::atomic); a folder this run created goes again on failure
    // and none when stdout cannot take their names (cli::outputs)
    let mut files = Outputs::new(a.force);
    let report: String = texts
        .iter()
        .map(|(name, _)| format!("{}\n", dir.join(name).display()))
        .collect();
    let written = texts
        .iter()
        .try_for_each(|(name, text)| files.text(&dir.join(name), text))
        .map_err(anyhow::Error::new)
        .and_then(|()| super::outputs::report_then_commit(out, report.as_bytes(), files));
    match written {
        Ok(_) => Ok(()),
        Err(e) => {
            if created {
                let _ = fs::remove_dir(dir);
            }
            Err(e)
        }
    }
}
