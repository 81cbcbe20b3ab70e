//! The Monte Carlo and the drop test watched from outside (Python's Ctrl-C, issue 28): the
//! same answer as unwatched, and stopped when the watch says so.

use bouncelab::analysis::mc::{Dist, McSpec, parse_vary};
use bouncelab::analysis::work::{Unwatched, Watch};
use bouncelab::{Ball, BallError};
use std::cell::Cell;

fn spec(samples: usize) -> McSpec {
    McSpec::new(
        parse_vary("k_p=5%,c=5%,k_r=5%").unwrap(),
        Dist::Normal,
        samples,
        3,
    )
    .unwrap()
}

#[test]
fn a_watched_run_is_the_same_run() {
    // 40 000 linear-law samples: three chunks of at most 16 384
    let golf = Ball::from_preset("golf").unwrap();
    let s = spec(40_000);
    let one = golf.monte_carlo(&s).unwrap();
    let watched = golf.monte_carlo_watched(&s, &Unwatched).unwrap();
    assert_eq!(watched, one);
}

/// Says stop at its `n`-th look, and counts its looks.
struct StopAt(u64, Cell<u64>);

impl Watch for StopAt {
    fn step(&self, _done: u64) -> bool {
        self.1.set(self.1.get() + 1);
        self.1.get() < self.0
    }
}

#[test]
fn a_watch_that_says_stop_stops_the_run() {
    let golf = Ball::from_preset("golf").unwrap();
    let watch = StopAt(2, Cell::new(0));
    let e = golf.monte_carlo_watched(&spec(40_000), &watch).unwrap_err();
    assert_eq!(e, BallError::Interrupted);
    assert_eq!(watch.1.get(), 2, "it stopped at the second look");
}

#[test]
fn a_watched_drop_is_the_same_drop_and_stops_when_told() {
    use bouncelab::drop::DropSetup;
    let tennis = Ball::from_preset("tennis").unwrap();
    let setup = DropSetup {
        height: 2.54,
        air: None,
        bounces: 5,
        min_rebound: 0.001,
    };
    let one = tennis.drop_test(&setup).unwrap();
    assert_eq!(tennis.drop_test_watched(&setup, &Unwatched).unwrap(), one);
    let watch = StopAt(3, Cell::new(0));
    let e = tennis.drop_test_watched(&setup, &watch).unwrap_err();
    assert_eq!(e, BallError::Interrupted);
    assert_eq!(watch.1.get(), 3, "it stopped before the third bounce");
}
