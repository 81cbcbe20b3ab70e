//! The checks of a shot (issue 57, docs/flight.md §4): the drag- and lift-free flight is the
//! parabola; an independent DOP853 integration with events agrees; each bounce is `oblique`
//! on the arriving state; the energy lost in flight is the drag's work.

use crate::flight_ode;
use bouncelab::api::{ShotReport, ShotSpec};
use bouncelab::flight::{self, Aero, Drag, Lift, Published};
use bouncelab::{Ball, api::ObliqueSpec};
use flight_ode::{Air, G, land};

fn ball(name: &str) -> Ball {
    Ball::from_preset(name).unwrap()
}

/// A tennis serve: 2.8 m, 50 m/s, 6° down, 200 rad/s topspin, μ = 0.6.
fn serve() -> ShotSpec {
    ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6)
}

#[test]
fn without_drag_and_lift_the_flight_is_the_parabola() {
    for (name, h, v, elev, spin) in [
        ("tennis", 2.8f64, 50.0f64, -6.0f64, 200.0f64),
        ("baseball", 1.0, 40.0, 30.0, -200.0),
        ("golf", 0.05, 70.0, 11.0, -300.0),
        ("superball", 1.5, 3.0, 80.0, 0.0),
    ] {
        let b = ball(name);
        let r = b.radius();
        let mut spec = ShotSpec::new(h, v, elev, spin, 0.4);
        spec.drag_coefficient = Some(0.0);
        spec.lift_coefficient = Some(0.0);
        spec.ends.bounces = 2;
        let shot = b.shot(&spec).unwrap();
        assert_eq!(shot.bounces.len(), 2);
        // each flight from (x0, y0, vx, vy) at t0 lands at the root of y0 + vy t − g t²/2 = R
        let (s, c) = elev.to_radians().sin_cos();
        let (mut t0, mut x0, mut y0, mut vx, mut vy) = (0.0, 0.0, h, v * c, v * s);
        let mut landings = shot.bounces.iter().map(|b| (b.t, b.x, b.vx_in, b.vy_in));
        let ends = std::iter::from_fn(|| landings.next()).chain(std::iter::once((
            shot.end.state.t,
            shot.end.state.x,
            shot.end.state.vx,
            shot.end.state.vy,
        )));
        for (k, (t, x, vx_got, vy_got)) in ends.enumerate() {
            let tf = (vy + (vy * vy + 2.0 * G * (y0 - r)).sqrt()) / G;
            let tol = |a: f64| 1e-12 * a.abs().max(1.0);
            let what = format!("{name}, landing {k}");
            assert!(
                (t - (t0 + tf)).abs() <= tol(t),
                "{what}: t {t} vs {}",
                t0 + tf
            );
            assert!(
                (x - (x0 + vx * tf)).abs() <= tol(x),
                "{what}: x {x} vs {}",
                x0 + vx * tf
            );
            assert!(
                (vx_got - vx).abs() <= tol(vx),
                "{what}: vx {vx_got} vs {vx}"
            );
            assert!(
                (vy_got - (vy - G * tf)).abs() <= tol(vy),
                "{what}: vy {vy_got}"
            );
            if let Some(bn) = shot.bounces.get(k) {
                (t0, x0, y0, vx, vy) = (bn.t, bn.x, r, bn.vx_out, bn.vy_out);
            }
        }
    }
}

fn close(what: &str, a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{what}: {a} vs {b} (tol {tol})"
    );
}

