//! Short power series the closed forms step by where a step is small (`map::fast`'s flow and
//! its lanes, the oblique impact's modes): 1/k! and the Horner sums of eˣ and of
//! (cos x, sin(x)/x), each summed from its highest term so that every caller's degree gives
//! the same bits wherever they share terms.

/// 1/k!, k ≤ 17.
pub(crate) const INV_FACTORIAL: [f64; 18] = {
    let mut c = [1.0; 18];
    let mut k = 1;
    while k < 18 {
        c[k] = c[k - 1] / k as f64;
        k += 1;
    }
    c
};

/// eˣ to x^N: Σ xᵏ/k!, k ≤ N (N ≤ 17).
pub(crate) fn exp_to<const N: usize>(x: f64) -> f64 {
    (0..=N).rev().fold(0.0, |sum, k| sum * x + INV_FACTORIAL[k])
}

/// (cos x, sin(x)/x), each to x^{2N} (N ≤ 8).
pub(crate) fn cos_sinc_to<const N: usize>(x: f64) -> (f64, f64) {
    let x2 = x * x;
    let sign = |k: usize| if k.is_multiple_of(2) { 1.0 } else { -1.0 };
    let cos = (0..=N)
        .rev()
        .fold(0.0, |sum, k| sum * x2 + sign(k) * INV_FACTORIAL[2 * k]);
    let sinc = (0..=N)
        .rev()
        .fold(0.0, |sum, k| sum * x2 + sign(k) * INV_FACTORIAL[2 * k + 1]);
    (cos, sinc)
}
