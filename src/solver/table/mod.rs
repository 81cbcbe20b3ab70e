//! The Hertz impact tabulated (issue 30 item 1): under the Hertz law without yield the
//! normalized impact depends on (λ̂, ζ̂) = (λL², ζ/L) alone, L = κ^{−2/5} (docs/model.md §5,
//! the Hertz scale of `solver::taylor`), so each output of its summary — e, F̂_m, t̂_f, ẑ_m,
//! ȳ at separation — is a smooth function of (log λ̂, log ζ̂). The table holds each one's
//! logarithm as a Chebyshev interpolant of degree `GRID.degree` on square patches of the
//! (log₁₀ λ̂, log₁₀ ζ̂) plane; an impact is then two logarithms, two bases and five sums.
//! A patch not within [`TOLERANCE`] as a whole is split in four (a quadtree, [`Cell`]), and
//! each part kept where it is within it: the parts reach the kink of F̂_m and ẑ_m from both
//! sides (docs/numerics.md).
//!
//! **Generated, verified.** `cargo run --release --example gen_hertz_table` (docs/numerics.md)
//! computes the node values with the Taylor steps without step limit or stiffness cut
//! ([`crate::solver::taylor::hertz_reference`]), measures each patch's error at the points
//! between its nodes against the same reference, and keeps a patch (or part) only where that
//! error is within [`TOLERANCE`] (`error` says how it is measured). The file is `hertz.bin`
//! (`format`, version 3: an index of the patches' records, each read at its patch's first
//! use). tests/physics/hertz_table.rs re-computes seeded nodes of patches and parts
//! (they must equal the file's), and meets the reference to 1e-12 at 1 000 seeded points off
//! the nodes of the kept squares.
//!
//! **Where it answers.** Inside the grid, in a kept patch or part; elsewhere (λ̂ = 0, far
//! out, a square across the kink, where e → 0 or the reference runs out of steps)
//! [`summary`] hands the impact to the Taylor steps, and `None` from them to the adaptive
//! solver.

pub mod cheb;
mod format;
mod kernel;

pub use format::{Patch, decode, encode, encode_v2};

use crate::model::contact::ContactLaw;
use crate::model::params::Normalized;
use crate::solver::taylor::{self, Summary};
use std::sync::OnceLock;

/// The outputs a node holds: e, F̂_m, t̂_f, ẑ_m and ȳ at separation (Hertz scale).
pub const OUTPUTS: usize = 5;
/// The largest error a kept patch (or part) showed between its nodes (`error`): 1e-12,
/// issue 30's precision.
pub const TOLERANCE: f64 = 1e-12;
/// The reference's step limit. The steps number about the stiffness 2ζ̂(1.6 + λ̂)·3.2 over 7
/// (BENCHMARKS.md: 1 095 steps at (30, 40)), and a creep's length times 2ζ̂·1.6 over 7: this
/// reaches a stiffness of 2·10⁵ (ζ̂λ̂ ≈ 3·10⁴, past the explorer's Hertz maps) at some 60 ms
/// a node, and keeps the tests' reference runs short.
pub const REFERENCE_STEPS: usize = 30_000;

/// The patches: `nu` × `nw` squares of side `du` × `dw` from (`u0`, `w0`) in
/// (u, w) = (log₁₀ λ̂, log₁₀ ζ̂), each with (degree + 1)² Chebyshev–Lobatto nodes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// The interpolants' degree along each axis.
    pub degree: usize,
    /// Patches along u = log₁₀ λ̂.
    pub nu: usize,
    /// Patches along w = log₁₀ ζ̂.
    pub nw: usize,
    /// The grid's first u.
    pub u0: f64,
    /// A patch's side along u, decades.
    pub du: f64,
    /// The grid's first w.
    pub w0: f64,
    /// A patch's side along w, decades.
    pub dw: f64,
}

/// The grid the committed table is built on (the generator writes this one).
pub const GRID: Grid = Grid {
    degree: 14,
    nu: 16,
    nw: 16,
    u0: -4.0,
    du: 0.5,
    w0: -4.0,
    dw: 0.5,
};

/// A square of the grid: patch (`iu`, `iw`), or at `level` ℓ > 0 the part (`a`, `b`) of it,
/// a, b < 2^ℓ, of side 2^−ℓ of the patch's (the quadtree of `Patch::parts`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cell {
    /// The patch along u = log₁₀ λ̂.
    pub iu: usize,
    /// The patch along w = log₁₀ ζ̂.
    pub iw: usize,
    /// How many times the patch was halved to reach this square.
    pub level: u32,
    /// The part along u, from the patch's lower edge, in sides of this square.
    pub a: usize,
    /// The part along w.
    pub b: usize,
}