#[test]
fn an_independent_dop853_agrees() {
    for (name, spec) in [
        ("tennis", serve()),
        ("tennis", ShotSpec::new(1.0, 30.0, 12.0, -150.0, 0.5)),
        ("baseball", ShotSpec::new(1.0, 45.0, 28.0, -250.0, 0.4)),
        ("golf", ShotSpec::new(0.03, 70.0, 11.0, -300.0, 0.4)),
        ("table-tennis", ShotSpec::new(0.3, 12.0, 10.0, 100.0, 0.3)),
    ] {
        let b = ball(name);
        let mut spec = spec;
        spec.ends.bounces = 1;
        if name == "table-tennis" {
            spec.lift_coefficient = Some(0.2);
            spec.spin_decay = Some(2.0);
        }
        let shot = b.shot(&spec).unwrap();
        let air = Air {
            aero: shot.aero,
            r: b.radius(),
            q: 0.5 * shot.aero.air_density * std::f64::consts::PI * b.radius().powi(2)
                / b.params.mass,
        };
        let l = spec.launch;
        let (s, c) = l.elevation_deg.to_radians().sin_cos();
        let x0 = [0.0, l.height, l.speed * c, l.speed * s, l.spin];
        let (t1, x1) = land(&air, 0.0, &x0);
        let b1 = &shot.bounces[0];
        for (what, a, e) in [
            ("t", b1.t, t1),
            ("x", b1.x, x1[0]),
            ("vx", b1.vx_in, x1[2]),
            ("vy", b1.vy_in, x1[3]),
            ("spin", b1.spin_in, x1[4]),
        ] {
            close(&format!("{name} first landing {what}"), a, e, 1e-9);
        }
        // on from the library's own rebound: the second landing
        let xb = [b1.x, b.radius(), b1.vx_out, b1.vy_out, b1.spin_out];
        let (t2, x2) = land(&air, b1.t, &xb);
        let e = shot.end.state;
        for (what, a, ex) in [
            ("t", e.t, t2),
            ("x", e.x, x2[0]),
            ("vx", e.vx, x2[2]),
            ("vy", e.vy, x2[3]),
        ] {
            close(&format!("{name} second landing {what}"), a, ex, 1e-9);
        }
    }
}

#[test]
fn each_bounce_is_oblique_on_the_arriving_state() {
    let b = ball("tennis");
    let mut spec = serve();
    spec.ends.bounces = 3;
    let shot: ShotReport = b.shot(&spec).unwrap();
    assert_eq!(shot.bounces.len(), 3);
    for (k, bn) in shot.bounces.iter().enumerate() {
        let sx = bn.vx_in.signum();
        let o = ObliqueSpec {
            v: Some(bn.vx_in.hypot(bn.vy_in)),
            angle_deg: (-bn.vy_in).atan2(sx * bn.vx_in).to_degrees(),
            spin: sx * bn.spin_in,
            friction: 0.6,
            tangential_stiffness: None,
            inertia_factor: None,
        };
        let r = b.oblique(&o, 0).unwrap();
        let what = format!("bounce {k}");
        close(&format!("{what} vx_out"), bn.vx_out, sx * r.vx_out, 1e-12);
        close(&format!("{what} vy_out"), bn.vy_out, r.vy_out, 1e-12);
        close(
            &format!("{what} spin_out"),
            bn.spin_out,
            sx * r.spin_out,
            1e-12,
        );
        close(&format!("{what} v_out"), bn.v_out, r.v_out, 1e-12);
        close(&format!("{what} angle_in"), bn.angle_in, o.angle_deg, 1e-12);
    }
}

#[test]
fn a_shot_bounces_with_its_tangential_damping() {
    // a steep landing that grips: the bounce is `oblique_damped` with the shot's c_t, and
    // not the undamped one (`shot --tangential-damping` was taken and ignored)
    let b = ball("tennis");
    let mut spec = ShotSpec::new(2.0, 15.0, -40.0, 0.0, 0.9);
    let plain = b.shot(&spec).unwrap();
    spec.tangential_damping = Some(5.0);
    let damped = b.shot(&spec).unwrap();
    let bn = &damped.bounces[0];
    assert!(!bn.slid_throughout);
    let o = ObliqueSpec {
        v: Some(bn.vx_in.hypot(bn.vy_in)),
        angle_deg: (-bn.vy_in).atan2(bn.vx_in).to_degrees(),
        spin: bn.spin_in,
        friction: 0.9,
        tangential_stiffness: None,
        inertia_factor: None,
    };
    let r = b.oblique_damped(&o, Some(5.0), 0).unwrap();
    close("vx_out", bn.vx_out, r.vx_out, 1e-12);
    close("spin_out", bn.spin_out, r.spin_out, 1e-12);
    assert!((bn.vx_out - plain.bounces[0].vx_out).abs() > 1e-3);
}

