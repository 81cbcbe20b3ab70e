//! Several parameters at once: restarts, the best minimum, and its uncertainty.

use super::cor::CorProblem;
use super::lm::{self, Residuals, Solution};
use super::stats::{CONDITION_MAX, uncertainty};
use super::trace::TraceProblem;
use super::verdict::{self, judge};
use super::{Param, fit_k_r};
use crate::measured::{CorPoint, MeasuredError, Trace};
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, ParamError};
use crate::text::sig;
use serde::Serialize;
use std::fmt;

/// What to fit to.
#[derive(Debug, Clone, Copy)]
pub enum FitData<'a> {
    /// A measured force–time pulse: the model's F(t) is fitted to it, with the start of
    /// contact in the data's clock and the force baseline fitted too.
    Trace(&'a Trace),
    /// COR against impact speed (with peak forces and contact times where given): the model's
    /// values at each speed are fitted to them (a drop test becomes such a table).
    Cor(&'a [CorPoint]),
}

/// One fitted quantity: value, standard error and 95 % interval (SI).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Estimate {
    /// Its name in the output ([`Param::name`], or `time_offset`, `baseline`).
    #[serde(skip)]
    pub name: &'static str,
    /// Its SI unit.
    #[serde(skip)]
    pub unit: &'static str,
    /// The fitted value.
    pub value: f64,
    /// Its standard error from cov = s² (JᵀJ)⁻¹ ([`super::stats`]); for a model parameter,
    /// fitted as θ = ln p, by the delta method, p s_θ.
    pub std_error: f64,
    /// The 95 % interval: exp(θ ± t₀.₉₇₅ s_θ) for a model parameter (so it stays positive),
    /// value ± t₀.₉₇₅ std_error for the offset and baseline; Student t at n − p degrees of
    /// freedom; NaN when the data leave no degree of freedom or do not pin the value.
    pub ci95: [f64; 2],
}

/// A fitted ball and how well the data pin it.
#[derive(Debug, Clone)]
pub struct MultiFit {
    /// The whole fitted ball (the free parameters moved, the rest as given).
    pub params: ImpactParams,
    /// The contact law fitted under.
    pub law: ContactLaw,
    /// One estimate for each free parameter, in the order given.
    pub fitted: Vec<Estimate>,
    /// Force–time: where the contact starts in the data's clock (s), and the force baseline.
    pub time_offset: Option<Estimate>,
    /// Force–time: the constant force (N) the data read when nothing touches.
    pub baseline: Option<Estimate>,
    /// Correlations between every fitted quantity, in the order of `names`.
    pub names: Vec<&'static str>,
    /// The correlation matrix, one row a quantity of `names`.
    pub correlation: Vec<Vec<f64>>,
    /// RMS of model − data: newtons for a trace, COR for a table.
    pub rms_residual: f64,
    /// Data points fitted (samples of a trace; values of a table).
    pub points: usize,
    /// Levenberg–Marquardt iterations over every start.
    pub iterations: usize,
    /// Whether the best start met a convergence test (not just the iteration budget).
    pub converged: bool,
    /// Condition number of the column-scaled Jacobian (see [`super::stats`]).
    pub condition: f64,
    /// What the caller should know, one line each: no degree of freedom left, a parameter
    /// the data cannot tell from the others, an interval wider than its value, a fit that
    /// stopped on its iteration budget.
    pub warnings: Vec<String>,
    /// The model at each data point: force (N) at each sample, or COR at each speed.
    pub model: Vec<f64>,
    /// Whether the fit answered: it converged and the data pin every free parameter
    /// ([`super::verdict::pinned`]). A fit that did not answer still reports what it found,
    /// but the command line exits 1 and refuses to save or plot it.
    pub identified: bool,
    /// The free parameters the data do not pin (an interval wider than a factor
    /// [`super::verdict::PIN_RATIO`], no finite interval, or a value on the search's bound).
    pub not_pinned: Vec<&'static str>,
    /// The free parameters that ran to the bound of their search (±5 decades from the start
    /// for a COR table, ±4 for a trace): the data ask for more than the model gives with the
    /// others held.
    pub on_bound: Vec<&'static str>,
    /// A test of whether the model can follow the data at all (systematic residuals); `None`
    /// where no test applies (too few points, no degree of freedom).
    pub lack_of_fit: Option<super::verdict::LackOfFit>,
}

