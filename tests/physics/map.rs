//! The design map (issue 21) against independent paths: each cell is what `run` gives at that
//! (λ, ζ) (through `Ball`, the command line's own path); the λ → 0 row approaches Maxwell's
//! closed form (docs/model.md §5, Eq. 28); the feasible mask is a brute-force check cell by cell;
//! every iso-line vertex lies at its level.

use bouncelab::map::{Axis, Map, MapSpec, Param, Quantity, Scale, Targets, compute};
use bouncelab::{Ball, ContactLaw, ImpactResponse};

fn axis(p: Param, from: f64, to: f64, n: usize) -> Axis {
    Axis::new(p, from, to, n, Scale::Log).unwrap()
}

/// `bouncelab run --lambda L --zeta Z` on the ball (Ball is the command line's path).
fn run(ball: &Ball, l: f64, z: f64) -> ImpactResponse {
    ball.clone()
        .with_lambda_zeta(Some(l), Some(z))
        .unwrap()
        .impact()
        .unwrap()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs()).max(1e-300) || (a.is_nan() && b.is_nan())
}

fn assert_cells_are_runs(map: &Map, ball: &Ball, normalized: bool) {
    for (i, &l) in map.lambdas.iter().enumerate() {
        for (j, &z) in map.zetas.iter().enumerate() {
            let c = map.cell(i, j).unwrap();
            let r = run(ball, l, z);
            let (f, t) = if normalized {
                (r.max_force_normalized, r.contact_time_normalized)
            } else {
                (r.max_force, r.contact_time)
            };
            let at = format!("λ = {l}, ζ = {z}");
            assert!(close(c.cor, r.cor), "{at}: cor {} vs {}", c.cor, r.cor);
            assert!(close(c.max_force, f), "{at}: force {} vs {f}", c.max_force);
            match (c.contact_time, t) {
                (Some(a), Some(b)) => assert!(close(a, b), "{at}: time {a} vs {b}"),
                (a, b) => assert_eq!(a, b, "{at}"),
            }
        }
    }
}

#[test]
fn normalized_cells_are_runs_for_every_law() {
    for (law, zp, n) in [
        (ContactLaw::Linear, None, 6),
        (ContactLaw::Linear, Some(0.3), 4),
        (ContactLaw::ElasticPlastic, Some(0.5), 3),
        (ContactLaw::Hertz, None, 3),
    ] {
        let spec = MapSpec::normalized(
            zp,
            law,
            axis(Param::Lambda, 0.01, 100.0, n),
            axis(Param::Zeta, 0.01, 10.0, n),
        )
        .unwrap();
        let ball = Ball::normalized(1.0, 0.1, zp, law).unwrap();
        // the fast linear-law path (as `bouncelab map` and the explorer take it) too
        for fast in [false, true] {
            let map = compute(spec.clone().with_fast(fast));
            assert_cells_are_runs(&map, &ball, true);
        }
    }
}

#[test]
fn dimensional_cells_are_runs_with_flattening() {
    for (preset, law, v0) in [
        ("golf", ContactLaw::Linear, 30.0),
        ("golf", ContactLaw::Linear, 1.0),
        ("superball", ContactLaw::ElasticPlastic, 3.12),
    ] {
        let ball = Ball::from_preset(preset)
            .unwrap()
            .with_law(law)
            .with_v0(v0)
            .unwrap();
        let spec = MapSpec::dimensional(
            ball.params,
            law,
            axis(Param::Lambda, 0.1, 10.0, 4),
            axis(Param::Zeta, 0.02, 2.0, 3),
        )
        .unwrap();
        for fast in [false, true] {
            assert_cells_are_runs(&compute(spec.clone().with_fast(fast)), &ball, false);
        }
        let map = compute(spec);
        // flattening at 30 m/s: the golf ball's COR is below the one without it
        if preset == "golf" && v0 == 30.0 {
            let no_flat = Ball::normalized(0.1, 0.02, None, law)
                .unwrap()
                .impact()
                .unwrap();
            assert!(map.cell(0, 0).unwrap().cor < no_flat.cor - 0.01);
        }
    }
}

