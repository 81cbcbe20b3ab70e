//! One work limit, checked before any work, for the command line and the library's sweeps
//! alike ([`crate::sweep_zeta`], [`crate::Ball::sweep_velocity`], and through them the Python
//! package).
//!
//! The work of a request is the number of impacts it solves, each weighted by the cost of its
//! law: the linear law runs the exact solver (about 7 µs an impact, optimized build), the
//! elastic–plastic and Hertz laws the adaptive one, some 40 times slower on the normalized
//! ball of the ζ sweeps (`--law hertz --points 20000` took 17.5 s for 60 000 impacts). A
//! request whose work exceeds [`LIMIT`] (about 7 s on one core) is refused before it starts:
//! `figure cor-zeta --points 20000 --lambda <500 values>` had run 67 s and written 628 MB.
//! (tests/cli/cli_guarantees.rs, `work_beyond_the_limit_is_refused_before_it_starts`.) The lower
//! layer, [`super::sweep::cor_vs_zeta`] and [`super::sweep::cor_vs_velocity`], applies no
//! limit: code that means to run more calls it.

use crate::model::contact::ContactLaw;
use std::fmt;

/// The most work a request may ask for, in linear-law impacts.
pub const LIMIT: u64 = 1_000_000;

/// What one impact costs under `law`, in linear-law impacts.
pub fn cost(law: ContactLaw) -> u64 {
    match law {
        ContactLaw::Linear => 1,
        _ => 40,
    }
}

/// Linear-law Monte Carlo samples that count as one impact: each is solved in closed form
/// ([`crate::map::fast`], some 0.3 µs against the exact solver's 2–3 µs, BENCHMARKS.md) unless
/// the ball flattens. 10⁷ samples are then the limit, as 10⁶ impacts are.
pub const SAMPLES_PER_IMPACT: u64 = 10;

/// Refuse a Monte Carlo of `samples` samples under `law` beyond the limit: a linear-law
/// sample counts 1/[`SAMPLES_PER_IMPACT`] of an impact, any other a whole impact.
pub fn check_samples(samples: usize, law: ContactLaw) -> Result<(), TooMuchWork> {
    check_samples_by(samples, law, Nominal::Solver)
}

/// Which path answers a Monte Carlo's nominal ball (`Ball::check_samples` decides): its
/// samples are counted by what that path costs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nominal {
    /// The adaptive solver may answer: a whole impact a sample.
    Solver,
    /// The Hertz table (under the elastic–plastic law: the impact stays below yield, where it
    /// is the Hertz impact, `solver::taylor::plastic`).
    Table,
    /// The Taylor steps, under the elastic–plastic law past yield.
    TaylorSteps,
}

/// Elastic–plastic samples past yield, each on the Taylor steps, that count as one impact
/// (of [`cost`] 40): a sample costs 2 of the work's units (a unit some 7 µs, [`LIMIT`] some
/// 7 s), about what the Taylor steps cost past yield: ≈ 73 000 instructions, 10–11 µs
/// (BENCHMARKS.md, "Fifth session (ep6)").
pub const TAYLOR_SAMPLES_PER_IMPACT: u64 = 20;

/// Refuse a Monte Carlo of `samples` samples under `law` whose nominal ball `nominal`
/// answers, beyond the limit. A linear-law sample counts 1/[`SAMPLES_PER_IMPACT`] of an
/// impact. Under Hertz and the elastic–plastic law a sample of a ball the Hertz table answers
/// counts 1/[`cost`] of an impact, some 7 µs of work — a sample the table answers takes some
/// 0.35 µs, one the spreads carry onto the Taylor steps some 15 µs (BENCHMARKS.md), so 10⁶
/// of them are the limit; an elastic–plastic sample past yield counts
/// 1/[`TAYLOR_SAMPLES_PER_IMPACT`] (500 000 the limit); any other a whole impact (25 000).
/// The nominal ball decides for every sample (the rule [`check_elements`] applies element by
/// element): of a ball below yield, the spreads may carry samples past it, each then costing
/// the Taylor steps' 10–15 µs against the 7 µs it counts — at worst, every sample past
/// yield, about twice the time [`LIMIT`] stands for (docs/guarantees.md).
pub fn check_samples_by(
    samples: usize,
    law: ContactLaw,
    nominal: Nominal,
) -> Result<(), TooMuchWork> {
    let n = samples as u64;
    let (impacts, what) = match (law, nominal) {
        (ContactLaw::Linear, _) => (
            n.div_ceil(SAMPLES_PER_IMPACT),
            format!(
                "{samples} samples ({SAMPLES_PER_IMPACT} linear-law samples count as one impact)"
            ),
        ),
        (ContactLaw::Hertz, Nominal::Table) => (
            n.div_ceil(cost(law)),
            format!(
                "{samples} samples ({} Hertz-law samples of a ball the Hertz table answers \
                 count as one impact)",
                cost(law)
            ),
        ),
        (ContactLaw::ElasticPlastic, Nominal::Table) => (
            n.div_ceil(cost(law)),
            format!(
                "{samples} samples ({} elastic-plastic-law samples of a ball the Hertz table \
                 answers below yield count as one impact)",
                cost(law)
            ),
        ),
        (ContactLaw::ElasticPlastic, Nominal::TaylorSteps) => (
            n.div_ceil(TAYLOR_SAMPLES_PER_IMPACT),
            format!(
                "{samples} samples ({TAYLOR_SAMPLES_PER_IMPACT} elastic-plastic-law samples \
                 past yield count as one impact)"
            ),
        ),
        _ => (n, format!("{samples} samples")),
    };
    // what a Monte Carlo's user can change is the number of samples (`mc` said "ask for
    // fewer points or values", which it takes none of: issue 52's trial)
    check(impacts as usize, law, &what).map_err(|e| TooMuchWork {
        ask: "ask for fewer samples",
        ..e
    })
}

