//! Measured data in the explorer (`o`) and the fit of the current ball to it (`f`, `F`): the
//! data loaded, the fit asked of the fit worker ([`super::worker`]) and what came back.
//! The fit is the library's ([`crate::analysis::fit::fit`]) with the free parameters the
//! command line's `fit` takes by default for the kind of data ([`Param::defaults`]).

use crate::analysis::fit::{self, Estimate, FitData, Param};
use crate::measured::{CorPoint, Data, Flight, Trace, drops_to_points};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use std::path::PathBuf;

/// A measured file the explorer holds: its data and the name it is labelled by.
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded {
    pub path: PathBuf,
    /// The file name: the legend label.
    pub label: String,
    pub data: Data,
}

/// The fit's part of the explorer's state: the measured data drawn on the charts, the data a
/// fit is fitted to, and the fit pane.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FitState {
    /// Measured data drawn on the charts (`bouncelab --measured FILE`).
    pub overlays: Vec<crate::figure::explorer::MeasuredOverlay>,
    /// The measured file's data, to fit to (`o`, `bouncelab --measured FILE`).
    pub loaded: Option<Loaded>,
    /// The last fit asked for (`f`) and its answer: the fit pane.
    pub pane: Option<FitPane>,
    /// The id of the last fit asked for.
    pub id: u64,
}

/// Read and parse the measured file at `path` (the loop's part of `o`): its data, or one
/// line `FILE:LINE:COLUMN: why` (`FILE: why` about the file as a whole).
pub fn load(path: &std::path::Path) -> Result<Data, String> {
    crate::measured::file::any(path).map_err(|e| e.to_string())
}

/// What a fit is fitted to: a trace, or COR against speed (a drop test becomes such a table).
#[derive(Debug, Clone, PartialEq)]
pub enum FitInput {
    Trace(Trace),
    Cor(Vec<CorPoint>),
}

/// One fit for the worker: the ball as it was when `f` was pressed, and the data.
#[derive(Debug, Clone, PartialEq)]
pub struct FitRequest {
    /// Tells this fit's answer from an earlier one's.
    pub id: u64,
    pub base: ImpactParams,
    pub law: ContactLaw,
    pub free: Vec<Param>,
    pub input: FitInput,
    pub label: String,
}

/// What a finished fit shows: the fitted ball, each free parameter with its standard error
/// and 95 % interval, and how well it matches.
#[derive(Debug, Clone, PartialEq)]
pub struct FitOutcome {
    pub params: ImpactParams,
    pub fitted: Vec<Estimate>,
    /// Force–time only: where the contact starts in the data's clock (s).
    pub time_offset: Option<Estimate>,
    /// RMS of model − data, in `rms_unit`.
    pub rms_residual: f64,
    pub rms_unit: &'static str,
    pub points: usize,
    pub converged: bool,
    pub warnings: Vec<String>,
    /// Whether the fit answered: converged, every free parameter pinned (docs/fitting.md).
    pub identified: bool,
    /// The free parameters the data do not pin.
    pub not_pinned: Vec<&'static str>,
}

/// What the fit worker says of a fit: how far it is (the model runs done, the seconds since
/// it started: the work budget's progress, `analysis::work::Watch`), or how it ended.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum FitNews {
    Progress(FitProgress),
    Done(Result<FitOutcome, String>),
}

impl From<Result<FitOutcome, String>> for FitNews {
    fn from(r: Result<FitOutcome, String>) -> FitNews {
        FitNews::Done(r)
    }
}

/// A running fit's progress: model runs done, seconds since it started.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitProgress {
    pub runs: u64,
    pub seconds: f64,
}

/// Where a fit is: out on the worker, or back. (The explorer holds one: the size of the
/// variants does not matter.)
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum FitStatus {
    Running,
    Done(Result<FitOutcome, String>),
}

