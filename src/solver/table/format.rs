//! The Hertz table's file: a header naming its grid, an index of the patches' records (each
//! one's length and checksum), then one record a patch. Version 3:
//!
//! ```text
//! "BLHERTZ" and the version, "3"               8 bytes
//! degree, patches along log λ̂, along log ζ̂   u32 × 3 (little-endian)
//! log₁₀ λ̂₀, Δ, log₁₀ ζ̂₀, Δ                     f64 × 4
//! per patch (log λ̂ outer): its record's length in bytes, the record's FNV-1a 64   u64 × 2
//! FNV-1a 64 of everything before (header and index)   u64
//! per patch, its record, back to back:
//!   tag u8 — 0: not kept, 1: kept, 2: split in four
//!   the error measured off the nodes f64
//!   if kept: ln of the 5 outputs at the (degree + 1)² nodes, output by output, f64 each
//!   if split: the four halves' records ((lower, lower), (lower, upper), (upper, lower),
//!     (upper, upper) halves in (log λ̂, log ζ̂)), each a record of the same form
//! ```
//!
//! So a reader checks the header and the index (some 6 kB) once, and a patch's record when it
//! first needs that patch ([`open`], [`Index::patch`]): the first impact of a process costs
//! one patch, not the whole file (BENCHMARKS.md, hertz7). Version 2 is the same records after
//! the header with no index, one FNV-1a of the whole file at its end; version 1 the same
//! without split records. Both still read (the whole file checked at [`open`]); any other
//! version is refused by name. FNV-1a written by hand: eight lines, against a dependency for
//! a checksum that guards a file the crate itself wrote (a truncated or hand-edited file, not
//! an adversary).

use super::{Grid, OUTPUTS};

/// The magic before the version digit.
const MAGIC: &[u8; 7] = b"BLHERTZ";
/// The version `encode` writes.
const VERSION: u8 = b'3';
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

/// The header both versions begin with: the magic, `version`, the grid.
fn header(grid: &Grid, version: u8) -> Vec<u8> {
    let mut out = MAGIC.to_vec();
    out.push(version);
    for n in [grid.degree, grid.nu, grid.nw] {
        out.extend_from_slice(&(n as u32).to_le_bytes());
    }
    for x in [grid.u0, grid.du, grid.w0, grid.dw] {
        out.extend_from_slice(&x.to_le_bytes());
    }
    out
}

/// The file's bytes for `patches` on `grid`, version 3.
pub fn encode(grid: &Grid, patches: &[Patch]) -> Vec<u8> {
    let records: Vec<Vec<u8>> = patches
        .iter()
        .map(|p| {
            let mut r = Vec::new();
            encode_patch(p, &mut r);
            r
        })
        .collect();
    let mut out = header(grid, VERSION);
    for r in &records {
        out.extend_from_slice(&(r.len() as u64).to_le_bytes());
        out.extend_from_slice(&fnv1a(r).to_le_bytes());
    }
    let sum = fnv1a(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    records.iter().for_each(|r| out.extend_from_slice(r));
    out
}

/// The file's bytes for `patches` on `grid` in version 2 (no index, one checksum at the
/// end): what the reader of older files is tested on.
pub fn encode_v2(grid: &Grid, patches: &[Patch]) -> Vec<u8> {
    let mut out = header(grid, b'2');
    patches.iter().for_each(|p| encode_patch(p, &mut out));
    let sum = fnv1a(&out);
    out.extend_from_slice(&sum.to_le_bytes());
    out
}

/// Reads what `encode` wrote (or a version-1 or -2 file), checking every checksum, the
/// version, the counts and that every kept value is finite.
pub fn decode(bytes: &[u8]) -> Result<(Grid, Vec<Patch>), String> {
    let index = open(bytes)?;
    let patches = (0..index.records.len())
        .map(|i| index.patch(i))
        .collect::<Result<_, _>>()?;
    Ok((index.grid, patches))
}

/// A patch's record in the file, and its checksum (`None` where the whole file's was
/// checked).
type Record<'a> = (&'a [u8], Option<u64>);

/// A file opened: its grid, and each patch's record not yet read.
pub struct Index<'a> {
    /// The grid the header names.
    pub grid: Grid,
    /// Each patch's record.
    records: Vec<Record<'a>>,
    /// The values of a kept square.
    per_patch: usize,
    /// How deep a record may split.
    depth: usize,
}

impl Index<'_> {
    /// Patch `i`'s record read, its checksum checked.
    pub fn patch(&self, i: usize) -> Result<Patch, String> {
        let &(bytes, sum) = self.records.get(i).ok_or_else(|| format!("no patch {i}"))?;
        if sum.is_some_and(|s| s != fnv1a(bytes)) {
            return Err(format!("patch {i}: checksum does not match"));
        }
        let mut r = Reader { bytes, at: 0 };
        let p = r
            .patch(self.per_patch, self.depth)
            .map_err(|e| format!("patch {i}: {e}"))?;
        if r.at != bytes.len() {
            return Err(format!(
                "patch {i}: {} bytes after its record",
                bytes.len() - r.at
            ));
        }
        Ok(p)
    }
}

