//! A shot's Monte Carlo (`Ball::shot_mc`, `bouncelab mc --shot`; docs/flight.md §7).

use bouncelab::Ball;
use bouncelab::api::{ShotMcSpec, ShotSpec, ShotSpread};

fn serve() -> ShotSpec {
    ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6)
}

/// Every warning of `shot`'s bounces, in order.
fn warnings_of(shot: bouncelab::api::ShotReport) -> Vec<String> {
    shot.bounces.into_iter().flat_map(|b| b.warnings).collect()
}

/// A narrow spread: 2 % on the speed, 30 rad/s on the spin.
fn narrow() -> ShotSpread {
    ShotSpread {
        speed: 0.02,
        spin: 30.0,
        ..ShotSpread::default()
    }
}

fn spec(spread: ShotSpread, samples: usize, seed: u64) -> ShotMcSpec {
    ShotMcSpec {
        shot: serve(),
        spread,
        uniform: false,
        samples,
        seed,
        after_bounce: None,
    }
}

#[test]
fn without_spread_every_sample_is_the_nominal_shot() {
    let ball = Ball::from_preset("tennis").unwrap();
    let nominal = ball.shot(&serve()).unwrap();
    let r = ball.shot_mc(&spec(ShotSpread::default(), 50, 3)).unwrap();
    let (name, x) = r.stats[0];
    assert_eq!(name, "landing_x");
    assert_eq!((x.min, x.max), (nominal.bounces[0].x, nominal.bounces[0].x));
    // the mean of 50 equal numbers, summed, is that number to rounding
    assert!(x.sd <= 1e-13 * x.mean, "{x:?}");
    assert_eq!(r.stats[5].1.q50, nominal.end.state.x);
}

#[test]
fn a_seed_gives_one_answer_and_the_spread_brackets_the_nominal() {
    let ball = Ball::from_preset("tennis").unwrap();
    let s = narrow();
    let a = ball.shot_mc(&spec(s, 400, 7)).unwrap();
    let b = ball.shot_mc(&spec(s, 400, 7)).unwrap();
    let c = ball.shot_mc(&spec(s, 400, 8)).unwrap();
    assert_eq!(a, b);
    assert_ne!(a.stats[0].1.mean, c.stats[0].1.mean);
    let nominal = ball.shot(&serve()).unwrap().bounces[0].x;
    let x = a.stats[0].1;
    assert!(x.q025 < nominal && nominal < x.q975, "{x:?} vs {nominal}");
    assert!(x.sd > 0.0 && a.failed == 0);
    // sample i is the nominal shot with its own draws: a shot of its own gives its numbers
    let one = spec(s, 400, 7).sample(11);
    assert_ne!(one.launch.speed, 50.0);
    assert_eq!(one.launch.elevation_deg, -6.0);
}

#[test]
fn bad_spreads_are_refused_by_name() {
    let ball = Ball::from_preset("tennis").unwrap();
    let bad = ShotSpread {
        spin: -1.0,
        ..ShotSpread::default()
    };
    let e = ball.shot_mc(&spec(bad, 10, 0)).unwrap_err().to_string();
    assert!(e.contains("invalid spin"), "{e}");
    let e = ball
        .shot_mc(&spec(ShotSpread::default(), 0, 0))
        .unwrap_err()
        .to_string();
    assert!(e.contains("invalid samples"), "{e}");
}

/// `Ball::shot_unwarned` (what `mc --shot`'s samples and Python's `shots` run) is `Ball::shot`
/// with its bounces' warnings not made: every number the same, bit for bit, over spread
/// launches of one and two bounces, the warnings `shot` makes among them.
#[test]
fn shot_unwarned_is_shot_without_its_warnings() {
    let ball = Ball::from_preset("tennis").unwrap();
    let wide = ShotSpread {
        speed: 0.3,
        spin: 150.0,
        elevation: 3.0,
        height: 0.3,
    };
    let mut warned = 0;
    for bounces in [1, 2] {
        let mut mc = spec(wide, 100, 5);
        mc.shot.ends.bounces = bounces;
        for i in 0..100 {
            let s = mc.sample(i);
            let (full, bare) = match (ball.shot(&s), ball.shot_unwarned(&s)) {
                (Ok(full), Ok(bare)) => (full, bare),
                (Err(a), Err(b)) => {
                    assert_eq!(a.to_string(), b.to_string());
                    continue;
                }
                (a, b) => panic!("sample {i}: {a:?} against {b:?}"),
            };
            assert!(bare.bounces.iter().all(|b| b.warnings.is_empty()));
            let mut filled = bare.clone();
            for (b, f) in filled.bounces.iter_mut().zip(&full.bounces) {
                warned += usize::from(!f.warnings.is_empty());
                b.warnings = f.warnings.clone();
            }
            assert_eq!(filled, full, "sample {i}");
        }
    }
    assert!(warned > 100, "the cases warn: {warned}");
}

/// The defect: `mc --shot` made every sample's warnings and said none of them, not even the
/// nominal shot's, which `shot` says for the same flags (its bounce is outside the tennis
/// ball's calibration) and `mc` says for its nominal impact. Its warnings are now the
/// nominal shot's, as `mc` states them. Fails on the old code (no `warnings`).
#[test]
fn the_monte_carlo_warns_as_its_nominal_shot() {
    let ball = Ball::from_preset("tennis").unwrap();
    let s = narrow();
    let mc = spec(s, 64, 1);
    let r = ball.shot_mc(&mc).unwrap();
    let nominal = warnings_of(ball.shot(&mc.shot).unwrap());
    assert!(
        nominal[0].starts_with("outside calibration:"),
        "{nominal:?}"
    );
    assert_eq!(r.warnings, nominal);
    // a baseball's line drive off the ground: the same rule
    let baseball = Ball::from_preset("baseball").unwrap();
    let drive = ShotMcSpec {
        shot: ShotSpec::new(1.0, 40.0, 10.0, -200.0, 0.5),
        ..mc
    };
    let nominal = warnings_of(baseball.shot(&drive.shot).unwrap());
    assert_eq!(baseball.shot_mc(&drive).unwrap().warnings, nominal);
}
