//! μ, K_t (and κ when the outgoing spin is measured) fitted to measured oblique bounces
//! (docs/oblique.md §9): the rows' outgoing v_x (and R ω_out) against the oblique model's, by
//! the fits' own bounded Levenberg–Marquardt ([`super::lm`]) in the logarithms of the
//! parameters, with intervals from the profile ([`super::profile`]; the Jacobian's,
//! [`super::stats`], where the profile's refits would pass the work limit) and the same
//! verdict ([`super::verdict`]: converged, every parameter pinned, none on its bound) as the
//! other fits. The normal impact of each row does not depend on μ, K_t or κ: it is solved once
//! (`oblique::NormalAt`) and only the tangential motion is run at each evaluation.

use super::lm::{self, Residuals};
use super::profile;
use super::{Estimate, MultiFitError};
use crate::analysis::work::{self, Watch};
use crate::measured::ObliqueRow;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::oblique::{NormalAt, Oblique};
use std::cell::Cell;

mod finish;
mod starts;
use finish::{Search, finish, rms_pair};
use starts::{bounds, starting_points};

/// The ball and where the fit starts: μ, K_t and κ are the starting values (κ is held when
/// the rows carry no outgoing spin).
#[derive(Debug, Clone, Copy)]
pub struct ObliqueStart {
    /// The ball (its normal model is held).
    pub params: ImpactParams,
    /// The contact law of the normal impact.
    pub law: ContactLaw,
    /// R (m).
    pub radius: f64,
    /// μ to start from; `None`: the largest apparent friction of the rows.
    pub friction: Option<f64>,
    /// K_t (N/m) to start from.
    pub tangential_stiffness: f64,
    /// κ to start from, or to hold.
    pub inertia_factor: f64,
    /// The tangential dashpot c_t (kg/s, > 0) to start a fit of it from; `None`: no dashpot,
    /// not fitted.
    pub tangential_damping: Option<f64>,
}

/// The fitted tangential model and how well the data pin it.
#[derive(Debug, Clone)]
pub struct ObliqueFit {
    /// `friction`, `tangential_stiffness` and, with spins, `inertia_factor`.
    pub fitted: Vec<Estimate>,
    /// κ as used: fitted, or held at the start's.
    pub inertia_factor: f64,
    /// c_t as fitted (kg/s), when it was (`ObliqueStart::tangential_damping`).
    pub tangential_damping: Option<f64>,
    /// The correlations between the fitted quantities, in the order of `fitted`.
    pub correlation: Vec<Vec<f64>>,
    /// RMS of the model's v_x,out − the data's (m/s).
    pub rms_vx: f64,
    /// RMS of the model's ω_out − the data's (rad/s), when measured.
    pub rms_spin: Option<f64>,
    /// RMS of the normal model's v_y,out − the data's (m/s): not fitted here (μ, K_t and κ do
    /// not move it); large, it says the normal ball is not this one.
    pub rms_vy: f64,
    /// The model's (v_x,out, ω_out) at each row.
    pub model: Vec<(f64, f64)>,
    /// Residuals fitted (a row's v_x, and its spin when measured).
    pub points: usize,
    /// Levenberg–Marquardt iterations over every start.
    pub iterations: usize,
    /// The best start met a convergence test.
    pub converged: bool,
    /// Condition number of the column-scaled Jacobian.
    pub condition: f64,
    /// What the caller should know, one line each.
    pub warnings: Vec<String>,
    /// Converged, every fitted quantity pinned, none on its bound.
    pub identified: bool,
    /// The fitted quantities the data do not pin (`verdict::pinned`).
    pub not_pinned: Vec<&'static str>,
    /// The fitted quantities that ran to the bound of their search.
    pub on_bound: Vec<&'static str>,
    /// Degrees of freedom were left but every residual is zero: the data show no scatter to
    /// estimate the uncertainty from (`verdict::NO_SCATTER`; no standard error or interval),
    /// as `MultiFit::no_scatter`.
    pub no_scatter: bool,
}

