//! The fit pane in a session file (issue 29 item 3): the fit asked for (its data's label, the
//! ball it started from, the law, the free parameters) and what came back — the fitted ball,
//! each estimate with its standard error and 95 % interval, the residual, the verdict — or
//! why it failed. A fit still running when `S` is pressed is not saved (`f` runs it again).

use crate::analysis::fit::{Estimate, Param};
use crate::model::params::ImpactParams;
use crate::tui::views::fit::state::{FitOutcome, FitPane, FitStatus};
use serde::{Deserialize, Serialize};

/// The fit pane as the file holds it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fit {
    /// The measured data's label (its file name).
    pub label: String,
    pub law: String,
    /// The free parameters, by their command-line names (`k_p`, `c`, …).
    pub free: Vec<String>,
    /// Why the fit failed (absent: it answered, `result`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The ball the fit started from (SI): the pane says `stale` once the ball is another.
    pub base: ImpactParams,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub result: Option<FitResult>,
    /// The data were drop tests, taken in vacuum (`FitPane::drops`; absent: other data).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub drops: bool,
}

/// A finished fit's answer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FitResult {
    pub rms_residual: f64,
    /// `N` for a trace, `(COR)` for COR data.
    pub rms_unit: String,
    pub points: usize,
    pub converged: bool,
    pub identified: bool,
    pub not_pinned: Vec<String>,
    pub warnings: Vec<String>,
    /// The fitted ball (SI).
    pub params: ImpactParams,
    /// Force–time only: where the contact starts in the data's clock (s).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_offset: Option<Value>,
    pub fitted: Vec<Value>,
}

/// One estimate: value, standard error, 95 % interval (SI; `nan` where not pinned).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Value {
    pub name: String,
    pub value: f64,
    pub std_error: f64,
    pub ci95: [f64; 2],
}

/// The names and units an estimate may have: the free parameters', the trace's offset and
/// baseline (src/analysis/fit/multi.rs).
fn known(name: &str) -> Option<(&'static str, &'static str)> {
    if let Some(p) = Param::parse(name) {
        return Some((p.name(), p.unit()));
    }
    [("time_offset", "s"), ("baseline", "N")]
        .into_iter()
        .find(|(n, _)| *n == name)
}

fn value_of(e: &Estimate) -> Value {
    Value {
        name: e.name.into(),
        value: e.value,
        std_error: e.std_error,
        ci95: e.ci95,
    }
}

fn estimate_of(v: &Value) -> Result<Estimate, String> {
    let (name, unit) =
        known(&v.name).ok_or_else(|| format!("fit: unknown estimate '{}'", v.name))?;
    Ok(Estimate {
        name,
        unit,
        value: v.value,
        std_error: v.std_error,
        ci95: v.ci95,
    })
}

impl Fit {
    /// The pane's fit, unless it is still running.
    pub fn of(pane: &FitPane) -> Option<Fit> {
        let (error, result) = match &pane.status {
            FitStatus::Running => return None,
            FitStatus::Done(Err(e)) => (Some(e.clone()), None),
            FitStatus::Done(Ok(o)) => (None, Some(FitResult::of(o))),
        };
        Some(Fit {
            label: pane.label.clone(),
            law: pane.law.name().into(),
            free: pane.free.iter().map(|p| p.name().into()).collect(),
            error,
            base: pane.base,
            result,
            drops: pane.drops,
        })
    }

    /// The pane again, with the id `id`; or why not (a name the explorer does not know).
    pub fn pane(&self, id: u64) -> Result<FitPane, String> {
        let law = self
            .law
            .parse()
            .map_err(|_| format!("fit: law: unknown law '{}'", self.law))?;
        let free = self
            .free
            .iter()
            .map(|n| Param::parse(n).ok_or_else(|| format!("fit: free: unknown parameter '{n}'")))
            .collect::<Result<Vec<_>, _>>()?;
        let status = match (&self.error, &self.result) {
            (Some(e), None) => FitStatus::Done(Err(e.clone())),
            (None, Some(r)) => FitStatus::Done(Ok(r.outcome()?)),
            _ => return Err("fit: one of error and result".into()),
        };
        Ok(FitPane {
            id,
            label: self.label.clone(),
            base: self.base,
            law,
            free,
            status,
            armed: false,
            progress: None,
            drops: self.drops,
        })
    }
}

impl FitResult {
    fn of(o: &FitOutcome) -> FitResult {
        FitResult {
            rms_residual: o.rms_residual,
            rms_unit: o.rms_unit.into(),
            points: o.points,
            converged: o.converged,
            identified: o.identified,
            not_pinned: o.not_pinned.iter().map(|s| s.to_string()).collect(),
            warnings: o.warnings.clone(),
            params: o.params,
            time_offset: o.time_offset.as_ref().map(value_of),
            fitted: o.fitted.iter().map(value_of).collect(),
        }
    }

    fn outcome(&self) -> Result<FitOutcome, String> {
        let rms_unit = ["N", "(COR)"]
            .into_iter()
            .find(|u| *u == self.rms_unit)
            .ok_or_else(|| format!("fit: rms_unit: '{}' is not N or (COR)", self.rms_unit))?;
        let not_pinned = self
            .not_pinned
            .iter()
            .map(|n| {
                known(n)
                    .map(|k| k.0)
                    .ok_or_else(|| format!("fit: not_pinned: '{n}'"))
            })
            .collect::<Result<Vec<_>, _>>()?;
        self.params.validate().map_err(|e| format!("fit: {e}"))?;
        Ok(FitOutcome {
            params: self.params,
            fitted: self
                .fitted
                .iter()
                .map(estimate_of)
                .collect::<Result<_, _>>()?,
            time_offset: self.time_offset.as_ref().map(estimate_of).transpose()?,
            rms_residual: self.rms_residual,
            rms_unit,
            points: self.points,
            converged: self.converged,
            warnings: self.warnings.clone(),
            identified: self.identified,
            not_pinned,
        })
    }
}
