//! A flattening impact of the linear law in closed form (issue 30 item 2): COR, F̄_m and τ_f
//! where the peak passes the flattening threshold (z̄_m > z̄_p), from two evaluations of
//! [`Flow`] where the Taylor steps (`solver::taylor`) take some twenty steps.
//!
//! Loading is F̄ = z̄ up to the turn (docs/model.md §3, Eq. 21): the flow of the module's
//! introduction, whose τ_m, z̄_m = z̄(τ_m), z̄''(τ_m) and ∫₀^τ_m z̄ come from one jet. Unloading
//! is the line F̄ = k u, u = z̄ − z̄_f, k = z̄_m/(z̄_m − z̄_f) (Eq. 22, z̄_f by Eqs. 18–19).
//! Eliminating ȳ from ᾱ'' = −F̄, ȳ' = 2ζ(F̄ − λȳ) gives
//!
//! ```text
//! u''' + 2ζ(k + λ) u'' + k u' + 2ζλk u = 0,
//! ```
//!
//! which in the time s = τ√k is the loading's cubic at (λ/k, ζ√k): the same flow, from the
//! peak's state u = z̄_m − z̄_f, du/ds = 0, d²u/ds² = z̄''(τ_m)/k (u, u', u'' are continuous at
//! the turn: F̄' = k z̄' = 0 on both sides) — [`Flow::from_state`]. Separation is u's first
//! zero (F̄ = 0); ᾱ'(τ_f) = 1 − ∫₀^τ_m z̄ dτ − √k ∫₀^s_f u ds, so e = ∫₀^τ_m z̄ + √k ∫₀^s_f u − 1,
//! and τ_f = τ_m + s_f/√k.
//!
//! `None` (the caller takes the Taylor steps, then the exact solver) where the ball does not
//! flatten, where u is seen rising before it reaches 0 (a reload: docs/model.md §3), and where
//! the rounding bound (inputs' and evaluation's, [`Flow::rounding`]) cannot keep [`KEEP`].

use super::flow::Flow;
use super::search::{self, taylor};
use super::{KEEP, Summary};
use crate::model::contact::{Contact, ContactLaw};
use std::f64::consts::FRAC_PI_2;

/// The loading's turn, and the bounds on its values' rounding.
struct Turn {
    /// τ_m.
    t: f64,
    /// z̄_m, z̄''(τ_m) and ∫₀^τ_m z̄.
    z_m: f64,
    z2: f64,
    integral: f64,
    /// Bounds on the rounding of z̄_m, z̄'(τ_m), z̄''(τ_m) and the integral.
    dz: [f64; 3],
    dint: f64,
}

/// The turn of the loading F̄ = z̄ at (λ, ζ): τ_m from the flow's events, the values at it
/// from the jet at the last point evaluated (h⁴ terms ≈ 1e-16: the step settled).
fn turn(lambda: f64, zeta: f64) -> Option<Turn> {
    let load = Flow::new_quick(lambda, zeta)?;
    let peak = search::peak(&load, zeta)?;
    let (h, j) = (peak.t - peak.point.t, &peak.jet);
    let (dz_m, dint) = load.rounding(&peak.point);
    Some(Turn {
        t: peak.t,
        z_m: peak.derivative(0),
        z2: taylor(&[j[2], j[3], j[4], j[5], 0.0], h),
        integral: taylor(&[load.integral(&peak.point), j[0], j[1], j[2], j[3]], h),
        dz: [
            dz_m,
            load.derivative_rounding(&peak.point, 1),
            load.derivative_rounding(&peak.point, 2),
        ],
        dint,
    })
}

/// The unloading's separation, u's first zero from the turn's state (u0, 0, u2): from the
/// pair's phase by Householder's steps where it oscillates (`search::fall_from_turn`), by the
/// bracket search otherwise, which also turns down a rise seen before the crossing (a reload).
fn separation(unload: &Flow, u0: f64, u2: f64) -> Option<search::Root> {
    if let Some(end) = search::fall_from_turn(unload) {
        return Some(end);
    }
    let cap = if unload.omega > 0.0 {
        (FRAC_PI_2 / unload.omega).min(2.0)
    } else {
        2.0
    };
    // the first step to where the parabola u0 + u2 s²/2 reaches 0, near the root: from there
    // Householder's step lands just past it, or the step itself brackets it
    let step0 = (-2.0 * u0 / u2).sqrt().min(cap);
    search::first_fall(unload, 0, (0.0, u0), (step0, cap), true)
}

/// COR, F̄_m and τ_f of the normalized linear-law impact at (λ, ζ) that flattens at z̄_p;
/// `None` where it does not flatten (F̄_m ≤ z̄_p: [`super::summary`] answers) or the closed
/// form cannot keep its precision.
pub fn flattening(lambda: f64, zeta: f64, zp_bar: f64) -> Option<Summary> {
    let ok = |x: f64| x.is_finite() && x > 0.0;
    if !(ok(zeta) && ok(zp_bar) && lambda.is_finite() && lambda >= 0.0) {
        return None;
    }
    let top = turn(lambda, zeta)?;
    let z_m = top.z_m;
    if !(z_m > zp_bar && top.z2 < 0.0) {
        return None;
    }
    let contact = Contact {
        law: ContactLaw::Linear,
        zp_bar,
        kappa: 1.0,
    };
    let u0 = z_m - contact.permanent_indentation(z_m);
    let k = z_m / u0;
    let (root_k, u2) = (k.sqrt(), top.z2 / k);
    let unload = Flow::from_state(lambda / k, zeta * root_k, [u0, 0.0, u2])?;
    let end = separation(&unload, u0, u2)?;
    let (he, je) = (end.t - end.point.t, &end.jet);
    let int_u = taylor(
        &[unload.integral(&end.point), je[0], je[1], je[2], je[3]],
        he,
    );
    let cor = top.integral + root_k * int_u - 1.0;
    let tau_f = top.t + end.t / root_k;
    // this evaluation's rounding, and the start's errors carried to s_f (the flow is linear
    // in its start: each error's own response): u0's, z̄_m's and through Eqs. 18–19 z̄_f's
    // (whose slope in z̄_m is below 1), and u2's
    let [dz_m, dz1, dz2] = top.dz;
    let (du_f, dint_u) = unload.rounding(&end.point);
    let carried = [[2.0 * dz_m, 0.0, 0.0], [0.0, 0.0, dz2 / k]];
    let carried = unload.responses(carried, &end.point);
    let du_f = du_f + carried[0].0.abs() + carried[1].0.abs();
    let dint_u = dint_u + carried[0].1.abs() + carried[1].1.abs();
    // τ_f carries the turn's error too: z̄' over z̄''
    let dtau = du_f / end.derivative(1).abs() / root_k + dz1 / top.z2.abs();
    let precise = dz_m <= KEEP * z_m
        && top.dint + root_k * dint_u <= KEEP * cor.abs()
        && dtau <= KEEP * tau_f;
    (precise && cor.is_finite() && tau_f.is_finite()).then_some(Summary {
        cor,
        max_force: z_m,
        contact_time: tau_f,
    })
}