impl Cell {
    /// The whole patch (iu, iw).
    pub fn patch(iu: usize, iw: usize) -> Cell {
        Cell {
            iu,
            iw,
            level: 0,
            a: 0,
            b: 0,
        }
    }

    /// Part `k` of this square halved both ways, `Patch::parts`' order: k = 2·(upper half in
    /// u) + (upper half in w).
    pub fn part(&self, k: usize) -> Cell {
        Cell {
            level: self.level + 1,
            a: 2 * self.a + k / 2,
            b: 2 * self.b + k % 2,
            ..*self
        }
    }
}

impl Grid {
    /// (λ̂, ζ̂) at the local coordinates (x, y) ∈ [−1, 1]² of patch (iu, iw).
    pub fn point(&self, iu: usize, iw: usize, x: f64, y: f64) -> (f64, f64) {
        self.cell_point(&Cell::patch(iu, iw), x, y)
    }

    /// (λ̂, ζ̂) at the local coordinates (x, y) ∈ [−1, 1]² of the square `c`. At level 0
    /// s = 1 and a = b = 0 leave every bit of `point`'s arithmetic for a whole patch, so a
    /// whole patch's nodes are those of the version-1 file
    /// (tests/physics/hertz_table.rs, `seeded_nodes_computed_again_equal_the_file`).
    pub fn cell_point(&self, c: &Cell, x: f64, y: f64) -> (f64, f64) {
        let s = 0.5f64.powi(c.level as i32);
        let u = self.u0 + self.du * (c.iu as f64 + s * (c.a as f64 + 0.5 * (x + 1.0)));
        let w = self.w0 + self.dw * (c.iw as f64 + s * (c.b as f64 + 0.5 * (y + 1.0)));
        (10f64.powf(u), 10f64.powf(w))
    }

    /// The patch holding (λ̂, ζ̂), its index and the point's place in it, (fu, fw) ∈ [0, 1]²
    /// from its lower corner; `None` outside.
    fn locate(&self, lambda_hat: f64, zeta_hat: f64) -> Option<(usize, f64, f64)> {
        let fu = (lambda_hat.log10() - self.u0) / self.du;
        let fw = (zeta_hat.log10() - self.w0) / self.dw;
        let inside = |f: f64, n: usize| (0.0..=n as f64).contains(&f);
        if !(inside(fu, self.nu) && inside(fw, self.nw)) {
            return None;
        }
        let (iu, iw) = (
            (fu as usize).min(self.nu - 1),
            (fw as usize).min(self.nw - 1),
        );
        Some((iu * self.nw + iw, fu - iu as f64, fw - iw as f64))
    }
}

/// Every square the table stores as a whole (a patch not split, or a part not split
/// further), with its cell, patch by patch (log λ̂ outer), each patch's parts in order.
pub fn leaves(patches: &[Patch], nw: usize) -> Vec<(Cell, &Patch)> {
    fn walk<'a>(c: Cell, p: &'a Patch, out: &mut Vec<(Cell, &'a Patch)>) {
        if p.parts.is_empty() {
            out.push((c, p));
        }
        for (k, q) in p.parts.iter().enumerate() {
            walk(c.part(k), q, out);
        }
    }
    let mut out = Vec::new();
    for (i, p) in patches.iter().enumerate() {
        walk(Cell::patch(i / nw, i % nw), p, &mut out);
    }
    out
}

/// The outputs of a summary, in the table's order.
pub fn outputs(s: &Summary) -> [f64; OUTPUTS] {
    [
        s.cor,
        s.max_force,
        s.contact_time,
        s.max_indentation,
        s.element_displacement,
    ]
}

/// The reference at (λ̂, ζ̂): the unlimited Taylor steps' outputs, `None` where they do not
/// answer within [`REFERENCE_STEPS`] or an output is not positive (no logarithm).
pub fn reference(lambda_hat: f64, zeta_hat: f64) -> Option<[f64; OUTPUTS]> {
    let s = taylor::hertz_reference(lambda_hat, zeta_hat, REFERENCE_STEPS)?;
    let o = outputs(&s);
    o.iter().all(|&x| x > 0.0 && x.is_finite()).then_some(o)
}

/// The table's error against the reference at one point: each output relative to its size,
/// but ȳ (which vanishes as ζ̂ → 0 or λ̂ → ∞, where its reference is good only to the
/// rounding of the state, of size ẑ) relative to ẑ_m, as tests/physics/taylor.rs measures z̄_f.
pub fn error(table: &[f64; OUTPUTS], reference: &[f64; OUTPUTS]) -> f64 {
    let rel = |k: usize, scale: f64| (table[k] - reference[k]).abs() / scale;
    if table.iter().chain(reference).any(|x| !x.is_finite()) {
        return f64::INFINITY;
    }
    (0..4).fold(rel(4, reference[3]), |w, k| w.max(rel(k, reference[k])))
}

