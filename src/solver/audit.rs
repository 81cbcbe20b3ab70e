//! The invariants every answer of the solvers must satisfy, whatever the (valid) input: no
//! NaN or infinity, 0 ≤ e ≤ 1, F(0) = 0, the energy balance closed, a finite contact time or
//! "no rebound", a ball that leaves outrunning the element its recoil spring retracts, and a
//! bounded number of steps. One checker, for the property tests and the solver tests over the
//! domain the README guarantees. The fuzz targets (`fuzz/src/checks.rs`) feed inputs far
//! outside it (λ, ζ up to 1e6, K_p down to 1e-15), where the energy balance is not promised;
//! they carry their own checks, and share only `energy_tolerance` with this one.

use super::{EnergyBudget, ImpactResponse, Method};

/// The most steps one impact may take, from the solvers' budgets. Exact solver: its phases
/// times its steps a phase. Adaptive solver: a new phase starts only while the impact's
/// budget is not spent, and one phase takes at most every budget of its integrator cascade,
/// then again to re-integrate to its event; twice over when samples are asked for (the
/// sampling run repeats the summary run). A run that reaches a budget is reported as
/// unresolved, never as an answer.
pub const STEP_BOUND: usize = {
    use super::{exact, numeric};
    let exact = exact::MAX_PHASES * exact::MAX_STEPS;
    let phase = 2 * numeric::CASCADE_BUDGET;
    let numeric = 2 * (numeric::TOTAL_STEPS + phase);
    if exact > numeric { exact } else { numeric }
};

/// The energy balance each integrator closes to, relative to ½ m v0² (what the property tests
/// hold it to, and what the README states), from 60 000 random impacts over the property
/// tests' domain, seeds 4242, 777 and 31337 (median / 99.9th percentile / worst):
/// - exact solver, dashpot energy by Gauss–Legendre on the exact flow: 1.6e-15 / 1.1e-7 /
///   6.7e-7 then, the worst where a creep lasts thousands of ω0⁻¹; since the fast/slow split
///   of the propagator, 4.8e-16 / 9.3e-13 / 9.4e-13 (60 000 random linear impacts, λ drawn
///   from 1e-11); with λ drawn from 1e-15 as well, 4.8e-16 / 3.2e-11 / 2.6e-10 (the 20 003
///   linear runs among the 60 000 impacts of `every_run_keeps_the_invariants`);
/// - DOPRI5, dissipation integrated as a fourth state at rtol 1e-10: 4.1e-11 / 3.0e-9 /
///   3.5e-9 (25 054 runs);
/// - a stiff integrator (the `differential-equations` crate's Radau5 or BDF, possibly
///   loosened) on some of the run: 1.9e-7 / 1.7e-5 / 2.2e-3 (14 952 runs), their error
///   estimates holding the dissipation less tightly than the state. The worst are creeps of
///   ~1e4 ω0⁻¹ taken in ~1e5 Radau5 steps, each adding ~1e-8 to the dissipation integral
///   (λ = 7.9e-12, ζ = 724, elastic–plastic); at rtol 1e-12 that ball reaches 8.3e-3.
pub fn energy_tolerance(r: &ImpactResponse) -> f64 {
    match (r.method, r.stiff) {
        (Method::Exact, _) => 1e-6,
        (Method::Numeric, false) => 1e-8,
        (Method::Numeric, true) => 5e-3,
    }
}

