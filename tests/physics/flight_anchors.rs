//! Published flights as anchors for the shot's models (issue 57 item 4, docs/flight.md §4):
//! each case states its source, the published figure, the model's and the tolerance, and why
//! the tolerance is what it is.

use bouncelab::Ball;
use bouncelab::api::ShotSpec;
use bouncelab::flight::{self, Aero, Ends, Launch, Published};

/// 1 mph in m/s, 1 yard in m, 1 rpm in rad/s (exact).
const MPH: f64 = 0.44704;
const YARD: f64 = 0.9144;
const RPM: f64 = std::f64::consts::PI / 30.0;
/// 1 ft in m, 1 inch in m, 1 oz in kg (exact).
const FOOT: f64 = 0.3048;
const INCH: f64 = 0.0254;
const OUNCE: f64 = 0.028349523125;

/// The average PGA Tour drive: ball speed 167.7 mph, launch 10.8°, 2599 rpm of backspin
/// (USGA & R&A Distance Report 2015, as quoted by the press, docs/flight.md §4), carrying
/// 275 yards (the Trackman PGA Tour average, ball speed 167 mph, as quoted by Golf Monthly,
/// 2023). Teed up: the ball's centre 5 cm above the ground.
fn tour_drive() -> ShotSpec {
    let mut spec = ShotSpec::new(0.05, 167.7 * MPH, 10.8, -2599.0 * RPM, 0.4);
    spec.ends.bounces = 0;
    spec
}

/// The model's `what` within `tolerance` (relative) of the published figure.
fn assert_near_published(what: &str, model: f64, published: f64, tolerance: f64) {
    let miss = model / published - 1.0;
    assert!(
        miss.abs() <= tolerance,
        "{what} {model:.3} against {published:.3} published ({:+.2} %)",
        100.0 * miss
    );
}

#[test]
fn a_tour_drive_carries_as_published() {
    let shot = Ball::from_preset("golf")
        .unwrap()
        .shot(&tour_drive())
        .unwrap();
    let carry = shot.end.state.x;
    let published = 275.0 * YARD;
    // ±15 %: the published golf-ball models themselves differ by that much on this drive
    // (docs/flight.md §4: Smits & Smith's, the default, carries it 10 % short; Lyu et al.'s
    // 2018 fit to launch-monitor flights 11 % long). Without lift (the old default) the
    // drive carried 137 m, 46 % short.
    assert_near_published("carry (m)", carry, published, 0.15);
}

#[test]
fn the_golf_spin_decay_has_smits_and_smiths_units() {
    // Smits & Smith (1994) in golf units: spin loss per second = 0.0004 × speed (mph) × spin;
    // the published worked case, a 7-iron at 120 mph and 7097 rpm, loses 340 rpm/s at first
    // (0.0004 × 120 × 7097 = 340.66)
    let g = Aero::published(Published::Golf, 1.204);
    let loss = -g.decay.rate(7097.0 * RPM, 120.0 * MPH) / RPM;
    assert!(
        (loss - 0.0004 * 120.0 * 7097.0).abs() < 1e-9,
        "{loss} rpm/s"
    );
}

/// Alan Nathan's trajectory calculator (TrajectoryCalculator-new-3D.xlsx, sheet
/// "BattedBallTrajectory-1", docs/flight.md §4): a ball of 5.125 oz and 9.125 in
/// circumference hit at 103 mph, 27.5° up, 2500 rpm of backspin, no sidespin, from 3 ft up,
/// in air of 1.19377 kg/m³ (70 °F, 50 % humidity, 29.92 inHg, 15 ft elevation), lands
/// 421.486 ft from the plate (launched 2 ft in front of it: 419.486 ft of carry) after
/// 5.5196 s. The calculator's ball is a point landing at z = 0; here its centre starts 3 ft
/// above the height where it lands (R).
const NATHAN_AIR: f64 = 1.193_767_224;

