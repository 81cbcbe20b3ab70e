//! The Hertz table of `solver::table` (issue 30 item 1) against its reference, the Taylor
//! steps without step limit or stiffness cut (`solver::taylor::hertz_reference`):
//!
//! - the committed file reads, on the grid the library evaluates;
//! - seeded nodes computed again equal the file's values (it cannot rot unseen);
//! - at 1 000 seeded points off the nodes, in the patches it keeps, and at 1 000 in the
//!   patches and parts it keeps, the table meets the reference to 1e-12, the tolerance the
//!   generator keeps each square within between its nodes;
//! - the file keeps split patches' parts and names its version;
//! - outside its grid, at λ̂ = 0 and in patches it does not keep, it does not answer, and
//!   `table::summary` is then the Taylor steps' answer.

use crate::common::embedded;
use crate::seeded::Seeded;
use bouncelab::solver::table::{self, GRID, Patch, cheb};
use bouncelab::solver::taylor;
use bouncelab::{ContactLaw, Normalized};

/// Seeded uniform numbers in [0, 1) (the tests' one generator, tests/support/seeded).
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut seeded = Seeded::new(seed);
    move || seeded.uniform()
}

fn kept() -> Vec<(usize, Vec<f64>)> {
    let (_, patches) = table::stored().unwrap();
    patches
        .into_iter()
        .enumerate()
        .filter_map(|(i, p)| p.values.map(|v| (i, v)))
        .collect()
}

#[test]
fn the_committed_table_reads_on_its_grid() {
    // version 3: an index of the records, so a process reads the patches it meets only
    assert_eq!(
        &include_bytes!("../../src/solver/table/hertz.bin")[..8],
        b"BLHERTZ3"
    );
    let (grid, patches) = table::stored().unwrap();
    assert_eq!(grid, GRID);
    assert_eq!(patches.len(), GRID.nu * GRID.nw);
    let kept = patches.iter().filter(|p| p.values.is_some()).count();
    eprintln!("{kept} of {} patches kept whole", patches.len());
    for p in &patches {
        // a kept patch was measured within the tolerance, a patch left out (or split) above it
        assert_eq!(
            p.values.is_some(),
            p.error <= table::TOLERANCE,
            "{}",
            p.error
        );
    }
}

/// The area the table answers, in patches (a part of level ℓ is 4^−ℓ of one).
fn kept_area(patches: &[Patch]) -> f64 {
    table::leaves(patches, GRID.nw)
        .iter()
        .filter(|(_, p)| p.values.is_some())
        .map(|(c, _)| 0.25f64.powi(c.level as i32))
        .sum()
}

/// Every square the table stores whole (a patch, or a part of a split one) was measured
/// within the tolerance if kept and above it if not; a split patch holds four parts and no
/// values; the kept area has not shrunk (187 whole patches within 1e-10 in the first table,
/// 209.25 within 1e-12 at ⅛ decade, KEPT_AREA patches' worth with the 1/16-decade squares:
/// docs/numerics.md).
#[test]
fn every_kept_square_was_measured_within_the_tolerance() {
    const KEPT_AREA: f64 = 211.9375;
    let (_, patches) = table::stored().unwrap();
    let leaves = table::leaves(&patches, GRID.nw);
    for (c, p) in &leaves {
        assert!(p.parts.is_empty());
        assert_eq!(
            p.values.is_some(),
            p.error <= table::TOLERANCE,
            "{c:?} {}",
            p.error
        );
    }
    fn splits_hold_four(p: &Patch) -> bool {
        p.parts.is_empty() || (p.parts.len() == 4 && p.values.is_none())
    }
    assert!(patches.iter().all(splits_hold_four));
    let area = kept_area(&patches);
    let parts = leaves
        .iter()
        .filter(|(c, p)| c.level > 0 && p.values.is_some());
    eprintln!("{area} patches' area kept, {} parts", parts.count());
    assert!(area >= KEPT_AREA, "{area}");
}

/// The reference computed again at node `(i, j)`, the point `(l, z)`, equals the ln of each
/// output `values` stores for it (output-major, `m` × `m` nodes each) to 1e-15, a failure
/// naming `part`: how many of them are equal bit for bit.
fn assert_node_is_the_reference(
    (l, z): (f64, f64),
    values: &[f64],
    (i, j): (usize, usize),
    part: &str,
) -> usize {
    let m = GRID.degree + 1;
    let r = table::reference(l, z).unwrap();
    let mut same_bits = 0;
    for (k, rk) in r.iter().enumerate() {
        let stored = values[k * m * m + i * m + j];
        assert!(
            (rk.ln() - stored).abs() <= 1e-15,
            "{part} node ({i}, {j}) output {k}: {} against {stored}",
            rk.ln()
        );
        same_bits += usize::from(rk.ln().to_bits() == stored.to_bits());
    }
    same_bits
}