/// The fit pane's content: the last fit asked for and its answer.
#[derive(Debug, Clone, PartialEq)]
pub struct FitPane {
    pub id: u64,
    pub label: String,
    pub base: ImpactParams,
    pub law: ContactLaw,
    pub free: Vec<Param>,
    pub status: FitStatus,
    /// `F` was pressed once on a fit that did not answer: the next `F` applies it anyway.
    pub armed: bool,
    /// While it runs: the worker's last word on its progress.
    pub progress: Option<FitProgress>,
    /// The data were drop tests: their COR taken in vacuum ([`request`]: `Flight::vacuum()`,
    /// as `bouncelab fit --drop-test` without `--drag-coefficient`), which the pane says.
    pub drops: bool,
}

/// How a finished fit stands to the ball on screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Standing {
    /// The ball is the one fitted from: `F` applies the fit.
    Ready,
    /// The ball is the fitted one.
    Applied,
    /// The ball changed since `f` (another parameter, law or v0): the values are shown,
    /// marked stale, and `F` refuses them; `f` fits again.
    Stale,
}

impl FitPane {
    /// How the fit stands to the ball `now` under `law`.
    pub fn standing(&self, now: &ImpactParams, law: ContactLaw) -> Standing {
        match &self.status {
            FitStatus::Done(Ok(o)) if law == self.law && *now == o.params => Standing::Applied,
            _ if law == self.law && *now == self.base => Standing::Ready,
            _ => Standing::Stale,
        }
    }
}

/// The fit of `base` under `law` to `loaded`, with the command line's default free
/// parameters for that kind of data.
pub fn request(
    id: u64,
    loaded: &Loaded,
    base: &ImpactParams,
    law: ContactLaw,
) -> Result<FitRequest, String> {
    let input = match &loaded.data {
        Data::Trace(t) => FitInput::Trace(t.clone()),
        Data::Cor(t) => FitInput::Cor(t.points.clone()),
        // each drop weighed by its rebound height's reading, as `fit --drop-test` weighs it,
        // and in vacuum, as it takes them without `--drag-coefficient` (the pane says so:
        // `FitPane::drops`)
        Data::Drop(d) => {
            let pairs: Vec<(f64, f64)> = d.drops.iter().map(|&(h, r, _)| (h, r)).collect();
            FitInput::Cor(drops_to_points(&pairs, &Flight::vacuum(), None))
        }
    };
    let (trace, n) = match &input {
        FitInput::Trace(t) => (true, t.time.len()),
        FitInput::Cor(p) => (false, p.len()),
    };
    if n == 0 {
        return Err(format!("{}: no data points to fit", loaded.label));
    }
    Ok(FitRequest {
        id,
        base: *base,
        law,
        free: Param::defaults(trace, n, law),
        input,
        label: loaded.label.clone(),
    })
}

/// Run `r` with the library's fit: the worker's job.
pub fn run(r: &FitRequest) -> Result<FitOutcome, String> {
    run_watched(r, &crate::analysis::work::Unwatched)
}

/// [`run`], each model run reported to `watch`, which may stop it (a later fit asked for).
pub fn run_watched(
    r: &FitRequest,
    watch: &dyn crate::analysis::work::Watch,
) -> Result<FitOutcome, String> {
    let (data, unit) = match &r.input {
        FitInput::Trace(t) => (FitData::Trace(t), "N"),
        FitInput::Cor(p) => (FitData::Cor(p), "(COR)"),
    };
    let f = fit::fit_watched(&r.base, r.law, data, &r.free, watch)
        .map_err(|e| format!("{}: {e}", r.label))?;
    Ok(FitOutcome {
        params: f.params,
        fitted: f.fitted,
        time_offset: f.time_offset,
        rms_residual: f.rms_residual,
        rms_unit: unit,
        points: f.points,
        converged: f.converged,
        warnings: f.warnings,
        identified: f.identified,
        not_pinned: f.not_pinned,
    })
}
