//! A dense force trace binned to the model's time resolution before it is fitted (issue 30,
//! item 4; docs/fitting.md, "Dense traces").
//!
//! Rows are grouped into bins of consecutive times; a bin stands for its rows by their mean
//! time t̄ and mean force f̄, and its residual is weighted by √n (n its rows):
//! w (F(t̄) − f̄) with w = √n. What holds: with independent noise of variance σ² on every row,
//! f̄ has variance σ²/n, so every weighted residual has variance σ² again, and the weighted
//! sum of squares estimates σ² with n_bins − p degrees of freedom — the intervals
//! ([`super::stats`]) and the runs test ([`super::verdict`]) keep their meaning. The price is
//! the model's curvature within a bin, F(t̄) against the bins' mean of F: |F''| h²/24 for a bin
//! h wide, about 4e-7 of the peak at [`PER_PULSE`] bins over the pulse (F'' ≈ π² F_m/t_c²),
//! and up to F'(0) h/8 in the one bin where the contact starts. (Tests: `tests` below,
//! `a_binned_fit_covers_the_truth_and_matches_the_row_by_row_one`.)

use crate::measured::{Trace, TraceSummary};

/// Traces up to this many rows are fitted row by row (every row its own residual, as before
/// binning existed): their fits cost milliseconds.
pub const ROW_BY_ROW_UP_TO: usize = 4_000;

/// Bins over the pulse's width: finer than the model's 400-sample minimum history
/// (`trace::TraceProblem::new`).
pub const PER_PULSE: f64 = 1_000.0;

/// Far from the pulse (more than one pulse width before its start or after its end) the
/// model is the baseline alone, and bins are 100 times wider.
const COARSE: f64 = 100.0;

/// The samples a fit compares the model with: rows, or bins standing for rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Samples {
    /// Mean time of each bin (s), increasing.
    pub time: Vec<f64>,
    /// Mean force of each bin (N).
    pub force: Vec<f64>,
    /// √(rows in the bin): the weight of its residual.
    pub weight: Vec<f64>,
}

impl Samples {
    /// Every row its own sample, of weight 1.
    pub fn rows(trace: &Trace) -> Samples {
        Samples {
            time: trace.time.clone(),
            force: trace.force.clone(),
            weight: vec![1.0; trace.time.len()],
        }
    }

    /// The trace in bins of [`PER_PULSE`] to the pulse's width (100 times wider further than a
    /// width from the pulse); a bin holds at least one row, in order.
    pub fn binned(trace: &Trace, s: &TraceSummary) -> Samples {
        bin(&trace.time, &trace.force, (s.t_start, s.t_end))
    }

    /// Rows or bins, as the trace's size asks ([`ROW_BY_ROW_UP_TO`]).
    pub fn of(trace: &Trace, s: &TraceSummary) -> Samples {
        if trace.time.len() <= ROW_BY_ROW_UP_TO {
            Samples::rows(trace)
        } else {
            Samples::binned(trace, s)
        }
    }

    /// How many samples (bins).
    pub fn len(&self) -> usize {
        self.time.len()
    }
}

/// Rows at times `t` (increasing) with forces `f` in bins, for a pulse over `pulse`.
fn bin(t: &[f64], f: &[f64], pulse: (f64, f64)) -> Samples {
    let width = (pulse.1 - pulse.0).max(f64::MIN_POSITIVE);
    let fine = width / PER_PULSE;
    let (near_from, near_to) = (pulse.0 - width, pulse.1 + width);
    let bin_width = |t: f64| {
        if (near_from..=near_to).contains(&t) {
            fine
        } else {
            COARSE * fine
        }
    };
    let mut out = Samples {
        time: Vec::new(),
        force: Vec::new(),
        weight: Vec::new(),
    };
    let mut i = 0;
    while i < t.len() {
        // a bin starts at its first row and takes the rows within its width
        let end = t[i] + bin_width(t[i]);
        let mut j = i + 1;
        while j < t.len() && t[j] < end {
            j += 1;
        }
        let n = (j - i) as f64;
        out.time.push(t[i..j].iter().sum::<f64>() / n);
        out.force.push(f[i..j].iter().sum::<f64>() / n);
        out.weight.push(n.sqrt());
        i = j;
    }
    out
}

