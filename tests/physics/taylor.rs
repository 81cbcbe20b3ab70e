//! The Taylor steps of `solver::taylor` (issue 30 items 1 and 2) against the solvers `run`
//! uses: the adaptive one for the Hertz and elastic–plastic laws, the exact one for the linear
//! law where the ball flattens.
//!
//! - over the property tests' domain (tests/physics/properties.rs's balls: λ ∈ [0, 1e4],
//!   ζ ∈ [1e-4, 1e4], v0 to 200 m/s, random mass, stiffness, flattening and K_h), a seeded
//!   proptest: wherever the Taylor steps answer, COR, F_m, t_f, z_m and z_f agree with the
//!   adaptive solver at its default tolerance (1e-10) to 1e-9, and with the exact solver to
//!   1e-12;
//! - at 1,000 seeded points of the normalized (λ, ζ, z̄_p) plane they meet a reference to
//!   1e-12: the adaptive solver at rtol 1e-14 (DOPRI5 at its tightest; an independent
//!   integration, of another method in another variable), the exact solver for the linear law.

use crate::domain;
use crate::seeded;

use bouncelab::solver::table;
use bouncelab::solver::taylor::{Summary, summary};
use bouncelab::{ContactLaw, ImpactParams, ImpactResponse, SolveOptions, simulate};
use domain::ball;
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestCaseError};
use seeded::Seeded;

fn config(cases: u32) -> ProptestConfig {
    let from_env = ProptestConfig::default();
    ProptestConfig {
        cases,
        rng_seed: if std::env::var_os("PROPTEST_RNG_SEED").is_some() {
            from_env.rng_seed
        } else {
            RngSeed::Fixed(20_261_125)
        },
        ..from_env
    }
}

/// The largest difference between the Taylor summary and a solver's response, each quantity
/// relative to its size (the COR and z̄_f absolutely, against 1 and z̄_m), τ_f relative to its
/// condition: the solvers find separation where z̄ falls to z̄_f, which it crosses at the
/// speed |z̄'| = |2ζλȳ_f − e| (F̄ = 0 there: ᾱ' = −e, ȳ' = −2ζλȳ_f), so an error of δ z̄_m
/// in z̄ moves τ_f by δ z̄_m/|z̄'|: where the ball barely leaves (e ~ 1e-7) that is most of
/// τ_f's error, in either solver, and the quantity compared is
/// |Δτ_f| / (τ_f + z̄_m/|z̄'|).
fn difference(s: &Summary, p: &ImpactParams, r: &ImpactResponse) -> f64 {
    let n = p.normalized();
    let zu = p.v0 / p.omega0();
    let z_m = r.max_indentation / zu;
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(f64::MIN_POSITIVE);
    let speed = (2.0 * n.zeta * n.lambda * s.element_displacement - s.cor).abs();
    let tau_f = r.contact_time_normalized.unwrap_or(f64::NAN);
    [
        (s.cor - r.cor).abs(),
        rel(s.max_force, r.max_force_normalized),
        (s.contact_time - tau_f).abs() / (tau_f + z_m / speed),
        rel(s.max_indentation, z_m),
        (s.permanent_indentation - r.permanent_indentation / zu).abs() / z_m,
    ]
    .into_iter()
    .fold(
        0.0,
        |m, d| if d.is_nan() { f64::INFINITY } else { m.max(d) },
    )
}

/// The solver `run` takes for `law`, at tolerance `rtol` (the exact solver ignores it).
fn solve(p: &ImpactParams, law: ContactLaw, rtol: f64) -> ImpactResponse {
    simulate(
        p,
        law,
        &SolveOptions {
            rtol,
            ..SolveOptions::default()
        },
    )
    .unwrap()
}

