use super::*;
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::solout::DefaultSolout;

/// The creep's system integrated by DOPRI5, with the dashpot's dissipation ∫v²/(2ζ) as a
/// third state: the closed form's independent reference.
struct Reduced(f64, f64);

impl ODE<f64, [f64; 3]> for Reduced {
    fn diff(&self, _t: f64, w: &[f64; 3], dw: &mut [f64; 3]) {
        let Reduced(lambda, zeta) = *self;
        dw[0] = w[1];
        dw[1] = -lambda * w[0] - w[1] / (2.0 * zeta);
        dw[2] = w[1] * w[1] / (2.0 * zeta);
    }
}

/// Every step of the reference from (y0, v0) to τ: (τ, [ȳ, v, dissipated]).
fn reference(c: &Creep, tau: f64) -> Vec<(f64, [f64; 3])> {
    // one absolute tolerance for all: below the smaller state's, or ȳ's sets v's
    let scale = c.w0.abs().min();
    let mut m = ExplicitRungeKutta::dopri5()
        .rtol(1e-12)
        .atol(1e-15 * scale)
        .max_steps(1_000_000);
    let y0 = [c.w0[0], c.w0[1], 0.0];
    let sol = solve_ode(
        &mut m,
        &Reduced(c.lambda, c.zeta),
        0.0,
        tau,
        &y0,
        &mut DefaultSolout::new(),
    )
    .expect("the reference integrates");
    sol.t.into_iter().zip(sol.y).collect()
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// (λ, ζ, ȳ0, v0): a weak dashpot's creep (overdamped, the separation ~5e4 ω0⁻¹ on),
/// a ball still moving in; an underdamped pair; critical damping exactly (q = 0) and
/// just off it; a ball already moving out.
const CASES: [(f64, f64, f64, f64); 5] = [
    (6.3e-14, 1e4, 1.9995e4, -1.4773e-5),
    (2.4e-13, 6012.0, 1.2020e4, 2.99e-5),
    (1.0, 1.0, 0.3, 0.2),
    (1.0, 0.25, 0.5, 0.1),
    (1.0 - 1e-9, 0.25, 0.5, -0.2),
];

#[test]
fn the_closed_form_follows_the_integrated_creep_to_its_separation() {
    for (lambda, zeta, y0, v0) in CASES {
        let c = Creep::new(lambda, zeta, y0, v0);
        let at = c.separation().expect("a recoil spring sends the ball out");
        let steps = reference(&c, at);
        let (_, [y, v, lost]) = *steps.last().unwrap();
        let w = c.at(at);
        let case = format!("λ = {lambda}, ζ = {zeta}: τ = {at}");
        assert!(
            rel(w[0], y) < 1e-9 && rel(w[1], v) < 1e-9,
            "{case}: {w:?} vs {y}, {v}"
        );
        // it leaves at the element's pace, with no force
        assert!(
            rel(-w[1], 2.0 * zeta * lambda * w[0]) < 1e-9,
            "{case}: v = {}",
            w[1]
        );
        // and not before: the integrated force stays positive up to it
        let force = |s: &[f64; 3]| lambda * s[0] + s[1] / (2.0 * zeta);
        let early = steps.iter().filter(|(t, _)| *t < 0.999 * at);
        assert!(
            early.clone().all(|(_, s)| force(s) > 0.0),
            "{case}: left early"
        );
        // the peak force: what the flow reaches at the reference's steps, and no more
        let peak = c.peak_force(Some(at));
        let reached = early.map(|(_, s)| force(s)).fold(c.force(&c.w0), f64::max);
        assert!(
            reached <= peak * (1.0 + 1e-9) && peak <= reached * 1.01,
            "{case}: {peak}"
        );
        // the energy identity the solver books the dashpot's share by
        let energy = |y: f64, v: f64| 0.5 * v * v + 0.5 * lambda * y * y;
        let by_identity = energy(y0, v0) - energy(w[0], w[1]);
        assert!(
            rel(by_identity, lost) < 1e-7,
            "{case}: {by_identity} vs {lost}"
        );
    }
}

#[test]
fn without_a_recoil_spring_a_ball_moving_in_never_leaves() {
    assert_eq!(Creep::new(0.0, 30.0, 2.0, 1e-3).separation(), None);
    assert_eq!(
        Creep::new(0.0, 30.0, 2.0, 1e-3).peak_force(None),
        1e-3 / 60.0
    );
    // moving out with no force: it has left
    assert_eq!(Creep::new(0.0, 30.0, 2.0, -1e-3).separation(), Some(0.0));
}