/// `bouncelab.impacts`' elements by the path that answers each (`api::first_pass` finds it
/// before any runs): the Hertz table's, the Taylor steps' past yield, or a whole impact's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Elements {
    /// All of them.
    pub n: usize,
    /// Those the Hertz table does not answer (outside it, or no rebound there): the Taylor
    /// steps or the adaptive solver, a whole impact each.
    pub off_table: usize,
    /// Elastic–plastic ones whose Hertz impact the table holds but which reach yield: the
    /// Taylor steps, 1/[`TAYLOR_SAMPLES_PER_IMPACT`] of an impact each.
    pub past_yield: usize,
}

impl Elements {
    /// `n` elements at the least they can cost: all answered by the table (or, on the linear
    /// law, by the closed forms).
    pub fn at_least(n: usize) -> Elements {
        Elements {
            n,
            off_table: 0,
            past_yield: 0,
        }
    }
}

/// Refuse the elements `e` of `bouncelab.impacts` (`api::first_pass`) under `law` beyond the
/// limit, each counted by the path that answers it. A linear-law element counts as a Monte
/// Carlo sample ([`check_samples`]). Under Hertz and the elastic–plastic law an element the
/// Hertz table answers (under the elastic–plastic law: below yield, where the impact is the
/// Hertz one) counts 1/[`cost`] of an impact (the table's 0.3 µs; [`check_samples_by`]'s
/// `Table`); an elastic–plastic element past yield 1/[`TAYLOR_SAMPLES_PER_IMPACT`] (the Taylor
/// steps' 10–11 µs); any other a whole impact (the Taylor steps or the adaptive solver). The
/// count is each element's own: the first pass found its path before anything ran.
pub fn check_elements(law: ContactLaw, e: Elements) -> Result<(), TooMuchWork> {
    if law == ContactLaw::Linear {
        return check_samples(e.n, law);
    }
    let per_impact = cost(law);
    let off = e.off_table.min(e.n);
    let past = e.past_yield.min(e.n - off);
    let table = (e.n - off - past) as u64;
    // in 1/40 of an impact: the table's 1 each, the Taylor steps' past yield 2, a whole 40
    let per_taylor = per_impact / TAYLOR_SAMPLES_PER_IMPACT;
    let units = (off as u64 * per_impact)
        .saturating_add(past as u64 * per_taylor)
        .saturating_add(table);
    let held = match law {
        ContactLaw::Hertz => "the Hertz table holds",
        _ => "the Hertz table holds below yield",
    };
    let mut parts = Vec::new();
    if off > 0 {
        parts.push(format!(
            "{off} of them outside the Hertz table, a whole impact each"
        ));
    }
    if past > 0 {
        parts.push(format!(
            "{past} past yield, {TAYLOR_SAMPLES_PER_IMPACT} to an impact"
        ));
    }
    let what = if parts.is_empty() {
        format!(
            "{} elements ({per_impact} elements {held} count as one impact)",
            e.n
        )
    } else {
        format!(
            "{} elements ({}; {per_impact} of the others count as one impact)",
            e.n,
            parts.join("; ")
        )
    };
    let impacts = units.div_ceil(per_impact);
    check(usize::try_from(impacts).unwrap_or(usize::MAX), law, &what)
}

/// How a sweep's or a fit's user asks for less work.
const ASK_FEWER: &str = "ask for fewer points or values";

/// A request beyond [`LIMIT`]; its message says how much and how to ask for less.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TooMuchWork {
    /// How the impacts were asked for ("500 λ values × 20000 points").
    pub what: String,
    /// Impacts asked for.
    pub impacts: usize,
    /// Their contact law.
    pub law: ContactLaw,
    /// Their work, impacts × [`cost`].
    pub work: u64,
    /// How to ask for less ("ask for fewer points or values", "ask for fewer samples").
    pub ask: &'static str,
}

impl fmt::Display for TooMuchWork {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let TooMuchWork {
            what,
            impacts,
            law,
            work,
            ask,
        } = self;
        write!(
            f,
            "too much work: {what} is {impacts} {law}-law impacts, worth {work} against the \
             work limit of {LIMIT} (an impact counts 1 with the linear law, {} with the \
             others); {ask}",
            cost(ContactLaw::Hertz)
        )
    }
}