/// 40 seeded nodes of kept parts (squares of split patches), computed again, equal the
/// file's values to 1e-15, as `seeded_nodes_computed_again_equal_the_file` for whole patches.
#[test]
fn seeded_nodes_of_the_parts_computed_again_equal_the_file() {
    let (_, patches) = table::stored().unwrap();
    let parts: Vec<_> = table::leaves(&patches, GRID.nw)
        .into_iter()
        .filter(|(c, p)| c.level > 0 && p.values.is_some())
        .collect();
    assert!(!parts.is_empty());
    let mut u = uniform(0x5eed_0031);
    let m = GRID.degree + 1;
    let xs = cheb::lobatto(GRID.degree);
    for _ in 0..40 {
        let (c, p) = &parts[(u() * parts.len() as f64) as usize];
        let values = p.values.as_ref().unwrap();
        let (i, j) = ((u() * m as f64) as usize, (u() * m as f64) as usize);
        let (l, z) = GRID.cell_point(c, xs[i], xs[j]);
        assert_node_is_the_reference((l, z), values, (i, j), &format!("{c:?}"));
    }
}

/// At 1 000 seeded points of the kept squares, patches and parts alike (log-uniform inside
/// each), the table meets the reference to POINT_BOUND, the tolerance: each square was kept
/// within it at the points between its nodes, and between those the interpolant's error is of
/// the same size (worst 8.7e-13 here; BENCHMARKS.md, hertz7).
#[test]
fn the_table_meets_the_reference_at_a_thousand_points_of_its_squares() {
    const POINT_BOUND: f64 = table::TOLERANCE;
    let (_, patches) = table::stored().unwrap();
    let kept: Vec<table::Cell> = table::leaves(&patches, GRID.nw)
        .into_iter()
        .filter(|(_, p)| p.values.is_some())
        .map(|(c, _)| c)
        .collect();
    let mut u = uniform(0x7ab1_e002);
    let mut worst = (0.0f64, 0.0, 0.0);
    for _ in 0..1000 {
        let c = kept[(u() * kept.len() as f64) as usize];
        let (l, z) = GRID.cell_point(&c, 2.0 * u() - 1.0, 2.0 * u() - 1.0);
        let t = table::hertz_hat(l, z).unwrap();
        let r = table::reference(l, z).unwrap();
        let d = table::error(&t, &r);
        assert!(d <= POINT_BOUND, "{c:?} λ̂ = {l}, ζ̂ = {z}: {d:e}");
        if d > worst.0 {
            worst = (d, l, z);
        }
    }
    eprintln!("worst {:e} at λ̂ = {}, ζ̂ = {}", worst.0, worst.1, worst.2);
}

/// The baseball's Hertz cell (λ̂ 1.43, ζ̂ 0.32), in the kink band the first table left to the
/// Taylor steps, is the table's now: its impact is the table's answer (`steps` 0) and meets
/// the reference to the tolerance, 1e-12.
#[test]
fn the_baseball_is_in_the_table() {
    let n = embedded("baseball").params().normalized();
    let s = table::summary(&n, ContactLaw::Hertz).unwrap();
    assert_eq!(s.steps, 0);
    let big_l = n.kappa.powf(-0.4);
    let (l, z) = (n.lambda * big_l * big_l, n.zeta / big_l);
    let d = table::error(
        &table::hertz_hat(l, z).unwrap(),
        &table::reference(l, z).unwrap(),
    );
    assert!(d <= table::TOLERANCE, "{d:e}");
}