impl MultiFit {
    /// Whether the fit had as many data as quantities fitted (no degree of freedom left): the
    /// values solve the data exactly and no standard error or interval can be estimated.
    pub fn exact(&self) -> bool {
        self.points <= self.names.len()
    }
}

/// Why a multi-parameter fit gave no answer; each message is one line.
#[derive(Debug, Clone, PartialEq)]
pub enum MultiFitError {
    /// The starting parameters are invalid.
    Params(ParamError),
    /// No parameter was freed.
    NoFree,
    /// A parameter was freed twice.
    Repeated(Param),
    /// K_h and K_p are tied by Eq. 16: one of them at a time.
    Tied,
    /// Fewer data points than quantities to fit.
    TooFew {
        /// Data points given.
        points: usize,
        /// Quantities to fit (free parameters, and a trace's offset and baseline).
        parameters: usize,
    },
    /// The trace holds no pulse to fit.
    NoPulse(MeasuredError),
    /// No start led to parameters the solver answers for.
    NoAnswer,
    /// The trace's impulse contradicts the impact speed and mass: I = m v0 (1 + e) needs
    /// 0 ≤ e ≤ 1, so v0 must lie in [I/(2m), I/m].
    Contradicts {
        /// The restitution the impulse implies at the given v0.
        implied: f64,
        /// The impact speed given (m/s).
        v0: f64,
        /// The impulse of the pulse (N s).
        impulse: f64,
        /// The speeds the impulse allows (m/s): I/(2m) and I/m.
        allowed: [f64; 2],
    },
    /// As many data as parameters, and no parameters of the model reproduce them (the miss of
    /// the best, or a parameter pressed on its bound): the message says what is reachable.
    OutOfReach(String),
    /// The fit ran but gave no answer (did not converge, or the data do not pin a
    /// parameter): the reason. Not the input's fault alone: the command line exits 1.
    Unanswered(String),
    /// `v0` is free but the data carry their own speeds (a COR table or drop tests).
    SpeedNotFree,
    /// A value that is not a finite number came up on the way (data or parameters far outside
    /// any ball's range).
    NonFinite,
}

impl fmt::Display for MultiFitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MultiFitError::Params(e) => write!(f, "{e}"),
            MultiFitError::NoFree => write!(f, "no free parameter to fit"),
            MultiFitError::Repeated(p) => write!(f, "free parameter {} given twice", p.name()),
            MultiFitError::Tied => write!(
                f,
                "k_h and k_p are tied (K_p = 1.5 K_h √z_p, Eq. 16): free one of them"
            ),
            MultiFitError::TooFew { points, parameters } => write!(
                f,
                "{points} data points, fewer than the {parameters} parameters fitted"
            ),
            MultiFitError::NoPulse(e) => write!(f, "{e}"),
            MultiFitError::NoAnswer => write!(
                f,
                "no starting point gave parameters the solver answers for"
            ),
            MultiFitError::Contradicts {
                implied,
                v0,
                impulse,
                allowed,
            } => write!(
                f,
                "the pulse's impulse {} N s implies e = {} at v0 = {} m/s (I = m v0 (1 + e)), \
                 outside 0 … 1: the trace allows v0 from {} to {} m/s (give --v0, or --free v0 \
                 to fit it)",
                crate::text::sig(*impulse, 4),
                crate::text::sig(*implied, 3),
                crate::text::number(*v0),
                crate::text::sig(allowed[0], 4),
                crate::text::sig(allowed[1], 4)
            ),
            MultiFitError::OutOfReach(m) => write!(f, "{m}"),
            MultiFitError::Unanswered(why) => write!(f, "the fit gave no answer: {why}"),
            MultiFitError::SpeedNotFree => write!(
                f,
                "v0 can be fitted from a force-time trace only: a COR table or drop test gives \
                 each row's speed"
            ),
            MultiFitError::NonFinite => write!(
                f,
                "the fit met a value that is not a finite number: the data lie far outside \
                 any ball's range"
            ),
        }
    }
}

impl std::error::Error for MultiFitError {}

