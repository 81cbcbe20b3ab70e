//! A shot: a ball launched in the vertical plane flies under gravity, drag and Magnus lift
//! (`aero`, `step`), bounces by an oblique impact given as a function (the api's
//! `Ball::shot` gives `Ball::oblique`), and flies on from its answer, until a number of
//! bounces, a distance or a time (docs/flight.md). x runs along the surface, y up; y is the
//! height of the ball's centre, which meets the surface at y = R. Pure: no I/O.
//!
//! Assumed (docs/flight.md §5): the contact is instantaneous in the path (the clock and x do
//! not advance over its milliseconds; its duration is the bounce's `contact_time`), the ball
//! leaves from where it landed, and the flight is planar (spin about the axis normal to it).

pub mod aero;
mod crossing;
pub mod published;
pub mod step;

pub use aero::{Aero, Decay, Drag, Lift};
pub use crossing::Crossing;
pub use published::Published;
pub use step::Body;

use serde::Serialize;
use step::Y;

/// Bounces allowed at most.
pub const MAX_BOUNCES: usize = 100;
/// Flight time allowed at most over a whole shot (s): a ball whose fixed lift carries it
/// round in circles ends with [`FlightError::Endless`] here, not in a hang.
pub const MAX_FLIGHT_TIME: f64 = 1000.0;
/// Steps allowed at most over a whole shot.
const MAX_STEPS: usize = 1_000_000;
/// The first step's size (s); the step control takes it from there.
const FIRST_STEP: f64 = 1e-2;

/// The ball's state in flight, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct State {
    /// Time since launch (s).
    pub t: f64,
    /// Along the surface from the launch (m).
    pub x: f64,
    /// The centre's height over the surface (m).
    pub y: f64,
    /// v_x (m/s).
    pub vx: f64,
    /// v_y (m/s), up.
    pub vy: f64,
    /// ω (rad/s), > 0 topspin for a ball moving in +x.
    pub spin: f64,
}

impl State {
    fn of(t: f64, y: &Y) -> State {
        State {
            t,
            x: y[0],
            y: y[1],
            vx: y[2],
            vy: y[3],
            spin: y[4],
        }
    }
}

/// How the ball is launched.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Launch {
    /// The centre's height (m), at least R.
    pub height: f64,
    /// |v| (m/s).
    pub speed: f64,
    /// The angle of v above the horizontal (degrees; negative: downward), in (−90, 90).
    pub elevation_deg: f64,
    /// ω (rad/s).
    pub spin: f64,
}

/// When the shot ends: the first of the landing after `bounces` bounces, x = `distance`,
/// t = `time`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ends {
    /// Bounces made before the shot may end on the surface.
    pub bounces: usize,
    /// x at which it ends (m).
    pub distance: Option<f64>,
    /// t at which it ends (s).
    pub time: Option<f64>,
}

/// The arriving state as `oblique` takes it: moving in +x (a ball arriving in −x is
/// mirrored, x → −x and ω → −ω, and its answer mirrored back).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Arrival {
    /// |v| (m/s).
    pub v: f64,
    /// atan2(−v_y, |v_x|) (degrees), the angle below the horizontal.
    pub angle_deg: f64,
    /// ω (rad/s) in the mirrored frame.
    pub spin: f64,
}

/// A bounce's answer in `oblique`'s frame: v_x, v_y away from the surface, ω.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rebound {
    /// v_x,out (m/s).
    pub vx: f64,
    /// v_y,out (m/s), up.
    pub vy: f64,
    /// ω_out (rad/s).
    pub spin: f64,
}

/// One bounce: where and when, what arrived and what left (in the flight's frame), and the
/// bounce function's own answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Bounce<P> {
    /// The state arriving (y = R).
    pub arriving: State,
    /// The state leaving (y = R, same t and x).
    pub leaving: State,
    /// What the bounce was asked.
    pub arrival: Arrival,
    /// Whether the ball arrived moving in −x (and was mirrored).
    pub mirrored: bool,
    /// The bounce's answer.
    pub answer: P,
}

/// One flight between launch or a bounce and a landing or the end, with its energy: E is
/// ½ m |v|² + m g y, the spin's ½ I ω² apart (the air's torque takes it, and no force).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Leg {
    /// Its start (s).
    pub t0: f64,
    /// Its end (s).
    pub t1: f64,
    /// E at the start (J).
    pub energy_start: f64,
    /// E at the end (J).
    pub energy_end: f64,
    /// ∫ |F_D · v| dt (J), the drag's work; lift does none (it is normal to v).
    pub drag_work: f64,
}

/// Why a shot ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EndReason {
    /// On the surface after the last bounce.
    Landing,
    /// At x = `distance`.
    Distance,
    /// At t = `time`.
    Time,
}

