//! `api::impact_row` (Python's `bouncelab.impacts`) against the solver `run` uses: the closed
//! form of the linear law and the exact solver give the same row to 1e-12 (the map's promise,
//! docs/map.md), over balls spread across the presets' range, flattening or not.

use bouncelab::api::impact_row;
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
            assert_eq!(row.permanent_indentation, r.permanent_indentation, "{p:?}");
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