/// Fit the `free` parameters of `base` to `data` under `law`.
pub fn fit(
    base: &ImpactParams,
    law: ContactLaw,
    data: FitData,
    free: &[Param],
) -> Result<MultiFit, MultiFitError> {
    check_free(free)?;
    base.validate().map_err(MultiFitError::Params)?;
    match data {
        FitData::Trace(trace) => {
            let summary = trace.summary().map_err(MultiFitError::NoPulse)?;
            too_few(trace.time.len(), free.len() + 2)?;
            if !free.contains(&Param::V0) {
                check_impulse(base, trace, &summary)?;
            }
            let p = TraceProblem::new(*base, law, free.to_vec(), trace, summary);
            // a minimum at the noise floor needs no further start
            let floor = 1.5 * summary.noise;
            let sol =
                best(&p, p.starts(), |x| p.bounds(x), floor).ok_or(MultiFitError::NoAnswer)?;
            let model = p.model(&sol.sol.x).map(|m| m.0).unwrap_or_default();
            let ball = p.ball(&sol.sol.x);
            let rms = rms(&sol.sol.residuals);
            let mut f = finish(ball, law, free, &sol, None, rms, model)?;
            // the model's misses matter only above the noise's scale (a noise-free synthetic
            // trace leaves rounding's systematic residuals)
            let lack = verdict::runs_test(&sol.sol.residuals)
                .filter(|_| rms > 1e-6 * summary.peak.abs().max(f64::MIN_POSITIVE));
            judge(&mut f, lack);
            Ok(f)
        }
        FitData::Cor(points) => {
            if free.contains(&Param::V0) {
                return Err(MultiFitError::SpeedNotFree);
            }
            fit_cor(base, law, points, free)
        }
    }
}

/// A trace whose impulse needs e outside [0, 1] at the given speed cannot come from this
/// ball: refused, with the speeds it allows (three standard errors of the impulse's noise
/// are given to it).
fn check_impulse(
    base: &ImpactParams,
    trace: &Trace,
    s: &crate::measured::TraceSummary,
) -> Result<(), MultiFitError> {
    let n = trace.time.len();
    let dt = (trace.time[n - 1] - trace.time[0]) / (n - 1).max(1) as f64;
    let (e, sd) = verdict::implied_cor(s, base.mass, base.v0, dt);
    if !(e.is_finite() && sd.is_finite()) {
        return Err(MultiFitError::NonFinite);
    }
    if e < -3.0 * sd || e > 1.0 + 3.0 * sd {
        let m = base.mass;
        return Err(MultiFitError::Contradicts {
            implied: e,
            v0: base.v0,
            impulse: s.impulse,
            allowed: [s.impulse / (2.0 * m), s.impulse / m],
        });
    }
    Ok(())
}

/// A COR table (with peak forces and contact times where given).
fn fit_cor(
    base: &ImpactParams,
    law: ContactLaw,
    points: &[CorPoint],
    free: &[Param],
) -> Result<MultiFit, MultiFitError> {
    let p = CorProblem::new(*base, law, free.to_vec(), points);
    too_few(p.count(), free.len())?;
    check_scale(&p)?;
    let mut sol = best(&p, p.starts(), |x| p.bounds(x), 0.0).ok_or(MultiFitError::NoAnswer)?;
    let mut t_dof = None;
    if p.count() > points.len() {
        // mixed kinds: weigh each by its own scatter, then fit again from there
        let kinds = p.rms_by_kind(&sol.sol.x).ok_or(MultiFitError::NoAnswer)?;
        let counts = p.count_by_kind();
        for k in 0..3 {
            if kinds[k].is_finite() && (k > 0 || points.iter().all(|q| q.cor_sd.is_none())) {
                p.scale[k].set(kinds[k].max(1e-6));
                // the weights are estimated from the data: the intervals take the degrees of
                // freedom of the kind with the fewest points, its share of the parameters
                // taken off (measured: 37–39 of 40 intervals cover, against 35–37 with the
                // n − p of all the data; tests/fit_recovery.rs,
                // cor_force_and_contact_time_jointly)
                let share = (free.len() * counts[k]).div_ceil(p.count());
                let dof = counts[k].saturating_sub(share).max(1);
                t_dof = Some(t_dof.map_or(dof, |d: usize| d.min(dof)));
            }
        }
        let again = best(&p, vec![sol.sol.x.clone()], |x| p.bounds(x), 0.0);
        let its = sol.sol.iterations;
        sol = again.ok_or(MultiFitError::NoAnswer)?;
        sol.sol.iterations += its;
    }
    let pred = p.predict(&sol.sol.x).ok_or(MultiFitError::NoAnswer)?;
    let model: Vec<f64> = pred.iter().map(|q| q.0).collect();
    let misses: Vec<f64> = model.iter().zip(points).map(|(m, q)| m - q.cor).collect();
    if p.count() == free.len() {
        verify_exact(&p, &sol, &pred)?;
    }
    let ball = p.ball(&sol.sol.x);
    let mut f = finish(ball, law, free, &sol, t_dof, rms(&misses), model)?;
    let dof = sol.sol.residuals.len().saturating_sub(free.len());
    // χ² when every row carries its standard deviation (and nothing else was measured), else
    // the runs test of the COR misses in the data's order of speed
    let lack = if points.iter().all(|q| q.cor_sd.is_some()) && p.count() == points.len() {
        verdict::chi2_test(&sol.sol.residuals, dof)
    } else {
        let mut by_speed: Vec<(f64, f64)> = points.iter().map(|q| q.v0).zip(misses).collect();
        by_speed.sort_by(|a, b| a.0.total_cmp(&b.0));
        let r: Vec<f64> = by_speed.iter().map(|m| m.1).collect();
        verdict::runs_test(&r).filter(|_| f.rms_residual > 1e-9)
    };
    judge(&mut f, lack);
    Ok(f)
}

