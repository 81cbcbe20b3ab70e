//! Flattening cells in lanes (`map::fast::lanes::flattenings`, issue 30 item 2) against the
//! scalar closed form (`map::fast::flattening`, itself held to the exact solver in
//! tests/physics/map_flatten.rs): over the tennis ball's map and seeded random (λ, ζ, z̄_p), every
//! cell the lanes answer is the scalar answer to 1e-12 (or, where the scalar path hands it to
//! the steps, the exact solver's), the lanes answer most flattening cells themselves (else the
//! comparison would be of the scalar path with itself), and AVX2 gives the portable bits.

use crate::seeded;

use bouncelab::map::fast::lanes::{
    FLAT_WIDE, LANES, flattening_lane1, flattening_lane1_portable, flattening_lanes4,
    flattening_lanes8, flattening_lanes8_portable, flattening_one, flattenings,
};
use bouncelab::map::fast::{Summary, flattening, summary};
use bouncelab::{ContactLaw, ImpactParams, SolveOptions, simulate};
use seeded::Seeded;

/// The bits of an answer.
fn bits(s: &Option<Summary>) -> Option<[u64; 3]> {
    s.map(|s| [s.cor, s.max_force, s.contact_time].map(f64::to_bits))
}

/// The worst relative difference over e, F̄_m and τ_f (e's absolute where it is below 1).
fn difference(a: &Summary, b: &Summary) -> f64 {
    let rel = |x: f64, y: f64| (x - y).abs() / y.abs();
    let cor = (a.cor - b.cor).abs() / b.cor.abs().max(1.0);
    cor.max(rel(a.max_force, b.max_force))
        .max(rel(a.contact_time, b.contact_time))
}

/// The exact solver's summary of the normalized ball.
fn exact(l: f64, z: f64, zp: f64) -> Summary {
    let p = ImpactParams::from_normalized(l, z, zp);
    let r = simulate(&p, ContactLaw::Linear, &SolveOptions::default()).unwrap();
    Summary {
        cor: r.cor,
        max_force: r.max_force_normalized,
        contact_time: r.contact_time_normalized.unwrap_or(f64::NAN),
    }
}

/// What [`check`] counted.
#[derive(Debug, Default)]
struct Counts {
    cells: usize,
    scalar: usize,
    lanes: usize,
    worst: f64,
}

/// Every cell through the lanes and through the scalar path; the lanes' own answers and
/// `flattenings`' are the scalar answer to 1e-12, or the exact solver's where only the lanes
/// answer.
fn check(cells: &[(f64, f64, f64)]) -> Counts {
    let mut c = Counts::default();
    let col =
        |k: usize| -> Vec<f64> { cells.iter().map(|p| [p.0, p.1, p.2][k]).collect::<Vec<_>>() };
    let (l, z, zp) = (col(0), col(1), col(2));
    let mut all = vec![None; cells.len()];
    flattenings(&l, &z, &zp, &mut all);
    for (g, group) in cells.chunks(FLAT_WIDE).enumerate() {
        let pad = |k: usize| {
            std::array::from_fn(|i| {
                [l.as_slice(), &z, &zp][k][g * FLAT_WIDE + i.min(group.len() - 1)]
            })
        };
        let own = flattening_lanes8(pad(0), pad(1), pad(2));
        for (i, &(l, z, zp)) in group.iter().enumerate() {
            let case = format!("λ = {l:e}, ζ = {z:e}, z̄_p = {zp:e}");
            assert_eq!(
                bits(&flattening_lane1(l, z, zp)),
                bits(&own[i]),
                "{case}: one"
            );
            let scalar = flattening(l, z, zp);
            c.cells += 1;
            c.scalar += usize::from(scalar.is_some());
            let Some(a) = own[i] else {
                let b = all[g * FLAT_WIDE + i];
                assert_eq!(
                    b.map(|s| s.cor),
                    scalar.map(|s| s.cor),
                    "{case}: handed back"
                );
                continue;
            };
            c.lanes += 1;
            assert_eq!(all[g * FLAT_WIDE + i], Some(a), "{case}: flattenings");
            let b = scalar.unwrap_or_else(|| exact(l, z, zp));
            let d = difference(&a, &b);
            assert!(d < 1e-12, "{case}: {d:e}, lanes {a:?} vs {b:?}");
            c.worst = c.worst.max(d);
        }
    }
    c
}

/// The tennis ball over the explorer's plane (λ, ζ = 1e-3 … 1e3, 61 × 61): its flattening
/// cells through the lanes agree with the scalar closed form, and the lanes answer at least
/// nine in ten of those the scalar path answers.
#[test]
fn the_tennis_map_flattens_in_lanes() {
    let cells = crate::map_flatten::tennis_flattening_cells(0.1, 60);
    let c = check(&cells);
    eprintln!("tennis: {c:?}");
    assert!(c.cells >= 2000, "{c:?}");
    assert!(c.lanes * 10 >= c.scalar * 9, "{c:?}");
}

/// A seeded random ball of [`random_flattening_balls_in_lanes`]: (λ, ζ) = 1e-6 … 1e4,
/// 1e-3 … 1e3, each log-uniform.
fn random_ball(s: &mut Seeded) -> (f64, f64) {
    (s.decades(-6.0, 10.0), s.decades(-3.0, 6.0))
}