impl ObliqueFit {
    /// Whether the fit had as many data as quantities fitted, or residuals all zero
    /// ([`ObliqueFit::no_scatter`]): the values solve the data exactly and no standard error
    /// or interval can be estimated (`MultiFit::exact`).
    pub fn exact(&self) -> bool {
        self.points <= self.fitted.len() || self.no_scatter
    }
}

/// What one row of one evaluation costs, in linear-law impacts: a row's normal impact is
/// solved once (`NormalAt`), and an evaluation runs only its tangential motion — 9.25 k
/// instructions a row against 12.56 k for the row's normal impact alone (callgrind, 27 rows
/// of 8–75°, `evaluation_cost` in tests/analysis/fit_oblique_coverage.rs; BENCHMARKS.md "The oblique
/// fit's evaluations"): 0.74 of an impact, priced as one.
const OBLIQUE_COST: u64 = 1;

struct Problem<'a> {
    rows: &'a [ObliqueRow],
    normals: Vec<NormalAt>,
    radius: f64,
    /// κ when held (no spins measured).
    kappa: Option<f64>,
    /// Where ln c_t is in x when it is fitted (last), else none.
    damping: Option<usize>,
    /// The fitted quantities' names, in the order of x.
    names: Vec<&'static str>,
    /// The weight of the spin residuals: R, then the ratio of the two kinds' scatter.
    spin_weight: Cell<f64>,
    watch: &'a dyn Watch,
    /// Evaluations run, and whether the watch stopped the fit.
    runs: Cell<u64>,
    halted: Cell<bool>,
}

impl Problem<'_> {
    fn spins(&self) -> bool {
        self.kappa.is_none()
    }

    /// (v_x,out, ω_out) of every row at x = (ln μ, ln K_t[, ln κ]).
    fn predict(&self, x: &[f64]) -> Option<Vec<(f64, f64)>> {
        let runs = self.runs.get() + 1;
        self.runs.set(runs);
        if self.halted.get() || !self.watch.step(runs) {
            self.halted.set(true);
            return None;
        }
        let kappa = self.kappa.unwrap_or_else(|| x[2].exp());
        let c_t = self.damping.map_or(0.0, |j| x[j].exp());
        self.rows
            .iter()
            .zip(&self.normals)
            .map(|(row, n)| {
                let o = Oblique::new(
                    row.angle_deg,
                    row.spin_in,
                    x[0].exp(),
                    x[1].exp(),
                    kappa,
                    self.radius,
                )
                .and_then(|o| o.with_tangential_damping(c_t))
                .ok()?;
                let r = n.solve(&o, 0).ok()?;
                Some((r.vx_out, r.spin_out))
            })
            .collect()
    }
}

impl Residuals for Problem<'_> {
    fn residuals(&self, x: &[f64]) -> Option<Vec<f64>> {
        let pred = self.predict(x)?;
        let w = self.spin_weight.get();
        let mut r: Vec<f64> = pred
            .iter()
            .zip(self.rows)
            .map(|(p, q)| p.0 - q.vx_out)
            .collect();
        if self.spins() {
            let spins = pred.iter().zip(self.rows);
            r.extend(spins.map(|(p, q)| w * (p.1 - q.spin_out.unwrap_or(f64::NAN))));
        }
        Some(r)
    }
    fn step(&self, _j: usize) -> f64 {
        1e-6
    }
    fn max_step(&self, _j: usize) -> f64 {
        2.0
    }
    fn stopped(&self) -> bool {
        self.halted.get()
    }
}

const NAMES: [&str; 4] = [
    "friction",
    "tangential_stiffness",
    "inertia_factor",
    "tangential_damping",
];