/// One patch's interpolants: the Chebyshev coefficients of each output's logarithm from its
/// node values (`Patch::values`'s layout).
pub fn coefficients(values: &[f64], degree: usize) -> Vec<f64> {
    let m = (degree + 1) * (degree + 1);
    let dct = cheb::Dct::new(degree);
    values
        .chunks_exact(m)
        .flat_map(|v| dct.coefficients(v))
        .collect()
}

/// The outputs from one patch's `coefficients` at local (x, y).
pub fn interpolate(coefficients: &[f64], degree: usize, x: f64, y: f64) -> [f64; OUTPUTS] {
    const MAX: usize = 32;
    assert!(degree < MAX, "degree {degree}");
    let (mut tx, mut ty) = ([0.0; MAX], [0.0; MAX]);
    let (tx, ty) = (&mut tx[..=degree], &mut ty[..=degree]);
    cheb::basis(x, tx);
    cheb::basis(y, ty);
    let m = (degree + 1) * (degree + 1);
    let mut out = [0.0; OUTPUTS];
    for (o, c) in out.iter_mut().zip(coefficients.chunks_exact(m)) {
        *o = cheb::eval(c, tx, ty).exp();
    }
    out
}

/// The committed table.
static DATA: &[u8] = include_bytes!("hertz.bin");

/// The committed table as stored (its grid and patches), or why it does not read.
pub fn stored() -> Result<(Grid, Vec<Patch>), String> {
    decode(DATA)
}

/// A patch (or part) ready to evaluate.
enum Node {
    /// The table does not answer here.
    Out,
    /// A kept square's coefficients, laid out for `kernel`.
    Kept(Box<kernel::Block>),
    /// A square split in four, `Patch::parts`' order.
    Split(Box<[Node; 4]>),
}

impl Node {
    fn of(p: &Patch, degree: usize) -> Node {
        if let [a, b, c, d] = &p.parts[..] {
            let part = |q| Node::of(q, degree);
            return Node::Split(Box::new([part(a), part(b), part(c), part(d)]));
        }
        p.values.as_ref().map_or(Node::Out, |v| {
            Node::Kept(kernel::block(&coefficients(v, degree)))
        })
    }

    /// The kept square holding the point at (fu, fw) ∈ [0, 1]² of this one, and the local
    /// coordinates there. Halving is exact in binary: (fu, fw) → 2f or 2f − 1 loses no bit,
    /// so an unsplit patch gets the first table's (x, y) = (2fu − 1, 2fw − 1).
    fn find(&self, mut fu: f64, mut fw: f64) -> Option<(&kernel::Block, f64, f64)> {
        let mut node = self;
        loop {
            match node {
                Node::Out => return None,
                Node::Kept(b) => return Some((b, 2.0 * fu - 1.0, 2.0 * fw - 1.0)),
                Node::Split(parts) => {
                    let (hu, hw) = (fu >= 0.5, fw >= 0.5);
                    fu = 2.0 * fu - f64::from(u8::from(hu));
                    fw = 2.0 * fw - f64::from(u8::from(hw));
                    node = &parts[2 * usize::from(hu) + usize::from(hw)];
                }
            }
        }
    }
}

/// The table ready to evaluate: the file's header and index as read, and each patch's tree
/// of kept squares made from its record at the patch's first use (the record's checksum, its
/// values and the transforms, some 3·10⁵ instructions a kept square; the whole file read and
/// made at once would cost 2·10⁸, BENCHMARKS.md "Fifth session (hertz6)" and hertz7's; a
/// process mostly meets few patches).
struct Table {
    index: format::Index<'static>,
    patches: Vec<OnceLock<Node>>,
}

/// The table, opened once; `None` when the file's header or index does not read or is not
/// on [`GRID`] (then every impact goes to the Taylor steps; tests/physics/hertz_table.rs fails on
/// it). A patch whose record does not read answers nowhere (tests/physics/hertz_table.rs reads every
/// record of the committed file).
fn table() -> Option<&'static Table> {
    static TABLE: OnceLock<Option<Table>> = OnceLock::new();
    TABLE
        .get_or_init(|| {
            let index = format::open(DATA).ok().filter(|i| i.grid == GRID)?;
            let patches = (0..GRID.nu * GRID.nw).map(|_| OnceLock::new()).collect();
            Some(Table { index, patches })
        })
        .as_ref()
}