#[test]
fn a_ball_arriving_backward_bounces_mirrored() {
    // the library's flight sent backward (elevation 150°, which `Ball::shot` does not take):
    // its bounce asks `oblique` for the mirrored state (|v_x|, −ω) and mirrors the answer back
    let b = ball("tennis");
    let aero = Aero::published(Published::Tennis, 1.204);
    let body = flight::Body::new(aero, b.params.mass, b.radius());
    let launch = flight::Launch {
        height: 1.2,
        speed: 20.0,
        elevation_deg: 150.0,
        spin: 150.0,
    };
    let ends = flight::Ends {
        bounces: 1,
        distance: None,
        time: None,
    };
    let ask = |a: &flight::Arrival| {
        let o = ObliqueSpec {
            v: Some(a.v),
            angle_deg: a.angle_deg,
            spin: a.spin,
            friction: 0.5,
            tangential_stiffness: None,
            inertia_factor: None,
        };
        b.oblique(&o, 0).map(|r| {
            (
                flight::Rebound {
                    vx: r.vx_out,
                    vy: r.vy_out,
                    spin: r.spin_out,
                },
                r,
            )
        })
    };
    let shot = flight::shot(&body, b.params.mass, &launch, &ends, 0, ask).unwrap();
    let bn = &shot.bounces[0];
    assert!(bn.mirrored && bn.arriving.vx < 0.0);
    // the same shot sent forward with the opposite spin is its mirror image
    let fwd = flight::Launch {
        elevation_deg: 30.0,
        spin: -150.0,
        ..launch
    };
    let f = flight::shot(&body, b.params.mass, &fwd, &ends, 0, ask).unwrap();
    let fb = &f.bounces[0];
    assert!(!fb.mirrored);
    close("mirror x", bn.arriving.x, -fb.arriving.x, 1e-12);
    close("mirror vx_out", bn.leaving.vx, -fb.leaving.vx, 1e-12);
    close("mirror vy_out", bn.leaving.vy, fb.leaving.vy, 1e-12);
    close("mirror spin_out", bn.leaving.spin, -fb.leaving.spin, 1e-12);
    close("mirror end x", shot.end.x, -f.end.x, 1e-12);
    close("asked spin", bn.arrival.spin, -bn.arriving.spin, 0.0);
}

#[test]
fn the_energy_lost_in_flight_is_the_drags_work() {
    for (name, spec) in [
        ("tennis", serve()),
        ("baseball", ShotSpec::new(1.0, 45.0, 28.0, -250.0, 0.4)),
        ("golf", ShotSpec::new(0.03, 70.0, 11.0, -300.0, 0.4)),
    ] {
        let b = ball(name);
        let shot = b.shot(&spec).unwrap();
        for (k, f) in shot.flights.iter().enumerate() {
            let lost = f.energy_start - f.energy_end;
            assert!(f.drag_work > 0.0);
            close(&format!("{name} flight {k}"), lost, f.drag_work, 1e-11);
        }
        // lift does no work: with drag off, no energy is lost, to the integration's error
        // (its tolerance is 1e-11 a step, src/flight/step.rs; 1.5e-12 measured)
        let mut free = spec;
        free.drag_coefficient = Some(0.0);
        let shot = b.shot(&free).unwrap();
        for f in &shot.flights {
            close(
                &format!("{name} without drag"),
                f.energy_end,
                f.energy_start,
                1e-11,
            );
        }
    }
}

#[test]
fn the_models_have_the_published_forms() {
    // Štěpánek (1988): C_L = 1/(2.022 + 0.981/S); at S = 0.2: 1/(2.022 + 4.905)
    let t = Aero::published(Published::Tennis, 1.204);
    assert!((t.lift.cl(0.2) - 1.0 / (2.022 + 0.981 / 0.2)).abs() < 1e-15);
    assert_eq!(t.drag, Drag::Constant { cd: 0.507 });
    // Nathan: C_L = 1.120 S/(0.583 + 2.333 S)
    let bb = Aero::published(Published::Baseball, 1.204);
    assert!((bb.lift.cl(0.25) - 1.120 * 0.25 / (0.583 + 2.333 * 0.25)).abs() < 1e-15);
    // golf's crisis: 0.7 below Re 3e4, 0.24 above 1.08e5, monotone between; plus 0.18 S
    let g = Aero::published(Published::Golf, 1.204);
    assert_eq!(g.drag.cd(1e4, 0.0, 0.0), 0.7);
    assert_eq!(g.drag.cd(2e5, 0.0, 0.0), 0.24);
    assert!((g.drag.cd(2e5, 0.1, 0.0) - (0.24 + 0.18 * 0.1)).abs() < 1e-15);
    let mid = g.drag.cd(6e4, 0.0, 0.0);
    assert!(mid < 0.7 && mid > 0.24);
    // C¹ across the crisis' ends (a smoothstep in ln Re)
    for re in [3.0e4, 1.08e5] {
        let h = re * 1e-7;
        let left = (g.drag.cd(re, 0.0, 0.0) - g.drag.cd(re - h, 0.0, 0.0)) / h;
        let right = (g.drag.cd(re + h, 0.0, 0.0) - g.drag.cd(re, 0.0, 0.0)) / h;
        assert!((left - right).abs() * re < 1e-4, "kink at Re = {re}");
    }
    // Smits & Smith's C_L(S): through their points, increasing between and beyond, smooth
    let pts = [
        (0.0, 0.0),
        (0.04, 0.10),
        (0.1, 0.16),
        (0.2, 0.23),
        (0.4, 0.33),
    ];
    for (s, cl) in pts {
        assert!((g.lift.cl(s) - cl).abs() < 1e-15, "S = {s}");
    }
    let grid: Vec<f64> = (0..=600).map(|i| i as f64 * 1e-3).collect();
    for w in grid.windows(2) {
        let (a, b) = (g.lift.cl(w[0]), g.lift.cl(w[1]));
        // increasing up to the last point, held beyond
        assert!(
            b > a || (w[0] >= 0.4 && b == a),
            "C_L not increasing at S = {}",
            w[1]
        );
        // C¹: no jump in the slope anywhere (a kink would show as a jump of the secant)
        if w[0] > 0.0 {
            let h = 1e-7;
            let left = (g.lift.cl(w[1]) - g.lift.cl(w[1] - h)) / h;
            let right = (g.lift.cl(w[1] + h) - g.lift.cl(w[1])) / h;
            assert!((left - right).abs() < 1e-4, "kink at S = {}", w[1]);
        }
    }
    // a ball with no published model says so
    let s = Aero::for_ball(ball("superball").flight_model, 1.204);
    assert!(s.assumed && s.lift == Lift::Constant { cl: 0.0 });
}

