//! The linear fast path in lanes (`map::fast::lanes`, issue 30 item 3) against the scalar
//! path (`map::fast::summary`): the same answers to 1e-12 over the 200 × 120 map's grid and
//! 40,000 seeded random points of the plane, the same `None`s (but where three real roots let
//! the lanes answer what the scalar path's bound refuses: then the exact solver's answer to
//! 1e-12), and the lanes settle most of the plane themselves (else this test could not fail:
//! every lane would be the scalar's).

use crate::seeded;

use bouncelab::map::fast::lanes::{
    LANES, WIDE, lanes_only, lanes_only_portable, lanes_only8, summaries, summary4,
};
use bouncelab::map::fast::{Summary, summary};
use bouncelab::{ContactLaw, SolveOptions, simulate_normalized};
use seeded::Seeded;

fn close(a: &Summary, b: &Summary) -> bool {
    let rel = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs().max(1e-300);
    // the COR to 1e-12 absolute too where it is tiny (a ball that barely rebounds)
    let cor = (a.cor - b.cor).abs() <= 1e-12 * b.cor.abs().max(1.0);
    cor && rel(a.max_force, b.max_force) && rel(a.contact_time, b.contact_time)
}

/// The exact solver's summary at (λ, ζ) (`bouncelab run`'s, docs/guarantees.md: 1e-12).
fn exact(lambda: f64, zeta: f64) -> Summary {
    let r = simulate_normalized(lambda, zeta, ContactLaw::Linear, &SolveOptions::default())
        .expect("the exact solver answers");
    Summary {
        cor: r.cor,
        max_force: r.max_force_normalized,
        contact_time: r.contact_time_normalized.expect("a contact time"),
    }
}

/// Checks every point in groups of four; returns (points, answered by the lanes themselves).
/// Where the scalar path answers, the lanes' answer is its to 1e-12; where it refuses (its
/// rounding bound with the slow root of three real ones cannot keep 1e-13) and the lanes
/// answer (from the fastest root, `lanes/hyper.rs`), theirs is the exact solver's to 1e-12 —
/// the map takes either in place of `run` on that promise.
fn check(points: &[(f64, f64)]) -> (usize, usize) {
    let (mut own, mut beyond) = (0, 0);
    for group in points.chunks(LANES) {
        let pad =
            |f: fn(&(f64, f64)) -> f64| std::array::from_fn(|i| f(&group[i.min(group.len() - 1)]));
        let (l, z): ([f64; LANES], [f64; LANES]) = (pad(|p| p.0), pad(|p| p.1));
        let (all, lanes) = (summary4(l, z), lanes_only(l, z));
        for i in 0..group.len() {
            let scalar = summary(l[i], z[i]);
            let case = format!("λ = {}, ζ = {}", l[i], z[i]);
            match (&all[i], &scalar) {
                (Some(a), Some(b)) => assert!(close(a, b), "{case}: {a:?} vs {b:?}"),
                (None, None) => {}
                (Some(a), None) if lanes[i].is_some() => {
                    beyond += 1;
                    let b = exact(l[i], z[i]);
                    assert!(
                        close(a, &b),
                        "{case}: lanes {a:?} vs the exact solver's {b:?}"
                    );
                }
                _ => panic!("{case}: {:?} vs {scalar:?}", all[i]),
            }
            if let Some(a) = &lanes[i] {
                own += 1;
                if let Some(b) = &scalar {
                    assert!(close(a, b), "{case}: lanes {a:?} vs {b:?}");
                }
            }
        }
    }
    eprintln!(
        "the lanes answered {own} of {} points ({beyond} the scalar path refuses)",
        points.len()
    );
    (points.len(), own)
}

/// [`check`] `points`, the lanes answering at least `share` (numerator, denominator) of
/// them themselves.
fn assert_lanes_answer(points: &[(f64, f64)], (num, den): (usize, usize)) {
    let (n, own) = check(points);
    assert!(own * den >= n * num, "the lanes answered {own} of {n}");
}