/// The first invariant `r` breaks, in words; `Ok` when it keeps them all. The energy check
/// needs the run made with `SolveOptions::with_energy`, the history checks with samples.
pub fn audit(r: &ImpactResponse) -> Result<(), String> {
    all_finite(r)?;
    if !(0.0..=1.0).contains(&r.cor) {
        return Err(format!("cor {} outside [0, 1]", r.cor));
    }
    match (r.rebound, r.contact_time, r.contact_time_normalized) {
        (true, Some(t), Some(tau)) => {
            finite("contact_time", t)?;
            finite("contact_time_normalized", tau)?;
            if t <= 0.0 || t != r.duration {
                return Err(format!("contact time {t} (duration {})", r.duration));
            }
        }
        (false, None, None) if r.cor == 0.0 => {}
        _ => {
            return Err(format!(
                "rebound {} with contact time {:?} and cor {}",
                r.rebound, r.contact_time, r.cor
            ));
        }
    }
    if r.max_force < 0.0 || r.max_indentation < 0.0 {
        return Err("negative peak force or indentation".into());
    }
    if !(0.0..=r.max_indentation).contains(&r.permanent_indentation) {
        return Err(format!(
            "permanent indentation {} outside [0, z_m = {}]",
            r.permanent_indentation, r.max_indentation
        ));
    }
    if r.steps > STEP_BOUND {
        return Err(format!("{} steps, above the bound {STEP_BOUND}", r.steps));
    }
    events(r)?;
    history(r)?;
    if let Some(e) = &r.energy {
        energy_balanced(r, e)?;
    }
    outruns_the_element(r)
}

/// `x`, named `name`, is finite.
fn finite(name: &str, x: f64) -> Result<(), String> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(format!("{name} is {x}"))
    }
}

/// Every number of the summary is finite.
fn all_finite(r: &ImpactResponse) -> Result<(), String> {
    finite("cor", r.cor)?;
    finite("max_force", r.max_force)?;
    finite("duration", r.duration)?;
    finite("max_indentation", r.max_indentation)?;
    finite("permanent_indentation", r.permanent_indentation)?;
    finite("max_force_normalized", r.max_force_normalized)?;
    finite("element_displacement", r.element_displacement)?;
    finite(
        "element_displacement_normalized",
        r.element_displacement_normalized,
    )?;
    finite("lambda", r.normalized.lambda)?;
    finite("zeta", r.normalized.zeta)?;
    Ok(())
}

/// The energy balance closes to the integrator's tolerance, and the dashpot only takes
/// energy out.
fn energy_balanced(r: &ImpactResponse, e: &EnergyBudget) -> Result<(), String> {
    for (name, x) in [
        ("initial kinetic energy", e.initial_kinetic),
        ("final kinetic energy", e.final_kinetic),
        ("dashpot energy", e.dashpot),
        ("contact energy", e.contact),
        ("spring energy", e.spring),
    ] {
        finite(name, x)?;
    }
    let tol = energy_tolerance(r);
    if e.relative_residual() > tol {
        return Err(format!(
            "energy balance off by {:e} of ½ m v0² (tolerance {tol:e})",
            e.relative_residual()
        ));
    }
    // the dashpot only takes energy out (to rounding of the quadrature)
    if e.dashpot < -tol * e.initial_kinetic {
        return Err(format!("dashpot energy {} < 0", e.dashpot));
    }
    Ok(())
}

/// A ball leaves only by outrunning the element the recoil spring retracts: at z̄_f there is
/// no force, ȳ' = −2ζλȳ, and z̄' = ᾱ' + 2ζλȳ must be ≤ 0 for z̄ to fall through it, so
/// e ≥ 2ζλȳ_f. A grazing separation (a weak dashpot's slow manifold) meets it with equality;
/// the adaptive solver takes one at 1e-3 of it (`numeric::PACE_SLACK`), hence the 2e-3 here.
/// A separation taken in the integrator's noise breaks it (tests/physics/properties.rs,
/// `every_run_keeps_the_invariants`, runs it over the domain).
///
/// ȳ_f with its sign: the element ends a hair below zero where a stiff integrator steps across
/// its relaxation (Radau5's stability function is negative far out on the stiff axis: ȳ_f =
/// −5.8e-10 at λ = 2 622, ζ = 1e4, elastic–plastic, where the relaxation at 2ζλ = 5e7 against
/// the force's fall puts it, by estimate, ~1e-12 above zero). The spring then pushes the
/// element after the ball, which it does not slow: the check takes ȳ_f with its sign, not
/// |ȳ_f| from the spring's energy (`an_element_left_below_zero_does_not_hold_the_ball_back`).
fn outruns_the_element(r: &ImpactResponse) -> Result<(), String> {
    let n = &r.normalized;
    if !r.rebound || n.lambda == 0.0 {
        return Ok(());
    }
    let pace = 2.0 * n.zeta * n.lambda * r.element_displacement_normalized;
    if r.cor < (1.0 - 2e-3) * pace {
        return Err(format!(
            "e = {:e} below 2ζλȳ_f = {pace:e}: the ball left slower than the element",
            r.cor
        ));
    }
    Ok(())
}