/// Fit μ and K_t (and κ when every row gives `spin_out`, and c_t when the start names one)
/// to `rows`; each evaluation is
/// reported to `watch`, which may stop the fit ([`MultiFitError::Interrupted`]); the work is
/// checked against the work limit before it starts.
pub fn fit_oblique(
    start: &ObliqueStart,
    rows: &[ObliqueRow],
    watch: &dyn Watch,
) -> Result<ObliqueFit, MultiFitError> {
    let p = Problem::new(start, rows, watch)?;
    let (spins, damped) = (p.spins(), p.damping.is_some());
    let x0 = first_point(start, &p);
    let starts = starting_points(&x0, spins, damped);
    let refits = if spins { REFINED } else { 0 };
    let vars = p.names.len();
    let (iterations, profiled) = budget(start, rows.len(), vars, starts.len() + refits)?;
    let (lo, hi) = bounds(&x0, spins, damped);
    let opts = lm::Options {
        max_iterations: iterations,
        ..lm::Options::default()
    };
    let found = minimize_each(&p, starts, &lo, &hi, opts).ok_or_else(|| no_minimum(&p))?;
    let mut iterations: usize = found.iter().map(|s| s.iterations).sum();
    let mut best = found[0].clone();
    if spins && let Some(refined) = refit_weighed(&p, &found, &lo, &hi, opts)? {
        iterations += refined.iter().map(|s| s.iterations).sum::<usize>();
        best = refined[0].clone();
    }
    best.iterations = iterations;
    let search = Search {
        lo: &lo,
        hi: &hi,
        opts,
        profiled,
    };
    finish(&p, best, &search)
}

impl<'a> Problem<'a> {
    /// The fit of `rows` from `start`, each row's normal impact solved once; an error when
    /// the rows give fewer residuals than there are quantities to fit, or a normal impact
    /// has no answer.
    fn new(
        start: &ObliqueStart,
        rows: &'a [ObliqueRow],
        watch: &'a dyn Watch,
    ) -> Result<Self, MultiFitError> {
        let spins = rows.iter().all(|r| r.spin_out.is_some());
        let damped = start.tangential_damping.is_some();
        let vars = 2 + usize::from(spins) + usize::from(damped);
        let count = rows.len() * if spins { 2 } else { 1 };
        if count < vars {
            return Err(MultiFitError::TooFew {
                points: count,
                parameters: vars,
            });
        }
        let normals = rows
            .iter()
            .map(|r| NormalAt::new(&start.params, start.law, r.v0, r.angle_deg))
            .collect::<Result<Vec<_>, _>>()
            .map_err(|_| MultiFitError::NoAnswer)?;
        Ok(Problem {
            rows,
            normals,
            radius: start.radius,
            kappa: (!spins).then_some(start.inertia_factor),
            damping: damped.then_some(vars - 1),
            names: (0..vars)
                .map(|j| {
                    if damped && j == vars - 1 {
                        NAMES[3]
                    } else {
                        NAMES[j]
                    }
                })
                .collect(),
            spin_weight: Cell::new(start.radius),
            watch,
            runs: Cell::new(0),
            halted: Cell::new(false),
        })
    }
}

/// Where the search starts, x = (ln μ, ln K_t[, ln κ][, ln c_t]): the start's values, μ the
/// rows' largest apparent friction when the start names none.
fn first_point(start: &ObliqueStart, p: &Problem) -> Vec<f64> {
    let mu0 = start
        .friction
        .unwrap_or_else(|| apparent_friction(p.rows, p));
    let mut x0 = vec![mu0.max(1e-3).ln(), start.tangential_stiffness.ln()];
    if p.spins() {
        x0.push(start.inertia_factor.ln());
    }
    if let Some(c) = start.tangential_damping {
        x0.push(c.ln());
    }
    x0
}

