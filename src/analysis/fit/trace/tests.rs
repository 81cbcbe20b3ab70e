//! One solver run serves the residuals, the Jacobian and the rows at the same parameters, and
//! gives what a fresh run gives.

use super::*;
use crate::analysis::fit::bins::Samples;
use crate::analysis::fit::lm::Residuals;

/// A watch that counts the model runs reported to it.
struct Count(Cell<u64>);

impl Watch for Count {
    fn step(&self, done: u64) -> bool {
        self.0.set(done);
        true
    }
}

/// The tennis ball's linear springs (presets/tennis.toml), dropped at 3 m/s.
fn ball() -> ImpactParams {
    ImpactParams {
        mass: 0.0577,
        k_p: 49_427.0,
        damping: 240.6405,
        k_r: 49_427.0,
        z_p: 0.0060342,
        k_h: ImpactParams::k_h_matching(49_427.0, 0.0060342),
        v0: 3.0,
    }
}

/// The model's own pulse as a trace: 600 rows over 12 ms, contact from 2 ms, baseline 0.2 N.
fn trace(p: &ImpactParams) -> Trace {
    let opts = SolveOptions::default().with_samples(4001);
    let h = simulate(p, ContactLaw::Linear, &opts).unwrap().history;
    let rows = 600;
    let time: Vec<f64> = (0..rows).map(|i| i as f64 * 12e-3 / rows as f64).collect();
    let force = time
        .iter()
        .map(|&t| 0.2 + interpolate(&h.t, &h.force, t - 2e-3).0)
        .collect();
    Trace::from_columns(time, force)
}

fn problem<'a>(tr: &'a Trace, watch: &'a dyn Watch) -> TraceProblem<'a> {
    let summary = tr.summary().unwrap();
    let free = vec![Param::KP, Param::C, Param::KR];
    let base = ImpactParams {
        k_p: 6e4,
        damping: 200.0,
        ..ball()
    };
    let data = Samples::rows(tr);
    TraceProblem::new(base, ContactLaw::Linear, free, tr, summary, data, watch)
}

#[test]
fn one_run_serves_residuals_jacobian_and_rows() {
    let tr = trace(&ball());
    let count = Count(Cell::new(0));
    let p = problem(&tr, &count);
    let x = p.starts()[0].clone();
    let r = p.residuals(&x).unwrap();
    assert_eq!((p.runs(), count.0.get()), (1, 1));
    // the linear law's exact Jacobian needs the run at x: the one just made (two runs before)
    let jac = p.jacobian(&x, &r).unwrap();
    assert_eq!(p.runs(), 1);
    // the rows at x (three runs before), and at another t0 and b: the same run
    let rows = p.model_at_rows(&x).unwrap();
    let mut moved = x.clone();
    moved[3] += 1e-4;
    moved[4] -= 0.05;
    let rows_moved = p.model_at_rows(&moved).unwrap();
    assert_eq!(p.runs(), 1);
    // each the same, bit for bit, as a problem that never ran gives
    let fresh = problem(&tr, &crate::analysis::work::Unwatched);
    assert_eq!(fresh.residuals(&x).unwrap(), r);
    let fresh = problem(&tr, &crate::analysis::work::Unwatched);
    assert_eq!(fresh.jacobian(&x, &r).unwrap(), jac);
    let fresh = problem(&tr, &crate::analysis::work::Unwatched);
    assert_eq!(fresh.model_at_rows(&x).unwrap(), rows);
    let fresh = problem(&tr, &crate::analysis::work::Unwatched);
    assert_eq!(fresh.model_at_rows(&moved).unwrap(), rows_moved);
    // other parameters: a run more, counted
    let mut other = x.clone();
    other[0] += 1e-3;
    p.residuals(&other).unwrap();
    assert_eq!((p.runs(), count.0.get()), (2, 2));
}

#[test]
fn a_stopped_fit_gets_no_answer_from_the_last_run() {
    struct StopAfter(u64);
    impl Watch for StopAfter {
        fn step(&self, done: u64) -> bool {
            done <= self.0
        }
    }
    let tr = trace(&ball());
    let watch = StopAfter(1);
    let p = problem(&tr, &watch);
    let x = p.starts()[0].clone();
    assert!(p.residuals(&x).is_some());
    let mut other = x.clone();
    other[0] += 1e-3;
    assert!(p.residuals(&other).is_none());
    assert!(p.stopped());
    // the run at x is still the last answered, but a stopped fit runs nothing more
    assert!(p.residuals(&x).is_none());
}
