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
    let n = samples as u64;
    let (impacts, what) = match law {
        ContactLaw::Linear => (
            n.div_ceil(SAMPLES_PER_IMPACT),
            format!(
                "{samples} samples ({SAMPLES_PER_IMPACT} linear-law samples count as one impact)"
            ),
        ),
        _ => (n, format!("{samples} samples")),
    };
    check(impacts as usize, law, &what)
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

/// Model runs a multi-parameter fit may make at most: each start's Levenberg–Marquardt
/// iterations (200, `fit::lm::Options`) each cost a trial run and a Jacobian (`free` + 1
/// runs), for at most `starts` starts. A bound, not an estimate: fits converge in 5–30
/// iterations (BENCHMARKS.md).
pub fn fit_runs(free: usize, starts: usize) -> u64 {
    starts as u64 * (1 + 200 * (free as u64 + 2))
}

/// Samples interpolated that cost about as much as one linear-law impact (≈ 1 µs: a few ns
/// each, against the exact solver's microseconds, BENCHMARKS.md).
pub const POINTS_PER_IMPACT: u64 = 200;

/// Refuse a trace fit beyond the limit before it starts: at most [`fit_runs`] model runs, each
/// one impact under `law` with `history` samples and an interpolation at `samples` times (the
/// trace's bins, `fit::bins`), priced in linear-law impacts.
pub fn check_trace_fit(
    rows: usize,
    samples: usize,
    free: usize,
    law: ContactLaw,
) -> Result<(), TooMuchWork> {
    let per_run = cost(law) + (samples as u64).div_ceil(POINTS_PER_IMPACT);
    let runs = fit_runs(free, 4);
    let work = runs.saturating_mul(per_run);
    if work > LIMIT {
        return Err(TooMuchWork {
            what: format!(
                "a fit of {free} parameters to {rows} rows in {samples} bins (up to {runs} \
                 model runs)"
            ),
            impacts: runs as usize,
            law,
            work,
        });
    }
    Ok(())
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
}
