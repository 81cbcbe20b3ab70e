//! Chebyshev interpolation on [−1, 1]²: the Chebyshev–Lobatto points x_j = cos(πj/n), the
//! coefficients of the interpolant through them (a discrete cosine transform of the first
//! kind, along each axis in turn), and the basis T_0(x) … T_n(x) by the three-term
//! recurrence. Written by hand: the transform of a 13 × 13 patch is a few thousand products,
//! and what the table needs of it is three short loops with no dependency to carry.

use std::f64::consts::PI;

/// The Chebyshev–Lobatto points of degree `n`: x_j = cos(πj/n), j = 0 … n (from 1 to −1).
pub fn lobatto(n: usize) -> Vec<f64> {
    (0..=n).map(|j| (PI * j as f64 / n as f64).cos()).collect()
}

/// The Chebyshev points of the first kind of degree `n`, x_j = cos(π(j + ½)/n), j = 0 … n − 1:
/// each lies between two Lobatto points of degree `n`, where an interpolant's error peaks.
pub fn between(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| (PI * (j as f64 + 0.5) / n as f64).cos())
        .collect()
}

/// cos(πjk/n) for j, k = 0 … n, `[j·(n+1) + k]`: the transform's matrix, computed once a
/// table (reading it cost 7·10⁸ instructions with a cosine a product).
fn cosines(n: usize) -> Vec<f64> {
    let m = n + 1;
    (0..m * m)
        .map(|jk| {
            let (j, k) = (jk / m, jk % m);
            (PI * (j * k % (2 * n)) as f64 / n as f64).cos()
        })
        .collect()
}

/// The two-dimensional transform of degree `n`: [`Dct::coefficients`] for many patches of one
/// degree, the cosines computed once.
#[derive(Debug, Clone)]
pub struct Dct {
    n: usize,
    cos: Vec<f64>,
}

impl Dct {
    /// The transform of degree `n` ≥ 1.
    pub fn new(n: usize) -> Dct {
        Dct { n, cos: cosines(n) }
    }

    /// The coefficients c_ij of Σ c_ij T_i(x) T_j(y) through the values `f[i·(n+1) + j]` at
    /// (x_i, y_j), the Lobatto points of degree n along each axis: the discrete cosine
    /// transform of the first kind along y (each row), then along x (each column). Along an
    /// axis a_k = (2/n) Σ″_j f_j cos(πjk/n), Σ″ halving the first and last terms, and a_0,
    /// a_n halved; each sum runs over j in order, every k at once (the same operations as
    /// one k at a time: the bits do not depend on the layout).
    pub fn coefficients(&self, f: &[f64]) -> Vec<f64> {
        let (n, m) = (self.n, self.n + 1);
        assert_eq!(f.len(), m * m, "a patch of degree {n} has {} values", m * m);
        let weight = |j: usize| if j == 0 || j == n { 0.5 } else { 1.0 };
        let finish = |k: usize, sum: f64| {
            let a = 2.0 * sum / n as f64;
            if k == 0 || k == n { 0.5 * a } else { a }
        };
        // along y: rows[i·m + k] = a_k of row i
        let mut rows = vec![-0.0; m * m];
        for (row, values) in rows.chunks_exact_mut(m).zip(f.chunks_exact(m)) {
            for (j, &fj) in values.iter().enumerate() {
                let wf = weight(j) * fj;
                for (s, &c) in row.iter_mut().zip(&self.cos[j * m..(j + 1) * m]) {
                    *s += wf * c;
                }
            }
            for (k, s) in row.iter_mut().enumerate() {
                *s = finish(k, *s);
            }
        }
        // along x: c[k·m + j] = a_k of column j, Σ over the rows i in order
        let mut c = vec![-0.0; m * m];
        for (k, out) in c.chunks_exact_mut(m).enumerate() {
            for (i, row) in rows.chunks_exact(m).enumerate() {
                let (w, cos) = (weight(i), self.cos[i * m + k]);
                for (s, &r) in out.iter_mut().zip(row) {
                    *s += w * r * cos;
                }
            }
            for s in out.iter_mut() {
                *s = finish(k, *s);
            }
        }
        c
    }
}

/// The coefficients c_ij of Σ c_ij T_i(x) T_j(y) through the values `f[i·(n+1) + j]` at
/// (x_i, y_j), the Lobatto points of degree n along each axis ([`Dct::coefficients`]).
pub fn coefficients(f: &[f64], n: usize) -> Vec<f64> {
    Dct::new(n).coefficients(f)
}