/// A fast path's summary `s` against the solver `run` takes: to 1e-9 for Hertz and
/// elastic–plastic (the adaptive solver), 1e-12 for the linear law (the exact one).
fn agrees(s: &Summary, p: &ImpactParams, law: ContactLaw) -> Result<(), TestCaseError> {
    let r = solve(p, law, 1e-10);
    if !r.rebound {
        // near "no rebound" two solvers may decide differently (as tests/physics/properties.rs
        // allows the exact and adaptive ones): only where e is below 1e-6
        prop_assert!(s.cor < 1e-6, "{law:?} {p:?}: {s:?} against no rebound");
        return Ok(());
    }
    let tol = if law == ContactLaw::Linear {
        1e-12
    } else {
        1e-9
    };
    let mut d = difference(s, p, &r);
    if d > tol && law != ContactLaw::Linear {
        // rtol 1e-10 does not hold every quantity to 1e-9 (a nearly rigid dashpot,
        // ζ = 1e-4, Hertz: 8.7e-10 in e, 1.1e-9 in F̄_m): the adaptive solver run
        // tightly enough to be good to 1e-9 itself must then agree
        d = difference(s, p, &solve(p, law, 1e-13));
    }
    prop_assert!(d <= tol, "{law:?} {p:?}: {d:e} ({s:?} against {r:?})");
    Ok(())
}

/// The Hertz table's answer `s` (`solver::table::hertz`; under the elastic–plastic law
/// below yield, `solver::table::summary`) against the adaptive solver for `law`, as
/// `agrees` — except where the adaptive run was stiff: its stiff cascade holds e only to
/// 6e-8 … 9e-8 there whatever rtol (BENCHMARKS.md, "a stiff solver tried and withdrawn";
/// here at λ̂ = 230, ζ̂ = 6.2 it is 9e-8 off), so the table must then meet the reference
/// it was built from, the Taylor steps without step limit, to 1e-9 (`table::error`), and the
/// adaptive solver to the 1e-6 its stiff runs promise (`integrator::LOOSEN`).
fn table_agrees(s: &Summary, p: &ImpactParams, law: ContactLaw) -> Result<(), TestCaseError> {
    let r = solve(p, law, 1e-10);
    if !r.stiff {
        return agrees(s, p, law);
    }
    let n = p.normalized();
    let l = n.kappa.powf(-0.4);
    let (lambda_hat, zeta_hat) = (n.lambda * l * l, n.zeta / l);
    let tabulated = table::hertz_hat(lambda_hat, zeta_hat).unwrap();
    let reference = table::reference(lambda_hat, zeta_hat).unwrap();
    let d = table::error(&tabulated, &reference);
    prop_assert!(
        d <= 1e-9,
        "{p:?}: {d:e} against the reference {reference:?}"
    );
    let d = difference(s, p, &r);
    prop_assert!(d <= 1e-6, "{p:?}: {d:e} ({s:?} against the stiff {r:?})");
    Ok(())
}

proptest! {
    #![proptest_config(config(600))]

    /// Over the property tests' domain, every answer of the Taylor steps is the adaptive
    /// solver's to 1e-9 (Hertz, elastic–plastic) or the exact solver's to 1e-12 (linear); so
    /// is every answer of the Hertz table (`solver::table`, issue 30 item 1).
    #[test]
    fn taylor_agrees_with_the_solvers_over_the_property_domain(
        p in ball(),
        law in prop::sample::select(ContactLaw::ALL.to_vec()),
    ) {
        prop_assume!(p.validate().is_ok());
        let n = p.normalized();
        if let Some(s) = summary(&n, law) {
            agrees(&s, &p, law)?;
        }
        if law == ContactLaw::Hertz && let Some(s) = bouncelab::solver::table::hertz(&n) {
            table_agrees(&s, &p, law)?;
        }
        // the elastic–plastic impact below yield, from the Hertz table (`taylor::plastic`)
        if law == ContactLaw::ElasticPlastic
            && let Some(s) = table::summary(&n, law).filter(|s| s.steps == 0)
        {
            table_agrees(&s, &p, law)?;
        }
    }
}