/// Peak forces and contact times more than [`verdict::SCALE_MAX`] from the starting ball's,
/// either way, lie beyond what the search (±5 decades in each parameter) can bring the model
/// to: refused, naming the row, rather than fitted to the other kinds while these are
/// outvoted.
fn check_scale(p: &CorProblem) -> Result<(), MultiFitError> {
    let x0: Vec<f64> = p.free.iter().map(|q| q.get(&p.base).ln()).collect();
    let Some(pred) = p.predict(&x0) else {
        return Ok(());
    };
    for (q, (_, f, t)) in p.points.iter().zip(&pred) {
        let kinds = [
            ("peak force", "N", q.max_force, Some(*f)),
            ("contact time", "s", q.contact_time, *t),
        ];
        for (what, unit, measured, model) in kinds {
            let (Some(m), Some(model)) = (measured, model) else {
                continue;
            };
            let ratio = m / model;
            if !(1.0 / verdict::SCALE_MAX..=verdict::SCALE_MAX).contains(&ratio) {
                let row = if q.line > 0 {
                    format!("line {}: ", q.line)
                } else {
                    String::new()
                };
                return Err(MultiFitError::OutOfReach(format!(
                    "{row}the {what} measured at v0 = {} m/s, {} {unit}, is {}× the model's {} \
                     {unit}: beyond a factor {} either way, out of the fit's reach",
                    sig(q.v0, 4),
                    sig(m, 4),
                    sig(ratio, 3),
                    sig(model, 4),
                    verdict::SCALE_MAX
                )));
            }
        }
    }
    Ok(())
}

/// An exact solve (as many data as parameters) must reproduce every datum to
/// [`verdict::EXACT_MISS`] with no parameter on its bound; otherwise the data are out of the
/// model's reach. One COR with K_r free says how far the model reaches ([`fit_k_r`]'s range).
fn verify_exact(
    p: &CorProblem,
    sol: &Best,
    pred: &[(f64, f64, Option<f64>)],
) -> Result<(), MultiFitError> {
    let rel = |m: f64, d: f64| (m - d).abs() <= verdict::EXACT_MISS * d.abs().max(1e-300);
    let hit = p.points.iter().zip(pred).all(|(q, (e, f, t))| {
        rel(*e, q.cor)
            && q.max_force.is_none_or(|m| rel(*f, m))
            && q.contact_time.is_none_or(|m| t.is_some_and(|t| rel(t, m)))
    });
    let pressed: Vec<&str> = (0..p.free.len())
        .filter(|&j| verdict::on_bound(sol.sol.x[j], sol.lo[j], sol.hi[j]))
        .map(|j| p.free[j].name())
        .collect();
    if hit && pressed.is_empty() {
        return Ok(());
    }
    if let ([q], [Param::KR]) = (p.points, p.free.as_slice()) {
        let at = ImpactParams { v0: q.v0, ..p.base };
        if let Err(e @ super::FitError::OutOfReach { .. }) = fit_k_r(&at, p.law, q.cor) {
            return Err(MultiFitError::OutOfReach(format!(
                "{e} at v0 = {} m/s",
                crate::text::sig(q.v0, 4)
            )));
        }
    }
    let closest: Vec<String> = p
        .points
        .iter()
        .zip(pred)
        .map(|(q, (e, _, _))| format!("COR {} for {}", sig(*e, 4), sig(q.cor, 4)))
        .collect();
    Err(MultiFitError::OutOfReach(format!(
        "out of reach: the model comes no closer than {}{}",
        closest.join(", "),
        if pressed.is_empty() {
            String::new()
        } else {
            format!(" ({} on the bound of the search)", pressed.join(", "))
        }
    )))
}