/// Events in time order, inside the run, a separation only at its end and only with a rebound.
fn events(r: &ImpactResponse) -> Result<(), String> {
    let mut last = 0.0;
    for (i, ev) in r.events.iter().enumerate() {
        if !(ev.t.is_finite() && ev.z.is_finite()) {
            return Err(format!("event {i} at t = {}, z = {}", ev.t, ev.z));
        }
        if ev.t < last || ev.t > r.duration * (1.0 + 1e-12) {
            return Err(format!("event {i} at t = {} out of order", ev.t));
        }
        last = ev.t;
        let is_separation = ev.kind == super::EventKind::Separation;
        if is_separation != (r.rebound && i + 1 == r.events.len()) {
            return Err(format!("event {i} ({:?}) misplaced", ev.kind));
        }
    }
    Ok(())
}

/// Samples finite, evenly timed from 0 to the end, with F(0) = 0 and F ≥ 0 throughout.
fn history(r: &ImpactResponse) -> Result<(), String> {
    let h = &r.history;
    let n = h.t.len();
    if h.force.len() != n || h.indentation.len() != n || h.displacement.len() != n {
        return Err("history columns of different lengths".into());
    }
    if n == 0 {
        return Ok(());
    }
    if h.t[0] != 0.0 || h.force[0] != 0.0 || h.indentation[0] != 0.0 {
        return Err(format!(
            "history starts at t = {}, F = {}, z = {} (want all 0)",
            h.t[0], h.force[0], h.indentation[0]
        ));
    }
    for i in 0..n {
        let row = [h.t[i], h.force[i], h.indentation[i], h.displacement[i]];
        if row.iter().any(|x| !x.is_finite()) {
            return Err(format!("history row {i} is {row:?}"));
        }
        if h.force[i] < 0.0 {
            return Err(format!("pulling force {} at row {i}", h.force[i]));
        }
        if i > 0 && h.t[i] < h.t[i - 1] {
            return Err(format!("history time goes back at row {i}"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ContactLaw, ImpactParams, SolveOptions, simulate};

    /// λ = 2 622, ζ = 1e4, elastic–plastic: Radau5 leaves the element a few 1e-10 below zero, where 2ζλ|ȳ_f| is of the order of e = 0.021.
    /// The element follows the ball; the separation is real.
    #[test]
    fn an_element_left_below_zero_does_not_hold_the_ball_back() {
        let p = ImpactParams {
            mass: 0.1430315158928167,
            k_p: 109.80712741683931,
            damping: 0.00019815322284955523,
            k_r: 287878.6075999775,
            z_p: 2.452094248582713e-8,
            k_h: 467488.2418047793,
            v0: 200.0,
        };
        let o = SolveOptions::default().with_energy();
        let r = simulate(&p, ContactLaw::ElasticPlastic, &o).unwrap();
        assert!(
            r.rebound && r.element_displacement_normalized < 0.0,
            "{r:?}"
        );
        assert_eq!(audit(&r), Ok(()));
        // the same separation with the element retracting at 1.5 e is slower than it
        let n = &r.normalized;
        let mut slower = r.clone();
        slower.element_displacement_normalized = 1.5 * r.cor / (2.0 * n.zeta * n.lambda);
        let why = audit(&slower).unwrap_err();
        assert!(why.contains("slower than the element"), "{why}");
    }
}