/// The calculator's launch for a ball of radius `radius`.
fn nathans_launch(radius: f64) -> Launch {
    Launch {
        height: 3.0 * FOOT + radius,
        speed: 103.0 * MPH,
        elevation_deg: 27.5,
        spin: -2500.0 * RPM,
    }
}

/// A carry and hang time against the calculator's, each to 1 %: the calculator steps its
/// equations by 0.01 s (position to second order, velocity to first), which shortens this
/// carry by 0.19 % (the same equations integrated finely carry 422.29 ft, docs/flight.md
/// §4); its drag constant 0.07182 rounds ½ρA/m 0.28 % high; its spin decays as
/// exp(−t|v|/(τ·100 mph)) with the present speed, here as dω/dt = −ω|v|/(τ·100 mph).
fn assert_near_nathans(carry: f64, hang: f64) {
    assert_near_published("carry (m)", carry, 419.485_568_9 * FOOT, 0.01);
    assert_near_published("hang time (s)", hang, 5.519_576_85, 0.01);
}

#[test]
fn a_batted_ball_carries_as_nathans_calculator() {
    let radius = 9.125 * INCH / (2.0 * std::f64::consts::PI);
    let mass = 5.125 * OUNCE;
    let body = flight::Body::new(
        Aero::published(Published::Baseball, NATHAN_AIR),
        mass,
        radius,
    );
    let ends = Ends {
        bounces: 0,
        distance: None,
        time: None,
    };
    let launch = nathans_launch(radius);
    let shot = flight::shot(&body, mass, &launch, &ends, 0, |_| Err::<(_, ()), _>(()))
        .expect("no bounce is asked");
    // expected here: +0.3 % (128.23 m). With the former default C_D 0.47 (assumed) the test
    // fails: 113.3 m, −11 %.
    assert_near_nathans(shot.end.x, shot.end.t);
}

/// The MLB ball is the calculator's (5.125 oz, 9.125 in: presets/baseball-mlb.toml), and its
/// preset names the baseball model (`aerodynamics`): the same flight through `Ball::shot`.
/// When the model was picked by the preset's name it flew as a smooth sphere without lift:
/// 95.3 m, −25 %.
#[test]
fn the_mlb_ball_carries_as_nathans_calculator() {
    let ball = Ball::from_preset("baseball-mlb").unwrap();
    let mut spec = ShotSpec::new(0.0, 0.0, 0.0, 0.0, 0.4);
    spec.launch = nathans_launch(ball.radius());
    spec.ends.bounces = 0;
    spec.air_density = NATHAN_AIR;
    let shot = ball.shot(&spec).unwrap();
    assert_near_nathans(shot.end.state.x, shot.end.state.t);
}

/// The driver's ball is a golf ball, and its preset says so (`aerodynamics = "golf"`): it
/// carries the tour drive as the paper's golf ball does. When the model was picked by the
/// preset's name it flew as a smooth sphere without lift: 103.5 m, −59 %.
#[test]
fn the_driver_ball_carries_the_tour_drive_as_golf_does() {
    let carry = |name| {
        let shot = Ball::from_preset(name)
            .unwrap()
            .shot(&tour_drive())
            .unwrap();
        shot.end.state.x
    };
    let (driver, golf) = (carry("golf-driver"), carry("golf"));
    assert_near_published("golf-driver's carry (m)", driver, 275.0 * YARD, 0.15);
    // the same model on a ball 2.8 % wider and 0.7 % heavier (the Rules' limits)
    assert!(
        (driver / golf - 1.0).abs() < 0.05,
        "{driver} m, golf's {golf} m"
    );
}

#[test]
fn the_baseball_drag_is_nathans_with_spin() {
    // the calculator's C_D = cd0 + cdspin × spin (rpm)/1000 = 0.3008 + 0.0292 × 2.5 at
    // 2500 rpm: its cell I6, 0.3738
    let bb = Aero::published(Published::Baseball, 1.204);
    let cd = bb.drag.cd(2e5, 0.2, -2500.0 * RPM);
    assert!((cd - 0.3738).abs() < 1e-12, "{cd}");
}
