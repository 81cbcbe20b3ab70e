//! Bounce sequences (src/drop): the drag-free rebound e(v_in)² H, drag, the C_d → 0 limit,
//! termination, and the trajectory.

use bouncelab::drop::{Air, DropBall, DropError, DropSetup, End, G, drop, impact};
use bouncelab::preset::Preset;
use bouncelab::{SolveOptions, simulate};

fn ball(p: &Preset) -> DropBall {
    DropBall {
        params: p.params(),
        law: p.law,
        radius: p.measured.radius,
    }
}

fn vacuum(height: f64, bounces: usize) -> DropSetup {
    DropSetup {
        air: None,
        bounces,
        ..DropSetup::new(height)
    }
}

/// Without drag v_in = √(2 g H) and the rebound is e(v_in)² H, bounce after bounce, with e
/// from a direct `simulate` at that speed (an independent path to the impact).
#[test]
fn without_drag_the_rebound_is_e_squared_h() {
    for p in Preset::embedded_all() {
        let b = ball(&p);
        for h in [0.305, 1.0, 2.54] {
            let run = drop(&b, &vacuum(h, 4)).unwrap();
            let mut from = h;
            for (i, bounce) in run.bounces.iter().enumerate() {
                let v_in = (2.0 * G * from).sqrt();
                assert!(
                    (bounce.v_in - v_in).abs() <= 1e-12 * v_in,
                    "{} #{i}",
                    p.name
                );
                let params = bouncelab::ImpactParams {
                    v0: v_in,
                    ..b.params
                };
                let e = simulate(&params, b.law, &SolveOptions::default())
                    .unwrap()
                    .cor;
                assert_eq!(bounce.cor, e, "{} #{i}", p.name);
                let want = e * e * from;
                assert!(
                    (bounce.rebound_height - want).abs() <= 1e-9 * want,
                    "{} H={h} #{i}: {} vs {want}",
                    p.name,
                    bounce.rebound_height
                );
                from = bounce.rebound_height;
            }
        }
    }
}

#[test]
fn drag_lowers_the_rebound_and_vanishing_drag_is_continuous() {
    for p in Preset::embedded_all() {
        let b = ball(&p);
        let h = 2.0;
        let free = drop(&b, &vacuum(h, 1)).unwrap().bounces[0];
        let with_air = |cd: f64| {
            let setup = DropSetup {
                air: Some(Air {
                    drag_coefficient: cd,
                    ..Air::default()
                }),
                bounces: 1,
                ..DropSetup::new(h)
            };
            drop(&b, &setup).unwrap().bounces[0]
        };
        let dragged = with_air(0.47);
        assert!(dragged.v_in < free.v_in, "{}", p.name);
        assert!(
            dragged.rebound_height < free.rebound_height,
            "{}: {} vs {}",
            p.name,
            dragged.rebound_height,
            free.rebound_height
        );
        let mut last = free.rebound_height - dragged.rebound_height;
        for cd in [1e-2, 1e-4, 1e-6, 1e-8, 1e-10] {
            let gap = free.rebound_height - with_air(cd).rebound_height;
            // drag still lowers the rebound, by less and less
            assert!(
                gap > 0.0 && gap < last,
                "{} C_d = {cd}: {gap} after {last}",
                p.name
            );
            last = gap;
        }
        assert!(last < 1e-8 * free.rebound_height, "{}: {last}", p.name);
    }
}