/// `n` points drawn from the seeded stream `seed`, each what `draw` gives where it gives one
/// (drawing again where it gives none).
fn seeded_points(
    seed: u64,
    n: usize,
    mut draw: impl FnMut(&mut Seeded) -> Option<(f64, f64)>,
) -> Vec<(f64, f64)> {
    let mut s = Seeded::new(seed);
    let mut points = Vec::with_capacity(n);
    while points.len() < n {
        points.extend(draw(&mut s));
    }
    points
}

/// The 200 × 120 map's grid (λ, ζ = 0.01 … 100, log-spaced), as benches/map.rs runs it.
#[test]
fn lanes_agree_with_the_scalar_path_over_the_map() {
    assert_lanes_answer(&grid(), (8, 10));
}

/// 40,000 seeded points, λ = 1e-4 … 1e4 and ζ = 1e-3 … 1e3 (log-uniform), with zeros, a
/// negative, NaN and infinities among them (the scalar path's `None`s and its ζ = 0).
#[test]
fn lanes_agree_with_the_scalar_path_at_random_points() {
    let mut points = seeded_points(2026, 40_000, |s| {
        Some((s.decades(-4.0, 8.0), s.decades(-3.0, 6.0)))
    });
    points.extend([
        (0.0, 0.5),
        (1.0, 0.0),
        (0.0, 2.0),
        (-1.0, 0.3),
        (f64::NAN, 0.3),
        (1.0, f64::INFINITY),
        (0.02, 1.7861026411617908),
    ]);
    assert_lanes_answer(&points, (7, 10));
}

/// `summaries` over a slice whose length is no multiple of four is `summary4` lane by lane:
/// a point's answer does not depend on its neighbours or on where the groups fall.
#[test]
fn a_point_s_answer_does_not_depend_on_its_group() {
    let points = seeded_points(7, 23, |s| {
        Some((s.decades(-2.0, 4.0), s.decades(-2.0, 4.0)))
    });
    let (l, z): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
    let mut whole = vec![None; points.len()];
    summaries(&l, &z, &mut whole);
    let mut shifted = vec![None; points.len() - 1];
    summaries(&l[1..], &z[1..], &mut shifted);
    assert_eq!(&whole[1..], &shifted[..]);
    for (i, &(l, z)) in points.iter().enumerate() {
        assert_eq!(whole[i], summary4([l; LANES], [z; LANES])[0], "point {i}");
    }
}

/// The dispatched kernel (AVX2 and FMA where the CPU has them, as this machine does) and the
/// portable one give the same bits over the 200 × 120 map's grid: the same operations, each
/// multiply-add fused in both (`vfmadd`, `f64::mul_add`), so a CPU without them prints the
/// same map.
#[test]
fn avx2_and_portable_kernels_agree_bit_for_bit() {
    let mut answered = 0;
    for i in 0..120 {
        for j in (0..200).step_by(LANES) {
            let l = [log_step(i, 120); LANES];
            let z = std::array::from_fn(|k| log_step(j + k, 200));
            let (a, b) = (lanes_only(l, z), lanes_only_portable(l, z));
            for k in 0..LANES {
                assert_eq!(bits(&a[k]), bits(&b[k]), "λ {}, ζ {}", l[k], z[k]);
                answered += usize::from(a[k].is_some());
            }
        }
    }
    // most lanes answer themselves: the comparison is of numbers, not of Nones
    assert!(answered >= 20_000, "{answered}");
}

