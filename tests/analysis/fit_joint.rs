//! Joint calibration (issue 52 item 5, docs/fitting.md "Joint calibration"): noisy synthetic
//! data of two and three kinds made from a ball no preset has, fitted at once, give the truth
//! back inside the intervals — narrower than either set's alone where both see the parameter —
//! and data sets made from two different balls are flagged, not averaged.

use crate::fit_common;

use bouncelab::ContactLaw;
use bouncelab::ImpactParams;
use bouncelab::analysis::fit::joint::{JointData, JointFit, JointSet, contradicted, fit_joint};
use bouncelab::analysis::fit::{Estimate, Param};
use bouncelab::analysis::work::Unwatched;
use bouncelab::measured::{CorPoint, StaticRow, Trace};
use bouncelab::model::static_chain::plates_deflection;
use fit_common::*;

fn covers(e: &Estimate, truth: f64) -> bool {
    e.ci95[0] <= truth && truth <= e.ci95[1]
}

fn width(e: &Estimate) -> f64 {
    e.ci95[1] - e.ci95[0]
}

/// Speeds across the onset of flattening (≈ 1.6 m/s for the truth), as `fit_recovery`'s.
const SPEEDS: [f64; 8] = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0];

/// Static deflections of `p` between two plates at loads 0.5 … 4 kg, each read with a
/// relative error of `rel` (sd).
fn deflections(p: &ImpactParams, rel: f64, rng: &mut Rng) -> Vec<StaticRow> {
    (1..=8)
        .map(|i| {
            let load_kg = 0.5 * i as f64;
            let d = plates_deflection(p, ContactLaw::Linear, load_kg);
            StaticRow {
                load_kg,
                deflection: d * (1.0 + rel * rng.normal()),
                sd: None,
                line: i + 1,
            }
        })
        .collect()
}

fn cor(points: &[CorPoint]) -> JointSet<'_> {
    JointSet {
        kind: "COR table",
        label: "cors.csv".into(),
        data: JointData::Cor(points),
    }
}

fn statics(rows: &[StaticRow]) -> JointSet<'_> {
    JointSet {
        kind: "static deflection",
        label: "static.csv".into(),
        data: JointData::Static(rows),
    }
}

fn trace_set(t: &Trace) -> JointSet<'_> {
    JointSet {
        kind: "force-time trace",
        label: "pulse.csv".into(),
        data: JointData::Trace(t),
    }
}

fn joint(base: &ImpactParams, sets: &[JointSet], free: &[Param]) -> JointFit {
    fit_joint(base, ContactLaw::Linear, sets, free, &Unwatched).unwrap()
}

fn estimate<'a>(j: &'a JointFit, name: &str) -> &'a Estimate {
    j.fit.fitted.iter().find(|e| e.name == name).unwrap()
}

/// A COR table (K_r and z_p through λ and flattening) and static deflections (K_r through
/// the springs in series, δ = 2F(1/K_p + 1/K_r)): jointly K_r is narrower than either alone
/// gives it, and so is z_p, which the COR table alone pins with K_r correlated.
#[test]
fn cor_table_and_static_deflections_recover_the_truth() {
    let t = truth();
    let mut rng = Rng::new(11);
    let points = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    let rows = deflections(&t, 0.01, &mut rng);
    let base = ImpactParams {
        k_r: t.k_r * 0.3,
        z_p: t.z_p * 2.0,
        ..t
    };
    let free = [Param::KR, Param::ZP];
    let both = joint(&base, &[cor(&points), statics(&rows)], &free);
    assert!(both.fit.identified, "{:?}", both.fit);
    assert!(!contradicted(&both.sets), "{:?}", both.sets);
    let (kr, zp) = (estimate(&both, "k_r"), estimate(&both, "z_p"));
    assert!(covers(kr, t.k_r), "{kr:?}");
    assert!(covers(zp, t.z_p), "{zp:?}");
    let table = joint(&base, &[cor(&points)], &free);
    let alone = joint(&base, &[statics(&rows)], &[Param::KR]);
    let (kr_t, zp_t, kr_s) = (
        estimate(&table, "k_r"),
        estimate(&table, "z_p"),
        estimate(&alone, "k_r"),
    );
    eprintln!("joint {kr:?} {zp:?}\ntable {kr_t:?} {zp_t:?}\nstatic {kr_s:?}");
    assert!(width(kr) < width(kr_t) && width(kr) < width(kr_s));
    assert!(width(zp) < width(zp_t));
    // each set's account: its rows, its misses in its unit, its scale estimated from them
    assert_eq!(both.sets.len(), 2);
    assert_eq!((both.sets[0].points, both.sets[0].unit), (8, "COR"));
    assert_eq!((both.sets[1].points, both.sets[1].unit), (8, "m"));
    for s in &both.sets {
        assert!(!s.sd_stated && s.sd_estimated.is_some(), "{s:?}");
        assert_eq!(s.lack_of_fit.unwrap().test, "F", "{s:?}");
    }
    // the static set's rms: the 1 % reading of deflections of a few mm
    let top = plates_deflection(&t, ContactLaw::Linear, 4.0);
    assert!(both.sets[1].rms_residual < 0.03 * top, "{:?}", both.sets[1]);
}