impl std::error::Error for TooMuchWork {}

/// Refuse `impacts` impacts under `law` beyond the limit; `what` says how they were asked
/// for ("500 λ values × 20000 points").
pub fn check(impacts: usize, law: ContactLaw, what: &str) -> Result<(), TooMuchWork> {
    let work = (impacts as u64).saturating_mul(cost(law));
    if work > LIMIT {
        return Err(TooMuchWork {
            what: what.to_string(),
            impacts,
            law,
            work,
            ask: ASK_FEWER,
        });
    }
    Ok(())
}

/// Long library work watched from outside (a fit's model runs): after each step it is told
/// how many steps are done and answers whether to go on. The library does no I/O; the watcher
/// draws the progress bar and reads Ctrl-C (`cli::budget`) or asks Python for a
/// KeyboardInterrupt.
pub trait Watch {
    /// `done` steps are done; `false` stops the work (it then ends with an "interrupted"
    /// error and no answer).
    fn step(&self, done: u64) -> bool;
}

/// No one watching: the work always goes on.
pub struct Unwatched;

impl Watch for Unwatched {
    fn step(&self, _done: u64) -> bool {
        true
    }
}

/// Impacts run between two looks of a [`Watch`] at a sweep: some 10 ms of work on one core
/// (linear law ≈ 7 µs an impact, the others 40 times that).
pub fn chunk(law: ContactLaw) -> usize {
    (1_024 / cost(law)).max(1) as usize
}

/// Most Levenberg–Marquardt iterations a start of a fit takes (`fit::lm::Options`).
pub const FIT_ITERATIONS: usize = 200;

/// Fewest iterations worth a start: a fit whose work allows fewer is refused before it
/// starts (fits converge in 5–30, BENCHMARKS.md).
pub const FIT_MIN_ITERATIONS: usize = 10;

/// Samples interpolated that cost about as much as one linear-law impact (a few tens of ns
/// each, against the exact solver's microseconds: benches/fit.rs, see [`HISTORY_PER_IMPACT`]).
pub const POINTS_PER_IMPACT: u64 = 100;

/// History samples that cost about one impact more each run: a trace fit's model runs record
/// the force at `history` times (benches/fit.rs: a linear-law run with 640 history samples and
/// 2 000 rows interpolated takes ≈ 240 µs, some 34 exact-solver impacts).
pub const HISTORY_PER_IMPACT: u64 = 100;

/// What one model run of a fit costs, in linear-law impacts: a trace fit's, one impact under
/// `law` recorded at `history` times and an interpolation at `samples` times (its rows or
/// bins, `fit::bins`); a COR table's, one impact a row (`samples` rows, no history).
pub fn fit_run_cost(samples: usize, history: usize, law: ContactLaw) -> u64 {
    if history > 0 {
        let recorded = 1 + (history as u64).div_ceil(HISTORY_PER_IMPACT);
        cost(law) * recorded + (samples as u64).div_ceil(POINTS_PER_IMPACT)
    } else {
        (samples as u64).saturating_mul(cost(law))
    }
}

/// The iterations each start of a fit may take, so that its whole work stays within
/// [`LIMIT`]: [`FIT_ITERATIONS`], fewer where a model run costs much (`run_cost`, from
/// [`fit_run_cost`]); a refusal when fewer than [`FIT_MIN_ITERATIONS`] would be left. A start
/// costs its ranking run, its first residuals and Jacobian (`vars` + 2 runs) and per
/// iteration a trial and a Jacobian (`vars` + 2 runs: a trace's slope is one more).
pub fn fit_iterations(
    run_cost: u64,
    vars: usize,
    starts: usize,
    law: ContactLaw,
    what: impl FnOnce() -> String,
) -> Result<usize, TooMuchWork> {
    let per_iteration = (vars as u64 + 2).saturating_mul(run_cost);
    let first = (vars as u64 + 3).saturating_mul(run_cost);
    let starts = starts.max(1) as u64;
    let budget = LIMIT / starts;
    let iterations = budget.saturating_sub(first) / per_iteration.max(1);
    if iterations < FIT_MIN_ITERATIONS as u64 {
        let least = first + FIT_MIN_ITERATIONS as u64 * per_iteration;
        let runs = starts * (vars as u64 + 3 + FIT_MIN_ITERATIONS as u64 * (vars as u64 + 2));
        return Err(TooMuchWork {
            what: format!(
                "{} ({} starts of at least {FIT_MIN_ITERATIONS} iterations, {runs} model runs)",
                what(),
                starts
            ),
            impacts: (runs.saturating_mul(run_cost) / cost(law).max(1)) as usize,
            law,
            work: least.saturating_mul(starts),
            ask: ASK_FEWER,
        });
    }
    Ok((iterations as usize).min(FIT_ITERATIONS))
}

#[cfg(test)]
mod tests;