// the history of benches/fit.rs's ball (`crate::bench_ball`, the sensitivity tests' too) read
// between the solver's samples, as the bench and tests/fit_memory.rs have it
#[cfg(test)]
#[path = "../../../tests/support/fit_common/force.rs"]
mod force;

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    #[test]
    fn bins_keep_every_row_once_and_weigh_by_the_root_of_their_count() {
        // 0.1 ms apart over 0 … 100 ms, a pulse from 40 to 50 ms: near bins 10 µs wide hold one
        // row, far bins 1 ms wide hold ten
        let time: Vec<f64> = (0..1000).map(|i| (i as f64 + 0.5) * 1e-4).collect();
        let force: Vec<f64> = (0..1000).map(|i| i as f64).collect();
        let b = bin(&time, &force, (0.040, 0.050));
        let rows: f64 = b.weight.iter().map(|w| w * w).sum();
        assert!((rows - 1000.0).abs() < 1e-9, "{rows}");
        let total: f64 = b.force.iter().zip(&b.weight).map(|(f, w)| f * w * w).sum();
        assert!((total - 499_500.0).abs() < 1e-6, "{total}");
        assert!(b.time.windows(2).all(|w| w[0] < w[1]));
        // the first bin: rows 0 … 9, mean time 0.5 ms, weight √10
        assert!((b.time[0] - 5e-4).abs() < 1e-15, "{}", b.time[0]);
        assert!((b.weight[0] - 10f64.sqrt()).abs() < 1e-15);
        // near the pulse, one row a bin
        let near = b.time.iter().position(|&t| t > 0.045).unwrap();
        assert_eq!(b.weight[near], 1.0);
    }

    use super::super::multi::fit_trace;
    use super::super::{MultiFit, Param};
    use super::force;
    use crate::analysis::work::Unwatched;
    pub(in crate::analysis::fit) use crate::bench_ball::truth;
    use crate::bench_ball::{normals, start};
    use crate::model::contact::ContactLaw;
    use crate::solver::{SolveOptions, simulate};

    /// `rows` samples over 10 ms, contact from 2.1 ms, baseline 0.3 N, noise σ = 3 N (the peak
    /// is ≈ 100 N) from a fixed pseudo-random sequence (`seed`).
    fn trace(rows: usize, seed: u64) -> Trace {
        let opts = SolveOptions::default().with_samples(20_001);
        let h = simulate(&truth(), ContactLaw::Linear, &opts)
            .unwrap()
            .history;
        let tf = *h.t.last().unwrap();
        let mut normal = normals(seed);
        let dt = 1e-2 / rows as f64;
        let time: Vec<f64> = (0..rows).map(|i| i as f64 * dt).collect();
        let force = time
            .iter()
            .map(|&t| force::force_at(&h, tf, t - 2.1e-3) + 0.3 + 3.0 * normal())
            .collect();
        Trace::from_columns(time, force)
    }

    fn fit(t: &Trace, choose: fn(&Trace, &TraceSummary) -> Samples) -> MultiFit {
        let free = [Param::KP, Param::C, Param::KR];
        fit_trace(&start(), ContactLaw::Linear, t, &free, &Unwatched, choose).unwrap()
    }

    #[test]
    fn a_binned_fit_covers_the_truth_and_matches_the_row_by_row_one() {
        // a moderate trace (20 000 rows, ≈ 6 a bin): both fits, the same answer to a small
        // fraction of the standard error, and standard errors alike
        let t = trace(20_000, 7);
        let (rows, bins) = (fit(&t, |t, _| Samples::rows(t)), fit(&t, Samples::binned));
        assert!(Samples::binned(&t, &t.summary().unwrap()).len() < 5_000);
        let truth = [8e4, 60.0, 1.2e5];
        for ((a, b), want) in rows.fitted.iter().zip(&bins.fitted).zip(truth) {
            let off = (a.value - b.value).abs() / a.std_error;
            assert!(off < 0.1, "{}: {a:?} against {b:?}", a.name);
            let se = b.std_error / a.std_error;
            assert!((0.9..1.1).contains(&se), "{}: {a:?} against {b:?}", a.name);
            assert!(b.ci95[0] < want && want < b.ci95[1], "{b:?}");
        }
        assert!(bins.identified && rows.identified);
        // a dense one (999 999 rows, the most a file may hold): binned, the truth within
        // the 95 % intervals, the noise's σ in the residuals, no lack of fit
        let t = trace(999_999, 11);
        let f = fit(&t, Samples::of);
        assert_eq!(f.points, 999_999);
        assert!(f.identified, "{f:?}");
        for (e, want) in f.fitted.iter().zip(truth) {
            assert!(e.ci95[0] < want && want < e.ci95[1], "{e:?}");
        }
        assert!(
            (f.rms_residual / 3.0 - 1.0).abs() < 0.05,
            "{}",
            f.rms_residual
        );
        assert!(f.lack_of_fit.is_none_or(|l| !l.significant()), "{f:?}");
    }
}
