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
/// patch rather than once a product (the table is read in some 3·10⁷ instructions, not 7·10⁸).
fn cosines(n: usize) -> Vec<f64> {
    let m = n + 1;
    (0..m * m)
        .map(|jk| {
            let (j, k) = (jk / m, jk % m);
            (PI * (j * k % (2 * n)) as f64 / n as f64).cos()
        })
        .collect()
}

/// The coefficients a_k of Σ a_k T_k(x) through the values f_j at the Lobatto points of
/// degree n = f.len() − 1: a_k = (2/n) Σ″_j f_j cos(πjk/n), Σ″ halving the first and last
/// terms, and a_0, a_n halved (the discrete cosine transform of the first kind); `cos` is
/// `cosines(n)`.
fn transform(f: &[f64], cos: &[f64]) -> Vec<f64> {
    let n = f.len() - 1;
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
}

/// The coefficients c_ij of Σ c_ij T_i(x) T_j(y) through the values `f[i·(n+1) + j]` at
/// (x_i, y_j), the Lobatto points of degree n along each axis.
pub fn coefficients(f: &[f64], n: usize) -> Vec<f64> {
    let m = n + 1;
    assert_eq!(f.len(), m * m, "a patch of degree {n} has {} values", m * m);
    let cos = cosines(n);
    // along y (each row i), then along x (each column j)
    let mut rows = vec![0.0; m * m];
    for i in 0..m {
        rows[i * m..(i + 1) * m].copy_from_slice(&transform(&f[i * m..(i + 1) * m], &cos));
    }
    let mut c = vec![0.0; m * m];
    for j in 0..m {
        let column: Vec<f64> = (0..m).map(|i| rows[i * m + j]).collect();
        for (i, a) in transform(&column, &cos).into_iter().enumerate() {
            c[i * m + j] = a;
        }
    }
    c
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