/// The outputs at (λ̂, ζ̂) from the table, `None` outside its grid or in a square it does
/// not keep: [`interpolate`]'s bits, by the five interpolants at once (`kernel`).
pub fn hertz_hat(lambda_hat: f64, zeta_hat: f64) -> Option<[f64; OUTPUTS]> {
    let (b, x, y) = kept_square(lambda_hat, zeta_hat)?;
    Some(kernel::eval(b, x, y).map(f64::exp))
}

/// The kept square holding (λ̂, ζ̂) and the local coordinates there; `None` outside the grid
/// or in a square the table does not keep.
fn kept_square(lambda_hat: f64, zeta_hat: f64) -> Option<(&'static kernel::Block, f64, f64)> {
    let t = table()?;
    let (patch, fu, fw) = GRID.locate(lambda_hat, zeta_hat)?;
    let node = t.patches[patch].get_or_init(|| {
        t.index
            .patch(patch)
            .map_or(Node::Out, |p| Node::of(&p, GRID.degree))
    });
    node.find(fu, fw)
}

/// (λ̂, ζ̂) and the length scale L = κ^{−2/5} of the normalized ball `n` (the Hertz scale of
/// docs/model.md §3); `None` for a κ that is not positive and finite.
fn hertz_point(n: &Normalized) -> Option<(f64, f64, f64)> {
    if !(n.kappa.is_finite() && n.kappa > 0.0) {
        return None;
    }
    let l = n.kappa.powf(-0.4);
    Some((n.lambda * l * l, n.zeta / l, l))
}

/// Whether the table holds the Hertz impact of `n` — where [`summary`] looks it up — without
/// evaluating it (a lookup, some tens of ns): `api::first_pass` finds the same by evaluating,
/// and tests/physics/rows_columns.rs checks its counts against this.
pub fn holds(n: &Normalized) -> bool {
    n.zp_bar > 0.0
        && hertz_point(n)
            .is_some_and(|(lambda_hat, zeta_hat, _)| kept_square(lambda_hat, zeta_hat).is_some())
}

/// The Hertz impact of the normalized ball `n` from the table, in the units of the run
/// (`taylor::summary`'s: z̄ = L ẑ, τ = L t̂, F̄ = F̂/L), `steps` 0; `None` where the table does
/// not answer.
pub fn hertz(n: &Normalized) -> Option<Summary> {
    let (lambda_hat, zeta_hat, l) = hertz_point(n)?;
    let [cor, f, t, z, y] = hertz_hat(lambda_hat, zeta_hat)?;
    Some(Summary {
        // e < 1 by dissipation; the interpolant's 1e-12 must not carry it past 1
        cor: cor.min(1.0),
        max_force: f / l,
        contact_time: t * l,
        max_indentation: z * l,
        permanent_indentation: 0.0,
        element_displacement: y * l,
        steps: 0,
    })
}

/// The fast summary of one impact: the table under the Hertz law where it answers, and
/// under the elastic–plastic law where its Hertz impact stays below yield
/// ([`taylor::plastic::below_yield`]); else the Taylor steps ([`taylor::summary`]), else,
/// where a phase is too stiff for their usual few steps, the Taylor steps given as many as
/// its stiffness needs ([`taylor::stiff_summary`]); `None` where the adaptive solver must run.
pub fn summary(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    tabulated(n, law)
        .or_else(|| taylor::summary(n, law))
        .or_else(|| taylor::stiff_summary(n, law))
}

/// [`summary`]'s table branch alone.
fn tabulated(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    match law {
        ContactLaw::Hertz if n.zp_bar > 0.0 => hertz(n),
        ContactLaw::ElasticPlastic if n.zp_bar > 0.0 => {
            hertz(n).and_then(|h| taylor::plastic::below_yield(n, h))
        }
        _ => None,
    }
}

/// [`summary`] of each of `ns`, the same bits: the table where it answers, the rest's Taylor
/// steps several at a time in lanes ([`taylor::batch::summaries`]), and one at a time with
/// more steps where a phase is too stiff for those ([`taylor::stiff_summary`]).
pub fn summaries(ns: &[Normalized], law: ContactLaw) -> Vec<Option<Summary>> {
    let mut out: Vec<Option<Summary>> = ns.iter().map(|n| tabulated(n, law)).collect();
    let rest: Vec<usize> = (0..ns.len()).filter(|&i| out[i].is_none()).collect();
    let picked: Vec<Normalized> = rest.iter().map(|&i| ns[i]).collect();
    for (i, s) in rest.into_iter().zip(taylor::batch::summaries(&picked, law)) {
        out[i] = s.or_else(|| taylor::stiff_summary(&ns[i], law));
    }
    out
}
