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
//! (tests/cli_guarantees.rs, `work_beyond_the_limit_is_refused_before_it_starts`.) The lower
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
    check(impacts as usize, law, &what)
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
}

impl fmt::Display for TooMuchWork {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let TooMuchWork {
            what,
            impacts,
            law,
            work,
        } = self;
        write!(
            f,
            "too much work: {what} is {impacts} {law}-law impacts, worth {work} against the \
             work limit of {LIMIT} (an impact counts 1 with the linear law, {} with the \
             others); ask for fewer points or values",
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
        });
    }
    Ok((iterations as usize).min(FIT_ITERATIONS))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_is_inclusive_and_weighs_the_law() {
        assert!(check(1_000_000, ContactLaw::Linear, "x").is_ok());
        assert!(check(1_000_001, ContactLaw::Linear, "x").is_err());
        assert!(check(25_000, ContactLaw::Hertz, "x").is_ok());
        let e = check(25_001, ContactLaw::ElasticPlastic, "25001 points").unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert_eq!(
            e.to_string(),
            "too much work: 25001 points is 25001 elastic-plastic-law impacts, worth 1000040 \
             against the work limit of 1000000 (an impact counts 1 with the linear law, 40 with \
             the others); ask for fewer points or values"
        );
    }

    #[test]
    fn monte_carlo_samples_count_a_tenth_on_the_linear_law() {
        assert!(check_samples(10_000_000, ContactLaw::Linear).is_ok());
        let e = check_samples(10_000_001, ContactLaw::Linear).unwrap_err();
        assert_eq!(e.work, 1_000_001);
        assert!(e.to_string().starts_with(
            "too much work: 10000001 samples (10 linear-law samples count as one impact) is \
             1000001 linear-law impacts"
        ));
        assert!(check_samples(25_000, ContactLaw::Hertz).is_ok());
        assert!(check_samples(25_001, ContactLaw::Hertz).is_err());
    }

    #[test]
    fn hertz_samples_the_table_answers_count_a_fortieth() {
        assert!(check_samples_by(1_000_000, ContactLaw::Hertz, Nominal::Table).is_ok());
        let e = check_samples_by(1_000_001, ContactLaw::Hertz, Nominal::Table).unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert!(e.to_string().starts_with(
            "too much work: 1000001 samples (40 Hertz-law samples of a ball the Hertz table \
             answers count as one impact) is 25001 hertz-law impacts"
        ));
        // an untabulated ball keeps a whole impact a sample
        assert!(check_samples_by(25_001, ContactLaw::Hertz, Nominal::Solver).is_err());
        assert!(check_samples_by(25_001, ContactLaw::ElasticPlastic, Nominal::Solver).is_err());
    }

    /// `n` elements, `off` of them outside the Hertz table, `past` past yield.
    fn elements(n: usize, off: usize, past: usize) -> Elements {
        Elements {
            n,
            off_table: off,
            past_yield: past,
        }
    }

    #[test]
    fn elements_count_by_whether_the_hertz_table_holds_them() {
        let (linear, hertz) = (ContactLaw::Linear, ContactLaw::Hertz);
        // the linear law: as Monte Carlo samples, ten to an impact
        assert!(check_elements(linear, Elements::at_least(10_000_000)).is_ok());
        assert!(check_elements(linear, Elements::at_least(10_000_001)).is_err());
        // Hertz: 40 held elements to an impact, one outside the table a whole impact
        assert!(check_elements(hertz, Elements::at_least(1_000_000)).is_ok());
        let e = check_elements(hertz, Elements::at_least(1_000_001)).unwrap_err();
        assert!(e.to_string().starts_with(
            "too much work: 1000001 elements (40 elements the Hertz table holds count as one \
             impact) is 25001 hertz-law impacts"
        ));
        assert!(check_elements(hertz, elements(25_000, 25_000, 0)).is_ok());
        let e = check_elements(hertz, elements(30_000, 30_000, 0)).unwrap_err();
        assert_eq!(e.work, 1_200_000);
        assert!(e.to_string().starts_with(
            "too much work: 30000 elements (30000 of them outside the Hertz table, a whole \
             impact each; 40 of the others count as one impact) is 30000 hertz-law impacts"
        ));
        // 12 000 outside and 520 000 held: 12 000 + 13 000 impacts, at the limit
        assert!(check_elements(hertz, elements(532_000, 12_000, 0)).is_ok());
        assert!(check_elements(hertz, elements(532_001, 12_001, 0)).is_err());
        // a count of more outside than there are elements is all of them
        let e = check_elements(hertz, elements(30_000, usize::MAX, 0)).unwrap_err();
        assert_eq!(e.work, 1_200_000);
    }

    #[test]
    fn elastic_plastic_elements_count_by_yield() {
        let ep = ContactLaw::ElasticPlastic;
        // below yield, the Hertz table's: 40 to an impact, so 10⁶ of them within the limit
        assert!(check_elements(ep, Elements::at_least(1_000_000)).is_ok());
        let e = check_elements(ep, Elements::at_least(1_000_001)).unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert!(e.to_string().starts_with(
            "too much work: 1000001 elements (40 elements the Hertz table holds below yield \
             count as one impact) is 25001 elastic-plastic-law impacts"
        ));
        // past yield, the Taylor steps': 20 to an impact
        assert!(check_elements(ep, elements(500_000, 0, 500_000)).is_ok());
        let e = check_elements(ep, elements(500_001, 0, 500_001)).unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert!(e.to_string().starts_with(
            "too much work: 500001 elements (500001 past yield, 20 to an impact; 40 of the \
             others count as one impact) is 25001 elastic-plastic-law impacts"
        ));
        // all three: 10 000 whole + 200 000 past yield (10 000) + 200 000 held (5 000)
        assert!(check_elements(ep, elements(410_000, 10_000, 200_000)).is_ok());
        let e = check_elements(ep, elements(410_001, 10_001, 200_000)).unwrap_err();
        assert!(e.to_string().starts_with(
            "too much work: 410001 elements (10001 of them outside the Hertz table, a whole \
             impact each; 200000 past yield, 20 to an impact; 40 of the others count as one \
             impact) is 25001 elastic-plastic-law impacts"
        ));
    }

    #[test]
    fn elastic_plastic_samples_count_by_their_path() {
        let ep = ContactLaw::ElasticPlastic;
        // below yield: the Hertz table's cost, 1/40 of an impact
        assert!(check_samples_by(1_000_000, ep, Nominal::Table).is_ok());
        let e = check_samples_by(1_000_001, ep, Nominal::Table).unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert!(e.to_string().starts_with(
            "too much work: 1000001 samples (40 elastic-plastic-law samples of a ball the \
             Hertz table answers below yield count as one impact) is 25001"
        ));
        // past yield: the Taylor steps', 1/20
        assert!(check_samples_by(500_000, ep, Nominal::TaylorSteps).is_ok());
        let e = check_samples_by(500_001, ep, Nominal::TaylorSteps).unwrap_err();
        assert_eq!(e.work, 1_000_040);
        assert!(e.to_string().starts_with(
            "too much work: 500001 samples (20 elastic-plastic-law samples past yield count \
             as one impact) is 25001 elastic-plastic-law impacts"
        ));
        // the solver: a whole impact; the Taylor steps' count is the elastic–plastic law's
        assert!(check_samples_by(25_001, ep, Nominal::Solver).is_err());
        assert!(check_samples_by(25_001, ContactLaw::Hertz, Nominal::TaylorSteps).is_err());
    }

    #[test]
    fn a_fit_takes_fewer_iterations_where_runs_cost_much_and_is_refused_below_ten() {
        // a 2 000-row trace, 640 history samples: runs of 1 × 8 + 20, the full 200 iterations
        let run = fit_run_cost(2_000, 640, ContactLaw::Linear);
        assert_eq!(run, 28);
        assert_eq!(
            fit_iterations(run, 5, 4, ContactLaw::Linear, String::new),
            Ok(200)
        );
        // 20 000 drop tests: a run is 20 000 impacts; even 10 iterations of 4 runs are too many
        let run = fit_run_cost(20_000, 0, ContactLaw::Linear);
        let e = fit_iterations(run, 2, 7, ContactLaw::Linear, || "20000 drops".into());
        let e = e.unwrap_err();
        assert!(e.work > LIMIT, "{e}");
        assert!(
            e.to_string()
                .starts_with("too much work: 20000 drops (7 starts"),
            "{e}"
        );
        // 300 COR points, 2 free: 1e6/7 per start, runs of 300 impacts, 5 to start and 4 an
        // iteration: (142 857 − 1 500)/1 200 = 117 iterations
        let run = fit_run_cost(300, 0, ContactLaw::Linear);
        assert_eq!(
            fit_iterations(run, 2, 7, ContactLaw::Linear, String::new),
            Ok(117)
        );
    }

    #[test]
    fn a_hertz_trace_fit_is_held_to_fewer_iterations() {
        // 3 000 bins, 1 000 history samples, 6 variables: runs of 40 × 11 + 30 = 470, 4 starts
        // of (250 000 − 9 × 470)/(8 × 470) = 65 iterations
        let run = fit_run_cost(3_000, 1_000, ContactLaw::Hertz);
        assert_eq!(run, 470);
        assert_eq!(
            fit_iterations(run, 6, 4, ContactLaw::Hertz, String::new),
            Ok(65)
        );
    }
}
