//! A net in a shot's path (issue 57, docs/flight.md §6): where the ball crosses it, by how
//! much it clears it, and that the flight is the same with and without it; `mc --shot`'s
//! fraction that clears it and its spread D m past each sample's bounce.

use bouncelab::Ball;
use bouncelab::api::{Net, ShotMcSpec, ShotReport, ShotSpec, ShotSpread, TENNIS_NET_HEIGHT};

fn tennis() -> Ball {
    Ball::from_preset("tennis").unwrap()
}

/// docs/flight.md §6's serve at `elevation` degrees, with the tennis net 11.89 m out.
fn serve(elevation: f64) -> ShotSpec {
    let mut s = ShotSpec::new(2.8, 50.0, elevation, 200.0, 0.6);
    s.net = Some(Net {
        x: 11.89,
        height: TENNIS_NET_HEIGHT,
    });
    s
}

/// The shot of `spec` ended where x reaches `d` (no net).
fn to_distance(ball: &Ball, spec: &ShotSpec, d: f64) -> ShotReport {
    let mut s = *spec;
    s.net = None;
    s.ends.distance = Some(d);
    ball.shot(&s).unwrap()
}

#[test]
fn a_net_changes_no_number_of_the_flight() {
    let ball = tennis();
    for elevation in [-6.0, -5.0] {
        let mut spec = serve(elevation);
        spec.samples = 50;
        spec.ends.bounces = 2;
        let mut with = ball.shot(&spec).unwrap();
        assert!(with.net.is_some());
        with.net = None;
        spec.net = None;
        assert_eq!(with, ball.shot(&spec).unwrap(), "{elevation}°");
    }
}

#[test]
fn the_ball_crosses_the_net_where_the_shot_to_its_distance_ends() {
    let ball = tennis();
    let r = ball.radius();
    for elevation in [-6.0, -5.0, -3.0] {
        let spec = serve(elevation);
        let net = ball.shot(&spec).unwrap().net.unwrap();
        let end = to_distance(&ball, &spec, 11.89).end.state;
        // located from the same step's start as the distance end: bit for bit
        assert_eq!(net.y, Some(end.y), "{elevation}°");
        assert_eq!(net.t, Some(end.t), "{elevation}°");
        assert_eq!(net.clearance, Some(end.y - r - TENNIS_NET_HEIGHT));
        assert_eq!(net.bounces_before, Some(0));
    }
}

/// docs/flight.md §6: the serve at −6° is in the net (its lowest point 3.0 cm under the top),
/// at −5° it clears it by 18 cm.
#[test]
fn the_docs_serve_meets_the_net_and_five_degrees_clears_it() {
    let ball = tennis();
    let low = ball.shot(&serve(-6.0)).unwrap().net.unwrap();
    assert!(!low.cleared);
    let c = low.clearance.unwrap();
    assert!((-0.0300..-0.0290).contains(&c), "{c}");
    assert_eq!(low.warnings.len(), 1);
    assert!(
        low.warnings[0].starts_with("the ball meets the net at x = 11.89 m")
            && low.warnings[0].contains("as if there were no net"),
        "{:?}",
        low.warnings
    );
    let high = ball.shot(&serve(-5.0)).unwrap().net.unwrap();
    assert!(high.cleared);
    let c = high.clearance.unwrap();
    assert!((0.183..0.184).contains(&c), "{c}");
    assert!(high.warnings.is_empty());
    // the numbers alone are made without the warning
    assert!(
        ball.shot_unwarned(&serve(-6.0))
            .unwrap()
            .net
            .unwrap()
            .warnings
            .is_empty()
    );
}

/// A ball that passes over the net's top with less than R(1/cos θ − 1) between them touches
/// the cord (the path is at θ to the horizontal): a positive clearance, not cleared.
#[test]
fn a_grazing_ball_touches_the_cord() {
    let ball = tennis();
    let r = ball.radius();
    let spec = serve(-5.0);
    let end = to_distance(&ball, &spec, 11.89).end.state;
    let cos = end.vx / end.vx.hypot(end.vy);
    let touch = r * (1.0 / cos - 1.0);
    assert!(touch > 1e-4, "{touch}");
    for (gap, cleared) in [(0.5 * touch, false), (2.0 * touch, true), (-0.01, false)] {
        let mut s = spec;
        s.net = Some(Net {
            x: 11.89,
            height: end.y - r - gap,
        });
        let net = ball.shot(&s).unwrap().net.unwrap();
        assert_eq!(net.cleared, cleared, "gap {gap}");
        assert!((net.clearance.unwrap() - gap).abs() < 1e-12);
    }
}