/// The seeded points of the normalized plane: λ over 1e-3 … 1e3, ζ over 1e-3 … 1e2 (both
/// log-uniform), z̄_p over 0.01 … 10 or none (a quarter of them), from the tests' seeded
/// generator (tests/support/seeded/mod.rs).
fn seeded_points(count: usize) -> Vec<(f64, f64, f64)> {
    let mut rng = Seeded::new(0x9e37_79b9_7f4a_7c15);
    (0..count)
        .map(|_| {
            let lambda = rng.log_uniform(1e-3, 1e3);
            let zeta = rng.log_uniform(1e-3, 1e2);
            let zp = if rng.uniform() < 0.25 {
                f64::INFINITY
            } else {
                rng.log_uniform(1e-2, 10.0)
            };
            (lambda, zeta, zp)
        })
        .collect()
}

/// At 1,000 seeded points per law the Taylor steps meet the reference to 1e-12, and answer
/// at most of them (the rest are stiff: the adaptive solver's).
#[test]
fn taylor_meets_the_reference_at_a_thousand_points() {
    for law in ContactLaw::ALL {
        let (mut answered, mut worst) = (0, 0.0f64);
        for (lambda, zeta, zp) in seeded_points(1000) {
            let p = ImpactParams::from_normalized(lambda, zeta, zp);
            let Some(s) = summary(&p.normalized(), law) else {
                continue;
            };
            answered += 1;
            let r = solve(&p, law, 1e-14);
            let d = difference(&s, &p, &r);
            assert!(
                d <= 1e-12,
                "{law:?} λ = {lambda}, ζ = {zeta}, z̄_p = {zp}: {d:e}"
            );
            worst = worst.max(d);
        }
        eprintln!("{law:?}: {answered} of 1000 answered, worst {worst:e}");
        // the linear law is taken only where the ball flattens
        let least = if law == ContactLaw::Linear { 200 } else { 600 };
        assert!(answered >= least, "{law:?}: {answered}");
    }
}

/// Hertz alone (ζ = 0, docs/model.md §5): e = 1, z̄_m = (5/(4κ))^{2/5}, F̄_m = κ z̄_m^{3/2},
/// τ_f = 2.9432751843… z̄_m ((4/5) B(2/5, 1/2)).
#[test]
fn hertz_alone_meets_its_closed_form() {
    for kappa in [1e-3, 0.05, 2.0 / 3.0, 1.0, 40.0, 1e4] {
        let n = bouncelab::Normalized {
            lambda: 0.0,
            zeta: 0.0,
            zp_bar: f64::INFINITY,
            kappa,
        };
        let s = summary(&n, ContactLaw::Hertz).unwrap();
        let z_m = (1.25 / kappa).powf(0.4);
        assert!((s.cor - 1.0).abs() < 1e-14, "{kappa}: {s:?}");
        assert!(
            (s.max_indentation / z_m - 1.0).abs() < 1e-14,
            "{kappa}: {s:?}"
        );
        assert!((s.max_force / (kappa * z_m.powf(1.5)) - 1.0).abs() < 1e-14);
        let tau_f = 2.943_275_184_324_704_7 * z_m;
        assert!(
            (s.contact_time / tau_f - 1.0).abs() < 1e-14,
            "{kappa}: {s:?}"
        );
    }
}

/// `s` against the adaptive solver at rtol 1e-12 for the elastic–plastic law: to 1e-9, or
/// where that run was stiff (its cascade holds e to 1e-7 only), as `table_agrees`.
fn elastic_plastic_agrees(s: &Summary, p: &ImpactParams, case: &str) -> f64 {
    let law = ContactLaw::ElasticPlastic;
    let r = solve(p, law, 1e-12);
    if r.stiff {
        table_agrees(s, p, law).unwrap_or_else(|e| panic!("{case}: {e}"));
        return 0.0;
    }
    assert!(r.rebound || s.cor < 1e-6, "{case}: {s:?} against {r:?}");
    let d = difference(s, p, &r);
    assert!(d <= 1e-9, "{case}: {d:e} ({s:?} against {r:?})");
    d
}