/// Eight lanes in one call (two AVX registers interleaved where the CPU has AVX2) give each
/// lane the bits of its group of four: over the 200 × 120 map's grid, seeded random points
/// and groups that mix valid balls with zeros, NaN and infinities (lanes the kernel leaves
/// out, whose neighbours must not notice).
#[test]
fn eight_lanes_are_two_fours_bit_for_bit() {
    let mut points = grid();
    let mut s = Seeded::new(88);
    points.extend((0..8_000).map(|_| (s.decades(-4.0, 8.0), s.decades(-3.0, 6.0))));
    let odd = [
        (0.0, 0.5),
        (1.0, 0.0),
        (f64::NAN, 0.3),
        (1.0, f64::INFINITY),
    ];
    for (k, p) in odd.iter().enumerate() {
        points.insert(3 + 11 * k, *p);
    }
    let mut answered = 0;
    for group in points.chunks_exact(WIDE) {
        let l: [f64; WIDE] = std::array::from_fn(|i| group[i].0);
        let z: [f64; WIDE] = std::array::from_fn(|i| group[i].1);
        let eight = lanes_only8(l, z);
        for half in 0..2 {
            let four = |a: &[f64; WIDE]| std::array::from_fn(|i| a[half * LANES + i]);
            let (four_l, four_z) = (four(&l), four(&z));
            let (fours, portable) = (
                lanes_only(four_l, four_z),
                lanes_only_portable(four_l, four_z),
            );
            for i in 0..LANES {
                let k = half * LANES + i;
                let case = format!("λ {}, ζ {}", l[k], z[k]);
                assert_eq!(bits(&eight[k]), bits(&fours[i]), "{case}");
                assert_eq!(bits(&eight[k]), bits(&portable[i]), "{case}");
                answered += usize::from(eight[k].is_some());
            }
        }
    }
    assert!(answered >= 25_000, "{answered}");
}

/// Where the pair part of z̄' starts negative (P = D + σA ≤ 0: a fast real mode carries
/// z̄'(0) = 1, λ ≲ 0.24 and ζ ≈ 0.64–5, left of the band of three real roots), the lanes
/// refine τ_m from the loading's start and keep it where z̄' falls only once before it
/// (`Flow4::falls_once`, kernel.rs): 4 000 seeded points of that corner, each the scalar
/// path's answer (its bracket search) to 1e-12, and most answered by the lanes themselves
/// (3 860 of the `seeded` points).
#[test]
fn lanes_settle_the_peak_where_the_pair_part_starts_negative() {
    let points = seeded_points(30, 4_000, |s| Some(corner_point(s)));
    assert_lanes_answer(&points, (3, 4));
}

/// Short contacts of a slow real mode (λ, ζ ≤ 0.016: |rτ_f| < 1e-3, where e^{rτ} − 1 takes
/// its series as the scalar path takes `exp_m1`): 2 000 seeded points, each the scalar
/// path's answer to 1e-12, and nine in ten answered by the lanes — before, the lanes handed
/// every lane with |rτ| < 1e-3 to the scalar path.
#[test]
fn lanes_settle_short_contacts_of_a_slow_real_mode() {
    let points = seeded_points(31, 2_000, |s| {
        Some((s.decades(-4.0, 2.2), s.decades(-4.0, 2.2)))
    });
    assert_lanes_answer(&points, (9, 10));
}

/// Where the cubic's three roots are real (λ ≲ 0.24, ζ ≈ 0.64–5: Cardano's discriminant ≤ 0,
/// no oscillating pair), the lanes take the slowest root by Newton from 0, cosh and sinh for
/// the pair of the other two, τ_m from 0 and τ_f from the slow modes' zero (`lanes/hyper.rs`):
/// 3 000 seeded points of that band, each the scalar path's answer (its bracket search) to
/// 1e-12 or, where the scalar path's bound refuses, the exact solver's (5 points), and 95 % of
/// them answered by the lanes themselves (2 931 of the `seeded` points) — a kernel without
/// the hyperbolic flow answers none of them.
#[test]
fn lanes_settle_the_band_of_three_real_roots() {
    let points = seeded_points(32, 3_000, |s| {
        Some(corner_point(s)).filter(|&(l, z)| three_real_roots(l, z))
    });
    assert_lanes_answer(&points, (95, 100));
}

/// A seeded point of the corner λ = 0.01 … 0.24, ζ = 0.64 … 5 (each log-uniform), where the
/// band of three real roots lies and the pair part of z̄' starts negative beside it.
fn corner_point(s: &mut Seeded) -> (f64, f64) {
    (
        0.01 * 24f64.powf(s.uniform()),
        0.64 * (5.0f64 / 0.64).powf(s.uniform()),
    )
}

