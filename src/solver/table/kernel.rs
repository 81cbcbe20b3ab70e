//! One kept patch's five interpolants at one point, evaluated together (issue 30 item 1: a
//! table impact in a few thousand instructions). The patch's coefficients are laid out at load
//! as `Block`: output by output, column by column (the index j of T_j(y)), each column's
//! rows i contiguous and padded to a multiple of four. One pass over a column adds
//! c_ij T_j(y) to the partial sums r_i of every row at once — independent sums, so the
//! compiler keeps four of them in one AVX register — then Σ_i T_i(x) r_i.
//!
//! **The same bits as `super::interpolate`.** Each r_i is summed over j in order from −0.0,
//! each output over i in order, one product and one sum at a time (Rust never fuses them,
//! and FMA is not enabled): the operations of `cheb::eval`, in its order, whatever the
//! register width. `the_kernel_is_interpolate_bit_for_bit` (below) checks it in every kept
//! patch, on the AVX build and the portable one.

use super::{GRID, OUTPUTS};

/// Nodes along an axis, the degree plus one.
pub(super) const M: usize = GRID.degree + 1;
/// A column's rows, padded to a multiple of four (the padding's coefficients are zero).
const ROWS: usize = M.next_multiple_of(4);

/// One kept patch's coefficients as the kernel reads them: `[k][j][i]` = c_ij of output k,
/// the coefficient of T_i(x) T_j(y).
pub(super) type Block = [[[f64; ROWS]; M]; OUTPUTS];

/// The `Block` of one patch's coefficients (`super::coefficients`' layout:
/// `[k·M² + i·M + j]`).
pub(super) fn block(coefficients: &[f64]) -> Box<Block> {
    assert_eq!(
        coefficients.len(),
        OUTPUTS * M * M,
        "a patch of degree {}",
        M - 1
    );
    let mut b = Box::new([[[0.0; ROWS]; M]; OUTPUTS]);
    for (k, c) in coefficients.chunks_exact(M * M).enumerate() {
        for (i, row) in c.chunks_exact(M).enumerate() {
            for (j, &a) in row.iter().enumerate() {
                b[k][j][i] = a;
            }
        }
    }
    b
}

/// T_0(x) … T_{M−1}(x) by `cheb::basis`'s recurrence, T_{k+1} = 2x T_k − T_{k−1}, in its
/// operations.
#[inline(always)]
fn basis(x: f64) -> [f64; M] {
    let mut t = [1.0; M];
    t[1] = x;
    for k in 2..M {
        t[k] = 2.0 * x * t[k - 1] - t[k - 2];
    }
    t
}

/// ln of the five outputs at local (x, y) from the patch's `b`.
#[inline(always)]
fn logs(b: &Block, x: f64, y: f64) -> [f64; OUTPUTS] {
    let (tx, ty) = (basis(x), basis(y));
    let mut out = [0.0; OUTPUTS];
    for (o, columns) in out.iter_mut().zip(b) {
        // r_i = Σ_j c_ij T_j(y), every row at once, j in order
        let mut r = [-0.0; ROWS];
        for (column, &t) in columns.iter().zip(&ty) {
            for (ri, &c) in r.iter_mut().zip(column) {
                *ri += c * t;
            }
        }
        // Σ_i T_i(x) r_i, i in order
        *o = tx.iter().zip(&r).fold(-0.0, |s, (&t, &ri)| s + t * ri);
    }
    out
}

/// ln of the five outputs at local (x, y) from the patch's `b`: in AVX registers where the
/// CPU has AVX, for the build's target elsewhere; the same bits either way.
pub(super) fn eval(b: &Block, x: f64, y: f64) -> [f64; OUTPUTS] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU has AVX, just checked
        return unsafe { avx::logs(b, x, y) };
    }
    logs(b, x, y)
}