/// A shot's answer.
#[derive(Debug, Clone, PartialEq)]
pub struct Shot<P> {
    /// The bounces, in order.
    pub bounces: Vec<Bounce<P>>,
    /// The state at the end.
    pub end: State,
    /// Why it ended.
    pub reason: EndReason,
    /// The flights.
    pub legs: Vec<Leg>,
    /// Samples evenly spaced in time from launch to the end, when asked for.
    pub trajectory: Vec<State>,
    /// Where the ball first crossed the watched x moving forward ([`shot_watching`]; `None`
    /// when nothing was watched or the shot ended before it).
    pub crossing: Option<Crossing>,
}

/// A shot without an answer.
#[derive(Debug, Clone, PartialEq)]
pub enum FlightError<E> {
    /// A bounce's own error.
    Bounce(E),
    /// No end within [`MAX_FLIGHT_TIME`] s or the step budget.
    Endless,
}

/// How a leg stopped.
enum Stop {
    Landing,
    Distance,
    Time,
}

/// The flight integrator's state across legs.
struct Flier<'a> {
    body: &'a Body,
    ends: &'a Ends,
    h: f64,
    steps: usize,
    /// Every accepted step's start, kept when samples are asked for.
    record: Option<Vec<(f64, Y)>>,
    /// The x watched for a crossing, until it is crossed.
    watch: Option<f64>,
    /// The crossing (t, state), once found.
    crossed: Option<(f64, Y)>,
}

impl Flier<'_> {
    /// The earliest event inside the accepted step of size `h` from `y` to `y1`, each
    /// located from the step's start: the step size to it, the state there (on the surface
    /// or at the distance exactly) and which.
    fn event(&self, (y, k1): (&Y, &Y), y1: &Y, h: f64) -> Option<(f64, Y, Stop)> {
        let (body, r) = (self.body, self.body.radius);
        let landing = (y[1] >= r && y1[1] < r).then(|| step::locate(body, (y, k1), (h, y1), 1, r));
        let far = self.ends.distance.filter(|&d| y[0] < d && y1[0] >= d);
        let distance = far.map(|d| (d, step::locate(body, (y, k1), (h, y1), 0, d)));
        match (landing, distance) {
            (Some(a), Some((d, b))) if b.0 < a.0 => Some((b.0, at(b.1, 0, d), Stop::Distance)),
            (Some(a), _) => Some((a.0, at(a.1, 1, r), Stop::Landing)),
            (None, Some((d, b))) => Some((b.0, at(b.1, 0, d), Stop::Distance)),
            (None, None) => None,
        }
    }

    /// One leg from (t, y) to its stop: the state there and why.
    fn leg(&mut self, mut t: f64, mut y: Y) -> Result<(f64, Y, Stop), ()> {
        let (body, r) = (self.body, self.body.radius);
        let mut k1 = body.rate(&y);
        loop {
            let mut h = self.h;
            if let Some(end) = self.ends.time {
                if t >= end {
                    return Ok((t, y, Stop::Time));
                }
                h = h.min(end - t);
            }
            self.steps += 1;
            if self.steps > MAX_STEPS || t > MAX_FLIGHT_TIME {
                return Err(());
            }
            // err: the error norm's square (`Body::step`)
            let (y1, k7, err) = body.step(&y, &k1, h);
            if err > 1.0 || !err.is_finite() {
                self.h = step::next_size(h, if err.is_finite() { err } else { 1e20 });
                continue;
            }
            // a step that rises and falls back below R in one go is halved until it ends
            // above R or starts falling: the landing is then the one downward crossing of the
            // step, bracketed from a start above R (or at R at a launch from the surface)
            if y1[1] < r && y[3] > 0.0 {
                self.h = 0.5 * h;
                continue;
            }
            if let Some(rec) = &mut self.record {
                rec.push((t, y));
            }
            let event = self.event((&y, &k1), &y1, h);
            self.watch_crossing((t, &y, &k1), (&y1, h), event.as_ref().map(|e| e.0));
            if let Some((hs, ys, stop)) = event {
                return Ok((t + hs, ys, stop));
            }
            let last = self.ends.time.is_some_and(|end| t + h >= end);
            t = if last {
                self.ends.time.unwrap_or(t + h)
            } else {
                t + h
            };
            y = y1;
            k1 = k7;
            self.h = step::next_size(h, err);
            if last {
                return Ok((t, y, Stop::Time));
            }
        }
    }
}

/// `y` with component `i` set to `value` (an event's, met to rounding).
fn at(mut y: Y, i: usize, value: f64) -> Y {
    y[i] = value;
    y
}

/// The energy ½ m |v|² + m g y of a state (J).
fn energy(mass: f64, y: &Y) -> f64 {
    mass * (0.5 * (y[2] * y[2] + y[3] * y[3]) + crate::drop::G * y[1])
}