/// FNV-1a 64, the file's checksum, written again here.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &x| {
        (h ^ u64::from(x)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// A split patch's parts go through the file and back; a version this build does not know
/// is refused by name, and version-1 (no splits) and version-2 files (no index) still read.
#[test]
fn the_file_keeps_its_parts_and_names_its_version() {
    let leaf = |e: f64| Patch {
        error: e,
        values: (e <= 1e-12).then(|| vec![0.25; table::OUTPUTS * 4]),
        parts: Vec::new(),
    };
    let split = Patch {
        error: 1e-6,
        values: None,
        parts: vec![leaf(1e-13), leaf(1e-3), leaf(2e-13), leaf(1e-14)],
    };
    let grid = table::Grid {
        degree: 1,
        nu: 1,
        nw: 2,
        ..GRID
    };
    let patches = vec![leaf(1e-13), split];
    let bytes = table::encode(&grid, &patches);
    assert_eq!(&bytes[..8], b"BLHERTZ3");
    assert_eq!(table::decode(&bytes).unwrap(), (grid, patches.clone()));
    // version 3 under another version digit, the header's checksum made again: refused
    let index_end = 8 + 12 + 32 + 16 * patches.len();
    let mut four = bytes.clone();
    four[7] = b'4';
    let sum = fnv1a(&four[..index_end]);
    four[index_end..index_end + 8].copy_from_slice(&sum.to_le_bytes());
    let err = table::decode(&four).unwrap_err();
    assert!(err.contains("version '4'"), "{err}");
    // version 2: the same records after the header, one checksum at the end
    let v2 = table::encode_v2(&grid, &patches);
    assert_eq!(&v2[..8], b"BLHERTZ2");
    assert_eq!(table::decode(&v2).unwrap(), (grid, patches.clone()));
    // the same bytes under another version digit, the checksum made again
    let with_version = |v: u8, body: &[u8]| {
        let mut b = body.to_vec();
        b[7] = v;
        let sum = fnv1a(&b);
        b.extend_from_slice(&sum.to_le_bytes());
        b
    };
    let body = &v2[..v2.len() - 8];
    // version 1 has no split records: the split one does not read there, the whole one does
    assert!(table::decode(&with_version(b'1', body)).is_err());
    let one = table::encode_v2(&table::Grid { nw: 1, ..grid }, &patches[..1]);
    let v1 = with_version(b'1', &one[..one.len() - 8]);
    assert_eq!(table::decode(&v1).unwrap().1, patches[..1]);
}

/// A damaged file does not read: a flipped bit in the header, in the index or in a record
/// (version 3, and version 2), a missing byte.
#[test]
fn a_damaged_table_does_not_read() {
    let p = Patch {
        error: 1e-12,
        values: Some(vec![0.5; table::OUTPUTS * 4]),
        parts: Vec::new(),
    };
    let grid = table::Grid {
        degree: 1,
        nu: 1,
        nw: 1,
        ..GRID
    };
    for bytes in [
        table::encode(&grid, std::slice::from_ref(&p)),
        table::encode_v2(&grid, std::slice::from_ref(&p)),
    ] {
        assert_eq!(table::decode(&bytes).unwrap(), (grid, vec![p.clone()]));
        for at in [20, 60, bytes.len() - 20] {
            let mut flipped = bytes.clone();
            flipped[at] ^= 4;
            assert!(table::decode(&flipped).is_err(), "byte {at}");
        }
        assert!(table::decode(&bytes[..bytes.len() - 1]).is_err());
    }
}

/// 40 seeded nodes of kept patches, computed again, equal the file's values (ln of each
/// output) to 1e-15: the file is what the generator writes from the reference.
#[test]
fn seeded_nodes_computed_again_equal_the_file() {
    let kept = kept();
    let mut u = uniform(0x5eed_0030);
    let m = GRID.degree + 1;
    let xs = cheb::lobatto(GRID.degree);
    let mut same_bits = 0;
    for _ in 0..40 {
        let (patch, values) = &kept[(u() * kept.len() as f64) as usize];
        let (i, j) = ((u() * m as f64) as usize, (u() * m as f64) as usize);
        let (iu, iw) = (patch / GRID.nw, patch % GRID.nw);
        let (l, z) = GRID.point(iu, iw, xs[i], xs[j]);
        let patch_name = format!("patch {patch}");
        same_bits += assert_node_is_the_reference((l, z), values, (i, j), &patch_name);
    }
    eprintln!("{same_bits} of 200 values bit for bit");
}

/// At 1 000 seeded points of the kept whole patches (log-uniform inside each, not the nodes)
/// the table meets the reference to the tolerance, 1e-12 (`table::error`; worst 4.8e-13).
#[test]
fn the_table_meets_the_reference_at_a_thousand_points() {
    let kept = kept();
    let mut u = uniform(0x7ab1_e001);
    let mut worst = (0.0f64, 0.0, 0.0);
    for _ in 0..1000 {
        let (patch, _) = &kept[(u() * kept.len() as f64) as usize];
        let (iu, iw) = (patch / GRID.nw, patch % GRID.nw);
        let (l, z) = GRID.point(iu, iw, 2.0 * u() - 1.0, 2.0 * u() - 1.0);
        let t = table::hertz_hat(l, z).unwrap();
        let r = table::reference(l, z).unwrap();
        let d = table::error(&t, &r);
        assert!(
            d <= table::TOLERANCE,
            "λ̂ = {l}, ζ̂ = {z}: {d:e} ({t:?} against {r:?})"
        );
        if d > worst.0 {
            worst = (d, l, z);
        }
    }
    eprintln!("worst {:e} at λ̂ = {}, ζ̂ = {}", worst.0, worst.1, worst.2);
}

fn ball(lambda: f64, zeta: f64, kappa: f64) -> Normalized {
    Normalized {
        lambda,
        zeta,
        zp_bar: f64::INFINITY,
        kappa,
    }
}

/// Outside the grid, at λ̂ = 0 or ζ̂ = 0, and for laws other than Hertz, `table::summary` is
/// the Taylor steps' answer (with as many steps as a stiff phase needs where their usual few
/// refuse it: `taylor::stiff_summary`); inside a kept patch it is the table's, scaled by
/// L = κ^{−2/5}.
#[test]
fn the_table_answers_inside_its_kept_patches_only() {
    let hi = 10f64.powf(GRID.u0 + GRID.du * GRID.nu as f64);
    for (l, z) in [
        (0.0, 1.0),
        (1.0, 0.0),
        (hi * 1.01, 1.0),
        (1.0, 1e-5),
        (f64::NAN, 1.0),
    ] {
        assert!(table::hertz_hat(l, z).is_none(), "{l} {z}");
        let n = ball(l, z, 1.0);
        assert_eq!(
            table::summary(&n, ContactLaw::Hertz),
            steps(&n, ContactLaw::Hertz)
        );
    }
    let (_, patches) = table::stored().unwrap();
    if let Some(out) = patches
        .iter()
        .position(|p| p.values.is_none() && p.parts.is_empty())
    {
        let (l, z) = GRID.point(out / GRID.nw, out % GRID.nw, 0.1, -0.2);
        assert!(table::hertz_hat(l, z).is_none());
    }
    // κ = 3: L = 3^{−0.4}; the normalized λ = λ̂/L², ζ = ζ̂ L
    let kappa: f64 = 3.0;
    let big_l = kappa.powf(-0.4);
    let (lh, zh) = (3.0, 0.05);
    let n = ball(lh / (big_l * big_l), zh * big_l, kappa);
    let [e, f, t, zm, y] = table::hertz_hat(lh, zh).unwrap();
    let s = table::summary(&n, ContactLaw::Hertz).unwrap();
    assert_eq!(s.steps, 0);
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-13;
    assert!(close(s.cor, e) && close(s.max_force, f / big_l) && close(s.contact_time, t * big_l));
    assert!(close(s.max_indentation, zm * big_l) && close(s.element_displacement, y * big_l));
    for law in [ContactLaw::Linear, ContactLaw::ElasticPlastic] {
        let n = Normalized { zp_bar: 0.3, ..n };
        assert_eq!(table::summary(&n, law), steps(&n, law));
    }
}

/// The Taylor steps' answer, with as many steps as the stiffness needs where their usual few
/// refuse a stiff phase.
fn steps(n: &Normalized, law: ContactLaw) -> Option<taylor::Summary> {
    taylor::summary(n, law).or_else(|| taylor::stiff_summary(n, law))
}

/// `table::holds` (the lookup alone, by which the work limit counts `bouncelab.impacts`'
/// elements) is true exactly where `table::hertz` answers: at 20 000 seeded balls
/// log-uniform over λ, ζ ∈ [1e-5, 1e5] and κ ∈ [0.1, 10] (across the grid's edges and its
/// gaps), and at the edge cases above.
#[test]
fn the_table_holds_a_ball_where_it_answers() {
    let mut u = uniform(0x5eed_4011);
    let mut log = |lo: f64, hi: f64| 10f64.powf(lo + (hi - lo) * u());
    let (mut held, mut out) = (0, 0);
    for _ in 0..20_000 {
        let n = ball(log(-5.0, 5.0), log(-5.0, 5.0), log(-1.0, 1.0));
        let answers = table::hertz(&n).is_some();
        assert_eq!(table::holds(&n), answers, "{n:?}");
        if answers { held += 1 } else { out += 1 }
    }
    assert!(held > 5_000 && out > 5_000, "held {held}, out {out}");
    for (l, z, k) in [
        (0.0, 1.0, 1.0),
        (1.0, 1.0, 0.0),
        (1.0, f64::NAN, 1.0),
        (1.0, 1.0, -1.0),
    ] {
        assert!(!table::holds(&ball(l, z, k)) && table::hertz(&ball(l, z, k)).is_none());
    }
    let no_flattening_room = Normalized {
        zp_bar: 0.0,
        ..ball(1.0, 1.0, 1.0)
    };
    assert!(!table::holds(&no_flattening_room));
}
