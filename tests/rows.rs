//! `api::impact_row` (Python's `bouncelab.impacts`) against the solver `run` uses: the closed
//! form of the linear law and the exact solver give the same row to 1e-12 (the map's promise,
//! docs/map.md), over balls spread across the presets' range, flattening or not.

use bouncelab::api::{ImpactRow, impact_row, impact_rows};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

/// A reproducible spread of balls: each parameter a decade either side of the superball's.
fn balls() -> Vec<ImpactParams> {
    let mut x = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        // xorshift64*: plain, seeded, enough to spread test points
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        (x.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut spread = |v: f64| v * 10f64.powf(2.0 * next() - 1.0);
    (0..400)
        .map(|_| {
            let (k_p, z_p) = (spread(5.45e4), spread(2e-3));
            ImpactParams {
                mass: spread(0.0495),
                k_p,
                k_r: spread(7.08e4),
                damping: spread(10.0),
                z_p,
                k_h: ImpactParams::k_h_matching(k_p, z_p),
                v0: spread(3.12),
            }
        })
        .filter(|p| p.validate().is_ok())
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1e-300) || (a.is_nan() && b.is_nan())
}

#[test]
fn a_row_is_the_solvers_answer() {
    let (mut fast, mut flattened) = (0, 0);
    for p in balls() {
        for law in [ContactLaw::Linear, ContactLaw::Hertz] {
            let row = impact_row(&p, law).unwrap();
            let r = simulate(&p, law, &SolveOptions::default()).unwrap();
            let t = r.contact_time.unwrap_or(f64::NAN);
            assert!(
                close(row.cor, r.cor),
                "{p:?} {law:?}: {} vs {}",
                row.cor,
                r.cor
            );
            assert!(close(row.max_force, r.max_force), "{p:?}: {row:?} vs {r:?}");
            assert!(close(row.contact_time, t), "{p:?}: {row:?}");
            assert!(
                close(row.max_indentation, r.max_indentation),
                "{p:?}: {row:?}"
            );
            // z_f: a flattening row's comes from the closed form's z_m by Eqs. 18–19 (slope
            // below 1), so it is good to z_m's rounding, not the solver's to the last bit
            assert!(
                (row.permanent_indentation - r.permanent_indentation).abs()
                    <= 1e-12 * r.max_indentation,
                "{p:?}: {row:?}"
            );
            assert_eq!(row.rebound, r.rebound, "{p:?}");
            let n = p.normalized();
            let closed = bouncelab::map::fast::summary(n.lambda, n.zeta)
                .is_some_and(|s| s.max_force <= n.zp_bar);
            fast += usize::from(law == ContactLaw::Linear && closed);
            flattened += usize::from(row.permanent_indentation > 0.0);
        }
    }
    // both paths taken
    assert!(
        fast > 50 && flattened > 50,
        "{fast} closed forms, {flattened} flattened"
    );
}

/// A row against `run`'s answer (`simulate`) to 1e-12 in every field (z_f to 1e-12 of z_m, the
/// scale of its rounding: Eqs. 18–19 take z_f from z_m with a slope below 1); whether it
/// came from the flattening's closed form (`map::fast::flattening` answers: e, F̄_m and τ_f
/// are its own, not the solver's, to the last bit).
fn row_is_runs(p: &ImpactParams, row: &ImpactRow) -> bool {
    let r = simulate(p, ContactLaw::Linear, &SolveOptions::default()).unwrap();
    let t = r.contact_time.unwrap_or(f64::NAN);
    let case = format!("{p:?}: {row:?} vs {r:?}");
    assert!(close(row.cor, r.cor), "{case}");
    assert!(close(row.max_force, r.max_force), "{case}");
    assert!(close(row.contact_time, t), "{case}");
    assert!(close(row.max_indentation, r.max_indentation), "{case}");
    let dz_f = (row.permanent_indentation - r.permanent_indentation).abs();
    assert!(dz_f <= 1e-12 * r.max_indentation, "{case}");
    assert_eq!(row.rebound, r.rebound, "{case}");
    let n = p.normalized();
    bouncelab::map::fast::flattening(n.lambda, n.zeta, n.zp_bar).is_some_and(|s| s.cor == row.cor)
}

/// The tennis ball (which flattens at its own speed) over speeds 2 … 60 m/s, row by row and
/// through `impact_rows` (the lanes first, then the flattening's closed form): each row is
/// `run`'s answer to 1e-12, it flattens (z_f > 0) at all but the slowest, and the closed form
/// answers them.
#[test]
fn tennis_rows_over_speeds_are_runs_answers() {
    let ball = bouncelab::Ball::from_preset("tennis").unwrap().params;
    let speeds: Vec<f64> = (0..=58).map(|i| 2.0 + i as f64).collect();
    let at = |v0: f64| ImpactParams { v0, ..ball };
    let rows = impact_rows(speeds.len(), ContactLaw::Linear, |i| at(speeds[i])).unwrap();
    let (mut closed, mut flattened) = (0, 0);
    for (&v0, row) in speeds.iter().zip(&rows) {
        let p = at(v0);
        assert_eq!(
            *row,
            impact_row(&p, ContactLaw::Linear).unwrap(),
            "v0 = {v0}"
        );
        closed += usize::from(row_is_runs(&p, row));
        flattened += usize::from(row.permanent_indentation > 0.0);
    }
    eprintln!(
        "tennis: {closed} closed forms, {flattened} of {} flatten",
        speeds.len()
    );
    assert!(flattened >= 55, "{flattened} of {} flatten", speeds.len());
    assert!(
        closed >= flattened - 2,
        "{closed} closed forms, {flattened} flattened"
    );
}

/// Seeded random linear balls that flatten — z_p a log-uniform 1e-3 … 1 of the peak z_m the
/// ball reaches without flattening — over λ = 1e-3 … 1e3, ζ = 1e-2 … 1e2, any mass, K_p and
/// speed: every row is `run`'s answer to 1e-12, and the closed form answers most of them.
#[test]
fn random_flattening_rows_are_runs_answers() {
    let mut x = 0x9e37_79b9_7f4a_7c15_u64 ^ 0x5a5a;
    let mut next = || {
        // xorshift64*, as `balls`
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        (x.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut rows, mut closed) = (0, 0);
    while rows < 300 {
        let (l, z) = (
            10f64.powf(6.0 * next() - 3.0),
            10f64.powf(4.0 * next() - 2.0),
        );
        let Some(peak) = bouncelab::map::fast::summary(l, z).map(|s| s.max_force) else {
            continue;
        };
        let (mass, k_p, v0) = (
            0.05 * 10f64.powf(2.0 * next() - 1.0),
            5e4 * 10f64.powf(2.0 * next() - 1.0),
            3.0 * 10f64.powf(2.0 * next() - 1.0),
        );
        let w0 = (k_p / mass).sqrt();
        let zp_bar = peak * 10f64.powf(-3.0 * next());
        let z_p = zp_bar * v0 / w0;
        let p = ImpactParams {
            mass,
            k_p,
            k_r: l * k_p,
            damping: (mass * k_p).sqrt() / (2.0 * z),
            z_p,
            k_h: ImpactParams::k_h_matching(k_p, z_p),
            v0,
        };
        if p.validate().is_err() {
            continue;
        }
        let row = impact_row(&p, ContactLaw::Linear).unwrap();
        rows += 1;
        closed += usize::from(row_is_runs(&p, &row));
    }
    eprintln!("random flattening balls: {closed} of {rows} from the closed form");
    assert!(
        closed * 100 >= rows * 75,
        "{closed} of {rows} from the closed form"
    );
}