/// T_0(x) … T_n(x) into `t` (n = t.len() − 1): T_{k+1} = 2x T_k − T_{k−1}.
pub fn basis(x: f64, t: &mut [f64]) {
    let mut prev = 1.0;
    let mut cur = x;
    for (k, tk) in t.iter_mut().enumerate() {
        *tk = match k {
            0 => 1.0,
            1 => x,
            _ => {
                let next = 2.0 * x * cur - prev;
                (prev, cur) = (cur, next);
                next
            }
        };
    }
}

/// Σ c_ij T_i(x) T_j(y) from the bases `tx`, `ty` (each n + 1 long).
pub fn eval(c: &[f64], tx: &[f64], ty: &[f64]) -> f64 {
    let m = tx.len();
    c.chunks_exact(m)
        .zip(tx)
        .map(|(row, ti)| ti * row.iter().zip(ty).map(|(a, tj)| a * tj).sum::<f64>())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A polynomial of degree ≤ n in each variable is its own interpolant: at points off the
    /// nodes the interpolant returns it to rounding.
    #[test]
    fn a_polynomial_of_the_degree_is_reproduced() {
        let n = 6;
        let p =
            |x: f64, y: f64| 1.0 + x - 2.0 * x * y * y + x.powi(6) * y.powi(5) - 0.5 * y.powi(6);
        let xs = lobatto(n);
        let f: Vec<f64> = xs
            .iter()
            .flat_map(|&x| xs.iter().map(move |&y| p(x, y)))
            .collect();
        let c = coefficients(&f, n);
        let (mut tx, mut ty) = (vec![0.0; n + 1], vec![0.0; n + 1]);
        for &(x, y) in &[(0.3, -0.7), (-0.95, 0.11), (0.5, 0.5), (1.0, -1.0)] {
            basis(x, &mut tx);
            basis(y, &mut ty);
            assert!((eval(&c, &tx, &ty) - p(x, y)).abs() < 1e-13, "{x} {y}");
        }
    }

    /// The transform one coefficient at a time, as it was written before `Dct` (one sum a_k
    /// after another, a column gathered and transformed): the bits `Dct` must keep.
    fn one_at_a_time(f: &[f64], n: usize) -> Vec<f64> {
        let m = n + 1;
        let cos = cosines(n);
        let transform = |f: &[f64]| -> Vec<f64> {
            (0..=n)
                .map(|k| {
                    let sum: f64 = (0..=n)
                        .map(|j| {
                            let w = if j == 0 || j == n { 0.5 } else { 1.0 };
                            w * f[j] * cos[j * (n + 1) + k]
                        })
                        .sum();
                    let a = 2.0 * sum / n as f64;
                    if k == 0 || k == n { 0.5 * a } else { a }
                })
                .collect()
        };
        let rows: Vec<f64> = f.chunks_exact(m).flat_map(transform).collect();
        let mut c = vec![0.0; m * m];
        for j in 0..m {
            let column: Vec<f64> = (0..m).map(|i| rows[i * m + j]).collect();
            for (i, a) in transform(&column).into_iter().enumerate() {
                c[i * m + j] = a;
            }
        }
        c
    }

    /// `Dct` gives the coefficients of the transform one at a time bit for bit (the table's
    /// interpolants are unchanged by the faster reading), on seeded values of degree 14.
    #[test]
    fn the_transform_keeps_its_bits() {
        let n = 14;
        let mut state = 0x000d_0c07_u64;
        let f: Vec<f64> = (0..(n + 1) * (n + 1))
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                (state >> 11) as f64 / (1u64 << 53) as f64 - 0.3
            })
            .collect();
        let bits = |c: Vec<f64>| c.into_iter().map(f64::to_bits).collect::<Vec<_>>();
        assert_eq!(bits(coefficients(&f, n)), bits(one_at_a_time(&f, n)));
    }

    /// The basis is cos(k arccos x).
    #[test]
    fn the_basis_is_the_cosines() {
        let mut t = [0.0; 9];
        basis(0.37, &mut t);
        for (k, tk) in t.iter().enumerate() {
            assert!((tk - (k as f64 * 0.37f64.acos()).cos()).abs() < 1e-14);
        }
    }
}
