//! The oblique impact (docs/oblique.md): its limits in closed form, the independent
//! integration over a grid, the energy balance, angle 90 against `run`, and bad input.

use bouncelab::oblique::{self, Oblique, ObliqueError, ObliqueResponse, mindlin_ratio, reference};
use bouncelab::{Ball, ImpactParams};

/// The tennis ball's radius (m), the oblique tests' R.
pub const R: f64 = 0.0335;

pub fn tennis() -> ImpactParams {
    Ball::from_preset("tennis").unwrap().params
}

pub fn setup(angle: f64, spin: f64, mu: f64, kt: f64, kappa: f64) -> Oblique {
    Oblique::new(angle, spin, mu, kt, kappa, R).unwrap()
}

/// The tangential answer `r` at 25 m/s against the independent integration's `(v_x, ω)`,
/// both normalized by the incoming speed scale (v_x against v, Rω against v): within 1e-8,
/// else a failure naming `case`. Returns the larger of the two, for the grid's worst.
fn assert_agrees_with_the_integration(r: &ObliqueResponse, (vx, w): (f64, f64), case: &str) -> f64 {
    let dv = (vx - r.vx_out).abs() / 25.0;
    let dw = R * (w - r.spin_out).abs() / 25.0;
    assert!(
        dv < 1e-8 && dw < 1e-8,
        "{case}: v_x {} vs {vx}, ω {} vs {w}",
        r.vx_out,
        r.spin_out
    );
    dv.max(dw)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// Each impact of `grid` (its name, and what `solve` takes) against the independent
/// integration, `solve` giving both (the answer; the integration's v_x, ω and switches): each
/// agrees ([`assert_agrees_with_the_integration`]), and the grid switches between stick and
/// slip more than `switches` times.
pub fn assert_the_grid_agrees<T>(
    grid: Vec<(String, T)>,
    solve: impl Fn(&T) -> (ObliqueResponse, (f64, f64, usize)),
    switches: usize,
) {
    let (mut worst, mut switched) = (0.0f64, 0);
    for (case, o) in &grid {
        let (r, (vx, w, n)) = solve(o);
        switched += n;
        worst = worst.max(assert_agrees_with_the_integration(&r, (vx, w), case));
    }
    assert!(
        switched > switches,
        "the grid must switch between stick and slip: {switched}"
    );
    let n = grid.len();
    eprintln!("worst disagreement {worst:e} over {n} impacts, {switched} switches");
}

/// What [`assert_the_grid_agrees`] takes of an impact of ball `p` at 25 m/s under the linear
/// law: the answer and the independent integration's.
pub fn at_25_m_s(
    p: &ImpactParams,
) -> impl Fn(&Oblique) -> (ObliqueResponse, (f64, f64, usize)) + '_ {
    |o| {
        let r = oblique::solve(p, 25.0, o, 0).unwrap();
        (r, reference::solve(p, 25.0, o).unwrap())
    }
}

#[test]
fn no_friction_leaves_the_tangential_motion_unchanged() {
    let p = tennis();
    for (angle, spin) in [(16.0, 0.0), (30.0, 300.0), (60.0, -500.0), (90.0, 200.0)] {
        let o = setup(angle, spin, 0.0, 0.8 * p.k_p, 0.55);
        let r = oblique::solve(&p, 25.0, &o, 0).unwrap();
        assert_eq!(r.vx_out, r.vx_in, "v_x at {angle}°, {spin} rad/s");
        assert_eq!(r.spin_out, spin, "ω at {angle}°, {spin} rad/s");
        assert!(r.energy.friction_dissipation.abs() < 1e-15);
    }
}

#[test]
fn a_stiff_spring_sliding_throughout_loses_mu_times_the_normal_impulse() {
    // Δv_x = −μ(1 + e)v_y, Δω = μ(1 + e)v_y m R/I (docs/oblique.md §3)
    let p = tennis();
    let (mu, kappa) = (0.1, 0.55);
    let o = setup(16.0, 0.0, mu, 1e6 * p.k_p, kappa);
    let r = oblique::solve(&p, 25.0, &o, 0).unwrap();
    assert!(r.slid_throughout);
    // no grip: zero time, +0 (the JSON says 0.0, not -0.0: a sum over no phases)
    assert!(
        r.grip_time == 0.0 && r.grip_time.is_sign_positive(),
        "grip_time {:?}",
        r.grip_time
    );
    let impulse = (1.0 + r.cor_normal) * r.vy_in;
    let dvx = r.vx_out - r.vx_in;
    assert!(
        rel(dvx, -mu * impulse) < 1e-6,
        "Δv_x {dvx} vs {}",
        -mu * impulse
    );
    let dw = r.spin_out - r.spin_in;
    let expected = mu * impulse / (kappa * R); // m R/I = 1/(κ R)
    assert!(rel(dw, expected) < 1e-6, "Δω {dw} vs {expected}");
    assert!(rel(r.apparent_friction, mu) < 1e-6);
}

#[test]
fn high_friction_and_a_stiff_spring_leave_rolling() {
    // v_x,out = (v_x + κRω)/(1 + κ): the contact point at rest, angular momentum about it kept
    let p = tennis();
    let kappa = 0.55;
    for (angle, spin) in [(16.0, 0.0), (30.0, 300.0), (45.0, -200.0)] {
        let o = setup(angle, spin, 3.0, 1e6 * p.k_p, kappa);
        let r = oblique::solve(&p, 25.0, &o, 0).unwrap();
        let rolling = (r.vx_in + kappa * R * spin) / (1.0 + kappa);
        assert!(rel(r.vx_out, rolling) < 1e-4, "{} vs {rolling}", r.vx_out);
        assert!((r.vx_out - R * r.spin_out).abs() < 1e-4 * r.vx_in);
    }
}