/// The file's header and index checked, each patch's record found: a version-3 file's by
/// its index (the records' own checksums checked by [`Index::patch`]), an older one's by a
/// scan of the records' tags after its whole checksum.
pub fn open(bytes: &[u8]) -> Result<Index<'_>, String> {
    let mut r = Reader { bytes, at: 0 };
    if r.take(7)? != MAGIC {
        return Err("not a Hertz table".into());
    }
    let version = r.take(1)?[0];
    if !matches!(version, b'1' | b'2' | VERSION) {
        return Err(format!(
            "a Hertz table of version {:?}; this build reads versions 1, 2 and 3",
            char::from(version)
        ));
    }
    let (degree, nu, nw) = (r.u32()?, r.u32()?, r.u32()?);
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
    let n = nu.checked_mul(nw).ok_or("too many patches")?;
    let records = if version == VERSION {
        indexed(&mut r, n)?
    } else {
        scanned(bytes, &mut r, n, per_patch, depth)?
    };
    Ok(Index {
        grid,
        records,
        per_patch,
        depth,
    })
}

/// A version-3 file's records by its index, `r` past the header.
fn indexed<'a>(r: &mut Reader<'a>, n: usize) -> Result<Vec<Record<'a>>, String> {
    let entries: Vec<(u64, u64)> = (0..n)
        .map(|_| Ok((r.u64()?, r.u64()?)))
        .collect::<Result<_, String>>()?;
    let sum = fnv1a(&r.bytes[..r.at]);
    if r.u64()? != sum {
        return Err("checksum does not match".into());
    }
    let records = entries
        .into_iter()
        .map(|(len, sum)| {
            let len = usize::try_from(len).map_err(|_| "a record's length")?;
            Ok((r.take(len)?, Some(sum)))
        })
        .collect::<Result<_, String>>()?;
    if r.at != r.bytes.len() {
        return Err(format!(
            "{} bytes after the last patch",
            r.bytes.len() - r.at
        ));
    }
    Ok(records)
}

/// A version-1 or -2 file's records, found by reading their tags, the whole file's checksum
/// checked first; `r` past the header.
fn scanned<'a>(
    bytes: &'a [u8],
    r: &mut Reader<'a>,
    n: usize,
    per_patch: usize,
    depth: usize,
) -> Result<Vec<Record<'a>>, String> {
    let body_len = bytes
        .len()
        .checked_sub(8)
        .ok_or("shorter than its checksum")?;
    let (body, sum) = bytes.split_at(body_len);
    if fnv1a(body) != u64::from_le_bytes(sum.try_into().map_err(|_| "checksum")?) {
        return Err("checksum does not match".into());
    }
    r.bytes = body;
    let mut records = Vec::with_capacity(n);
    for _ in 0..n {
        let from = r.at;
        r.skip(per_patch, depth)?;
        records.push((&body[from..r.at], None));
    }
    if r.at != body.len() {
        return Err(format!("{} bytes after the last patch", body.len() - r.at));
    }
    Ok(records)
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        let s = self
            .bytes
            .get(self.at..self.at.saturating_add(n))
            .ok_or_else(|| format!("ends at byte {} inside a record", self.bytes.len()))?;
        self.at += n;
        Ok(s)
    }
    fn u32(&mut self) -> Result<usize, String> {
        Ok(u32::from_le_bytes(self.take(4)?.try_into().map_err(|_| "u32")?) as usize)
    }
    fn u64(&mut self) -> Result<u64, String> {
        Ok(u64::from_le_bytes(
            self.take(8)?.try_into().map_err(|_| "u64")?,
        ))
    }
    /// Past one record, its parts to `depth` more levels, its values not read.
    fn skip(&mut self, per_patch: usize, depth: usize) -> Result<(), String> {
        let tag = self.take(9)?[0];
        match tag {
            0 => Ok(()),
            1 => self.take(8 * per_patch).map(drop),
            2 if depth > 0 => (0..4).try_for_each(|_| self.skip(per_patch, depth - 1)),
            _ => Err(format!("a record tagged {tag} at byte {}", self.at - 9)),
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::table::GRID;

    /// `open` checks the header and the index only: a damaged record fails when its patch is
    /// read, and the other patches still read (the first impact reads one record, not the
    /// file); in a version-2 file, with one checksum for all, the damage fails `open`.
    #[test]
    fn a_patch_reads_alone() {
        let kept = |x: f64| Patch {
            error: 1e-13,
            values: Some(vec![x; OUTPUTS * 4]),
            parts: Vec::new(),
        };
        let grid = Grid {
            degree: 1,
            nu: 1,
            nw: 3,
            ..GRID
        };
        let patches = [kept(0.5), kept(0.25), kept(0.125)];
        let mut bytes = encode(&grid, &patches);
        let record = 9 + 8 * OUTPUTS * 4;
        // a value of the middle record
        let at = bytes.len() - record - 20;
        bytes[at] ^= 1;
        let index = open(&bytes).unwrap();
        assert_eq!(index.grid, grid);
        assert_eq!(index.patch(0).unwrap(), patches[0]);
        assert_eq!(index.patch(2).unwrap(), patches[2]);
        let err = index.patch(1).unwrap_err();
        assert_eq!(err, "patch 1: checksum does not match");
        assert!(decode(&bytes).is_err());
        let mut v2 = encode_v2(&grid, &patches);
        let at = v2.len() - 8 - record - 20;
        v2[at] ^= 1;
        assert!(open(&v2).is_err());
    }
}
