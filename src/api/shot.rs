//! A shot of a [`Ball`] (docs/flight.md): its flight (`crate::flight`) with every bounce by
//! [`Ball::oblique`] on the arriving state, as `bouncelab shot` and Python's
//! `bouncelab.shot` run it.

use super::shot_net::{Net, NetReport};
use super::{Ball, BallError, ObliqueSpec};
use crate::flight::{
    self, Aero, Arrival, Decay, Drag, EndReason, Ends, FlightError, Launch, Leg, Lift, Rebound,
    State,
};
use crate::oblique::{ObliqueError, ObliqueResponse};
use crate::target::Target;
use serde::Serialize;

/// What a shot asks beyond the ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShotSpec {
    /// Where and how it leaves.
    pub launch: Launch,
    /// When it ends.
    pub ends: Ends,
    /// The surface's μ.
    pub friction: f64,
    /// K_t (N/m; `None`: the ball's, as `oblique`'s).
    pub tangential_stiffness: Option<f64>,
    /// κ (`None`: the ball's).
    pub inertia_factor: Option<f64>,
    /// A tangential dashpot c_t (kg/s) in parallel with K_t at each bounce, as `oblique
    /// --tangential-damping` (`None` or 0: none).
    pub tangential_damping: Option<f64>,
    /// ρ (kg/m³); 0 is vacuum.
    pub air_density: f64,
    /// C_D fixed (`None`: the ball's published C_D(Re)).
    pub drag_coefficient: Option<f64>,
    /// C_L fixed (`None`: the ball's published C_L(S)).
    pub lift_coefficient: Option<f64>,
    /// τ (s) fixed, dω/dt = −ω/τ (`None`: the ball's published decay; 0: no decay).
    pub spin_decay: Option<f64>,
    /// Trajectory samples (0: none, else 2 … [`super::MAX_SAMPLES`]).
    pub samples: usize,
    /// The surface every bounce is on, at rest ([`Ball::oblique_on`]'s; `Target::wall()`:
    /// the rigid plate, [`Ball::oblique_damped`]'s very answer).
    pub surface: Target,
    /// A net across the path (`None`: none): the report says whether the ball clears it;
    /// the flight is the same (docs/flight.md §6).
    pub net: Option<Net>,
}

impl ShotSpec {
    /// A shot from `height` at `speed`, `elevation_deg`, `spin` on a surface of friction
    /// `friction`: one bounce, the ball's models, standard air, no samples.
    pub fn new(height: f64, speed: f64, elevation_deg: f64, spin: f64, friction: f64) -> Self {
        ShotSpec {
            launch: Launch {
                height,
                speed,
                elevation_deg,
                spin,
            },
            ends: Ends {
                bounces: 1,
                distance: None,
                time: None,
            },
            friction,
            tangential_stiffness: None,
            inertia_factor: None,
            tangential_damping: None,
            air_density: crate::drop::flight::AIR_DENSITY,
            drag_coefficient: None,
            lift_coefficient: None,
            spin_decay: None,
            samples: 0,
            surface: Target::wall(),
            net: None,
        }
    }
}

/// One bounce of a shot (the JSON's `bounces` [...]): in the flight's frame (v_x signed,
/// ω positive for topspin on a ball moving in +x); angles to the surface, in the direction
/// of motion, as `oblique` gives them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShotBounce {
    /// Time of the landing (s).
    pub t: f64,
    /// Where it lands (m).
    pub x: f64,
    /// Arriving speed (m/s).
    pub v_in: f64,
    /// Arriving angle below the horizontal, atan2(−v_y, |v_x|) (degrees).
    pub angle_in: f64,
    /// Arriving spin (rad/s).
    pub spin_in: f64,
    /// Arriving v_x (m/s, signed).
    pub vx_in: f64,
    /// Arriving v_y (m/s, negative: down).
    pub vy_in: f64,
    /// Leaving speed (m/s).
    pub v_out: f64,
    /// Leaving angle above the surface (degrees).
    pub angle_out: f64,
    /// Leaving spin (rad/s).
    pub spin_out: f64,
    /// Leaving v_x (m/s, signed).
    pub vx_out: f64,
    /// Leaving v_y (m/s, up).
    pub vy_out: f64,
    /// The bounce's normal COR.
    pub cor_normal: f64,
    /// Its contact time (s).
    pub contact_time: f64,
    /// Whether the contact point slid throughout.
    pub slid_throughout: bool,
    /// The bounce's warnings (`oblique`'s; empty, not made, from [`Ball::shot_unwarned`]).
    pub warnings: Vec<String>,
}

/// The state at the end of a shot, and why it ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShotEnd {
    /// Why it ended.
    pub reason: EndReason,
    /// The state.
    #[serde(flatten)]
    pub state: State,
    /// |v| (m/s).
    pub speed: f64,
}

