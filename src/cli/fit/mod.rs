//! `bouncelab fit`: the model fitted to measurements (docs/fitting.md). One COR fits the
//! recoil spring K_r (and λ) at the ball's ζ, z_p and v0 (docs/model.md §4), as it always
//! has; a COR table, a force–time trace or drop tests fit several parameters at once
//! ([`multi`]). The types the fit's files share ([`FitArgs`], [`Source`], [`Loaded`]) live
//! here; `multi` uses `plot`, `report`, `report_text` and `save`, which use only these types
//! and each other downward (`save` and `plot` use `report_text`, which uses `report`).

use super::ball::BallArgs;
use super::output::{self, given, human, table};
use crate::analysis::fit::Param;
use crate::api::FitReport;
use crate::cli::output::TextJson;
use crate::measured::{CorPoint, Trace};
use clap::Args;
use std::io::Write;
use std::path::PathBuf;

mod joint;
mod leak;
pub mod multi;
mod oblique;
mod plot;
mod report;
mod report_text;
mod save;
mod save_shift;
mod temperature;

#[derive(Debug, Clone, Args)]
pub struct FitArgs {
    #[command(flatten)]
    pub ball: BallArgs,
    /// Measured coefficient of restitution to match, in [0, 1]
    #[arg(long, value_name = "E", value_parser = super::number::number, allow_hyphen_values = true)]
    pub cor: Option<f64>,
    /// COR against impact speed: CSV with columns v0 and cor (optional cor_sd, max_force_N,
    /// contact_time_s)
    #[arg(long, value_name = "FILE")]
    pub cor_table: Option<PathBuf>,
    /// Force–time trace: CSV with a time column (time, t, time_s, time_ms, time_us) and a
    /// force column (force, F, force_N, force_kN)
    #[arg(long, value_name = "FILE")]
    pub force_time: Option<PathBuf>,
    /// Drop height (m), with --rebound-height; repeatable
    #[arg(long, value_name = "H", requires = "rebound_height", value_parser = super::number::number, allow_hyphen_values = true)]
    pub drop_height: Vec<f64>,
    /// Rebound height (m) of each --drop-height, in the same order
    #[arg(long, value_name = "R", requires = "drop_height", value_parser = super::number::number, allow_hyphen_values = true)]
    pub rebound_height: Vec<f64>,
    /// Drop tests from a CSV with columns drop_height_m, rebound_height_m
    #[arg(long, value_name = "FILE")]
    pub drop_test: Option<PathBuf>,
    /// Static deflections between two plates: CSV with columns load_kg, deflection_m
    /// (optional deflection_sd_m); fitted jointly with any --drop-test, --cor-table and
    /// --force-time given (docs/fitting.md, "Joint calibration")
    #[arg(long = "static", value_name = "FILE")]
    pub static_deflection: Option<PathBuf>,
    /// Oblique bounces: CSV with columns v0, angle_deg, spin_in, vx_out, vy_out (optional
    /// spin_out); fits friction and tangential_stiffness (and inertia_factor with spin_out)
    #[arg(long, value_name = "FILE")]
    pub oblique: Option<PathBuf>,
    /// Pressure readings of an inflated ball over time: CSV with a time column (time_s,
    /// time_min, time_h, time_d) and a gauge pressure column (pressure_pa, _kpa, _bar, _psi,
    /// …; optional pressure_sd_… in the same units); fits its leak p0·e^(−k t)
    #[arg(long, value_name = "FILE")]
    pub pressure_loss: Option<PathBuf>,
    /// CORs of a solid ball at several temperatures: CSV with columns temperature_c, v0, cor
    /// (optional cor_sd); fits an Arrhenius shift of its dashpot, c_ref and E_a
    #[arg(long, value_name = "FILE", conflicts_with = "pressure_loss")]
    pub cor_temperature: Option<PathBuf>,
    /// With --oblique: fit the tangential dashpot c_t too, starting from this value, kg/s
    /// (docs/oblique.md §9) [default: no dashpot]
    #[arg(long, value_name = "KG_PER_S", requires = "oblique", value_parser = super::number::number, allow_hyphen_values = true)]
    pub tangential_damping: Option<f64>,
    /// Drop tests: correct for quadratic air drag with this drag coefficient (≈ 0.47 for a
    /// smooth sphere) [default: no drag]
    #[arg(long, value_name = "CD", value_parser = super::number::number, allow_hyphen_values = true)]
    pub drag_coefficient: Option<f64>,
    /// Drop tests: air density for the drag correction, kg/m³
    #[arg(
        long,
        value_name = "RHO",
        default_value_t = 1.204,
        requires = "drag_coefficient",
        value_parser = super::number::number,
        allow_hyphen_values = true
    )]
    pub air_density: f64,
    /// Drop tests: how precisely the rebound heights were read (standard deviation, m): each
    /// COR then carries its error, σ_R ∂e/∂R, and the fit judges the scatter by χ²
    /// [default: unknown — each drop still weighed by its reading (a low rebound's COR less),
    /// the scale taken from the misses]
    #[arg(long, value_name = "S", value_parser = super::number::number, allow_hyphen_values = true)]
    pub rebound_height_sd: Option<f64>,
    /// Impact speed v0 (m/s) the COR or the trace was measured at [default: the preset's
    /// measured v0]
    #[arg(long, value_name = "V", value_parser = super::number::number, allow_hyphen_values = true)]
    pub v0: Option<f64>,
    /// Parameters to fit, comma-separated, from k_p, c, k_r, z_p, k_h [default: k_p,c,k_r
    /// for a trace (k_h,c,k_r for the Hertz law), k_r,z_p for a COR table or drop tests of
    /// three points or more, k_r for fewer]
    #[arg(long, value_name = "P,P,...", value_delimiter = ',')]
    pub free: Option<Vec<String>>,
    /// Save the fitted ball as the user preset NAME (never overwriting one without --force)
    #[arg(long, value_name = "NAME")]
    pub save: Option<String>,
    /// Draw data, model and residuals as one SVG
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    /// Overwrite an existing --plot file or --save preset
    #[arg(long)]
    pub force: bool,
    /// Output format
    #[arg(long, value_enum, default_value = "text")]
    pub format: TextJson,
}

