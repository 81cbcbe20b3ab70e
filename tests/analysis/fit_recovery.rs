//! Fits recover known parameters (not a preset's) from data the solver made, with noise and
//! an unknown time offset, within their reported 95 % intervals.

use crate::fit_common;

use bouncelab::analysis::fit::{FitData, MultiFit, Param, fit};
use bouncelab::measured::CorPoint;
use bouncelab::{ContactLaw, ImpactParams};
use fit_common::*;

/// The fit of K_r and z_p (the linear law) to `pts`, started from the truth's with each off by
/// the factor `off` gives it.
fn fit_k_r_z_p(t: &ImpactParams, off: (f64, f64), pts: &[CorPoint]) -> MultiFit {
    let start = ImpactParams {
        k_r: t.k_r * off.0,
        z_p: t.z_p * off.1,
        ..*t
    };
    let free = [Param::KR, Param::ZP];
    fit(&start, ContactLaw::Linear, FitData::Cor(pts), &free).unwrap()
}

/// Both intervals of a K_r, z_p fit hold the truth's values.
fn assert_covers_k_r_z_p(f: &MultiFit, t: &ImpactParams) {
    assert!(covers(&f.fitted[0], t.k_r), "{:?}", f.fitted[0]);
    assert!(covers(&f.fitted[1], t.z_p), "{:?}", f.fitted[1]);
}

#[test]
fn force_time_trace_with_noise_and_offset() {
    let t = truth();
    let mut rng = Rng::new(1);
    let offset = 0.8e-3;
    let tr = trace(
        &t,
        ContactLaw::Linear,
        offset,
        1.0,
        0.3,
        (2000, 5e-6),
        &mut rng,
    );
    let free = [Param::KP, Param::C, Param::KR];
    let start = std::time::Instant::now();
    let f = fit(&guess(&t), ContactLaw::Linear, FitData::Trace(&tr), &free).unwrap();
    eprintln!("{:?} {:?}", start.elapsed(), f.iterations);
    eprintln!(
        "{:#?} {:?} {:?} {}",
        f.fitted, f.time_offset, f.baseline, f.rms_residual
    );
    assert!(f.converged, "{f:?}");
    for (e, truth) in f.fitted.iter().zip([t.k_p, t.damping, t.k_r]) {
        assert!(covers(e, truth), "{}: {e:?} vs {truth}", e.name);
        assert!(e.std_error < 0.05 * e.value, "{e:?}");
    }
    assert!(
        covers(f.time_offset.as_ref().unwrap(), offset),
        "{:?}",
        f.time_offset
    );
    assert!((f.rms_residual - 1.0).abs() < 0.1, "{}", f.rms_residual);
    assert!(f.warnings.is_empty(), "{:?}", f.warnings);
}

/// Speeds from well below to well above the onset of flattening (≈ 1.6 m/s here), where e
/// falls with speed: K_r and z_p both show.
const SPEEDS: [f64; 8] = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0];

#[test]
fn cor_table_with_flattening() {
    let t = truth();
    let mut rng = Rng::new(7);
    let pts = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    let f = fit_k_r_z_p(&t, (0.2, 4.0), &pts);
    eprintln!("{:#?} {} {}", f.fitted, f.rms_residual, f.iterations);
    assert!(f.converged);
    assert_covers_k_r_z_p(&f, &t);
    assert!(f.rms_residual < 0.01, "{}", f.rms_residual);
    assert_eq!(f.model.len(), SPEEDS.len());
}

/// Drops from 0.2 … 1.8 m (v0 ≈ 2 … 6 m/s), rebound heights read to ±3 mm, each COR given
/// by hand the standard deviation that reading makes of it (e = √(R/H): σ_e = σ_R / (2√(R H)),
/// nine times larger at 0.2 m than at 1.8 m) — the table's own path to what
/// `Ball::drops_to_cor_read` computes for `fit --drop-height` (tests/analysis/fit_drop_coverage.rs
/// counts its coverage).
#[test]
fn drop_test() {
    use bouncelab::measured::drop_to_cor;
    let t = truth();
    let mut rng = Rng::new(11);
    let pts: Vec<CorPoint> = [0.2, 0.5, 0.8, 1.2, 1.8]
        .iter()
        .map(|&h| {
            let v0 = (2.0 * bouncelab::measured::G * h).sqrt();
            let e = bouncelab::simulate(
                &bouncelab::ImpactParams { v0, ..t },
                ContactLaw::Linear,
                &Default::default(),
            )
            .unwrap()
            .cor;
            let rebound = e * e * h + 0.003 * rng.normal();
            let (v0, cor) = drop_to_cor(h, rebound, &bouncelab::measured::Flight::vacuum());
            CorPoint {
                v0,
                cor,
                cor_sd: Some(0.003 / (2.0 * (rebound * h).sqrt())),
                cor_sd_relative: 1.0,
                max_force: None,
                contact_time: None,
                line: 0,
            }
        })
        .collect();
    let f = fit_k_r_z_p(&t, (3.0, 0.5), &pts);
    eprintln!("{:#?}", f.fitted);
    assert_covers_k_r_z_p(&f, &t);
}

