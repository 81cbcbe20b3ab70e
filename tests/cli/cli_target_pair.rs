//! `collide --target-preset` puts both balls' chains in series (issue 53 item 5,
//! docs/targets.md §8): identical balls head-on at ±v bounce exactly as one of them off the
//! rigid wall at v. The command once gave the partner its mass only (a rigid body): tennis on
//! tennis at ±10 m/s gave e 0.7047, the impact of m/2 at 20 m/s, where the wall's is 0.7219.

use crate::common;
use common::{argv, argv_with, f, json};

/// `collide --preset P --target-preset P` at ±v against `run --preset P --v0 v`, on each law:
/// e, F_m, t_f, z_m and z_f, and each ball leaving at e·v, to 1e-9 relative.
#[test]
fn identical_balls_head_on_at_the_cli_are_the_wall_impact() {
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs().max(1e-300);
    for (name, v) in [("tennis", "10"), ("golf", "20"), ("superball", "3")] {
        for law in ["linear", "hertz", "elastic-plastic"] {
            let base = ["--preset", name, "--law", law, "--v0", v];
            let pair = json(
                &[
                    &["collide"][..],
                    &base,
                    &argv_with(
                        "--target-preset {} --target-speed {} --format json",
                        &[name, v],
                    ),
                ]
                .concat(),
            );
            let wall = json(&[&["run"][..], &base, &["--format", "json"]].concat());
            let what = format!("{name} {law}");
            assert_eq!(pair["rebound"], true, "{what}");
            for key in [
                "cor",
                "max_force",
                "contact_time",
                "max_indentation",
                "permanent_indentation",
            ] {
                let (p, w) = (f(&pair, key), f(&wall, key));
                let d = if w == 0.0 { p.abs() } else { rel(p, w) };
                assert!(d <= 1e-9, "{what} {key}: pair {p} wall {w}");
            }
            let out = f(&wall, "cor") * v.parse::<f64>().unwrap();
            assert!(rel(f(&pair, "ball_speed_out"), out) <= 1e-9, "{what}");
            assert!(rel(-f(&pair, "target_speed_out"), out) <= 1e-9, "{what}");
        }
    }
    // the figure: tennis at ±10 m/s, e 0.7219 (the wall's), no longer 0.7047
    let tennis = json(&argv(
        "collide --preset tennis --v0 10 --target-preset tennis --target-speed 10 --format json",
    ));
    assert!((f(&tennis, "cor") - 0.7427).abs() < 5e-5, "{tennis}");
}
