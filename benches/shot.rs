//! Speed of one shot with one bounce (median recorded in BENCHMARKS.md; target ≤ 20 µs), and
//! of its flight alone. Run: `cargo bench --bench shot`.

use bouncelab::Ball;
use bouncelab::api::ShotSpec;
use bouncelab::flight::{self, Aero, Ends, Launch, Published, Rebound};
use divan::black_box;

fn main() {
    divan::main();
}

/// The serve of docs/flight.md: 2.8 m, 50 m/s, 6° down, 200 rad/s topspin, μ = 0.6, to the
/// landing after one bounce, through `Ball::shot` (the oblique bounce included).
#[divan::bench]
fn shot_one_bounce(b: divan::Bencher) {
    let ball = Ball::from_preset("tennis").unwrap();
    let spec = ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6);
    b.bench(|| black_box(&ball).shot(black_box(&spec)).unwrap().end.state.x);
}

/// The same shot without its bounce's warnings (`Ball::shot_unwarned`): what each sample of
/// `mc --shot` runs.
#[divan::bench]
fn shot_one_bounce_unwarned(b: divan::Bencher) {
    let ball = Ball::from_preset("tennis").unwrap();
    let spec = ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6);
    b.bench(|| {
        black_box(&ball)
            .shot_unwarned(black_box(&spec))
            .unwrap()
            .end
            .state
            .x
    });
}

/// The same two flights with a bounce that costs nothing (v_y reversed): the integration's
/// share.
#[divan::bench]
fn flights_alone(b: divan::Bencher) {
    let ball = Ball::from_preset("tennis").unwrap();
    let body = flight::Body::new(
        Aero::published(Published::Tennis, 1.204),
        ball.params.mass,
        ball.radius(),
    );
    let launch = Launch {
        height: 2.8,
        speed: 50.0,
        elevation_deg: -6.0,
        spin: 200.0,
    };
    let ends = Ends {
        bounces: 1,
        distance: None,
        time: None,
    };
    b.bench(|| {
        flight::shot(black_box(&body), 0.057, &launch, &ends, 0, |a| {
            let (s, c) = a.angle_deg.to_radians().sin_cos();
            Ok::<_, ()>((
                Rebound {
                    vx: 0.7 * a.v * c,
                    vy: 0.7 * a.v * s,
                    spin: a.spin,
                },
                (),
            ))
        })
        .unwrap()
        .end
        .x
    });
}