/// A trace made with the elastic–plastic law (Hertz up to z_p, then linear) fitted with the
/// linear law: the fit finishes, and its residual is well above the noise and above the fit
/// of the right law to the same data.
#[test]
fn another_law_fits_worse_and_does_not_crash() {
    let t = bouncelab::ImpactParams {
        z_p: 2e-3,
        ..truth()
    };
    let t = bouncelab::ImpactParams {
        k_h: bouncelab::ImpactParams::k_h_matching(t.k_p, t.z_p),
        ..t
    };
    let mut rng = Rng::new(5);
    let tr = trace(
        &t,
        ContactLaw::ElasticPlastic,
        0.8e-3,
        0.5,
        0.0,
        (500, 1.6e-5),
        &mut rng,
    );
    let free = [Param::KP, Param::C, Param::KR];
    let wrong = fit(&guess(&t), ContactLaw::Linear, FitData::Trace(&tr), &free).unwrap();
    let right = fit(
        &guess(&t),
        ContactLaw::ElasticPlastic,
        FitData::Trace(&tr),
        &free,
    )
    .unwrap();
    assert!(right.rms_residual < 0.6, "{}", right.rms_residual);
    assert!(
        wrong.rms_residual > 1.5 * right.rms_residual,
        "{} vs {}",
        wrong.rms_residual,
        right.rms_residual
    );
    assert!(wrong.fitted.iter().all(|e| e.value.is_finite()));
}

/// The Hertz law: K_h (with c and K_r) from a trace; K_p only sets units there.
#[test]
fn hertz_trace_recovers_k_h() {
    let t = truth();
    let mut rng = Rng::new(9);
    let tr = trace(
        &t,
        ContactLaw::Hertz,
        0.5e-3,
        0.5,
        0.0,
        (500, 1.6e-5),
        &mut rng,
    );
    let free = [Param::KH, Param::C, Param::KR];
    let f = fit(&guess(&t), ContactLaw::Hertz, FitData::Trace(&tr), &free).unwrap();
    eprintln!("{:#?} {}", f.fitted, f.rms_residual);
    for (e, truth) in f.fitted.iter().zip([t.k_h, t.damping, t.k_r]) {
        assert!(covers(e, truth), "{}: {e:?} vs {truth}", e.name);
    }
}

/// COR, peak force and contact time at six speeds, fitted jointly: K_p, c and K_r (which the
/// COR alone cannot separate) come back within their intervals, each kind weighed by its own
/// scatter. With six points a kind, the scatter estimated from the data is itself uncertain
/// (the intervals take five degrees of freedom for it); over 20 seeds at least 17 intervals of
/// each parameter must cover (measured: 37–39 of 40 over seeds 300–339; seed 21, not in this
/// range, misses K_p by 6 standard errors).
#[test]
fn cor_force_and_contact_time_jointly() {
    let t = truth();
    let free = [Param::KP, Param::C, Param::KR];
    let mut hits = [0; 3];
    let mut last = Vec::new();
    for seed in 300..320 {
        let mut rng = Rng::new(seed);
        let pts: Vec<bouncelab::measured::CorPoint> = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0]
            .iter()
            .map(|&v0| {
                let p = bouncelab::ImpactParams { v0, ..t };
                let r = bouncelab::simulate(&p, ContactLaw::Linear, &Default::default()).unwrap();
                bouncelab::measured::CorPoint {
                    v0,
                    cor: r.cor + 0.005 * rng.normal(),
                    cor_sd: None,
                    cor_sd_relative: 1.0,
                    max_force: Some(r.max_force * (1.0 + 0.02 * rng.normal())),
                    contact_time: Some(r.contact_time.unwrap() * (1.0 + 0.01 * rng.normal())),
                    line: 0,
                }
            })
            .collect();
        let f = fit(&guess(&t), ContactLaw::Linear, FitData::Cor(&pts), &free).unwrap();
        assert_eq!(f.points, 18);
        for (j, (e, truth)) in f.fitted.iter().zip([t.k_p, t.damping, t.k_r]).enumerate() {
            hits[j] += covers(e, truth) as usize;
        }
        last = pts;
    }
    assert!(hits.iter().all(|&h| h >= 17), "{hits:?} of 20");
    // the COR alone cannot pin three parameters: the fit says so
    let cor_only: Vec<_> = last
        .iter()
        .map(|p| bouncelab::measured::CorPoint {
            max_force: None,
            contact_time: None,
            ..*p
        })
        .collect();
    let g = fit(
        &guess(&t),
        ContactLaw::Linear,
        FitData::Cor(&cor_only),
        &free,
    )
    .unwrap();
    assert!(!g.warnings.is_empty(), "{:?}", g.fitted);
}