#[test]
fn a_net_past_the_bounce_is_crossed_after_it_and_one_past_the_end_not_at_all() {
    let ball = tennis();
    let mut spec = serve(-6.0);
    spec.net = Some(Net {
        x: 20.0,
        height: 0.5,
    });
    let net = ball.shot(&spec).unwrap().net.unwrap();
    assert_eq!(net.bounces_before, Some(1));
    assert_eq!(net.y, Some(to_distance(&ball, &spec, 20.0).end.state.y));
    spec.net = Some(Net {
        x: 40.0,
        height: 0.5,
    });
    let net = ball.shot(&spec).unwrap().net.unwrap();
    assert_eq!((net.clearance, net.y, net.cleared), (None, None, false));
    assert_eq!(
        net.warnings,
        ["the ball does not reach the net at x = 40 m before the shot ends"]
    );
}

#[test]
fn a_net_with_no_distance_or_height_is_refused_by_name() {
    let ball = tennis();
    for (x, height) in [
        (0.0, 0.9),
        (-1.0, 0.9),
        (5.0, 0.0),
        (f64::NAN, 0.9),
        (5.0, f64::INFINITY),
    ] {
        let mut s = serve(-5.0);
        s.net = Some(Net { x, height });
        let e = ball.shot(&s).unwrap_err().to_string();
        assert!(e.contains("net"), "{x}, {height}: {e}");
    }
}

fn mc(shot: ShotSpec, spread: ShotSpread, after_bounce: Option<f64>) -> ShotMcSpec {
    ShotMcSpec {
        shot,
        spread,
        uniform: false,
        samples: 300,
        seed: 5,
        after_bounce,
    }
}

/// The fraction that clears is the count of the samples whose own shot clears it.
#[test]
fn the_monte_carlo_counts_the_samples_that_clear_the_net() {
    let ball = tennis();
    let spread = ShotSpread {
        elevation: 0.5,
        speed: 0.02,
        ..ShotSpread::default()
    };
    let spec = mc(serve(-5.5), spread, None);
    let r = ball.shot_mc(&spec).unwrap();
    let net = r.net.unwrap();
    let own: Vec<f64> = (0..300)
        .map(|i| ball.shot(&spec.sample(i)).unwrap().net.unwrap())
        .filter(|n| n.cleared)
        .map(|n| n.clearance.unwrap())
        .collect();
    assert_eq!(net.cleared, own.len());
    assert!(0 < net.cleared && net.cleared < 300, "{net:?}");
    assert_eq!(net.fraction, own.len() as f64 / 300.0);
    let c = net.clearance.unwrap();
    assert!(c.min < 0.0 && c.max > 0.0, "{c:?}");
    // without a net there is no net answer
    assert!(
        ball.shot_mc(&mc(
            ShotSpec::new(2.8, 50.0, -5.5, 200.0, 0.6),
            spread,
            None
        ))
        .unwrap()
        .net
        .is_none()
    );
}

/// `after_bounce`: each sample ends D m past its own bounce (not the nominal's), and the
/// end's height and time are spread.
#[test]
fn the_monte_carlo_ends_each_sample_past_its_own_bounce() {
    let ball = tennis();
    let spread = ShotSpread {
        speed: 0.02,
        spin: 30.0,
        ..ShotSpread::default()
    };
    let spec = mc(
        ShotSpec::new(2.8, 50.0, -5.0, 200.0, 0.6),
        spread,
        Some(1.0),
    );
    let r = ball.shot_mc(&spec).unwrap();
    let names: Vec<&str> = r.end_stats.iter().map(|(n, _)| *n).collect();
    assert_eq!(names, ["end_y", "end_t"]);
    assert_eq!(r.after_bounce, Some(1.0));
    let mut past = Vec::new();
    let mut heights = Vec::new();
    for i in 0..300 {
        let s = spec.sample(i);
        let d = ball.after_bounce_distance(&s, 1.0).unwrap();
        let mut to = s;
        to.ends.distance = Some(d);
        let shot = ball.shot(&to).unwrap();
        past.push(shot.end.state.x - shot.bounces[0].x);
        heights.push(shot.end.state.y);
    }
    assert!(past.iter().all(|p| (p - 1.0).abs() < 1e-12), "{past:?}");
    heights.sort_by(f64::total_cmp);
    let y = r.end_stats[0].1;
    assert_eq!((y.min, y.max), (heights[0], heights[299]));
    assert_eq!(y.q50, heights[149]);
    assert!(y.sd > 0.0);
    // the end's x spreads as the landing does, a metre on
    let (landing, end) = (r.stats[0].1, r.stats[5].1);
    assert!((end.mean - landing.mean - 1.0).abs() < 1e-9);
    // a landing end has no end height to spread
    let plain = ball.shot_mc(&mc(spec.shot, spread, None)).unwrap();
    assert!(plain.end_stats.is_empty());
}