/// A shot's answer.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShotReport {
    /// The air and the models flown.
    pub aero: Aero,
    /// The bounces, in order.
    pub bounces: Vec<ShotBounce>,
    /// The end.
    pub end: ShotEnd,
    /// Each flight's energy and the drag's work.
    pub flights: Vec<Leg>,
    /// Samples (t, x, y, vx, vy, spin), when asked for.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub trajectory: Vec<State>,
    /// The net's answer, when the shot has a net.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub net: Option<NetReport>,
    /// Each bounce's full oblique answer (in its own frame, mirrored when `mirrored`).
    #[serde(skip)]
    pub responses: Vec<(ObliqueResponse, bool)>,
}

impl ShotReport {
    /// Each bounce's warnings followed by the surface's ([`super::SurfaceUsed::warnings`]):
    /// every bounce is on it, each answer as `oblique`'s there (`shot`, Python's `shot`).
    pub fn warn_of(&mut self, surface: &super::SurfaceUsed) {
        let said = surface.warnings();
        for b in &mut self.bounces {
            b.warnings.extend(said.iter().cloned());
        }
    }

    /// The shot's warnings as one list, for answers that print them once (text, and CSV's
    /// stderr): the bounces' in order, then the net's, each distinct line once — the
    /// surface's, which every bounce carries, is said once, not once a bounce (JSON keeps
    /// each bounce's own; `cli_shot_surface::the_surface_is_warned_of_once_a_shot`).
    pub fn warnings(&self) -> Vec<&str> {
        let bounces = self.bounces.iter().flat_map(|b| &b.warnings);
        let mut said: Vec<&str> = Vec::new();
        for w in bounces.chain(self.net.iter().flat_map(|n| &n.warnings)) {
            if !said.contains(&w.as_str()) {
                said.push(w);
            }
        }
        said
    }
}

fn invalid(field: &'static str, value: f64, reason: &str) -> BallError {
    BallError::Invalid {
        field,
        value,
        reason: reason.into(),
    }
}

/// `Ok` when `x` is finite and `ok(x)`, else the field's error.
fn check(field: &'static str, x: f64, ok: bool, reason: &str) -> Result<(), BallError> {
    if x.is_finite() && ok {
        Ok(())
    } else {
        Err(invalid(field, x, reason))
    }
}

impl Ball {
    /// The air and the models a shot of this ball flies in (docs/flight.md §2): the
    /// published ones its preset names ([`Ball::flight_model`]), each replaced by a fixed
    /// value given.
    pub fn aero(&self, spec: &ShotSpec) -> Aero {
        let mut a = Aero::for_ball(self.flight_model, spec.air_density);
        if let Some(cd) = spec.drag_coefficient {
            a.drag = Drag::Constant { cd };
        }
        if let Some(cl) = spec.lift_coefficient {
            a.lift = Lift::Constant { cl };
        }
        if let Some(tau) = spec.spin_decay {
            a.decay = if tau == 0.0 {
                Decay::None
            } else {
                Decay::Time { tau }
            };
        }
        a
    }

    fn check_shot(&self, s: &ShotSpec, r: f64) -> Result<(), BallError> {
        let l = &s.launch;
        check(
            "height",
            l.height,
            l.height >= r,
            "the centre must be at least R above the surface",
        )?;
        check("speed", l.speed, l.speed >= 0.0, "must be zero or positive")?;
        let e = l.elevation_deg;
        check(
            "elevation",
            e,
            e.abs() <= 90.0,
            "must lie in -90 … 90 degrees",
        )?;
        check("spin", l.spin, true, "must be finite")?;
        check(
            "friction",
            s.friction,
            s.friction >= 0.0,
            "must be zero or positive",
        )?;
        let n = s.ends.bounces;
        if n > flight::MAX_BOUNCES {
            return Err(invalid("bounces", n as f64, "must lie in 0 … 100"));
        }
        if let Some(d) = s.ends.distance {
            check("distance", d, d > 0.0, "must be positive")?;
        }
        if let Some(t) = s.ends.time {
            check("time", t, t > 0.0, "must be positive")?;
        }
        let rho = s.air_density;
        check(
            "air_density",
            rho,
            (0.0..=100.0).contains(&rho),
            "must lie in 0 … 100 kg/m³",
        )?;
        for (field, x) in [
            ("drag_coefficient", s.drag_coefficient),
            ("lift_coefficient", s.lift_coefficient),
            ("spin_decay", s.spin_decay),
        ] {
            if let Some(x) = x {
                check(field, x, x >= 0.0, "must be zero or positive")?;
            }
        }
        if let Some(net) = &s.net {
            check("net", net.x, net.x > 0.0, "its distance must be positive")?;
            check(
                "net",
                net.height,
                net.height > 0.0,
                "its height must be positive",
            )?;
        }
        if s.samples == 1 || s.samples > super::MAX_SAMPLES {
            return Err(BallError::Samples(s.samples));
        }
        Ok(())
    }

