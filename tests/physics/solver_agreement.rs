//! The two independent solvers agree, the energy balance closes, COR grows with λ, the cases
//! the properties found (a soft spring's slow release, a NaN after τ = 1.5e10, creeps against
//! 40-digit references), and stiff runs are checked by their energy balance.

use bouncelab::{ContactLaw, ImpactParams, Method, SolveOptions, simulate};

fn run(p: &ImpactParams, law: ContactLaw, method: Method) -> bouncelab::ImpactResponse {
    let o = SolveOptions {
        rtol: 1e-12,
        ..SolveOptions::default()
    }
    .with_method(method)
    .with_energy();
    simulate(p, law, &o).unwrap()
}

const LAMBDAS: [f64; 5] = [0.0, 0.4, 1.0, 1.3, 5.0];
const ZETAS: [f64; 7] = [0.02, 0.07, 0.16, 0.61, 1.0, 3.0, 30.0];

/// Exact (sum of exponentials) vs DOPRI5/Radau5 on the linear law: e, F̄_m, τ_f to 1e-8,
/// without and with flattening (z̄_p = 0.3: the ball leaves flattened).
#[test]
fn exact_and_numeric_agree_on_a_grid() {
    for zp in [f64::INFINITY, 0.3] {
        for lambda in LAMBDAS {
            for zeta in ZETAS {
                let p = ImpactParams::from_normalized(lambda, zeta, zp);
                let (a, b) = (
                    run(&p, ContactLaw::Linear, Method::Exact),
                    run(&p, ContactLaw::Linear, Method::Numeric),
                );
                let ctx = format!("λ={lambda} ζ={zeta} z̄p={zp}");
                assert_eq!(a.rebound, b.rebound, "{ctx}");
                assert!(
                    (a.cor - b.cor).abs() < 1e-8,
                    "{ctx}: e {} vs {}",
                    a.cor,
                    b.cor
                );
                assert!(
                    (a.max_force_normalized - b.max_force_normalized).abs() < 1e-8,
                    "{ctx}: F̄m"
                );
                if let (Some(ta), Some(tb)) = (a.contact_time_normalized, b.contact_time_normalized)
                {
                    assert!(
                        (ta - tb).abs() < 1e-8 * ta.max(1.0),
                        "{ctx}: τf {ta} vs {tb}"
                    );
                }
                assert!(
                    (a.permanent_indentation - b.permanent_indentation).abs() < 1e-8,
                    "{ctx}: z_f"
                );
            }
        }
    }
}

/// ½mv0² − ½mv_f² = dashpot + contact + spring, to 1e-9 of ½mv0², for every law and both
/// solvers. The dashpot term is integrated (quadrature / an extra ODE state), the contact term
/// comes from the law's closed forms, the spring term from y at separation.
#[test]
fn energy_balance_closes() {
    for zp in [f64::INFINITY, 0.3, 2.0] {
        for lambda in LAMBDAS {
            for zeta in ZETAS {
                let p = ImpactParams::from_normalized(lambda, zeta, zp);
                let mut runs = vec![
                    run(&p, ContactLaw::Linear, Method::Exact),
                    run(&p, ContactLaw::Linear, Method::Numeric),
                ];
                if zp.is_finite() {
                    runs.push(run(&p, ContactLaw::ElasticPlastic, Method::Numeric));
                    runs.push(run(&p, ContactLaw::Hertz, Method::Numeric));
                }
                for r in runs {
                    let e = r.energy.unwrap();
                    assert!(
                        e.relative_residual() < 1e-9,
                        "λ={lambda} ζ={zeta} z̄p={zp} {} {:?}: residual {:e} {e:?}",
                        r.law,
                        r.method,
                        e.relative_residual()
                    );
                }
            }
        }
    }
}

/// At fixed ζ the COR increases with λ (docs/model.md §4: the fit of K_r is a monotone root find).
#[test]
fn cor_increases_with_lambda() {
    for zeta in [0.05, 0.16, 0.61, 2.0, 10.0] {
        let mut last = -1.0;
        for i in 0..60 {
            let lambda = 0.05 * i as f64;
            let r = run(
                &ImpactParams::from_normalized(lambda, zeta, f64::INFINITY),
                ContactLaw::Linear,
                Method::Exact,
            );
            assert!(r.cor > last, "ζ={zeta} λ={lambda}: {} after {last}", r.cor);
            last = r.cor;
        }
    }
}

/// A soft recoil spring releases a creeping ball slowly (λ = 1e-9, ζ = 3000, z̄_p = 1e-7: its
/// two slow modes −6.2e-6 and −1.6e-4 beside a fast −1.7e5). The exact solver used to take the
/// slow pair for one mode, "settle" at τ = 4e-4 and report no rebound; a 40-digit reference
/// has the ball leave at τ ≈ 4.2e4 with e ≈ 0.03.
#[test]
fn soft_spring_release_is_a_rebound_for_both() {
    let p = ImpactParams::from_normalized(1e-9, 3000.0, 1e-7);
    let e = run(&p, ContactLaw::Linear, Method::Exact);
    let n = run(&p, ContactLaw::Linear, Method::Numeric);
    assert!(e.rebound && n.rebound, "{e:?} {n:?}");
    assert!((e.cor - 0.0299).abs() < 1e-3, "e = {}", e.cor);
    assert!((e.cor - n.cor).abs() < 1e-6, "{} vs {}", e.cor, n.cor);
}