#[test]
fn sequences_end_with_decreasing_heights() {
    for p in Preset::embedded_all() {
        let b = ball(&p);
        // a count far above what the minimum rebound allows: the minimum ends the sequence
        let setup = DropSetup {
            bounces: 1000,
            min_rebound: 1e-3,
            ..DropSetup::new(1.0)
        };
        let run = drop(&b, &setup).unwrap();
        assert_eq!(run.end, End::MinRebound, "{}", p.name);
        assert!(run.bounces.len() < 1000);
        let last = run.bounces.last().unwrap();
        assert!(last.rebound_height < 1e-3);
        for w in run.bounces.windows(2) {
            assert!(w[1].rebound_height < w[0].rebound_height, "{}", p.name);
            assert!(w[1].t_start > w[0].t_start, "{}", p.name);
        }
        // the count ends it first when it is small
        let short = drop(&b, &DropSetup::new(1.0)).unwrap();
        assert!(short.bounces.len() <= 10);
        assert!(short.end == End::Count || short.end == End::MinRebound);
    }
}

/// A ball that sinks into its dashpot (λ = 0, ζ ≥ 1: docs/model.md §2) stays on the plate: the
/// sequence ends at the first impact with e = 0.
#[test]
fn a_ball_without_rebound_ends_the_sequence() {
    let p = Preset::embedded_all().remove(0);
    let mut b = ball(&p);
    b.params = b.params.with_lambda_zeta(0.0, 2.0);
    let run = drop(&b, &DropSetup::new(1.0)).unwrap();
    assert_eq!(run.end, End::NoRebound);
    assert_eq!(run.bounces.len(), 1);
    assert_eq!(run.bounces[0].cor, 0.0);
    assert_eq!(run.bounces[0].rebound_height, 0.0);
    assert_eq!(run.height_at(run.duration() + 1.0), 0.0);
}

#[test]
fn the_trajectory_joins_release_contacts_and_apexes() {
    let p = Preset::embedded_all().remove(3);
    let run = drop(&ball(&p), &DropSetup::new(2.54)).unwrap();
    let traj = run.trajectory(1e-3);
    assert_eq!(
        (traj[0].t, traj[0].height, traj[0].velocity),
        (0.0, 2.54, 0.0)
    );
    for w in traj.windows(2) {
        assert!(w[1].t >= w[0].t);
    }
    assert!(traj.iter().all(|s| s.height >= 0.0 && s.height <= 2.54));
    for b in &run.bounces {
        assert!(traj.iter().any(|s| s.t == b.t_start && s.height == 0.0));
        let apex = traj
            .iter()
            .find(|s| s.height == b.rebound_height && s.velocity == 0.0);
        assert!(apex.is_some(), "apex {}", b.rebound_height);
    }
    // the animation's height agrees with the sampled trajectory
    for s in traj.iter().step_by(37) {
        assert!((run.height_at(s.t) - s.height).abs() < 1e-9, "t = {}", s.t);
    }
    assert!((run.duration() - traj.last().unwrap().t).abs() < 1e-12);
    // and a contact lasts what the impact solver says
    let first = run.bounces[0];
    let r = impact(&ball(&p), first.v_in).unwrap();
    assert_eq!(first.contact_time, r.contact_time.unwrap());
    assert_eq!(first.max_force, r.max_force);
}

#[test]
fn bad_conditions_name_their_field() {
    let b = ball(&Preset::embedded_all().remove(0));
    let name = |setup: DropSetup| match drop(&b, &setup) {
        Err(DropError::Input { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(DropSetup::new(0.0)), "height");
    assert_eq!(name(DropSetup::new(f64::NAN)), "height");
    assert_eq!(name(DropSetup::new(1e9)), "height");
    let bad_cd = DropSetup {
        air: Some(Air {
            drag_coefficient: -0.1,
            ..Air::default()
        }),
        ..DropSetup::new(1.0)
    };
    assert_eq!(name(bad_cd), "drag_coefficient");
    assert_eq!(
        name(DropSetup {
            bounces: 0,
            ..DropSetup::new(1.0)
        }),
        "bounces"
    );
    assert_eq!(
        name(DropSetup {
            min_rebound: -1.0,
            ..DropSetup::new(1.0)
        }),
        "min_rebound"
    );
    let e = drop(&b, &DropSetup::new(-2.0)).unwrap_err();
    assert_eq!(e.to_string(), "invalid height: -2 (must be positive)");
}