/// Whether s³ + 2ζ(1 + λ)s² + s + 2ζλ has three real roots: Cardano's discriminant
/// q²/4 + p³/27 ≤ 0 (s = t − a2/3, t³ + pt + q).
fn three_real_roots(lambda: f64, zeta: f64) -> bool {
    let (a2, a0) = (2.0 * zeta * (1.0 + lambda), 2.0 * zeta * lambda);
    let shift = a2 / 3.0;
    let p = 1.0 - a2 * shift;
    let q = (2.0 * shift * shift - 1.0) * shift + a0;
    0.25 * q * q + p * p * p / 27.0 <= 0.0
}

/// Step `i` of `n` log-spaced from 0.01 to 100: the map's λ (n = 120) and ζ (n = 200).
fn log_step(i: usize, n: usize) -> f64 {
    10f64.powf(-2.0 + 4.0 * i as f64 / (n - 1) as f64)
}

/// The 200 × 120 map's grid, λ outer (as benches/map.rs runs it).
fn grid() -> Vec<(f64, f64)> {
    (0..120)
        .flat_map(|i| (0..200).map(move |j| (log_step(i, 120), log_step(j, 200))))
        .collect()
}

/// A summary's numbers as bits, to compare two kernels bit for bit.
fn bits(s: &Option<Summary>) -> Option<[u64; 3]> {
    s.map(|s| [s.cor, s.max_force, s.contact_time].map(f64::to_bits))
}

/// The lanes leave at most 11 of the 200 × 120 map's 24 000 cells to the scalar path (the
/// kernel of f36c05f left 67: 28 where P ≤ 0 and the real mode alone does not outrun the pair's
/// slope, 28 whose slow pair the real mode overtakes before the pair's own zero, 11 of three
/// real roots whose rounding bound refuses), and every cell they answer is the exact solver's
/// to 1e-12 where the scalar path hands it there too (the cells of the band's edge: λ ≤ 0.25,
/// ζ = 0.6–1.2).
#[test]
fn lanes_hand_back_few_cells_of_the_map() {
    let points = grid();
    let mut handed = 0;
    for group in points.chunks_exact(WIDE) {
        let l: [f64; WIDE] = std::array::from_fn(|i| group[i].0);
        let z: [f64; WIDE] = std::array::from_fn(|i| group[i].1);
        let lanes = lanes_only8(l, z);
        for (k, lane) in lanes.iter().enumerate() {
            let Some(a) = lane else {
                handed += 1;
                continue;
            };
            if l[k] <= 0.25 && (0.6..=1.2).contains(&z[k]) {
                let b = exact(l[k], z[k]);
                let case = format!("λ = {}, ζ = {}", l[k], z[k]);
                assert!(
                    close(a, &b),
                    "{case}: lanes {a:?} vs the exact solver's {b:?}"
                );
            }
        }
    }
    eprintln!("the lanes handed {handed} of {} cells back", points.len());
    assert!(handed <= 11, "the lanes handed {handed} cells back");
}

/// Beside the band of three real roots (λ ≲ 0.24, ζ ≈ 0.6–1: the pair oscillates slowly), the
/// lanes prove τ_m first where M, the pair part of z̄', rises (`Flow4::pair_rises`), and find
/// τ_f where the real mode overtakes the slow pair from its own start (`lanes/overtake.rs`):
/// 2 000 seeded points of that strip, each the scalar path's answer (its bracket search) to
/// 1e-12 and the exact solver's to 1e-12, and 99 % answered by the lanes themselves (1 995 of
/// the `seeded` points; the kernel of f36c05f 1 743).
#[test]
fn lanes_settle_the_slow_pairs_beside_the_band() {
    let points = seeded_points(33, 2_000, |s| {
        Some((s.log_uniform(0.01, 0.25), s.log_uniform(0.6, 1.0)))
            .filter(|&(l, z)| !three_real_roots(l, z))
    });
    assert_lanes_answer(&points, (99, 100));
    for &(l, z) in &points {
        if let Some(a) = summary4([l; LANES], [z; LANES])[0] {
            let b = exact(l, z);
            assert!(
                close(&a, &b),
                "λ = {l}, ζ = {z}: {a:?} vs the exact solver's {b:?}"
            );
        }
    }
}