/// Three kinds at once: a force–time trace at the truth's speed (v0 known), a COR table and
/// static deflections; K_p, c, K_r and z_p all come back inside their intervals.
#[test]
fn a_trace_a_table_and_deflections_at_once() {
    let t = truth();
    let mut rng = Rng::new(5);
    let tr = trace(
        &t,
        ContactLaw::Linear,
        0.8e-3,
        1.0,
        0.3,
        (2000, 5e-6),
        &mut rng,
    );
    let points = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    let rows = deflections(&t, 0.01, &mut rng);
    let free = [Param::KP, Param::C, Param::KR, Param::ZP];
    let sets = [trace_set(&tr), cor(&points), statics(&rows)];
    let j = joint(&guess(&t), &sets, &free);
    assert!(j.fit.identified, "{:?} {:?}", j.fit, j.sets);
    assert!(!contradicted(&j.sets), "{:?}", j.sets);
    for (name, truth) in [
        ("k_p", t.k_p),
        ("c", t.damping),
        ("k_r", t.k_r),
        ("z_p", t.z_p),
    ] {
        let e = estimate(&j, name);
        assert!(covers(e, truth), "{name}: {e:?} against {truth}");
    }
    assert!(covers(j.fit.time_offset.as_ref().unwrap(), 0.8e-3));
    // the trace weighed by its own noise, 1 N
    let sd = j.sets[0].sd_estimated.unwrap();
    assert!((sd - 1.0).abs() < 0.15, "{:?}", j.sets[0]);
}

/// Deflections of a ball with twice the recoil spring against CORs of the truth: each set
/// alone is fitted well, together they contradict — the fit says so (an F test far beyond
/// chance for a set) and gives no answer, never a tight interval between the two.
#[test]
fn contradicting_sets_are_flagged() {
    let t = truth();
    let mut rng = Rng::new(3);
    let points = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    let stiffer = ImpactParams {
        k_r: 2.0 * t.k_r,
        ..t
    };
    let rows = deflections(&stiffer, 0.01, &mut rng);
    let j = joint(&t, &[cor(&points), statics(&rows)], &[Param::KR, Param::ZP]);
    eprintln!("{:?}", j.sets);
    assert!(contradicted(&j.sets), "{:?}", j.sets);
    assert!(!j.fit.identified);
    let worst = j.fit.lack_of_fit.unwrap();
    assert!(worst.significant() && worst.test == "F", "{worst:?}");
    assert!(
        j.fit.warnings.iter().any(|w| w.contains("contradict")),
        "{:?}",
        j.fit.warnings
    );
    // the same deflections with a table of the same stiffer ball agree
    let points = cor_table(&stiffer, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    let j = joint(&t, &[cor(&points), statics(&rows)], &[Param::KR, Param::ZP]);
    assert!(!contradicted(&j.sets) && j.fit.identified, "{:?}", j.sets);
}

/// Stated standard deviations are taken as known: the sets are not rescaled, each is judged
/// by χ², and a set whose misses are far beyond its stated sd fails it.
#[test]
fn stated_deviations_are_judged_by_chi2() {
    let t = truth();
    let mut rng = Rng::new(9);
    let mut points = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.005, &mut rng);
    points.iter_mut().for_each(|p| p.cor_sd = Some(0.005));
    let mut rows = deflections(&t, 0.01, &mut rng);
    rows.iter_mut()
        .for_each(|r| r.sd = Some(0.01 * r.deflection));
    let free = [Param::KR, Param::ZP];
    let j = joint(&t, &[cor(&points), statics(&rows)], &free);
    assert!(j.fit.stated_sd && j.fit.identified, "{:?}", j.fit);
    for s in &j.sets {
        assert!(s.sd_stated && s.sd_estimated.is_none(), "{s:?}");
        let lack = s.lack_of_fit.unwrap();
        assert!(lack.test == "chi2" && !lack.significant(), "{s:?}");
    }
    assert!(covers(estimate(&j, "k_r"), t.k_r));
    // deflections stated ten times too precise for their scatter: χ² flags them
    rows.iter_mut()
        .for_each(|r| r.sd = Some(0.001 * r.deflection));
    let j = joint(&t, &[cor(&points), statics(&rows)], &free);
    assert!(j.sets[1].lack_of_fit.unwrap().significant(), "{:?}", j.sets);
    assert!(!j.fit.identified);
}

/// Significant figures: `v` rounded to `n` of them, as a file written at that precision holds.
fn rounded(v: f64, n: i32) -> f64 {
    let scale = 10f64.powi(n - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// A COR table the model made at full precision (its misses at the truth ~1e-13, far below the
/// floor its scale is given) beside deflections of the same ball rounded to 6 figures (issue
/// 52's trial: `fit --cor-table cor.csv --drop-test drops.csv` said CONTRADICTS, F 1.7e5): the
/// table's F test divided the joint answer's nudge by its own alone-fit's float noise. A miss
/// below the set's resolution is no contradiction; the same exact table beside deflections
/// of a stiffer ball still is one.
#[test]
fn an_exact_set_beside_rounded_data_is_not_a_contradiction() {
    let t = truth();
    let mut rng = Rng::new(5);
    let points = cor_table(&t, ContactLaw::Linear, &SPEEDS, 0.0, &mut rng);
    let mut rows = deflections(&t, 0.0, &mut rng);
    rows.iter_mut()
        .for_each(|r| r.deflection = rounded(r.deflection, 6));
    let free = [Param::KR, Param::ZP];
    let j = joint(&t, &[cor(&points), statics(&rows)], &free);
    assert!(!contradicted(&j.sets) && j.fit.identified, "{:?}", j.sets);
    assert!(covers(estimate(&j, "k_r"), t.k_r), "{:?}", j.fit);
    let stiffer = ImpactParams {
        k_r: 1.2 * t.k_r,
        ..t
    };
    let rows = deflections(&stiffer, 0.0, &mut rng);
    let j = joint(&t, &[cor(&points), statics(&rows)], &free);
    assert!(contradicted(&j.sets) && !j.fit.identified, "{:?}", j.sets);
}
