//! The solver's contract, for both fuzz targets (`super` holds the targets' decoding and
//! the preset's checks): `simulate` and `simulate_normalized` give the error `validate` names
//! for invalid input, and for valid input a response that keeps the contract, each part of it
//! a named check below.

use super::check_one_line;
use bouncelab::model::params::{Field, validate_lambda_zeta};
use bouncelab::solver::{EventKind, ImpactResponse, Method, SolveOptions};
use bouncelab::{ContactLaw, ImpactParams, ParamError, SolveError, simulate, simulate_normalized};

/// The fields a `ParamError` may name for a bad input (as opposed to a solver-side failure).
const INPUT_FIELDS: [Field; 11] = [
    Field::Mass,
    Field::KP,
    Field::Damping,
    Field::KR,
    Field::ZP,
    Field::KH,
    Field::V0,
    Field::Lambda,
    Field::Zeta,
    Field::ZpBar,
    Field::Method,
];

/// The error `simulate` must give, if any: the first field `validate` rejects, else the exact
/// solver asked for a law it does not run.
fn expected_error(
    params: &ImpactParams,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Option<ParamError> {
    params.validate().err().or_else(|| {
        (opts.method == Some(Method::Exact) && law != ContactLaw::Linear).then_some(ParamError {
            field: Field::Method,
            value: f64::NAN,
            reason: "",
        })
    })
}

/// `simulate`: invalid input is an error naming the field `validate` names; valid input gives a
/// response that keeps the contract (`check_response`). Returns the response.
pub fn check_simulate(
    params: &ImpactParams,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Option<ImpactResponse> {
    let result = simulate(params, law, opts);
    check_result(result, expected_error(params, law, opts), params, law, opts)
}

/// `simulate_normalized(λ, ζ)`: the same contract, on the normalized ball.
pub fn check_simulate_normalized(
    lambda: f64,
    zeta: f64,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Option<ImpactResponse> {
    let result = simulate_normalized(lambda, zeta, law, opts);
    let params = ImpactParams::from_normalized(lambda, zeta, f64::INFINITY);
    let expected = match validate_lambda_zeta(lambda, zeta) {
        Err(e) => Some(e),
        Ok(()) => {
            // a pair that passes its own check makes a valid ball
            if let Err(e) = params.validate() {
                panic!("λ = {lambda:e}, ζ = {zeta:e} pass validate_lambda_zeta, not validate: {e}");
            }
            expected_error(&params, law, opts)
        }
    };
    let response = check_result(result, expected, &params, law, opts)?;
    let n = response.normalized;
    assert!(
        close(n.lambda, lambda, 1e-12) && close(n.zeta, zeta, 1e-12),
        "asked λ = {lambda:e}, ζ = {zeta:e}; ran {n:?}"
    );
    Some(response)
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

fn check_result(
    result: Result<ImpactResponse, SolveError>,
    expected: Option<ParamError>,
    params: &ImpactParams,
    law: ContactLaw,
    opts: &SolveOptions,
) -> Option<ImpactResponse> {
    let result = match result {
        Ok(r) => Ok(r),
        Err(SolveError::Param(e)) => Err(e),
        // "no answer" (a step budget ran out) is an honest outcome for valid input only, and
        // in one line
        Err(e @ SolveError::Unresolved { .. }) => {
            let msg = e.to_string();
            assert!(
                expected.is_none() && !msg.contains('\n') && !msg.is_empty(),
                "{msg} for {params:?} (expected {expected:?})"
            );
            return None;
        }
    };
    match (result, expected) {
        (Err(e), Some(want)) => {
            check_param_error(&e);
            assert_eq!(e.field, want.field, "{e} for {params:?}");
            if want.field != Field::Method {
                assert!(
                    e.value.to_bits() == want.value.to_bits()
                        || (e.value.is_nan() && want.value.is_nan()),
                    "{e}: the value is not the one validate names ({})",
                    want.value
                );
            }
            None
        }
        (Err(e), None) => {
            // valid input may fail only for a reason of the solver's own, never by naming an
            // input field that validate accepted
            check_param_error(&e);
            assert!(
                !INPUT_FIELDS.contains(&e.field),
                "{e} for input that validates: {params:?}"
            );
            None
        }
        (Ok(r), Some(want)) => {
            panic!("simulate accepted input that should fail with {want}: {params:?} → {r:?}")
        }
        (Ok(r), None) => {
            check_response(&r, params, law, opts);
            Some(r)
        }
    }
}

fn check_param_error(e: &ParamError) {
    let shown = e.to_string();
    check_one_line(e.reason, &shown);
    assert!(
        shown.starts_with(&format!("invalid {}: ", e.field)),
        "the message names the field: {shown:?}"
    );
}
/// The response of a run on valid input: finite numbers, 0 ≤ e ≤ 1, a contact time exactly
/// when the ball rebounds, a history that starts at rest at t = 0, an energy budget when asked.
pub fn check_response(r: &ImpactResponse, p: &ImpactParams, law: ContactLaw, opts: &SolveOptions) {
    let ctx = || format!("{p:?}, {law}, {opts:?}");
    check_method(r, law, opts, &ctx);
    check_numbers(r, &ctx);
    check_events(r, &ctx);
    check_history(r, opts.samples, &ctx);
    check_energy(r, opts.energy, &ctx);
}

/// The law asked for, and the exact solver exactly where it runs (the linear law, unless the
/// numeric solver was asked for).
fn check_method(
    r: &ImpactResponse,
    law: ContactLaw,
    opts: &SolveOptions,
    ctx: &dyn Fn() -> String,
) {
    assert_eq!(r.law, law);
    let exact = law == ContactLaw::Linear && opts.method != Some(Method::Numeric);
    assert_eq!(
        r.method,
        if exact {
            Method::Exact
        } else {
            Method::Numeric
        },
        "{}",
        ctx()
    );
}

/// The results: finite and not negative, 0 ≤ e ≤ 1, a contact time exactly when the ball
/// rebounds (e = 0 when it does not), z_f ≤ z_m.
fn check_numbers(r: &ImpactResponse, ctx: &dyn Fn() -> String) {
    for (name, v) in [
        ("cor", r.cor),
        ("max_force", r.max_force),
        ("duration", r.duration),
        ("max_indentation", r.max_indentation),
        ("permanent_indentation", r.permanent_indentation),
        ("max_force_normalized", r.max_force_normalized),
    ] {
        assert!(v.is_finite() && v >= 0.0, "{name} = {v}: {}", ctx());
    }
    assert!((0.0..=1.0).contains(&r.cor), "cor = {}: {}", r.cor, ctx());
    assert_eq!(
        r.contact_time.is_some(),
        r.rebound,
        "contact time iff rebound: {}",
        ctx()
    );
    assert_eq!(r.contact_time_normalized.is_some(), r.rebound, "{}", ctx());
    if let (Some(t), Some(tau)) = (r.contact_time, r.contact_time_normalized) {
        assert!(t.is_finite() && t > 0.0, "contact time {t}: {}", ctx());
        assert!(tau.is_finite() && tau > 0.0, "τ_f {tau}: {}", ctx());
    }
    if !r.rebound {
        assert_eq!(r.cor, 0.0, "no rebound, e = 0: {}", ctx());
    }
    assert!(
        r.permanent_indentation <= r.max_indentation,
        "z_f {} above z_m {}: {}",
        r.permanent_indentation,
        r.max_indentation,
        ctx()
    );
}

/// The events: finite, in time order, within the run; a separation last exactly on rebound.
fn check_events(r: &ImpactResponse, ctx: &dyn Fn() -> String) {
    let mut t_prev = 0.0;
    for e in &r.events {
        assert!(e.t.is_finite() && e.z.is_finite(), "{e:?}: {}", ctx());
        assert!(
            e.t >= t_prev && e.t <= r.duration,
            "{e:?} out of order: {}",
            ctx()
        );
        t_prev = e.t;
    }
    assert_eq!(
        r.events.last().map(|e| e.kind) == Some(EventKind::Separation),
        r.rebound,
        "a separation event iff rebound: {:?}: {}",
        r.events,
        ctx()
    );
}

/// The history: `n` finite samples of each series, from t = 0 at F = 0, t increasing, F ≥ 0.
fn check_history(r: &ImpactResponse, n: usize, ctx: &dyn Fn() -> String) {
    let h = &r.history;
    for (name, v) in [
        ("t", &h.t),
        ("force", &h.force),
        ("indentation", &h.indentation),
        ("displacement", &h.displacement),
    ] {
        assert_eq!(v.len(), n, "history {name} has {} samples of {n}", v.len());
        assert!(
            v.iter().all(|x| x.is_finite()),
            "history {name} not finite: {v:?}: {}",
            ctx()
        );
    }
    if n > 0 {
        assert_eq!(h.t[0], 0.0, "history starts at t = 0: {}", ctx());
        assert_eq!(h.force[0], 0.0, "history starts at F = 0: {}", ctx());
        assert!(
            h.t.windows(2).all(|w| w[0] <= w[1]),
            "history t not increasing: {:?}",
            h.t
        );
        assert!(
            h.force.iter().all(|&f| f >= 0.0),
            "negative force: {:?}: {}",
            h.force,
            ctx()
        );
    }
}

/// The energy budget: there when `energy` asked for it; finite; the kinetic energy put in
/// positive, what is stored and left not negative, the dashpot's loss within its tolerance.
fn check_energy(r: &ImpactResponse, energy: bool, ctx: &dyn Fn() -> String) {
    if energy {
        assert!(r.energy.is_some(), "energy asked, none given: {}", ctx());
    }
    if let Some(b) = r.energy {
        for (name, v) in [
            ("initial_kinetic", b.initial_kinetic),
            ("final_kinetic", b.final_kinetic),
            ("dashpot", b.dashpot),
            ("contact", b.contact),
            ("spring", b.spring),
            ("relative_residual", b.relative_residual()),
        ] {
            assert!(v.is_finite(), "energy {name} = {v}: {b:?}: {}", ctx());
        }
        assert!(b.initial_kinetic > 0.0, "{b:?}: {}", ctx());
        // the dashpot only dissipates; its integral may come out a little below zero, by no
        // more than the integrator's energy tolerance (Radau5's is loose: see `audit`)
        let tol = bouncelab::solver::audit::energy_tolerance(r);
        assert!(
            b.final_kinetic >= 0.0 && b.spring >= 0.0 && b.dashpot >= -tol * b.initial_kinetic,
            "{b:?}: {}",
            ctx()
        );
    }
}