/// `logs` with the rows' partial sums four to a register, written with the intrinsics: left
/// to itself the compiler kept them two to a register (1 900 instructions an impact against
/// some 1 100; callgrind, BENCHMARKS.md). The same products and sums, lane by lane, in the
/// same order.
#[cfg(target_arch = "x86_64")]
mod avx {
    use super::{Block, OUTPUTS, ROWS, basis};
    use std::arch::x86_64::{__m256d, _mm256_storeu_pd};
    use std::arch::x86_64::{_mm256_add_pd, _mm256_loadu_pd, _mm256_mul_pd, _mm256_set1_pd};

    /// Registers a column's rows fill.
    const REGS: usize = ROWS / 4;

    /// `super::logs` in AVX registers.
    ///
    /// # Safety
    /// The CPU must have AVX.
    #[target_feature(enable = "avx")]
    pub(super) unsafe fn logs(b: &Block, x: f64, y: f64) -> [f64; OUTPUTS] {
        let (tx, ty) = (basis(x), basis(y));
        let mut out = [0.0; OUTPUTS];
        for (o, columns) in out.iter_mut().zip(b) {
            let mut r: [__m256d; REGS] = [_mm256_set1_pd(-0.0); REGS];
            for (column, &t) in columns.iter().zip(&ty) {
                let t = _mm256_set1_pd(t);
                for (k, rk) in r.iter_mut().enumerate() {
                    // SAFETY: column holds ROWS = 4·REGS values, k < REGS
                    let c = unsafe { _mm256_loadu_pd(column.as_ptr().add(4 * k)) };
                    *rk = _mm256_add_pd(*rk, _mm256_mul_pd(c, t));
                }
            }
            let mut rows = [0.0; ROWS];
            for (k, rk) in r.iter().enumerate() {
                // SAFETY: rows holds ROWS = 4·REGS values, k < REGS
                unsafe { _mm256_storeu_pd(rows.as_mut_ptr().add(4 * k), *rk) };
            }
            *o = tx.iter().zip(&rows).fold(-0.0, |s, (&t, &ri)| s + t * ri);
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::cheb;
    use super::*;

    /// `cheb::eval` of each output's coefficients: the sums `super::interpolate` exponentiates.
    fn sums(c: &[f64], x: f64, y: f64) -> [f64; OUTPUTS] {
        let (mut tx, mut ty) = ([0.0; M], [0.0; M]);
        cheb::basis(x, &mut tx);
        cheb::basis(y, &mut ty);
        std::array::from_fn(|k| cheb::eval(&c[k * M * M..(k + 1) * M * M], &tx, &ty))
    }

    /// In every kept patch and part, at seeded points and at the corners, the kernel (AVX and
    /// portable) gives `interpolate`'s logarithms bit for bit.
    #[test]
    fn the_kernel_is_interpolate_bit_for_bit() {
        let (_, stored) = super::super::stored().unwrap();
        let leaves = super::super::leaves(&stored, GRID.nw);
        let kept: Vec<&[f64]> = leaves
            .iter()
            .filter_map(|(_, p)| p.values.as_deref())
            .collect();
        let mut state = 0x6b65_726e_656c_u64;
        let mut u = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            2.0 * ((state >> 11) as f64 / (1u64 << 53) as f64) - 1.0
        };
        let mut checked = 0;
        for values in &kept {
            let c = super::super::coefficients(values, GRID.degree);
            let b = block(&c);
            for (x, y) in [
                (1.0, 1.0),
                (-1.0, -1.0),
                (1.0, -1.0),
                (u(), u()),
                (u(), u()),
            ] {
                let want = sums(&c, x, y).map(f64::to_bits);
                assert_eq!(eval(&b, x, y).map(f64::to_bits), want, "{x} {y}");
                assert_eq!(logs(&b, x, y).map(f64::to_bits), want, "{x} {y}");
                checked += 1;
            }
        }
        // five points in each kept square, of the 652 the table keeps
        assert_eq!(checked, 5 * kept.len());
        assert!(kept.len() >= 652, "{}", kept.len());
    }
}