    /// One bounce of a shot as the report gives it, its warnings not made
    /// ([`Ball::shot`] makes them).
    fn shot_bounce(&self, b: &flight::Bounce<ObliqueResponse>) -> ShotBounce {
        let r = &b.answer;
        let sx = if b.mirrored { -1.0 } else { 1.0 };
        ShotBounce {
            t: b.arriving.t,
            x: b.arriving.x,
            v_in: r.v_in,
            angle_in: r.angle_in_deg,
            spin_in: b.arriving.spin,
            vx_in: b.arriving.vx,
            vy_in: b.arriving.vy,
            v_out: r.v_out,
            angle_out: r.angle_out_deg,
            spin_out: sx * r.spin_out,
            vx_out: b.leaving.vx,
            vy_out: b.leaving.vy,
            cor_normal: r.cor_normal,
            contact_time: r.contact_time,
            slid_throughout: r.slid_throughout,
            warnings: Vec::new(),
        }
    }

    /// A shot (docs/flight.md): the flight from the launch, each bounce `oblique` on the
    /// arriving state (on `spec.surface`), until the ends.
    ///
    /// ```
    /// use bouncelab::{Ball, api::ShotSpec};
    /// let ball = Ball::from_preset("tennis")?;
    /// // a serve: 2.8 m up, 50 m/s, 6° down, 200 rad/s of topspin, on a court of μ = 0.6
    /// let shot = ball.shot(&ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6))?;
    /// assert_eq!(shot.bounces.len(), 1);
    /// assert!(shot.bounces[0].v_out < shot.bounces[0].v_in);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn shot(&self, spec: &ShotSpec) -> Result<ShotReport, BallError> {
        let mut shot = self.shot_unwarned(spec)?;
        for (b, (r, _)) in shot.bounces.iter_mut().zip(&shot.responses) {
            b.warnings = self.oblique_warnings(r);
        }
        if let Some(net) = &mut shot.net {
            net.warnings = net.warning().into_iter().collect();
        }
        Ok(shot)
    }

    /// [`Ball::shot`] with its bounces' `warnings` left empty, not made: for a caller that
    /// reads the numbers only (`mc --shot`'s samples, Python's `shots`). Making them (the
    /// ball copied at the bounce's v_y, the calibration warning formatted) is 7 % of the
    /// serve's instructions (callgrind, `benches/shot.rs`), spent on text no one read there.
    /// Every number is `shot`'s
    /// (`shot_unwarned_is_shot_without_its_warnings`, tests/physics).
    pub fn shot_unwarned(&self, spec: &ShotSpec) -> Result<ShotReport, BallError> {
        let radius = Some(self.radius())
            .filter(|r| r.is_finite())
            .ok_or(BallError::Oblique(ObliqueError::Missing("radius")))?;
        self.check_shot(spec, radius)?;
        let aero = self.aero(spec);
        let body = flight::Body::new(aero, self.params.mass, radius);
        let mut responses = Vec::new();
        let bounce = |a: &Arrival| {
            let o = ObliqueSpec {
                v: Some(a.v),
                angle_deg: a.angle_deg,
                spin: a.spin,
                friction: spec.friction,
                tangential_stiffness: spec.tangential_stiffness,
                inertia_factor: spec.inertia_factor,
            };
            let r = self.oblique_on(&o, spec.tangential_damping, 0, &spec.surface)?;
            let rebound = Rebound {
                vx: r.vx_out,
                vy: r.vy_out,
                spin: r.spin_out,
            };
            Ok::<_, BallError>((rebound, r))
        };
        let shot = flight::shot_watching(
            &body,
            self.params.mass,
            &spec.launch,
            &spec.ends,
            spec.samples,
            spec.net.map(|n| n.x),
            bounce,
        )
        .map_err(|e| match e {
            FlightError::Bounce(e) => e,
            FlightError::Endless => BallError::Invalid {
                field: "shot",
                value: flight::MAX_FLIGHT_TIME,
                reason: "no end within this many seconds of flight: give --time or --distance"
                    .into(),
            },
        })?;
        let bounces = shot.bounces.iter().map(|b| self.shot_bounce(b)).collect();
        let net = spec
            .net
            .map(|n| NetReport::of(&n, shot.crossing.as_ref(), radius));
        for b in shot.bounces {
            responses.push((b.answer, b.mirrored));
        }
        let e = shot.end;
        Ok(ShotReport {
            aero,
            bounces,
            end: ShotEnd {
                reason: shot.reason,
                state: e,
                speed: e.vx.hypot(e.vy),
            },
            flights: shot.legs,
            trajectory: shot.trajectory,
            net,
            responses,
        })
    }
}