/// A shot of `body` (of `mass`) launched as `launch` until `ends`, each bounce by `bounce`;
/// `samples` trajectory samples (0: none, else ≥ 2).
pub fn shot<P, E>(
    body: &Body,
    mass: f64,
    launch: &Launch,
    ends: &Ends,
    samples: usize,
    bounce: impl FnMut(&Arrival) -> Result<(Rebound, P), E>,
) -> Result<Shot<P>, FlightError<E>> {
    shot_watching(body, mass, launch, ends, samples, None, bounce)
}

/// [`shot`], and where the ball first crosses x = `watch` moving forward (a net's plane,
/// docs/flight.md §6): `Shot::crossing`. The flight is the same bit for bit: the crossing is
/// located from its step's start, and the step is taken as without the watch.
pub fn shot_watching<P, E>(
    body: &Body,
    mass: f64,
    launch: &Launch,
    ends: &Ends,
    samples: usize,
    watch: Option<f64>,
    mut bounce: impl FnMut(&Arrival) -> Result<(Rebound, P), E>,
) -> Result<Shot<P>, FlightError<E>> {
    let (s, c) = launch.elevation_deg.to_radians().sin_cos();
    let mut y: Y = [
        0.0,
        launch.height,
        launch.speed * c,
        launch.speed * s,
        launch.spin,
        0.0,
    ];
    let mut fl = Flier {
        body,
        ends,
        h: FIRST_STEP,
        steps: 0,
        record: (samples > 0).then(Vec::new),
        watch,
        crossed: None,
    };
    let (mut t, mut bounces, mut legs) = (0.0, Vec::new(), Vec::new());
    let mut crossing = None;
    loop {
        let (t0, e0) = (t, energy(mass, &y));
        let (t1, y1, stop) = fl.leg(t, y).map_err(|()| FlightError::Endless)?;
        if let Some((tc, yc)) = fl.crossed.take() {
            crossing = Some(Crossing {
                state: State::of(tc, &yc),
                bounces: bounces.len(),
            });
        }
        legs.push(Leg {
            t0,
            t1,
            energy_start: e0,
            energy_end: energy(mass, &y1),
            drag_work: mass * y1[5],
        });
        let (t_end, y_end) = (t1, y1);
        let reason = match stop {
            Stop::Landing if bounces.len() < ends.bounces => None,
            Stop::Landing => Some(EndReason::Landing),
            Stop::Distance => Some(EndReason::Distance),
            Stop::Time => Some(EndReason::Time),
        };
        if let Some(reason) = reason {
            let end = State::of(t_end, &y_end);
            let trajectory = fl
                .record
                .as_ref()
                .map_or_else(Vec::new, |rec| sample(body, rec, end, samples));
            return Ok(Shot {
                bounces,
                end,
                reason,
                legs,
                trajectory,
                crossing,
            });
        }
        let b = bounce_at(body.radius, t_end, &y_end, &mut bounce).map_err(FlightError::Bounce)?;
        (t, y) = (t_end, b.1);
        bounces.push(b.0);
    }
}

/// The bounce of a ball arriving in state `y` at `t` (on the surface, radius `r`), mirrored
/// when it moves in −x: its record and the state it leaves in (y = R, the work reset).
fn bounce_at<P, E>(
    r: f64,
    t: f64,
    y: &Y,
    bounce: &mut impl FnMut(&Arrival) -> Result<(Rebound, P), E>,
) -> Result<(Bounce<P>, Y), E> {
    let mirrored = y[2] < 0.0;
    let sx = if mirrored { -1.0 } else { 1.0 };
    let arrival = Arrival {
        v: y[2].hypot(y[3]),
        angle_deg: (-y[3]).atan2(sx * y[2]).to_degrees(),
        spin: sx * y[4],
    };
    let (rb, answer) = bounce(&arrival)?;
    let out = [y[0], r, sx * rb.vx, rb.vy, sx * rb.spin, 0.0];
    let record = Bounce {
        arriving: State::of(t, y),
        leaving: State::of(t, &out),
        arrival,
        mirrored,
        answer,
    };
    Ok((record, out))
}

/// `n` states evenly spaced in time over [0, end.t], each one step from the last accepted
/// step's start at or before it (the last sample is the end itself).
fn sample(body: &Body, rec: &[(f64, Y)], end: State, n: usize) -> Vec<State> {
    (0..n)
        .map(|j| {
            if j + 1 == n || rec.is_empty() {
                return end;
            }
            let ts = end.t * j as f64 / (n - 1) as f64;
            let k = rec.partition_point(|(t, _)| *t <= ts).max(1) - 1;
            let (tk, yk) = rec[k];
            State::of(ts, &body.advance(&yk, ts - tk))
        })
        .collect()
}