/// Followed to τ = 1.5e10 (λ = 6e-12, ζ = 1), the exact flow's real pair used to be formed as
/// e^{cτ} e^{∓hτ} = 0 · ∞: NaN in the history and the energy audit.
#[test]
fn a_very_long_creep_stays_finite() {
    let p = ImpactParams::from_normalized(6.1e-12, 1.0, 0.216);
    let o = SolveOptions::default().with_energy().with_samples(64);
    let r = simulate(&p, ContactLaw::Linear, &o).unwrap();
    let all = r.history.indentation.iter().chain(&r.history.displacement);
    assert!(
        all.clone().count() > 0 && all.copied().all(f64::is_finite),
        "{r:?}"
    );
    assert!(r.energy.unwrap().relative_residual() < 1e-6);
}

/// Creeps against a 40-digit reference (mpmath: eigen-decomposition of each phase, roots by
/// findroot). The exact solver's three-node propagator carried the rounding of A w at the fast
/// rate into the slow modes: at λ = 3.3e-5 its energy balance closed to 1.03e-6 only, at
/// λ = 1.9e-8 it unloaded at a negative indentation and reported no rebound, and at
/// λ = 3.1e-12 (whose recoil mode it dropped as too slow) it reported no rebound either. At
/// λ = 3.2e-8 it read a rounding past a slow turning point as a reload (e = 0.27 for 0.666).
#[test]
fn creeps_match_a_40_digit_reference() {
    // (λ, ζ, z̄_p, e, τ_f)
    let cases = [
        (
            3.3209876543209876e-5,
            9999.614911426166,
            6.9149004312559905e-9,
            0.986_484_162_227_137_9,
            543.654_318_073_487_5,
        ),
        (
            1.9e-8,
            1e4,
            f64::INFINITY,
            0.599_220_495_004_848_6,
            20_485.026_563_914_116,
        ),
        (
            3.1e-12,
            733.0,
            2.5e-8,
            6.661_414_317_425_988e-6,
            34_947.032_602_652_197,
        ),
        // a turning point so slow that z̄ went on rising by a rounding past it: a "reload"
        (
            3.154490140717403e-8,
            1e4,
            1.2732793521200203e-5,
            0.665_979_968_814_120_8,
            16_259.827_785_203_368,
        ),
    ];
    for (lambda, zeta, zp, cor, tau_f) in cases {
        let p = ImpactParams::from_normalized(lambda, zeta, zp);
        let r = run(&p, ContactLaw::Linear, Method::Exact);
        let ctx = format!("λ={lambda} ζ={zeta} z̄p={zp}: {r:?}");
        assert!(r.rebound, "{ctx}");
        assert!(
            (r.cor - cor).abs() < 1e-10 * cor,
            "e {} vs {cor}, {ctx}",
            r.cor
        );
        let t = r.contact_time_normalized.unwrap();
        assert!(
            (t - tau_f).abs() < 1e-10 * tau_f,
            "τ_f {t} vs {tau_f}, {ctx}"
        );
        let residual = r.energy.unwrap().relative_residual();
        assert!(residual < 1e-12, "residual {residual:e}, {ctx}");
    }
}

/// The stiff integrators' error estimates can pass steps far less accurate than rtol; a run
/// they carried checks itself by its energy balance and, where that is looser than 100 rtol,
/// runs again with DOPRI5 first (src/solver/numeric/mod.rs, `checked_run`). The reference at
/// (λ, ζ) = (30, 40) under Hertz comes from two independent methods that agree on it to
/// 4e-15: explicit Taylor steps of order 20 with no step limit (1 095 steps) and a Radau IIA
/// of order 9 (BENCHMARKS.md, "Second session (hertzfast)"). The stiff cascade alone gave
/// 0.99998462568 at rtol 1e-10 and 0.99998465660 at 1e-12: 6e-8 and 9e-8 off.
#[test]
fn stiff_runs_are_checked_by_their_energy_balance() {
    const REFERENCE: f64 = 0.99998456324582;
    let p = ImpactParams::from_normalized(30.0, 40.0, f64::INFINITY);
    for rtol in [1e-10, 1e-12] {
        let o = SolveOptions {
            rtol,
            ..SolveOptions::default()
        }
        .with_energy();
        let r = simulate(&p, ContactLaw::Hertz, &o).unwrap();
        assert!(
            (r.cor - REFERENCE).abs() < 1e-11,
            "rtol {rtol}: e = {} against {REFERENCE}",
            r.cor
        );
    }
    // stiff cells (2ζ(k + λ) > 2000 somewhere in the contact) that DOPRI5 can cross within its
    // step budget at the default rtol: each balance closes to 100 rtol (the stiff cascade alone
    // left 7.8e-8 … 4.2e-7)
    let o = SolveOptions::default().with_energy();
    let cells = [
        (0.1, 1000.0),
        (1.0, 1000.0),
        (10.0, 100.0),
        (30.0, 100.0),
        (100.0, 40.0),
    ];
    for (lambda, zeta) in cells {
        let p = ImpactParams::from_normalized(lambda, zeta, f64::INFINITY);
        let r = simulate(&p, ContactLaw::Hertz, &o).unwrap();
        let residual = r.energy.unwrap().relative_residual();
        assert!(
            residual < 100.0 * o.rtol,
            "λ={lambda} ζ={zeta}: balance off by {residual:e}"
        );
    }
}