/// What a fit is given.
#[derive(Debug, Clone)]
pub enum Source {
    Cor(f64),
    CorTable(PathBuf),
    Trace(PathBuf),
    /// (drop, rebound) heights from the command line
    Drops(Vec<(f64, f64)>),
    DropFile(PathBuf),
    /// Oblique bounces (`--oblique`, docs/oblique.md §9).
    Oblique(PathBuf),
}

/// The data of a fit, loaded and labelled.
pub struct Loaded {
    /// "force-time trace", "COR table", "drop test", "COR".
    pub kind: &'static str,
    /// The file, or `None` for data given on the command line.
    pub file: Option<String>,
    /// The legend label: the file name, or what was typed.
    pub label: String,
    pub trace: Option<Trace>,
    pub points: Vec<CorPoint>,
    /// (drop, rebound) heights of drop tests.
    pub drops: Vec<(f64, f64)>,
    /// Joint fits (`joint`): each set's record for the saved preset's `[calibration]`;
    /// empty for a fit of one data set.
    pub joint: Vec<crate::preset::CalibrationData>,
    /// The air the drops were converted in (`None`: vacuum, the default), which the report
    /// states: `bouncelab drop` runs through air unless `--no-drag`.
    pub air: Option<crate::measured::Air>,
    /// Line after the file's last, for errors about the whole file.
    pub end_line: usize,
}

