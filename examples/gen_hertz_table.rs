//! Writes the Hertz table `src/solver/table/hertz.bin` (issue 30 item 1; docs/numerics.md):
//! for each patch of `table::GRID`, the reference (the Taylor steps without step limit or
//! stiffness cut) at its Chebyshev–Lobatto nodes, then at the points between them, where the
//! interpolant's error is measured; a patch whose error exceeds `table::TOLERANCE` is split in
//! four, down to 1/16 decade (`MAX_LEVEL`, the last halving where the reference is quick),
//! and each part kept where it is within it; where the
//! reference does not answer, or a square at the last level is not within it, the square is
//! stored as not kept (the Taylor steps answer there).
//!
//! ```text
//! cargo run --release --example gen_hertz_table [-- OUT]            the table (default path)
//! cargo run --release --example gen_hertz_table -- --reuse OLD [OUT]   the same, the squares
//!                     OLD keeps within the tolerance taken from it, not computed again
//! cargo run --release --example gen_hertz_table -- --probe U W D N  one patch, side D decades,
//!                                                                   degree N, from (U, W)
//! cargo run --release --example gen_hertz_table -- --line U0 W0 U1 W1 N  the reference
//!                                                   at N + 1 points of a segment
//! cargo run --release --example gen_hertz_table -- --calls N   N table impacts of the
//!                     superball (Hertz), for callgrind: (cost of N + 200 − cost of N) / 200
//! cargo run --release --example gen_hertz_table -- --coverage   which path answers the cells
//!                     of the normalized Hertz map (λ, ζ = 0.01 … 100) and the presets
//! cargo run --release --example gen_hertz_table -- --gaps   the stored squares holding the
//!                     map's cells the table does not answer, their errors and cell counts
//! cargo run --release --example gen_hertz_table -- --errors N   the table against the
//!                     reference at N seeded points of the kept squares: the distribution
//! ```

use bouncelab::solver::table::{self, Cell, GRID, Grid, OUTPUTS, Patch, cheb};
use chacha20::ChaCha8Rng;
use chacha20::rand_core::{Rng, SeedableRng};
use rayon::prelude::*;
use std::time::Instant;

/// How many times a patch is halved at most: ½ decade → ¼ → ⅛ → 1/16. Every square of the
/// explorer's normalized Hertz map the table left out at ⅛ decade was measured above the
/// tolerance, none out of the reference's steps (`--gaps`, BENCHMARKS.md "hertz7"); the
/// third halving keeps the parts of them away from the kink. It is tried only where the
/// reference is quick (`slow`).
const MAX_LEVEL: u32 = 3;
/// The level from which a square is split again only where the reference at its corners
/// takes at most `QUICK_STEPS` steps: a halving costs 4 × 481 reference runs, minutes a square
/// in the long creeps at λ̂ ≈ 1e-4, ζ̂ ≥ 10 (thousands of steps a run).
const SLOW_FROM: u32 = 2;
/// See `SLOW_FROM`: the kink band's squares take tens of steps.
const QUICK_STEPS: usize = 1_000;

/// `println!`, but a closed pipe (`--coverage | head`) ends the program quietly, where
/// `println!` panics.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write;
        if let Err(e) = writeln!(std::io::stdout(), $($arg)*) {
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                std::process::exit(0);
            }
            panic!("writing to stdout: {e}");
        }
    }};
}

/// The reference at the nodes of square `c`, ln of each output, output by output.
fn node_values(grid: &Grid, c: &Cell) -> Option<Vec<f64>> {
    let xs = cheb::lobatto(grid.degree);
    let m = xs.len();
    let nodes: Vec<(usize, usize)> = (0..m).flat_map(|i| (0..m).map(move |j| (i, j))).collect();
    let at: Vec<[f64; OUTPUTS]> = nodes
        .par_iter()
        .map(|&(i, j)| {
            let (l, z) = grid.cell_point(c, xs[i], xs[j]);
            table::reference(l, z)
        })
        .collect::<Option<_>>()?;
    Some(
        (0..OUTPUTS)
            .flat_map(|k| at.iter().map(move |o| o[k].ln()))
            .collect(),
    )
}

