//! The Hertz table's file: a header naming its grid, one record a patch, an FNV-1a checksum.
//!
//! ```text
//! "BLHERTZ" and the version, "2"               8 bytes
//! degree, patches along log λ̂, along log ζ̂   u32 × 3 (little-endian)
//! log₁₀ λ̂₀, Δ, log₁₀ ζ̂₀, Δ                     f64 × 4
//! per patch (log λ̂ outer), a record:
//!   tag u8 — 0: not kept, 1: kept, 2: split in four
//!   the error measured off the nodes f64
//!   if kept: ln of the 5 outputs at the (degree + 1)² nodes, output by output, f64 each
//!   if split: the four halves' records ((lower, lower), (lower, upper), (upper, lower),
//!     (upper, upper) halves in (log λ̂, log ζ̂)), each a record of the same form
//! FNV-1a 64 of everything before                u64
//! ```
//!
//! Version 1 (the first table: no split records, "BLHERTZ1") still reads; any other version
//! is refused by name. FNV-1a written by hand: eight lines, against a dependency for a
//! checksum that guards a file the crate itself wrote (a truncated or hand-edited file, not
//! an adversary).

use super::{Grid, OUTPUTS};

/// The magic before the version digit.
const MAGIC: &[u8; 7] = b"BLHERTZ";
/// The version `encode` writes.
const VERSION: u8 = b'2';
/// The deepest split `decode` accepts (a bound against a damaged file, far past the
/// generator's `MAX_LEVEL`).
const DEPTH_LIMIT: usize = 8;

/// One patch (or a part of one) as stored.
#[derive(Debug, Clone, PartialEq)]
pub struct Patch {
    /// The largest error measured between the nodes (`super::error`), ∞ where the reference
    /// did not answer at some node or check point.
    pub error: f64,
    /// ln of the outputs at the nodes, `values[k·(n+1)² + i·(n+1) + j]` for output k at node
    /// (i, j); `None` for a patch the table does not answer as a whole (error above the
    /// tolerance).
    pub values: Option<Vec<f64>>,
    /// The four halves of a patch split in both directions (`Cell::part`'s order), each a
    /// patch of its own; empty for a patch not split. A split patch has no values.
    pub parts: Vec<Patch>,
}

/// FNV-1a, 64 bits.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

fn encode_patch(p: &Patch, out: &mut Vec<u8>) {
    let tag = if p.parts.is_empty() {
        u8::from(p.values.is_some())
    } else {
        2
    };
    out.push(tag);
    out.extend_from_slice(&p.error.to_le_bytes());
    if tag == 2 {
        assert_eq!(p.parts.len(), 4, "a split patch has four parts");
        p.parts.iter().for_each(|q| encode_patch(q, out));
    } else {
        for v in p.values.iter().flatten() {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
}

/// The file's bytes for `patches` on `grid`.
pub fn encode(grid: &Grid, patches: &[Patch]) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    out.push(VERSION);
    for n in [grid.degree, grid.nu, grid.nw] {
        out.extend_from_slice(&(n as u32).to_le_bytes());
    }
    for x in [grid.u0, grid.du, grid.w0, grid.dw] {
        out.extend_from_slice(&x.to_le_bytes());
    }
    patches.iter().for_each(|p| encode_patch(p, &mut out));
    let sum = fnv1a(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    out
}

/// Reads what `encode` wrote (or a version-1 file), checking the checksum, the version, the
/// counts and that every kept value is finite.
pub fn decode(bytes: &[u8]) -> Result<(Grid, Vec<Patch>), String> {
    let body_len = bytes
        .len()
        .checked_sub(8)
        .ok_or("shorter than its checksum")?;
    let (body, sum) = bytes.split_at(body_len);
    if fnv1a(body) != u64::from_le_bytes(sum.try_into().map_err(|_| "checksum")?) {
        return Err("checksum does not match".into());
    }
    let mut r = Reader { bytes: body, at: 0 };
    if r.take(7)? != MAGIC {
        return Err("not a Hertz table".into());
    }
    let version = r.take(1)?[0];
    if version != b'1' && version != VERSION {
        return Err(format!(
            "a Hertz table of version {:?}; this build reads versions 1 and 2",
            char::from(version)
        ));
    }
    let mut count = || -> Result<usize, String> {
        Ok(u32::from_le_bytes(r.take(4)?.try_into().map_err(|_| "u32")?) as usize)
    };
    let (degree, nu, nw) = (count()?, count()?, count()?);
    let grid = Grid {
        degree,
        nu,
        nw,
        u0: r.f64()?,
        du: r.f64()?,
        w0: r.f64()?,
        dw: r.f64()?,
    };
    let per_patch = OUTPUTS * (degree + 1) * (degree + 1);
    // version 1 has no split records: depth 0
    let depth = if version == b'1' { 0 } else { DEPTH_LIMIT };
    let mut patches = Vec::with_capacity(nu * nw);
    for _ in 0..nu * nw {
        patches.push(r.patch(per_patch, depth)?);
    }
    if r.at != body.len() {
        return Err(format!("{} bytes after the last patch", body.len() - r.at));
    }
    Ok((grid, patches))
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take(&mut self, n: usize) -> Result<&[u8], String> {
        let s = self
            .bytes
            .get(self.at..self.at + n)
            .ok_or_else(|| format!("ends at byte {} inside a record", self.bytes.len()))?;
        self.at += n;
        Ok(s)
    }
    fn f64(&mut self) -> Result<f64, String> {
        Ok(f64::from_le_bytes(
            self.take(8)?.try_into().map_err(|_| "f64")?,
        ))
    }
    /// One record, its parts to `depth` more levels.
    fn patch(&mut self, per_patch: usize, depth: usize) -> Result<Patch, String> {
        let tag = self.take(1)?[0];
        let error = self.f64()?;
        let (values, parts) = match tag {
            0 => (None, Vec::new()),
            1 => (Some(self.values(per_patch)?), Vec::new()),
            2 if depth > 0 => {
                let parts = (0..4)
                    .map(|_| self.patch(per_patch, depth - 1))
                    .collect::<Result<_, _>>()?;
                (None, parts)
            }
            _ => return Err(format!("a record tagged {tag} at byte {}", self.at - 9)),
        };
        Ok(Patch {
            error,
            values,
            parts,
        })
    }
    /// A kept patch's values in one take (one f64 at a time cost 60 instructions each).
    fn values(&mut self, per_patch: usize) -> Result<Vec<f64>, String> {
        let v: Vec<f64> = self
            .take(8 * per_patch)?
            .chunks_exact(8)
            .map(|b| f64::from_le_bytes(b.try_into().expect("a chunk of 8")))
            .collect();
        if !v.iter().all(|x| x.is_finite()) {
            return Err("a kept value is not finite".into());
        }
        Ok(v)
    }
}