fn check_free(free: &[Param]) -> Result<(), MultiFitError> {
    if free.is_empty() {
        return Err(MultiFitError::NoFree);
    }
    for (i, p) in free.iter().enumerate() {
        if free[..i].contains(p) {
            return Err(MultiFitError::Repeated(*p));
        }
    }
    if free.contains(&Param::KP) && free.contains(&Param::KH) {
        return Err(MultiFitError::Tied);
    }
    Ok(())
}

fn too_few(points: usize, parameters: usize) -> Result<(), MultiFitError> {
    if points < parameters {
        return Err(MultiFitError::TooFew { points, parameters });
    }
    Ok(())
}

/// s² = Σr²/(n − p) at a minimum.
fn variance(s: &Solution) -> f64 {
    2.0 * s.cost / s.residuals.len().saturating_sub(s.x.len()).max(1) as f64
}

fn rms(r: &[f64]) -> f64 {
    (r.iter().map(|v| v * v).sum::<f64>() / r.len().max(1) as f64).sqrt()
}

/// A minimum and the box it was searched in.
pub(super) struct Best {
    pub sol: Solution,
    pub lo: Vec<f64>,
    pub hi: Vec<f64>,
}

/// Whether a solution's residuals and Jacobian are finite numbers (the SVD of the uncertainty
/// is undefined otherwise).
fn finite(s: &Solution) -> bool {
    s.residuals.iter().all(|r| r.is_finite()) && s.jacobian.iter().all(|j| j.is_finite())
}

/// The lowest minimum over `starts`; stops early once the RMS residual is at `floor`, or when
/// two starts have converged to the same lowest cost (to 1e-9) where the data pin every
/// parameter: the restarts are there to escape a local minimum, and two ways into the same
/// one make another unlikely. (A flat region, where a parameter has no effect, is not such a
/// minimum: two starts in it would agree and stop the search too early.)
fn best<P: Residuals>(
    p: &P,
    starts: Vec<Vec<f64>>,
    bounds: impl Fn(&[f64]) -> (Vec<f64>, Vec<f64>),
    floor: f64,
) -> Option<Best> {
    // the most promising start first: one evaluation each
    let mut starts: Vec<(f64, Vec<f64>)> = starts
        .into_iter()
        .filter_map(|x0| Some((p.residuals(&x0).map(|r| rms(&r))?, x0)))
        .collect();
    starts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut best: Option<Best> = None;
    let mut iterations = 0;
    for (_, x0) in starts {
        let (lo, hi) = bounds(&x0);
        let Some(s) = lm::minimize(p, &x0, &lo, &hi, lm::Options::default()) else {
            continue;
        };
        iterations += s.iterations;
        let same = best.as_ref().map(|b| &b.sol).is_some_and(|b| {
            b.converged
                && (s.cost - b.cost).abs() <= (1e-9 * b.cost).max(1e-3 * variance(b))
                && finite(&s)
                && uncertainty(&s.jacobian, &s.residuals).condition < CONDITION_MAX
        });
        let done = s.converged && (rms(&s.residuals) <= floor || same);
        let done = done && s.residuals.iter().all(|r| r.is_finite());
        if best.as_ref().is_none_or(|b| s.cost < b.sol.cost) {
            best = Some(Best { sol: s, lo, hi });
        }
        if done {
            break;
        }
    }
    best.map(|mut b| {
        b.sol.iterations = iterations;
        b
    })
}

