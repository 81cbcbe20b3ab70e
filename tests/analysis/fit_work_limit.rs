//! A fit's work limit is asked before any model run (docs/guarantees.md, the work budget):
//! the refusal of a fit too large costs nothing.

use bouncelab::analysis::fit::{FitData, Param};

/// 200 000 drops to `bouncelab.fit_drops` took 5 s (a million, 26 s) before "too much
/// work": the scale check ran the model at every row before the work limit was asked.
#[test]
fn a_cor_fit_beyond_the_work_limit_runs_no_model_first() {
    struct Count(std::cell::Cell<u64>);
    impl bouncelab::analysis::work::Watch for Count {
        fn step(&self, _done: u64) -> bool {
            self.0.set(self.0.get() + 1);
            true
        }
    }
    let points: Vec<_> = (0..50_000)
        .map(|i| bouncelab::measured::CorPoint::new(1.0 + 1e-5 * f64::from(i), 0.75))
        .collect();
    let watch = Count(std::cell::Cell::new(0));
    let ball = bouncelab::Ball::from_preset("superball").unwrap();
    let e = ball
        .fit_watched(FitData::Cor(&points), Some(&[Param::KR, Param::ZP]), &watch)
        .unwrap_err();
    assert!(
        e.to_string().starts_with("too much work: a fit of 2"),
        "{e}"
    );
    assert_eq!(watch.0.get(), 0, "model runs before the refusal");
}