/// Below yield the elastic–plastic impact is the Hertz impact (docs/model.md §3: z̄_m ≤ z̄_p
/// gives z̄_f = 0 and Eq. 12 is Eq. 10 again; `taylor::plastic`). Over a grid of λ (0 and
/// 1e-12 among them), ζ (a nearly rigid dashpot to heavy damping and a weak one) and z̄_p,
/// wherever `table::summary` answers from the table (`steps` 0) it gives the Hertz table's
/// summary with z̄_f = 0, a peak below z̄_p, and meets the adaptive solver at rtol 1e-12 to
/// 1e-9; elsewhere it gives the Taylor steps' answer unchanged (with as many steps as a stiff
/// phase needs: `taylor::stiff_summary`).
#[test]
fn elastic_plastic_below_yield_is_the_hertz_impact() {
    let law = ContactLaw::ElasticPlastic;
    let (mut tabulated, mut worst) = (0, 0.0f64);
    for lambda in [0.0, 1e-12, 1e-3, 0.1, 1.0, 10.0, 300.0] {
        for zeta in [1e-3, 0.05, 0.3, 1.0, 3.0, 20.0] {
            for zp in [0.3, 1.3, 2.0, 5.0, 100.0] {
                let case = format!("λ = {lambda}, ζ = {zeta}, z̄_p = {zp}");
                let p = ImpactParams::from_normalized(lambda, zeta, zp);
                let n = p.normalized();
                let s = table::summary(&n, law);
                let Some(s) = s.filter(|s| s.steps == 0) else {
                    let steps = summary(&n, law)
                        .or_else(|| bouncelab::solver::taylor::stiff_summary(&n, law));
                    assert_eq!(s, steps, "{case}");
                    continue;
                };
                tabulated += 1;
                let hertz = table::hertz(&n).unwrap();
                let want = Summary {
                    permanent_indentation: 0.0,
                    ..hertz
                };
                assert_eq!(s, want, "{case}");
                assert!(s.max_indentation < zp, "{case}: {s:?}");
                worst = worst.max(elastic_plastic_agrees(&s, &p, &case));
            }
        }
    }
    eprintln!("{tabulated} of 210 from the table, worst {worst:e}");
    assert!(tabulated >= 60, "{tabulated}");
}

/// Peaks just below and just above yield: at κ = 1 (m = K_p = v0 = 1, K_h = 1: the Hertz
/// scale is the run's) z̄_p = ẑ_m (1 + δ), ẑ_m the Hertz table's peak at (λ, ζ). The table
/// answers only past its margin (`taylor::plastic::YIELD_MARGIN`, 1e-8: δ ≥ 2e-8 here);
/// nearer, and past yield (δ < 0), the Taylor steps do; each answer meets the adaptive solver
/// at rtol 1e-12 to 1e-9 — across yield the impact changes continuously (z̄_f grows as δ²).
#[test]
fn elastic_plastic_near_yield() {
    let law = ContactLaw::ElasticPlastic;
    let mut settings = 0;
    for (lambda, zeta) in [
        (1.0, 0.3),
        (1e-3, 0.2),
        (0.3, 0.01),
        (10.0, 0.1),
        (2.0, 0.2),
        (0.1, 0.1),
        (3.0, 0.5),
    ] {
        // the kept patches only (the table's kink band, λ̂ ≲ 1 and ζ̂ ≈ 0.3 … 30, is not)
        let Some(hertz) = table::hertz_hat(lambda, zeta) else {
            continue;
        };
        settings += 1;
        let z_m = hertz[3];
        for delta in [-1e-3, -1e-5, -1e-8, 1e-9, 5e-9, 2e-8, 1e-6, 1e-3] {
            let case = format!("λ = {lambda}, ζ = {zeta}, δ = {delta}");
            let p = ImpactParams {
                mass: 1.0,
                k_p: 1.0,
                damping: 1.0,
                k_r: 0.0,
                z_p: z_m * (1.0 + delta),
                k_h: 1.0,
                v0: 1.0,
            }
            .with_lambda_zeta(lambda, zeta);
            p.validate().unwrap();
            let s = table::summary(&p.normalized(), law).unwrap_or_else(|| panic!("{case}"));
            assert_eq!(s.steps == 0, delta >= 2e-8, "{case}: {s:?}");
            elastic_plastic_agrees(&s, &p, &case);
        }
    }
    assert!(settings >= 5, "{settings}");
}
