//! The flight's closed forms (src/drop/flight.rs) against a direct integration of
//! m v' = −m g − k v|v| by DOPRI5 (differential-equations), and the drag-free limit.

use bouncelab::drop::{Air, Flight, G};
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::solout::DefaultSolout;

/// State (height, upward velocity); x = k/m.
struct Vertical(f64);

impl ODE<f64, [f64; 2]> for Vertical {
    fn diff(&self, _t: f64, s: &[f64; 2], ds: &mut [f64; 2]) {
        ds[0] = s[1];
        ds[1] = -G - self.0 * s[1] * s[1].abs();
    }
}

/// (t, [h, v]) at every step from `start` over [0, t_end].
fn integrate(x: f64, start: [f64; 2], t_end: f64) -> Vec<(f64, [f64; 2])> {
    let mut m = ExplicitRungeKutta::dopri5()
        .rtol(1e-12)
        .atol(1e-14)
        .max_steps(1_000_000);
    let sol = solve_ode(
        &mut m,
        &Vertical(x),
        0.0,
        t_end,
        &start,
        &mut DefaultSolout::new(),
    )
    .expect("the reference integrates");
    sol.t.into_iter().zip(sol.y).collect()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// Flights of a tennis ball, a table-tennis ball (drag strong: v_t ≈ 8.6 m/s), a ball under a
/// heavy drag coefficient, and a fall long enough to near the terminal speed.
fn flights() -> Vec<(Flight, f64)> {
    let air = Some(Air::default());
    vec![
        (Flight::new(0.0577, 0.0335, air), 2.54),
        (Flight::new(0.0027, 0.020, air), 0.305),
        (
            Flight::new(
                0.0027,
                0.020,
                Some(Air {
                    drag_coefficient: 5.0,
                    ..Air::default()
                }),
            ),
            3.0,
        ),
        (Flight::new(0.6085, 0.12167, air), 200.0),
    ]
}

#[test]
fn closed_forms_follow_the_integrated_fall() {
    for (f, h) in flights() {
        let t_fall = f.fall_time(h);
        let steps = integrate(f.drag_per_mass, [h, 0.0], t_fall);
        for (t, [hh, v]) in &steps {
            let (s, speed) = f.fall_at(*t);
            assert!(
                close(h - s, *hh, 1e-9),
                "x={} t={t}: {} vs {hh}",
                f.drag_per_mass,
                h - s
            );
            assert!(
                close(speed, -v, 1e-9),
                "x={} t={t}: {speed} vs {}",
                f.drag_per_mass,
                -v
            );
        }
        // at the fall time the integrated ball is at the plate with the closed form's speed
        let (_, [h_end, v_end]) = steps.last().unwrap();
        assert!(h_end.abs() < 1e-9 * h.max(1.0), "{h_end}");
        assert!(close(-v_end, f.fall_speed(h), 1e-9), "{v_end}");
    }
}

#[test]
fn closed_forms_follow_the_integrated_rise() {
    for (f, h) in flights() {
        let u = f.fall_speed(h) * 0.8;
        let t_up = f.rise_time(u);
        let steps = integrate(f.drag_per_mass, [0.0, u], t_up);
        for (t, [hh, v]) in &steps {
            let (h_c, v_c) = f.rise_at(u, *t);
            assert!(
                close(h_c, *hh, 1e-9),
                "x={} t={t}: {h_c} vs {hh}",
                f.drag_per_mass
            );
            assert!(
                close(v_c, *v, 1e-9),
                "x={} t={t}: {v_c} vs {v}",
                f.drag_per_mass
            );
        }
        // at the rise time the integrated ball is at rest at the closed-form apex
        let (_, [h_end, v_end]) = steps.last().unwrap();
        assert!(v_end.abs() < 1e-9 * u, "{v_end}");
        assert!(close(*h_end, f.rise_height(u), 1e-9), "{h_end}");
        // the launch speed for the apex inverts the apex, the fall height the fall speed
        assert!(close(f.launch_speed_for(f.rise_height(u)), u, 1e-12));
        assert!(close(f.fall_height_for(f.fall_speed(h)).unwrap(), h, 1e-9));
        assert_eq!(f.fall_height_for(1.0001 * f.terminal_speed()), None);
    }
}

#[test]
fn vanishing_drag_tends_to_vacuum() {
    let vac = Flight::vacuum();
    let (h, u, t) = (2.54, 5.0, 0.3);
    let mut last = f64::INFINITY;
    for cd in [1e-1, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11] {
        let f = Flight::new(
            0.0577,
            0.0335,
            Some(Air {
                drag_coefficient: cd,
                ..Air::default()
            }),
        );
        let gaps = [
            (f.fall_speed(h) - vac.fall_speed(h)) / vac.fall_speed(h),
            (f.fall_time(h) - vac.fall_time(h)) / vac.fall_time(h),
            (f.rise_height(u) - vac.rise_height(u)) / vac.rise_height(u),
            (f.rise_time(u) - vac.rise_time(u)) / vac.rise_time(u),
            (f.fall_at(t).0 - vac.fall_at(t).0) / vac.fall_at(t).0,
            (f.rise_at(u, t).0 - vac.rise_at(u, t).0) / vac.rise_at(u, t).0,
        ];
        let worst = gaps.iter().map(|g| g.abs()).fold(0.0, f64::max);
        // drag only slows: every gap is a loss, and it shrinks in proportion to C_d
        assert!(gaps[0] < 0.0 && gaps[2] < 0.0, "C_d = {cd}: {gaps:?}");
        assert!(worst < 0.05 * cd.max(1e-13) + 1e-14, "C_d = {cd}: {gaps:?}");
        assert!(worst <= last, "C_d = {cd}: {worst} after {last}");
        last = worst;
    }
    // the vacuum forms themselves
    assert!(close(vac.fall_speed(h), (2.0 * G * h).sqrt(), 1e-15));
    assert!(close(vac.rise_height(u), u * u / (2.0 * G), 1e-15));
}

/// `drop --height 3000` printed t_start `inf` for every bounce (JSON `null`): artanh(v/v_t)
/// with v/v_t rounded to 1. The fall time from high up is the terminal-speed time plus a
/// constant, t = (v_t/g)(xs + ln 2) to e^{−2xs}, and it follows the integrated fall at the
/// heights that were right before.
#[test]
fn a_fall_from_high_up_takes_a_finite_time() {
    let air = Some(Air::default());
    let f = Flight::new(0.0374, 0.02155, air);
    let (vt, x) = (f.terminal_speed(), f.drag_per_mass);
    for h in [3000.0, 1e4, 1e5] {
        let t = f.fall_time(h);
        let far = (vt / 9.80665) * (x * h + std::f64::consts::LN_2);
        assert!(t.is_finite() && close(t, far, 1e-12), "h {h}: {t} vs {far}");
        // the fall reaches the ground then: fall_at, the closed form of the motion, agrees
        assert!(close(f.fall_at(t).0, h, 1e-12), "h {h}: {:?}", f.fall_at(t));
    }
    for (f, h) in flights() {
        let (s, _) = f.fall_at(f.fall_time(h));
        assert!(close(s, h, 1e-12), "x={}: {s} vs {h}", f.drag_per_mass);
    }
    // both forms at the switch, xs = 1
    let h = 1.0 / x;
    let (below, above) = (
        f.fall_time(h * (1.0 - 1e-15)),
        f.fall_time(h * (1.0 + 1e-15)),
    );
    assert!(close(below, above, 1e-14), "{below} {above}");
}