impl FitArgs {
    /// The one kind of data given, or an error listing the choices.
    pub fn source(&self) -> anyhow::Result<Source> {
        let mut given = Vec::new();
        if let Some(e) = self.cor {
            given.push(Source::Cor(e));
        }
        if let Some(p) = &self.cor_table {
            given.push(Source::CorTable(p.clone()));
        }
        if let Some(p) = &self.force_time {
            given.push(Source::Trace(p.clone()));
        }
        if !self.drop_height.is_empty() {
            if self.drop_height.len() != self.rebound_height.len() {
                anyhow::bail!(
                    "{} --drop-height but {} --rebound-height: give one rebound height per drop",
                    self.drop_height.len(),
                    self.rebound_height.len()
                );
            }
            let pairs = self
                .drop_height
                .iter()
                .copied()
                .zip(self.rebound_height.iter().copied());
            given.push(Source::Drops(pairs.collect()));
        }
        if let Some(p) = &self.drop_test {
            given.push(Source::DropFile(p.clone()));
        }
        if let Some(p) = &self.oblique {
            given.push(Source::Oblique(p.clone()));
        }
        // air drag corrects drop heights only: with other data it is refused, not ignored
        // (tests/analysis/fit_answers.rs, drag_is_refused_where_there_is_no_flight)
        let drops = matches!(given.as_slice(), [Source::Drops(_) | Source::DropFile(_)]);
        if self.drag_coefficient.is_some() && given.len() == 1 && !drops {
            anyhow::bail!(
                "--drag-coefficient corrects drop tests (--drop-height, --drop-test) only: a \
                 COR, a COR table or a force-time trace has no flight to correct"
            );
        }
        if self.rebound_height_sd.is_some() && given.len() == 1 && !drops {
            anyhow::bail!(
                "--rebound-height-sd is the reading of drop tests' rebound heights \
                 (--drop-height, --drop-test) only: these data have no rebound height"
            );
        }
        match given.len() {
            1 => Ok(given.pop().unwrap_or(Source::Cor(f64::NAN))),
            0 => anyhow::bail!(
                "nothing to fit: give --cor E, --cor-table FILE, --force-time FILE, \
                 --drop-height H --rebound-height R, --drop-test FILE, --oblique FILE, or \
                 --pressure-loss FILE"
            ),
            _ => anyhow::bail!(self.excluded()),
        }
    }

    /// Why the data given cannot be fitted together (`joint::wanted` took every pair a joint
    /// fit takes): `--cor` and `--oblique` fit alone, and drop tests are given once.
    fn excluded(&self) -> String {
        let flags: Vec<&str> = [
            ("--cor", self.cor.is_some()),
            ("--cor-table", self.cor_table.is_some()),
            ("--force-time", self.force_time.is_some()),
            (
                "--drop-height/--rebound-height",
                !self.drop_height.is_empty(),
            ),
            ("--drop-test", self.drop_test.is_some()),
            ("--oblique", self.oblique.is_some()),
        ]
        .into_iter()
        .filter_map(|(flag, given)| given.then_some(flag))
        .collect();
        let Some(alone) = flags.iter().find(|f| ["--cor", "--oblique"].contains(f)) else {
            return "give drop tests once: --drop-test FILE or --drop-height/--rebound-height"
                .into();
        };
        let rest: Vec<&str> = flags.iter().filter(|f| *f != alone).copied().collect();
        format!(
            "{alone} fits alone, without {}: a joint fit takes --drop-test (or \
             --drop-height/--rebound-height), --cor-table, --force-time and --static{}",
            rest.join(", "),
            if *alone == "--cor" {
                " (put a single COR in a COR table to fit it with them)"
            } else {
                ""
            }
        )
    }

    /// Whether any data or option a fit of one file of its own (`--pressure-loss`,
    /// `--cor-temperature`) takes nothing from was given: those fits refuse them rather than
    /// ignore them.
    pub fn beyond_a_file_fit(&self) -> bool {
        self.cor.is_some()
            || self.cor_table.is_some()
            || self.force_time.is_some()
            || !self.drop_height.is_empty()
            || self.drop_test.is_some()
            || self.static_deflection.is_some()
            || self.oblique.is_some()
            || self.free.is_some()
            || self.save.is_some()
            || self.plot.is_some()
            || self.v0.is_some()
            || self.drag_coefficient.is_some()
            || self.rebound_height_sd.is_some()
    }

    /// `--free` as parameters; `None` when not given.
    pub fn free_params(&self) -> anyhow::Result<Option<Vec<Param>>> {
        let Some(list) = &self.free else {
            return Ok(None);
        };
        Ok(Some(crate::analysis::fit::parse_free(list)?))
    }
}

pub fn run(a: &FitArgs, out: &mut dyn Write) -> anyhow::Result<()> {
    if let Some(path) = &a.pressure_loss {
        return leak::run(a, path, out);
    }
    if let Some(path) = &a.cor_temperature {
        return temperature::run(a, path, out);
    }
    if joint::wanted(a) {
        return joint::run(a, out);
    }
    let source = a.source()?;
    let free = a.free_params()?;
    match (&source, free.as_deref()) {
        (Source::Oblique(p), _) => oblique::run(a, p, out),
        (Source::Cor(e), None) | (Source::Cor(e), Some([Param::KR])) => single(a, *e, out),
        _ => multi::run(a, &source, free, out),
    }
}