/// The largest error of the square's interpolant at the points between its nodes (∞ where
/// the reference does not answer).
fn patch_error(grid: &Grid, c: &Cell, values: &[f64]) -> f64 {
    let coef = table::coefficients(values, grid.degree);
    let xs = cheb::between(grid.degree);
    let points: Vec<(f64, f64)> = xs
        .iter()
        .flat_map(|&x| xs.iter().map(move |&y| (x, y)))
        .collect();
    points
        .par_iter()
        .map(|&(x, y)| {
            let (l, z) = grid.cell_point(c, x, y);
            table::reference(l, z).map_or(f64::INFINITY, |r| {
                table::error(&table::interpolate(&coef, grid.degree, x, y), &r)
            })
        })
        .reduce(|| 0.0, f64::max)
}

/// The stiffness 2ζ̂(1.6 + λ̂)·3.2 at the square's stiffest corner (`taylor::summary`'s
/// measure); past the reference's steps at ≈ 7 of it a step, the square is not tried.
fn too_stiff(grid: &Grid, c: &Cell) -> bool {
    let (l, z) = grid.cell_point(c, 1.0, 1.0);
    2.0 * z * (1.6 + l) * 3.2 / 7.0 > table::REFERENCE_STEPS as f64
}

/// Whether the reference answers at the square's four corners (where it fails, it mostly
/// fails there first: the creep is longest, the stiffness largest at a corner).
fn corners_answer(grid: &Grid, c: &Cell) -> bool {
    [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
        .par_iter()
        .all(|&(x, y)| {
            let (l, z) = grid.cell_point(c, x, y);
            table::reference(l, z).is_some()
        })
}

/// Whether the reference takes more than `QUICK_STEPS` steps (or does not answer) at a
/// corner of the square `c`.
fn slow(grid: &Grid, c: &Cell) -> bool {
    [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
        .par_iter()
        .any(|&(x, y)| {
            let (l, z) = grid.cell_point(c, x, y);
            bouncelab::solver::taylor::hertz_reference(l, z, QUICK_STEPS).is_none()
        })
}

/// The square `c` as a whole: kept where its error is within the tolerance.
fn build(grid: &Grid, c: &Cell) -> Patch {
    let values = if too_stiff(grid, c) || !corners_answer(grid, c) {
        None
    } else {
        node_values(grid, c)
    };
    let Some(values) = values else {
        return Patch {
            error: f64::INFINITY,
            values: None,
            parts: Vec::new(),
        };
    };
    let error = patch_error(grid, c, &values);
    Patch {
        error,
        values: (error <= table::TOLERANCE).then_some(values),
        parts: Vec::new(),
    }
}

/// The square `c`, split in four where it is not within the tolerance as a whole but its
/// error was measured (a finite error: the reference answers throughout; where it does not,
/// the stiff corner and the long creeps, the parts would not either), to `MAX_LEVEL`; a
/// split none of whose parts is kept is not stored. `old` is the same square in an earlier
/// file (`--reuse`): a square kept there within the tolerance is taken as it is (the same
/// reference at the same nodes: tests/physics/hertz_table.rs), a split one's error, or a finite one
/// above the tolerance, is not measured again.
fn build_tree(grid: &Grid, c: Cell, old: Option<&Patch>) -> Patch {
    let reused =
        old.filter(|o| o.values.is_some() && o.parts.is_empty() && o.error <= table::TOLERANCE);
    if let Some(o) = reused {
        return o.clone();
    }
    let whole = match old {
        Some(o) if !o.parts.is_empty() || o.error.is_finite() => Patch {
            error: o.error,
            values: None,
            parts: Vec::new(),
        },
        _ => build(grid, &c),
    };
    if whole.values.is_some()
        || c.level >= MAX_LEVEL
        || !whole.error.is_finite()
        || (c.level >= SLOW_FROM && slow(grid, &c))
    {
        return whole;
    }
    let parts: Vec<Patch> = (0..4)
        .map(|k| build_tree(grid, c.part(k), old.and_then(|o| o.parts.get(k))))
        .collect();
    if parts
        .iter()
        .all(|p| p.values.is_none() && p.parts.is_empty())
    {
        return whole;
    }
    Patch { parts, ..whole }
}

fn probe(args: &[String]) {
    let num = |i: usize| args[i].parse::<f64>().expect("a number");
    let grid = Grid {
        degree: num(3) as usize,
        nu: 1,
        nw: 1,
        u0: num(0),
        du: num(2),
        w0: num(1),
        dw: num(2),
    };
    let t = Instant::now();
    let p = build(&grid, &Cell::patch(0, 0));
    if let Some(v) = &p.values {
        worst(&grid, v);
    } else if let Some(v) = node_values(&grid, &Cell::patch(0, 0)) {
        worst(&grid, &v);
    }
    say!(
        "patch λ̂ 1e{} ζ̂ 1e{} side {} degree {}: error {:.3e}, {:.2} s",
        grid.u0,
        grid.w0,
        grid.du,
        grid.degree,
        p.error,
        t.elapsed().as_secs_f64()
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--probe") {
        return probe(&args[1..]);
    }
    if args.first().map(String::as_str) == Some("--line") {
        return line(&args[1..]);
    }
    match args.first().map(String::as_str) {
        Some("--calls") => return calls(&args[1..]),
        Some("--coverage") => return coverage(),
        Some("--gaps") => return gaps(),
        Some("--errors") => return errors(&args[1..]),
        _ => {}
    }
    // `--reuse OLD [OUT]`: the squares kept in OLD within the tolerance taken as they are
    let (old, args) = match args.first().map(String::as_str) {
        Some("--reuse") => {
            let bytes = std::fs::read(&args[1]).expect("reading the old table");
            let (grid, patches) = table::decode(&bytes).expect("the old table reads");
            assert_eq!(grid, GRID, "the old table is on another grid");
            (Some(patches), &args[2..])
        }
        _ => (None, &args[..]),
    };
    let out = args
        .first()
        .cloned()
        .unwrap_or_else(|| "src/solver/table/hertz.bin".into());
    let start = Instant::now();
    let mut patches = Vec::new();
    for iu in 0..GRID.nu {
        for iw in 0..GRID.nw {
            let t = Instant::now();
            let o = old.as_ref().map(|o| &o[iu * GRID.nw + iw]);
            let p = build_tree(&GRID, Cell::patch(iu, iw), o);
            let (l, z) = GRID.point(iu, iw, -1.0, -1.0);
            let leaves = table::leaves(std::slice::from_ref(&p), 1);
            let kept = leaves.iter().filter(|(_, q)| q.values.is_some());
            let area: f64 = kept.map(|(c, _)| 0.25f64.powi(c.level as i32)).sum::<f64>() + 0.0;
            say!(
                "λ̂ {l:9.3e} ζ̂ {z:9.3e}: error {:.2e}, {} squares, {:.4} of it kept ({:.2} s)",
                p.error,
                leaves.len(),
                area,
                t.elapsed().as_secs_f64()
            );
            patches.push(p);
        }
    }
    let bytes = table::encode(&GRID, &patches);
    std::fs::write(&out, &bytes).expect("writing the table");
    let leaves = table::leaves(&patches, GRID.nw);
    let kept: Vec<_> = leaves.iter().filter(|(_, p)| p.values.is_some()).collect();
    let area: f64 = kept.iter().map(|(c, _)| 0.25f64.powi(c.level as i32)).sum();
    let by_level: Vec<usize> = (0..=MAX_LEVEL)
        .map(|l| kept.iter().filter(|(c, _)| c.level == l).count())
        .collect();
    say!(
        "{out}: {} bytes, {} squares kept (by level {by_level:?}), {area:.4} of {} patches' area, {:.1} s",
        bytes.len(),
        kept.len(),
        patches.len(),
        start.elapsed().as_secs_f64()
    );
}

/// `--line U0 W0 U1 W1 N`: the reference's outputs along a segment of the (log λ̂, log ζ̂)
/// plane, to see where a patch is not smooth.
fn line(args: &[String]) {
    let num = |i: usize| args[i].parse::<f64>().expect("a number");
    let n = num(4) as usize;
    for k in 0..=n {
        let t = k as f64 / n as f64;
        let u = num(0) + t * (num(2) - num(0));
        let w = num(1) + t * (num(3) - num(1));
        let s = bouncelab::solver::taylor::hertz_reference(10f64.powf(u), 10f64.powf(w), 400_000);
        say!("{u:.4} {w:.4} {s:?}");
    }
}

/// The probe's worst point and output.
fn worst(grid: &Grid, values: &[f64]) {
    let c = table::coefficients(values, grid.degree);
    let xs = cheb::between(grid.degree);
    let mut w = (0.0, 0, 0.0, 0.0);
    for &x in &xs {
        for &y in &xs {
            let (l, z) = grid.point(0, 0, x, y);
            let Some(r) = table::reference(l, z) else {
                continue;
            };
            let t = table::interpolate(&c, grid.degree, x, y);
            for k in 0..OUTPUTS {
                let e = (t[k] - r[k]).abs() / r[k];
                if e > w.0 {
                    w = (e, k, l.log10(), z.log10());
                }
            }
        }
    }
    say!(
        "worst {:.3e} output {} at log λ̂ {:.4} log ζ̂ {:.4}",
        w.0,
        w.1,
        w.2,
        w.3
    );
}

/// `--calls N`: N impacts of the superball's adopted set through `table::hertz` (each from its
/// SI parameters, as the bench `table_hertz_summary` times them), the table read first: under
/// `valgrind --tool=callgrind` the difference of two counts over the difference of the calls
/// is one impact's instructions (BENCHMARKS.md).
fn calls(args: &[String]) {
    let n: usize = args[0].parse().expect("a count");
    let p = bouncelab::preset::Preset::embedded()[0].params();
    assert!(table::hertz(&p.normalized()).is_some());
    let mut sum = 0.0;
    for _ in 0..n {
        sum += table::hertz(&std::hint::black_box(p).normalized())
            .expect("the superball is in a kept patch")
            .cor;
    }
    say!("{n} calls, Σe = {sum}");
}

/// Which path answers a Hertz impact: 0 the table, 1 the Taylor steps, 2 the adaptive solver.
fn path(n: &bouncelab::Normalized) -> usize {
    if table::hertz(n).is_some() {
        0
    } else if bouncelab::solver::taylor::summary(n, bouncelab::ContactLaw::Hertz).is_some() {
        1
    } else {
        2
    }
}

/// `--coverage`: the cells of `benches/map.rs`'s normalized Hertz map (60 λ × 200 ζ, log-spaced
/// over 0.01 … 100, κ = 2/3) and each preset's Hertz impact, by the path that answers them.
fn coverage() {
    let log = |i: usize, n: usize| 10f64.powf(-2.0 + 4.0 * i as f64 / (n - 1) as f64);
    let mut count = [0usize; 3];
    for i in 0..60 {
        for j in 0..200 {
            let p =
                bouncelab::ImpactParams::from_normalized(log(i, 60), log(j, 200), f64::INFINITY);
            count[path(&p.normalized())] += 1;
        }
    }
    say!(
        "normalized Hertz map 60 × 200: table {}, Taylor steps {}, adaptive {}",
        count[0],
        count[1],
        count[2]
    );
    for preset in bouncelab::preset::Preset::embedded_all() {
        let n = preset.params().normalized();
        let l = n.kappa.powf(-0.4);
        say!(
            "{:>12}: λ̂ {:.3e} ζ̂ {:.3e}: {}",
            preset.name,
            n.lambda * l * l,
            n.zeta / l,
            ["table", "Taylor steps", "adaptive"][path(&n)]
        );
    }
}

/// The map's cells of `coverage` as (λ̂, ζ̂).
fn map_cells() -> Vec<(f64, f64)> {
    let log = |i: usize, n: usize| 10f64.powf(-2.0 + 4.0 * i as f64 / (n - 1) as f64);
    let mut out = Vec::new();
    for i in 0..60 {
        for j in 0..200 {
            let p =
                bouncelab::ImpactParams::from_normalized(log(i, 60), log(j, 200), f64::INFINITY);
            let n = p.normalized();
            let l = n.kappa.powf(-0.4);
            out.push((n.lambda * l * l, n.zeta / l));
        }
    }
    out
}

/// `--gaps`: each stored square that holds cells of the normalized Hertz map the table does
/// not answer, with its measured error and how many such cells it holds.
fn gaps() {
    let (_, patches) = table::stored().expect("the table reads");
    let leaves = table::leaves(&patches, GRID.nw);
    let mut count = vec![0usize; leaves.len()];
    for (l, z) in map_cells() {
        if table::hertz_hat(l, z).is_some() {
            continue;
        }
        let (u, w) = (l.log10(), z.log10());
        let holds = |c: &Cell| {
            let (l0, z0) = GRID.cell_point(c, -1.0, -1.0);
            let (l1, z1) = GRID.cell_point(c, 1.0, 1.0);
            (l0.log10()..=l1.log10()).contains(&u) && (z0.log10()..=z1.log10()).contains(&w)
        };
        match leaves.iter().position(|(c, _)| holds(c)) {
            Some(k) => count[k] += 1,
            None => say!("no square holds λ̂ {l:.3e} ζ̂ {z:.3e}"),
        }
    }
    for ((c, p), n) in leaves.iter().zip(&count).filter(|(_, n)| **n > 0) {
        let (l0, z0) = GRID.cell_point(c, -1.0, -1.0);
        let (l1, z1) = GRID.cell_point(c, 1.0, 1.0);
        say!(
            "{c:?} λ̂ {l0:.3e}…{l1:.3e} ζ̂ {z0:.3e}…{z1:.3e}: error {:.2e}, {n} cells",
            p.error
        );
    }
}

/// `--errors N`: `table::error` at N seeded points, log-uniform over the area the table
/// answers, as quantiles; and how many stored squares were measured within 1e-12 … 1e-10.
fn errors(args: &[String]) {
    let n: usize = args[0].parse().expect("a count");
    let (_, patches) = table::stored().expect("the table reads");
    let leaves = table::leaves(&patches, GRID.nw);
    // the Monte Carlo's generator (ChaCha8, `analysis::mc`), 53 bits to a uniform in [0, 1)
    let mut rng = ChaCha8Rng::seed_from_u64(0x7ab1_e001);
    let mut u = move || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    // uniform over the area the table answers: a uniform point of the grid, drawn again
    // until the table answers there
    let span = |x0: f64, d: f64, n: usize, t: f64| 10f64.powf(x0 + d * n as f64 * t);
    let mut e: Vec<f64> = Vec::with_capacity(n);
    while e.len() < n {
        let l = span(GRID.u0, GRID.du, GRID.nu, u());
        let z = span(GRID.w0, GRID.dw, GRID.nw, u());
        if let Some(t) = table::hertz_hat(l, z) {
            e.push(table::reference(l, z).map_or(f64::INFINITY, |r| table::error(&t, &r)));
        }
    }
    let measured = |x: f64| leaves.iter().filter(|(_, p)| p.error <= x).count();
    say!(
        "squares measured within 1e-12: {}, 1e-11: {}, 1e-10: {}",
        measured(1e-12),
        measured(1e-11),
        measured(1e-10)
    );
    e.sort_by(f64::total_cmp);
    let q = |f: f64| e[((n - 1) as f64 * f) as usize];
    let under = |x: f64| e.iter().filter(|&&d| d <= x).count();
    say!(
        "{n} points: median {:.2e}, 90 % {:.2e}, 99 % {:.2e}, max {:.2e}; ≤ 1e-12: {}, ≤ 1e-11: {}",
        q(0.5),
        q(0.9),
        q(0.99),
        q(1.0),
        under(1e-12),
        under(1e-11)
    );
}
