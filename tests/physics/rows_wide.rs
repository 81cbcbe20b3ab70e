//! Python's `impacts` against `run_params` over a wide, hostile grid (issue 54 item 9: a
//! review saw them 1.7e-6 apart in a peak force, where the docs promise 1e-6). The rows are
//! `api::impact_rows`' (the two passes `impacts` runs are its rows bit for bit:
//! tests/physics/rows_columns.rs), `run_params` is the adaptive solver at its default
//! tolerance (`simulate`, as `Ball::impact` runs a Hertz or elastic–plastic ball). Over every
//! parameter three decades either side of the superball's, and the presets from 0.5 to 60 m/s,
//! each row meets `run_params` to 1e-6 in e, F_m, t_f and z_m (z_f to 1e-6 of z_m) — the
//! bound docs/numerics.md states for a stiff run — and, where that run was not stiff, the
//! adaptive solver at rtol 1e-13 to 1e-9, and `run_params` itself to the adaptive solver at
//! rtol 1e-13 to `RUN_BOUND` (issue 54 item 9: the docs promised 1e-9 of a run that is not
//! stiff, and one was 2.5e-7 off in its contact time). Not reproduced: the widest gaps found here are
//! printed (`cargo test --test physics rows_wide -- --nocapture`).

use crate::rows::{row_fields, run_fields};
use crate::seeded::Seeded;

use bouncelab::api::{ImpactRow, impact_rows};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};

/// Seeded balls with every parameter log-uniform over three decades either side of the
/// superball's (k_h Eq. 16's), then every preset at 0.5 … 60 m/s.
fn grid() -> Vec<ImpactParams> {
    let mut rng = Seeded::new(0x54_0009);
    let mut wide = |v: f64| rng.log_uniform(v / 1e3, v * 1e3);
    let mut balls: Vec<ImpactParams> = (0..180)
        .map(|_| {
            let (k_p, z_p) = (wide(5.45e4), wide(2e-3));
            ImpactParams {
                mass: wide(0.0495),
                k_p,
                k_r: wide(7.08e4),
                damping: wide(10.0),
                z_p,
                k_h: ImpactParams::k_h_matching(k_p, z_p),
                v0: wide(3.12),
            }
        })
        .collect();
    for (name, _) in bouncelab::preset::EMBEDDED {
        let ball = bouncelab::Ball::from_preset(name).unwrap().params;
        balls.extend([0.5, 3.0, 12.0, 30.0, 60.0].map(|v0| ImpactParams { v0, ..ball }));
    }
    balls.retain(|p| p.validate().is_ok());
    balls
}

/// The largest relative difference of e, F_m, t_f and z_m, and of z_f against z_m.
fn apart(row: &ImpactRow, r: &bouncelab::ImpactResponse) -> f64 {
    let (got, want) = (row_fields(row), run_fields(r));
    let d = (0..4).fold(0.0f64, |w, k| {
        let d = (got[k] - want[k]).abs() / want[k].abs();
        if got[k] == want[k] {
            w
        } else if d.is_nan() {
            f64::INFINITY
        } else {
            w.max(d)
        }
    });
    d.max((row.permanent_indentation - r.permanent_indentation).abs() / r.max_indentation)
}

/// How far `run_params` at its default rtol (1e-10, a step's tolerance, not the answer's) may
/// be from the adaptive solver at rtol 1e-13, both runs not stiff, in e, F_m, t_f and z_m (z_f
/// against z_m): docs/numerics.md's bounds (issue 54 item 9: the docs said 1e-9 of a run that
/// is not stiff). Found over this grid: 7.4e-10, 1.06e-9, 4.1e-10, 7.1e-10 under Hertz; under
/// the elastic–plastic law 5.1e-10, 3.1e-10, 3.1e-10 (z_m, z_f) but 2.46e-7 in the contact
/// time of a ball far past yield (z̄_p = 1.3e-5, λ = 0.18, ζ = 0.66): the separation at z̄_f,
/// where the 3/2-power force vanishes, is found to the event's slack, not to rtol.
const RUN_BOUND: [f64; 5] = [2e-9, 2e-9, 5e-7, 2e-9, 2e-9];

/// The relative gaps of `r` from `t` in e, F_m, t_f and z_m, and of z_f against z_m.
fn run_gaps(r: &bouncelab::ImpactResponse, t: &bouncelab::ImpactResponse) -> [f64; 5] {
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    let time = |x: &bouncelab::ImpactResponse| x.contact_time.unwrap_or(f64::NAN);
    [
        rel(r.cor, t.cor),
        rel(r.max_force, t.max_force),
        rel(time(r), time(t)),
        rel(r.max_indentation, t.max_indentation),
        (r.permanent_indentation - t.permanent_indentation).abs() / t.max_indentation,
    ]
}

#[test]
fn impacts_meet_run_params_to_the_documented_bound_over_a_wide_grid() {
    let balls = grid();
    assert!(balls.len() > 170, "{} balls", balls.len());
    for law in [ContactLaw::Hertz, ContactLaw::ElasticPlastic] {
        let rows = impact_rows(balls.len(), law, |i| balls[i]).unwrap();
        let (mut worst, mut worst_stiff, mut stiff, mut compared) = (0.0f64, 0.0f64, 0, 0);
        let mut worst_run = [0.0f64; 5];
        let mut tight_stiff = 0;
        for (p, row) in balls.iter().zip(&rows) {
            let Ok(r) = simulate(p, law, &SolveOptions::default()) else {
                continue;
            };
            if !r.rebound || !row.rebound {
                assert_eq!(
                    row.rebound, r.rebound,
                    "{p:?} {law:?}: {row:?} against {r:?}"
                );
                continue;
            }
            compared += 1;
            let d = apart(row, &r);
            assert!(d <= 1e-6, "{p:?} {law:?}: {d:e} ({row:?} against {r:?})");
            if r.stiff {
                stiff += 1;
                worst_stiff = worst_stiff.max(d);
                continue;
            }
            worst = worst.max(d);
            let tight = SolveOptions {
                rtol: 1e-13,
                ..SolveOptions::default()
            };
            let t = simulate(p, law, &tight).unwrap();
            if t.stiff {
                // at rtol 1e-13 DOPRI5 ran out of steps and the stiff cascade took over: the
                // reference is then the looser of the two (1e-6, docs/numerics.md)
                tight_stiff += 1;
                continue;
            }
            if d > 1e-9 {
                let d = apart(row, &t);
                assert!(d <= 1e-9, "{p:?} {law:?}: {d:e} from rtol 1e-13");
            }
            // run_params itself, at its default rtol, against rtol 1e-13
            let own = run_gaps(&r, &t);
            for (w, g) in worst_run.iter_mut().zip(own) {
                *w = w.max(g);
            }
            let within = own.iter().zip(RUN_BOUND).all(|(g, b)| *g <= b);
            assert!(
                within,
                "{p:?} {law:?}: run_params from rtol 1e-13 by {own:?}"
            );
        }
        eprintln!(
            "{law:?}: {compared} rows against run_params, {stiff} stiff runs; widest gap \
             {worst:e} (not stiff), {worst_stiff:e} (stiff); run_params (not stiff) from rtol \
             1e-13 in e, F_m, t_f, z_m, z_f: {worst_run:?} ({tight_stiff} stiff at 1e-13, \
             not compared)"
        );
        assert!(compared > 150, "{law:?}: {compared} compared");
    }
}
