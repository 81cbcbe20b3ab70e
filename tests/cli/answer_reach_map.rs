//! The map's count of the cells whose ball's centre passes its radius (the reach of
//! tests/cli/answer_reach.rs, cell by cell): the cells counted, and the cells it could not
//! check counted apart, not as within.

use bouncelab::model::contact::ContactLaw;
use bouncelab::solver::{Method, SolveOptions, simulate};
use bouncelab::{Ball, api};

/// The superball's map over λ 1e-4 … 10 and ζ 0.01 … 100, 9 × 9 cells, under `law`.
fn superball_map(law: ContactLaw) -> bouncelab::map::MapSpec {
    use bouncelab::map::{Axis, MapSpec, Param, Scale};
    let base = Ball::from_preset("superball").unwrap().params;
    MapSpec::dimensional(
        base,
        law,
        Axis::new(Param::Lambda, 1e-4, 10.0, 9, Scale::Log).unwrap(),
        Axis::new(Param::Zeta, 0.01, 100.0, 9, Scale::Log).unwrap(),
    )
    .unwrap()
}

/// Every cell of `map` solved by `run`'s solver and read exactly: (z_m, the centre's α_max
/// by `method`), λ-major as the map's cells.
fn solved_cells(
    spec: &bouncelab::map::MapSpec,
    map: &bouncelab::map::Map,
    method: Method,
) -> Vec<(f64, f64)> {
    let law = spec.law;
    map.lambdas
        .iter()
        .flat_map(|&l| map.zetas.iter().map(move |&z| (l, z)))
        .map(|(l, z)| {
            let p = spec.params_at(l, z);
            let r = simulate(&p, law, &SolveOptions::default()).unwrap();
            let alpha = api::peak_displacement(&p, law, method).unwrap();
            (r.max_indentation, alpha)
        })
        .collect()
}

/// `map` warned of cells whose indentation passes the radius only. Its count of cells whose
/// centre passes it, decided by exact bounds where they decide and by the cell's flow where
/// they do not, against every cell solved and read exactly, at radii that leave both kinds.
#[test]
fn the_map_counts_the_cells_whose_centre_passes_the_radius() {
    use bouncelab::map::compute;
    for law in [ContactLaw::Linear, ContactLaw::Hertz] {
        let spec = superball_map(law);
        let map = compute(spec.clone());
        let method = if law == ContactLaw::Linear {
            Method::Exact
        } else {
            Method::Numeric
        };
        let exact = solved_cells(&spec, &map, method);
        let mut alphas: Vec<f64> = exact.iter().map(|e| e.1).collect();
        alphas.sort_by(f64::total_cmp);
        let mut mixed = false;
        // radii a little above a cell's α, never on it: the map reads open cells by the
        // Taylor steps, which agree with the solver's α to 1e-8 (the_map_reads_open_cells_by_
        // the_taylor_steps_as_the_solver_does), so a radius equal to a cell's α is a tie
        // either side may break
        for radius in [
            0.02155,
            2e-4,
            alphas[20] * 1.000_001,
            alphas[40] * 1.000_001,
            alphas[60] * 1.000_001,
        ] {
            // α ≥ z: a cell whose indentation passes counts as its centre's
            let past = exact.iter().filter(|(_, a)| *a > radius).count();
            let alone = exact
                .iter()
                .filter(|(z, a)| *z <= radius && *a > radius)
                .count();
            mixed |= past > alone && alone > 0;
            let w = api::map_displacement_warning(&map, radius);
            assert_eq!(w.is_some(), alone > 0, "{law:?} R {radius}: {w:?}");
            if let Some(w) = w {
                let counts = format!("in {past} of 81 cells, {alone} of them with");
                assert!(
                    w.contains(&counts),
                    "{law:?} R {radius}: {w} against {counts}"
                );
            }
        }
        assert!(
            mixed,
            "{law:?}: no radius left cells past by indentation and by centre alone"
        );
    }
}

/// A map cell whose impact, run again for its centre, gives no answer is "not checked", never
/// "within": the warning counts such cells, so none passes silently (the old count read a
/// failed run as within R). No real cell was found to fail (every cell of the three laws over
/// λ, ζ 1e-4 … 1e4 at 1, 10 and 60 m/s re-solves), so the run is made to fail: the map's
/// base K_h is spoilt after its cells were computed. The linear law never reads K_h (not in
/// its cells, their z_m from F_m, nor the bounds), so every cell and bound stays as computed,
/// while the run again refuses the parameters (`ImpactParams::validate`: invalid k_h).
#[test]
fn the_map_counts_cells_it_could_not_check_not_as_within() {
    use bouncelab::map::compute;
    let law = ContactLaw::Linear;
    let spec = superball_map(law);
    let mut map = compute(spec.clone());
    let exact = solved_cells(&spec, &map, Method::Exact);
    map.spec.base.k_h = f64::NAN;
    let mut alphas: Vec<f64> = exact.iter().map(|e| e.1).collect();
    alphas.sort_by(f64::total_cmp);
    let number = |w: &str, before: &str| -> usize {
        let head = &w[..w.find(before).unwrap()];
        head.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let mut unchecked_seen = false;
    for radius in [alphas[20], alphas[40] * 1.000_001, alphas[60]] {
        let alone = exact
            .iter()
            .filter(|(z, a)| *z <= radius && *a > radius)
            .count();
        let w = api::map_displacement_warning(&map, radius).expect("a warning");
        let unchecked = if w.contains("could not be checked") {
            assert!(w.contains("invalid k_h"), "R {radius}: {w}");
            number(
                &w,
                " of 81 cells the peak displacement of the ball's centre could not",
            )
        } else {
            0
        };
        let told = if w.starts_with("peak displacement") {
            number(&w, " of them with the peak indentation within it")
        } else {
            0
        };
        unchecked_seen |= unchecked > 0;
        // every cell past R by its centre alone is told past or told not checked
        assert!(
            told <= alone && alone <= told + unchecked,
            "R {radius}: {alone} in {w}"
        );
    }
    assert!(unchecked_seen, "no radius left a cell to its run again");
}