/// Seeded random flattening balls (λ = 1e-6 … 1e4, ζ = 1e-3 … 1e3 log-uniform, z̄_p a
/// log-uniform 1e-4 … 1 of the peak), 8 000 of them, and groups that mix them with lanes the
/// kernel leaves out (zeros, NaN, ∞, a ball that does not flatten).
#[test]
fn random_flattening_balls_in_lanes() {
    let mut s = Seeded::new(0x5eed_f1a7_0000_0007);
    let mut cells = Vec::new();
    while cells.len() < 8000 {
        let (l, z) = random_ball(&mut s);
        let f = 10f64.powf(-4.0 * s.uniform());
        let Some(peak) = summary(l, z).map(|s| s.max_force) else {
            continue;
        };
        cells.push((l, z, f * peak));
        if cells.len() % 97 == 0 {
            let odd = [0.0, f64::NAN, f64::INFINITY, -1.0][cells.len() % 4];
            cells.push((odd, z, f * peak));
            cells.push((l, odd, f * peak));
            cells.push((l, z, 2.0 * peak));
        }
    }
    let c = check(&cells);
    eprintln!("random: {c:?}");
    assert!(c.lanes * 10 >= c.scalar * 8, "{c:?}");
}

/// The AVX2 kernel (two registers) and the portable one give the same bits over random
/// cells, and so does the four-lane call (one register, the Monte Carlo's) on each half.
#[test]
fn avx2_and_portable_flattening_agree_bit_for_bit() {
    let mut s = Seeded::new(7);
    let mut answered = 0;
    for _ in 0..1000 {
        let cells: [(f64, f64, f64); FLAT_WIDE] = std::array::from_fn(|_| {
            let (l, z) = (s.decades(-3.0, 6.0), s.decades(-3.0, 4.0));
            let peak = summary(l, z).map_or(1.0, |s| s.max_force);
            (l, z, peak * 10f64.powf(-3.0 * s.uniform()))
        });
        let l = cells.map(|c| c.0);
        let (z, zp) = (cells.map(|c| c.1), cells.map(|c| c.2));
        let (a, b) = (
            flattening_lanes8(l, z, zp),
            flattening_lanes8_portable(l, z, zp),
        );
        let half = |x: &[f64; FLAT_WIDE], h: usize| std::array::from_fn(|i| x[h * LANES + i]);
        let fours = [0, 1].map(|h| flattening_lanes4(half(&l, h), half(&z, h), half(&zp, h)));
        for k in 0..FLAT_WIDE {
            let case = format!("λ {}, ζ {}, z̄_p {}", l[k], z[k], zp[k]);
            assert_eq!(bits(&a[k]), bits(&b[k]), "{case}");
            let four = &fours[k / LANES][k % LANES];
            assert_eq!(bits(&a[k]), bits(four), "four: {case}");
            answered += usize::from(a[k].is_some());
        }
    }
    assert!(answered >= 4000, "{answered}");
}

/// A cell alone on one lane (`flattening_lane1`, FMA enabled where the CPU has it, and its
/// portable compilation) is its lane in a group of eight bit for bit, handed back where that
/// lane is; `flattening_one` (the lone cell's call: the explorer's cursor, `run`, a row) is
/// `flattenings`' answer in any grouping, here the cells shuffled into other groups, with
/// lanes the kernel leaves out (zeros, NaN, ∞, balls that do not flatten) among them.
#[test]
fn one_lane_is_the_maps_lane_bit_for_bit() {
    let mut s = Seeded::new(0x0e1a_0000_0000_0008);
    let mut cells = Vec::new();
    while cells.len() < 3000 {
        let (l, z) = random_ball(&mut s);
        let peak = summary(l, z).map_or(1.0, |s| s.max_force);
        cells.push((l, z, peak * 10f64.powf(-4.0 * s.uniform())));
        if cells.len() % 89 == 0 {
            let odd = [0.0, f64::NAN, f64::INFINITY, -1.0][cells.len() % 4];
            cells.extend([
                (odd, z, 0.5),
                (l, odd, 0.5),
                (l, z, odd),
                (l, z, 2.0 * peak),
            ]);
        }
    }
    let col = |k: usize| -> Vec<f64> { cells.iter().map(|p| [p.0, p.1, p.2][k]).collect() };
    let (l, z, zp) = (col(0), col(1), col(2));
    let mut all = vec![None; cells.len()];
    flattenings(&l, &z, &zp, &mut all);
    // the same cells three places on: other neighbours in every group of eight
    let turn = |v: &[f64]| -> Vec<f64> { v[3..].iter().chain(&v[..3]).copied().collect() };
    let mut turned = vec![None; cells.len()];
    flattenings(&turn(&l), &turn(&z), &turn(&zp), &mut turned);
    let (mut lanes, mut handed) = (0, 0);
    for (g, group) in cells.chunks(FLAT_WIDE).enumerate() {
        let pad = |k: usize| {
            std::array::from_fn(|i| [&l, &z, &zp][k][g * FLAT_WIDE + i.min(group.len() - 1)])
        };
        let eight = flattening_lanes8(pad(0), pad(1), pad(2));
        for (i, &(l, z, zp)) in group.iter().enumerate() {
            let (k, case) = (g * FLAT_WIDE + i, format!("λ {l:e}, ζ {z:e}, z̄_p {zp:e}"));
            let one = flattening_lane1(l, z, zp);
            assert_eq!(bits(&one), bits(&eight[i]), "{case}: one lane");
            assert_eq!(
                bits(&flattening_lane1_portable(l, z, zp)),
                bits(&one),
                "{case}"
            );
            let alone = flattening_one(l, z, zp);
            assert_eq!(bits(&alone), bits(&all[k]), "{case}: flattening_one");
            let back = (k + cells.len() - 3) % cells.len();
            assert_eq!(bits(&alone), bits(&turned[back]), "{case}: regrouped");
            lanes += usize::from(one.is_some());
            handed += usize::from(one.is_none() && alone.is_some());
        }
    }
    eprintln!("{lanes} cells on the lane, {handed} handed back and answered by the scalar path");
    assert!(lanes >= 2000 && handed > 0, "{lanes}, {handed}");
}