/// Estimates, correlations and warnings at the minimum `sol`.
fn finish(
    params: ImpactParams,
    law: ContactLaw,
    free: &[Param],
    best: &Best,
    t_dof: Option<usize>,
    rms_residual: f64,
    model: Vec<f64>,
) -> Result<MultiFit, MultiFitError> {
    let sol = &best.sol;
    if !finite(sol) || !rms_residual.is_finite() {
        return Err(MultiFitError::NonFinite);
    }
    let mut u = uncertainty(&sol.jacobian, &sol.residuals);
    if let Some(d) = t_dof {
        u.t975 = super::stats::t975(d);
    }
    let k = free.len();
    // a trace has the contact start and the baseline after the parameters
    let trace = sol.x.len() > k;
    let se = |j: usize| u.covariance[(j, j)].sqrt();
    let mut fitted: Vec<Estimate> = free
        .iter()
        .enumerate()
        .map(|(j, p)| {
            // an interval symmetric in ln p: exp(θ ± t s_θ); the standard error by the delta
            // method, s_p = p s_θ
            let (theta, s) = (sol.x[j], se(j));
            Estimate {
                name: p.name(),
                unit: p.unit(),
                value: theta.exp(),
                std_error: theta.exp() * s,
                ci95: [(theta - u.t975 * s).exp(), (theta + u.t975 * s).exp()],
            }
        })
        .collect();
    let linear = |j: usize, name, unit| Estimate {
        name,
        unit,
        value: sol.x[j],
        std_error: se(j),
        ci95: [sol.x[j] - u.t975 * se(j), sol.x[j] + u.t975 * se(j)],
    };
    let (time_offset, baseline) = if trace {
        (
            Some(linear(k, "time_offset", "s")),
            Some(linear(k + 1, "baseline", "N")),
        )
    } else {
        (None, None)
    };
    let mut names: Vec<&'static str> = fitted.iter().map(|e| e.name).collect();
    names.extend(time_offset.iter().chain(&baseline).map(|e| e.name));
    let n = names.len();
    let correlation = (0..n)
        .map(|i| (0..n).map(|j| u.correlation[(i, j)]).collect())
        .collect();
    let warnings = warnings(&fitted, &names, &u, sol);
    for e in &mut fitted {
        if !e.std_error.is_finite() {
            e.ci95 = [f64::NAN, f64::NAN];
        }
    }
    let not_pinned = verdict::not_pinned(&fitted, best, names.len());
    let on_bound = (0..free.len())
        .filter(|&j| verdict::on_bound(sol.x[j], best.lo[j], best.hi[j]))
        .map(|j| free[j].name())
        .collect();
    Ok(MultiFit {
        params,
        law,
        fitted,
        time_offset,
        baseline,
        names,
        correlation,
        rms_residual,
        points: sol.residuals.len(),
        iterations: sol.iterations,
        converged: sol.converged,
        condition: u.condition,
        warnings,
        model,
        identified: false,
        not_pinned,
        on_bound,
        lack_of_fit: None,
    })
}

fn warnings(
    fitted: &[Estimate],
    names: &[&str],
    u: &super::stats::Uncertainty,
    sol: &Solution,
) -> Vec<String> {
    let mut w = Vec::new();
    let dof = sol.residuals.len().saturating_sub(names.len());
    if dof == 0 {
        w.push(
            "as many data as parameters: no residual is left to estimate the uncertainty".into(),
        );
    }
    if u.condition > CONDITION_MAX {
        w.push(format!(
            "{} is not identifiable from these data: the fit cannot tell it from the other \
             parameters (condition number {:.1e}); fix it (leave it out of --free) or add data",
            names[u.weakest], u.condition
        ));
    }
    for e in fitted {
        if dof > 0 && e.std_error.is_finite() && e.ci95[1] - e.ci95[0] > e.value {
            w.push(format!(
                "the 95 % interval of {} is wider than its value: the data barely pin it",
                e.name
            ));
        }
    }
    if !sol.converged {
        w.push(format!(
            "the fit stopped after {} iterations without converging",
            sol.iterations
        ));
    }
    w
}