/// One COR: K_r by a root find (the original `fit`, its output unchanged).
fn single(a: &FitArgs, cor: f64, stdout: &mut dyn Write) -> anyhow::Result<()> {
    multi::check_outputs(a)?;
    let b = a.ball.resolve(a.v0)?;
    let f = b.fit_cor(cor)?;
    let p = &b.params;
    let r = FitReport::new(&b, cor, &f);
    let fitted = crate::model::params::ImpactParams { k_r: f.k_r, ..*p };
    let warnings = b.cor_fit_warnings(&fitted);
    // the report first in memory: it goes out with the files, or not at all (cli::outputs)
    let mut report = Vec::new();
    let out = &mut report;
    match a.format {
        TextJson::Json => output::json_on(
            out,
            &SingleJson {
                r,
                warnings: &warnings,
                ball: b.record_json(),
            },
            output::Met::RigidPlate,
            &b.conditions,
        )?,
        TextJson::Text => {
            writeln!(out, "{}, {} law", b.label(), r.ball.law)?;
            // the COR is read as the ball's on the rigid plate, as the JSON's surface says
            output::ball_lines(out, &b, output::Met::RigidPlate)?;
            writeln!(
                out,
                "fitting K_r at v0 = {} m/s, holding m, K_p, c (ζ = {}) and z_p",
                given(r.v0, 6),
                human(r.zeta, 4)
            )?;
            writeln!(out)?;
            let rows = vec![
                // typed, shown as typed: 0.99999999999, never a rounded 1 (as `peers`)
                vec!["target COR".into(), crate::text::number(r.target_cor)],
                vec!["fitted K_r".into(), format!("{} N/m", human(r.k_r, 5))],
                vec!["fitted λ = K_r/K_p".into(), human(r.lambda, 5)],
                vec!["model COR at the fit".into(), human(r.cor, 6)],
            ];
            let rows = [rows, start_rows(a, &b, &r)?].concat();
            table(out, "  ", &rows)?;
            output::warning_lines(out, &warnings)?;
        }
    }
    multi::single_extras(a, &b, &fitted, cor, stdout, &report)
}

/// The text's rows of the K_r the fit started from, named for what it is: the preset's; the
/// one given (`--k-r`, `--lambda`); or, where conditions away from the record's moved it, the
/// one at these conditions with the preset's at its record's beside it (`preset_k_r` in JSON
/// is the first: the ball the fit started from).
fn start_rows(a: &FitArgs, b: &crate::Ball, r: &FitReport) -> anyhow::Result<Vec<Vec<String>>> {
    let value = |k_r: f64, lambda: f64| format!("{} N/m (λ = {})", human(k_r, 5), human(lambda, 5));
    let start = value(r.preset_k_r, r.preset_lambda);
    let given = b.overrides.iter().any(|o| o == "k_r" || o == "lambda");
    // the same ball at its record's conditions: the K_r the preset gives
    let record = match b.conditions_moved() {
        Some(_) => {
            let args = BallArgs {
                conditions: Default::default(),
                ..a.ball.clone()
            };
            Some(args.resolve(a.v0)?.params).filter(|p| p.k_r != r.preset_k_r)
        }
        None => None,
    };
    Ok(match (given, record) {
        (false, None) => vec![vec!["preset's K_r".into(), start]],
        (true, None) => vec![vec!["K_r given".into(), start]],
        (true, Some(_)) => vec![vec!["K_r given, at these conditions".into(), start]],
        (false, Some(p)) => vec![
            vec!["K_r at these conditions".into(), start],
            vec![
                "preset's K_r at its record's conditions".into(),
                value(p.k_r, p.k_r / p.k_p),
            ],
        ],
    })
}

/// `fit --cor E --format json`: the library's report and what the caller should know of the
/// fitted ball ([`crate::Ball::fitted_warnings`]; `[]` when nothing).
#[derive(serde::Serialize)]
struct SingleJson<'a> {
    #[serde(flatten)]
    r: FitReport<'a>,
    warnings: &'a [String],
    /// The ball the fit started from (docs/cli.md, "The ball object").
    ball: crate::api::BallRecord,
}
