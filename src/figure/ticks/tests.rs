//! The tick engine's cases: the picture's axes and the terminal's.

use super::*;

fn axis(log: bool, range: Option<(f64, f64)>) -> Axis {
    Axis {
        label: "x".into(),
        key: "x".into(),
        scale: 1.0,
        log,
        range,
    }
}

#[test]
fn nice_linear_ticks() {
    let t = linear_ticks(&axis(false, None), Some((0.0, 117.3)));
    assert_eq!((t.lo, t.hi), (0.0, 140.0));
    assert_eq!(
        t.major,
        vec![0.0, 20.0, 40.0, 60.0, 80.0, 100.0, 120.0, 140.0]
    );
    assert_eq!(t.decimals, Some(0));
    let t = linear_ticks(&axis(false, Some((0.0, 1.05))), None);
    assert_eq!(t.major.len(), 6);
    assert_eq!(t.label(t.major[1]), "0.2");
    let t = linear_ticks(&axis(false, None), Some((0.0, 2.74)));
    assert_eq!(t.hi, 3.0);
    assert_eq!(t.decimals, Some(1));
    assert_eq!(tick_label(-0.0001, 2), "0.00");
}

#[test]
fn decade_ticks() {
    let t = log_ticks(&axis(true, Some((0.01, 100.0))), None);
    assert_eq!(t.major, vec![-2.0, -1.0, 0.0, 1.0, 2.0]);
    assert_eq!(t.minor.len(), 4 * 8);
    let labels: Vec<String> = t.major.iter().map(|&e| decade_label(e)).collect();
    assert_eq!(labels, ["0.01", "0.1", "1", "10", "100"]);
    assert_eq!(decade_label(6.0), "1e6");
}

#[test]
fn nice_ceilings() {
    assert_eq!(nice_ceil(1.3), 2.0);
    assert_eq!(nice_ceil(2.2), 2.5);
    assert_eq!(nice_ceil(14.5), 20.0);
    assert_eq!(nice_ceil(50.0), 50.0);
    assert_eq!(nice_ceil(0.0), 1.0);
}

#[test]
fn step_labels() {
    assert_eq!(step_label(0.5, 0.25), "0.50");
    assert_eq!(step_label(0.75, 0.25), "0.75");
    assert_eq!(step_label(40.0, 20.0), "40");
    assert_eq!(step_label(1.0, 0.2), "1.0");
    assert_eq!(step_label(-0.0, 0.5), "0.0");
}

fn labels(t: &Ticks) -> Vec<String> {
    t.labels().into_iter().map(|(_, l)| l).collect()
}

#[test]
fn fitted_ticks_are_round() {
    let a = fitted(0.0, 117.3, 6);
    assert_eq!([a.lo, a.hi], [0.0, 125.0]);
    assert_eq!(labels(&a), ["0", "25", "50", "75", "100", "125"]);
    let a = fitted(0.0, 1.0, 3);
    assert_eq!([a.lo, a.hi], [0.0, 1.0]);
    assert_eq!(a.major.len(), 3);
    let a = fitted(0.0, 2.74, 7);
    assert_eq!([a.lo, a.hi], [0.0, 3.0]);
    assert_eq!(labels(&a)[1], "0.5");
    // little room: few ticks, but the range is not stretched to the next big tick
    let a = fitted(0.0, 2.74, 2);
    assert!(a.lo == 0.0 && (a.hi - 2.8).abs() < 1e-12);
    assert_eq!(labels(&a), ["0", "2"]);
    let a = fitted(0.0, 121.8, 3);
    assert_eq!([a.lo, a.hi], [0.0, 130.0]);
    assert_eq!(a.major.len(), 3);
}

#[test]
fn degenerate_ranges_still_give_an_axis() {
    for (lo, hi) in [
        (0.0, 0.0),
        (0.0, f64::NAN),
        (f64::NAN, f64::NAN),
        (2.0, 1.0),
    ] {
        let a = fitted(lo, hi, 4);
        assert!(a.hi > a.lo && a.lo.is_finite() && a.hi.is_finite());
    }
}

#[test]
fn terminal_decades() {
    let got: Vec<_> = (-4..=4).map(|k| decade_label(f64::from(k))).collect();
    assert_eq!(
        got,
        [
            "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000", "1e4"
        ]
    );
    assert_eq!(covering((-2, 2), [0.16, 0.61]), (-2, 2));
    assert_eq!(covering((-2, 2), [0.005, f64::NAN, 0.0]), (-3, 2));
    assert_eq!(covering((-2, 2), [500.0]), (-2, 3));
    let t = log_ticks(&axis(true, Some((0.01, 100.0))), None);
    assert_eq!(t.major.len(), 5);
    assert_eq!([t.lo, t.hi], [-2.0, 2.0]);
}

#[test]
fn log_labels_are_the_richest_set_that_fits() {
    let close = |a: &[f64], b: &[f64]| {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * y)
    };
    let all = log::labels(0.01, 100.0, |_| true);
    assert_eq!(all.len(), 13, "1, 2, 5 × 10^k from 0.01 to 100: {all:?}");
    let nine = log::labels(0.01, 100.0, |v| v.len() <= 9);
    let want = [0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0];
    assert!(close(&nine, &want), "{nine:?}");
    let decades = log::labels(0.01, 100.0, |_| false);
    assert!(
        close(&decades, &[0.01, 0.1, 1.0, 10.0, 100.0]),
        "{decades:?}"
    );
    // the ends are taken with their slack, and a range inside one decade has no decade
    assert!(close(
        &log::marks(0.2 * (1.0 + 1e-12), 5.0, &[1.0, 2.0, 5.0]),
        &[0.2, 0.5, 1.0, 2.0, 5.0]
    ));
    assert!(log::labels(3.0, 4.0, |_| false).is_empty());
}