#[test]
fn topspin_pulls_down_and_backspin_holds_up() {
    let b = ball("tennis");
    let land = |spin: f64| {
        b.shot(&ShotSpec::new(1.0, 25.0, 8.0, spin, 0.6))
            .unwrap()
            .bounces[0]
            .x
    };
    let (top, none, back) = (land(300.0), land(0.0), land(-300.0));
    assert!(top < none && none < back, "{top} {none} {back}");
}

#[test]
fn trajectory_samples_lie_on_the_parabola_and_end_at_the_end() {
    let b = ball("tennis");
    let r = b.radius();
    let mut spec = ShotSpec::new(1.5, 20.0, 35.0, 100.0, 0.5);
    spec.drag_coefficient = Some(0.0);
    spec.lift_coefficient = Some(0.0);
    spec.ends.bounces = 0;
    spec.samples = 50;
    let shot = b.shot(&spec).unwrap();
    assert_eq!(shot.trajectory.len(), 50);
    let (s, c) = 35f64.to_radians().sin_cos();
    for p in &shot.trajectory {
        let (x, y) = (20.0 * c * p.t, 1.5 + 20.0 * s * p.t - 0.5 * G * p.t * p.t);
        close("sample x", p.x, x, 1e-12);
        close("sample y", p.y, y, 1e-12);
        close("sample vy", p.vy, 20.0 * s - G * p.t, 1e-12);
        assert!(p.y >= r - 1e-12);
    }
    assert_eq!(shot.trajectory[0].t, 0.0);
    assert_eq!(*shot.trajectory.last().unwrap(), shot.end.state);
}

#[test]
fn each_bad_value_is_refused_by_its_name() {
    let b = ball("tennis");
    type Spoil = fn(&mut ShotSpec);
    let cases: [(&str, Spoil); 12] = [
        ("height", |s| s.launch.height = 0.01),
        ("speed", |s| s.launch.speed = -1.0),
        ("elevation", |s| s.launch.elevation_deg = 91.0),
        ("spin", |s| s.launch.spin = f64::NAN),
        ("friction", |s| s.friction = -0.1),
        ("bounces", |s| s.ends.bounces = 101),
        ("distance", |s| s.ends.distance = Some(0.0)),
        ("time", |s| s.ends.time = Some(f64::INFINITY)),
        ("air_density", |s| s.air_density = -1.0),
        ("drag_coefficient", |s| s.drag_coefficient = Some(-0.1)),
        ("lift_coefficient", |s| s.lift_coefficient = Some(f64::NAN)),
        ("spin_decay", |s| s.spin_decay = Some(-1.0)),
    ];
    for (field, spoil) in cases {
        let mut spec = serve();
        spoil(&mut spec);
        let e = b.shot(&spec).unwrap_err().to_string();
        assert!(e.starts_with(&format!("invalid {field}: ")), "{field}: {e}");
    }
    let mut spec = serve();
    spec.samples = 1;
    assert!(b.shot(&spec).unwrap_err().to_string().contains("samples"));
}