/// The iterations each of `fits` starts may take under the work limit, and whether the
/// intervals can be the profile's: its fits count as starts; where they would pass the
/// limit, the intervals are the Jacobian's, and a warning says so.
fn budget(
    start: &ObliqueStart,
    rows: usize,
    vars: usize,
    fits: usize,
) -> Result<(usize, bool), MultiFitError> {
    let run = (rows as u64) * OBLIQUE_COST * work::cost(start.law).min(4);
    let what = || format!("an oblique fit of {vars} parameters to {rows} rows");
    let profiles = fits + 2 * vars * profile::FITS_PER_SIDE;
    Ok(
        match work::fit_iterations(run, vars, profiles, start.law, what) {
            Ok(iterations) => (iterations, true),
            Err(_) => (
                work::fit_iterations(run, vars, fits, start.law, what)?,
                false,
            ),
        },
    )
}

/// Why no minimum came back: the watch stopped the fit, or no start gave an answer.
fn no_minimum(p: &Problem) -> MultiFitError {
    if p.stopped() {
        MultiFitError::Interrupted
    } else {
        MultiFitError::NoAnswer
    }
}

/// With spins: the spins weighed by the scatter of the two kinds, then fitted again from
/// there (as a COR table of mixed kinds is, `multi::fit_cor`) — from each of the best
/// distinct minima of `found`, not only the best: the weights move the minima, and the one
/// that was best under the first weights need not be under the second
/// (`spins_do_not_stop_in_a_local_minimum`, tests/analysis/fit_oblique_coverage.rs).
/// The new minima, best first; none when either kind shows no scatter.
fn refit_weighed(
    p: &Problem,
    found: &[lm::Solution],
    lo: &[f64],
    hi: &[f64],
    opts: lm::Options,
) -> Result<Option<Vec<lm::Solution>>, MultiFitError> {
    let pred = p.predict(&found[0].x).ok_or(MultiFitError::NoAnswer)?;
    let (vx, spin) = rms_pair(&pred, p.rows);
    if vx > 0.0 && spin > 0.0 {
        p.spin_weight.set(vx / spin);
        let again = distinct(found, REFINED);
        let refined = minimize_each(p, again, lo, hi, opts).ok_or_else(|| no_minimum(p))?;
        Ok(Some(refined))
    } else {
        Ok(None)
    }
}

/// The largest apparent friction |Δv_x|/(v_y,in + v_y,out) of the rows: a row that slid
/// throughout shows μ itself, one that gripped less.
fn apparent_friction(rows: &[ObliqueRow], p: &Problem) -> f64 {
    rows.iter()
        .zip(&p.normals)
        .map(|(r, _)| {
            let theta = r.angle_deg.to_radians();
            let (vx, vy) = (r.v0 * theta.cos(), r.v0 * theta.sin());
            (vx - r.vx_out).abs() / (vy + r.vy_out)
        })
        .fold(0.0, f64::max)
}

/// The minimum from each start, best (lowest cost) first; `None` when stopped or when no
/// start gave an answer.
fn minimize_each(
    p: &Problem,
    starts: Vec<Vec<f64>>,
    lo: &[f64],
    hi: &[f64],
    opts: lm::Options,
) -> Option<Vec<lm::Solution>> {
    let mut found = Vec::new();
    for x0 in starts {
        if p.stopped() {
            return None;
        }
        found.extend(lm::minimize(p, &x0, lo, hi, opts));
    }
    found.sort_by(|a, b| a.cost.total_cmp(&b.cost));
    (!found.is_empty()).then_some(found)
}

/// How many of the first fit's distinct minima the spin-weighted fit starts from.
const REFINED: usize = 3;

/// The first `most` minima of `found` (best first) that lie apart — by more than 1e-4 in
/// some logarithm — from every one kept before.
fn distinct(found: &[lm::Solution], most: usize) -> Vec<Vec<f64>> {
    let mut kept: Vec<Vec<f64>> = Vec::new();
    for s in found {
        let apart = |k: &Vec<f64>| k.iter().zip(&s.x).any(|(a, b)| (a - b).abs() > 1e-4);
        if kept.len() < most && kept.iter().all(apart) {
            kept.push(s.x.clone());
        }
    }
    kept
}