#[test]
fn angle_90_is_run() {
    let ball = Ball::from_preset("tennis").unwrap();
    let run = ball.impact().unwrap();
    let o = setup(90.0, 0.0, 0.6, 0.8 * ball.params.k_p, 0.55);
    let r = oblique::solve(&ball.params, ball.params.v0, &o, 0).unwrap();
    assert!((r.cor_normal - run.cor).abs() < 1e-12);
    assert!(r.vx_out.abs() <= 1e-12 && r.spin_out.abs() <= 1e-12);
    assert!(r.max_friction_force.abs() <= 1e-12);
    assert_eq!(r.contact_time, run.contact_time.unwrap());
    assert_eq!(r.cor_tangential, None);
}

#[test]
fn the_independent_integration_agrees_over_a_grid() {
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    let mut grid = Vec::new();
    for angle in [5.0, 16.0, 30.0, 45.0, 60.0, 85.0] {
        for spin in [-500.0, -100.0, 0.0, 150.0, 500.0] {
            for mu in [0.05, 0.3, 0.6, 2.0] {
                let case = format!("{angle}°, {spin} rad/s, μ {mu}");
                grid.push((case, setup(angle, spin, mu, kt, 0.55)));
            }
        }
    }
    assert_the_grid_agrees(grid, at_25_m_s(&p), 50);
}

#[test]
fn the_energy_balance_closes() {
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    for angle in [5.0, 16.0, 45.0, 80.0] {
        for spin in [-400.0, 0.0, 300.0] {
            for mu in [0.1, 0.6, 2.0] {
                let o = setup(angle, spin, mu, kt, 0.55);
                let r = oblique::solve(&p, 25.0, &o, 0).unwrap();
                let e = r.energy;
                assert!(
                    e.residual < 1e-12,
                    "{angle}° {spin} {mu}: residual {:e}",
                    e.residual
                );
                assert!(e.friction_dissipation >= 0.0);
            }
        }
    }
}

#[test]
fn bad_input_names_the_field() {
    let p = tennis();
    let cases: [(Oblique, &str); 6] = [
        (
            Oblique {
                angle_deg: 0.0,
                ..ok()
            },
            "invalid angle: 0",
        ),
        (
            Oblique {
                angle_deg: 90.5,
                ..ok()
            },
            "invalid angle: 90.5",
        ),
        (
            Oblique {
                friction: -0.1,
                ..ok()
            },
            "invalid friction: -0.1",
        ),
        (
            Oblique {
                tangential_stiffness: 0.0,
                ..ok()
            },
            "invalid tangential_stiffness: 0",
        ),
        (
            Oblique {
                inertia_factor: 0.0,
                ..ok()
            },
            "invalid inertia_factor: 0",
        ),
        (
            Oblique {
                inertia_factor: 1.5,
                ..ok()
            },
            "invalid inertia_factor: 1.5",
        ),
    ];
    for (o, message) in cases {
        let err = oblique::solve(&p, 25.0, &o, 0).unwrap_err();
        assert!(matches!(err, ObliqueError::Invalid(_)));
        let text = err.to_string();
        assert!(text.starts_with(message), "{text}");
        assert!(!text.contains('\n'));
        assert!(!err.is_no_answer());
    }
}

fn ok() -> Oblique {
    Oblique {
        angle_deg: 16.0,
        spin: 0.0,
        friction: 0.6,
        tangential_stiffness: 2e4,
        inertia_factor: 0.55,
        radius: R,
        tangential_damping: 0.0,
    }
}

/// The peak friction force (exact per phase, docs/oblique.md §3) is never exceeded by a
/// dense history's largest, and comes within 1e-6 of it.
pub fn assert_peak_friction_is_the_historys(r: &ObliqueResponse, angle: f64) {
    assert_peak_friction_within(r, 1e-12, &format!("{angle}°"));
}

/// A dense history's largest friction force exceeds the peak `r` reports by at most `above`
/// (relative) and comes within 1e-6 of it; a failure names `case`.
pub fn assert_peak_friction_within(r: &ObliqueResponse, above: f64, case: &str) {
    let h = r.history.as_ref().unwrap();
    let sampled = h.friction_force.iter().fold(0.0f64, |m, f| m.max(f.abs()));
    let peak = r.max_friction_force;
    assert!(
        sampled <= peak * (1.0 + above),
        "{case}: {sampled} > {peak}"
    );
    assert!(sampled >= peak * (1.0 - 1e-6), "{case}: {sampled} ≪ {peak}");
}

#[test]
fn the_peak_friction_force_is_the_historys_largest() {
    // exact per phase (docs/oblique.md §3): a dense history never exceeds it, and comes close
    let p = tennis();
    let kt = mindlin_ratio(0.5) * p.k_p;
    for (angle, spin, mu) in [(16.0, 300.0, 0.6), (45.0, -200.0, 2.0), (70.0, 0.0, 0.3)] {
        let o = setup(angle, spin, mu, kt, 0.55);
        let r = oblique::solve(&p, 25.0, &o, 20_001).unwrap();
        assert_peak_friction_is_the_historys(&r, angle);
    }
}