/// λ → 0 is Maxwell's element (Eq. 28): e = exp(−πζ/√(1−ζ²)), τ_f = π/√(1−ζ²) for ζ < 1.
/// The map's smallest-λ row meets it, and more closely as λ falls.
#[test]
fn the_small_lambda_row_approaches_maxwell() {
    let zeta = Axis::new(Param::Zeta, 0.05, 0.9, 8, Scale::Linear).unwrap();
    let spec = MapSpec::normalized(
        None,
        ContactLaw::Linear,
        axis(Param::Lambda, 1e-9, 1e-5, 3),
        zeta,
    )
    .unwrap();
    let map = compute(spec);
    let pi = std::f64::consts::PI;
    for (j, &z) in map.zetas.iter().enumerate() {
        let s = (1.0 - z * z).sqrt();
        let (e, tau) = ((-pi * z / s).exp(), pi / s);
        let dev = |i: usize| {
            let c = map.cell(i, j).unwrap();
            (c.cor - e)
                .abs()
                .max((c.contact_time.unwrap() - tau).abs() / tau)
        };
        assert!(dev(0) < 1e-7, "ζ = {z}: {}", dev(0));
        assert!(dev(0) < dev(2), "ζ = {z}: closer at smaller λ");
    }
}

/// The feasible mask against the constraints checked by hand on `run`'s answers.
#[test]
fn feasible_region_is_the_brute_force_check() {
    let ball = Ball::from_preset("golf").unwrap().with_v0(30.0).unwrap();
    let spec = MapSpec::dimensional(
        ball.params,
        ContactLaw::Linear,
        axis(Param::Lambda, 0.05, 20.0, 9),
        axis(Param::Zeta, 0.01, 3.0, 8),
    )
    .unwrap();
    let map = compute(spec);
    let targets = Targets::parse("cor>=0.75,max_force<=9000,contact_time>=0.00045").unwrap();
    let mask = map.feasible(&targets);
    let mut count = 0;
    for (i, &l) in map.lambdas.iter().enumerate() {
        for (j, &z) in map.zetas.iter().enumerate() {
            let r = run(&ball, l, z);
            let want = r.cor >= 0.75
                && r.max_force <= 9000.0
                && r.contact_time.is_some_and(|t| t >= 0.00045);
            assert_eq!(mask[i * map.zetas.len() + j], want, "λ = {l}, ζ = {z}");
            count += usize::from(want);
        }
    }
    assert!(count > 0 && count < mask.len(), "a mixed region: {count}");
    // its outline separates feasible from infeasible cells: each vertex midway on an edge
    for line in map.feasible_outline(&targets) {
        for &(i, j) in &line.index {
            let whole = i.fract() == 0.0 || j.fract() == 0.0;
            assert!(
                whole && (i.fract() == 0.5 || j.fract() == 0.5),
                "({i}, {j})"
            );
        }
    }
}

/// Every vertex of an iso-line lies on a grid edge where the linear interpolation of the two
/// cells is the level (to rounding), and the true COR there is the level within the grid's
/// error (the difference of the two cells).
#[test]
fn contour_vertices_lie_at_their_level() {
    let spec = MapSpec::normalized(
        None,
        ContactLaw::Linear,
        axis(Param::Lambda, 0.01, 100.0, 24),
        axis(Param::Zeta, 0.01, 100.0, 30),
    )
    .unwrap();
    let map = compute(spec);
    let field = map.field(Quantity::Cor);
    let nz = map.zetas.len();
    let ball = Ball::normalized(1.0, 0.1, None, ContactLaw::Linear).unwrap();
    for level in [0.3, 0.6, 0.9] {
        let lines = map.contours(Quantity::Cor, level);
        assert!(!lines.is_empty(), "level {level}");
        for line in &lines {
            for (k, &(i, j)) in line.index.iter().enumerate() {
                let (a, b, t) = if i.fract() == 0.0 {
                    let (i, j0) = (i as usize, j.floor() as usize);
                    (field[i * nz + j0], field[i * nz + j0 + 1], j.fract())
                } else {
                    let (i0, j) = (i.floor() as usize, j as usize);
                    (field[i0 * nz + j], field[(i0 + 1) * nz + j], i.fract())
                };
                let interp = a + (b - a) * t;
                assert!((interp - level).abs() < 1e-12, "({i}, {j}): {interp}");
                if k % 7 == 0 {
                    let (l, z) = line.points[k];
                    let e = run(&ball, l, z).cor;
                    assert!((e - level).abs() <= (b - a).abs(), "({l}, {z}): e = {e}");
                }
            }
        }
    }
}
