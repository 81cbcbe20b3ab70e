//! Uncertainty of a least-squares fit from the Jacobian at the minimum: cov = s² (JᵀJ)⁻¹ with
//! s² = Σr²/(n − p) (the residual variance), Student-t intervals with n − p degrees of
//! freedom, correlations, and which parameter the data cannot pin (a near-zero singular value
//! of the column-scaled Jacobian).

use nalgebra::DMatrix;

/// Covariance and what it says.
#[derive(Debug, Clone)]
pub struct Uncertainty {
    /// s² (JᵀJ)⁺, NaN throughout when there is no degree of freedom left.
    pub covariance: DMatrix<f64>,
    /// cov_ij / √(cov_ii cov_jj), in [−1, 1].
    pub correlation: DMatrix<f64>,
    /// t quantile 0.975 at n − p degrees of freedom (NaN when n = p).
    pub t975: f64,
    /// Ratio of largest to smallest singular value of J with unit-norm columns.
    pub condition: f64,
    /// Variable that dominates the smallest singular direction.
    pub weakest: usize,
}

/// Above this condition number (of the column-scaled Jacobian) a combination of parameters
/// changes the residuals by less than 1e-8 of what the others do: not identifiable.
pub const CONDITION_MAX: f64 = 1e8;

/// Where a fit's scale of the residuals comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spread {
    /// Estimated from the residuals: s² = Σr²/(n − p), Student's t at n − p.
    Residuals,
    /// Estimated kind by kind (a COR table with forces or contact times): s² as above, the
    /// residuals already divided by their kind's scatter, Student's t at these degrees of
    /// freedom.
    Kinds(usize),
    /// Every residual divided by its stated standard deviation (`cor_sd` on every row): the
    /// covariance (JᵀJ)⁻¹ not rescaled (s² = 1) and the normal quantile 1.96, as SciPy's
    /// `curve_fit(..., absolute_sigma=True)`; with degrees of freedom left (else as
    /// `Residuals`: an exact solve). docs/fitting.md, tests/analysis/fit_stated_sd.rs.
    Stated,
}

/// The 0.975 quantile of the standard normal distribution.
pub const Z975: f64 = 1.959_963_984_540_054;

/// The uncertainty of a least-squares minimum from its Jacobian `jac` (one row a residual, one
/// column a variable) and its `residuals`, with n − p degrees of freedom.
pub fn uncertainty(jac: &DMatrix<f64>, residuals: &[f64]) -> Uncertainty {
    uncertainty_by(jac, residuals, Spread::Residuals)
}

/// [`uncertainty`] with the scale of the residuals from `spread`.
pub fn uncertainty_by(jac: &DMatrix<f64>, residuals: &[f64], spread: Spread) -> Uncertainty {
    let (n, p) = jac.shape();
    let dof = n.saturating_sub(p);
    let stated = spread == Spread::Stated && dof > 0;
    let s2 = if stated {
        1.0
    } else if dof > 0 {
        residuals.iter().map(|r| r * r).sum::<f64>() / dof as f64
    } else {
        f64::NAN
    };
    // scale columns to unit norm so the condition number is about the parameters' roles,
    // not their units
    let norms: Vec<f64> = (0..p).map(|j| jac.column(j).norm().max(1e-300)).collect();
    let mut scaled = jac.clone();
    for (j, norm) in norms.iter().enumerate() {
        scaled.column_mut(j).scale_mut(1.0 / norm);
    }
    let (condition, weakest) = conditioning(&scaled);
    let cov = covariance(&scaled, &norms, s2);
    Uncertainty {
        correlation: correlation(&cov),
        covariance: cov,
        t975: match spread {
            Spread::Kinds(d) => t975(d),
            _ if stated => Z975,
            _ => t975(dof),
        },
        condition,
        weakest,
    }
}

/// The condition number of the column-scaled Jacobian `scaled` (largest over smallest
/// singular value), and the variable that dominates its smallest singular direction.
fn conditioning(scaled: &DMatrix<f64>) -> (f64, usize) {
    let p = scaled.ncols();
    let svd = scaled.clone().svd(false, true);
    let sv = &svd.singular_values;
    let (imin, smin) =
        sv.iter().enumerate().fold(
            (0, f64::INFINITY),
            |a, (i, &s)| if s < a.1 { (i, s) } else { a },
        );
    let smax = sv.iter().cloned().fold(0.0, f64::max);
    let weakest = svd.v_t.as_ref().map_or(0, |vt| {
        (0..p).fold(0, |b, j| {
            if vt[(imin, j)].abs() > vt[(imin, b)].abs() {
                j
            } else {
                b
            }
        })
    });
    (smax / smin, weakest)
}

/// s² (JᵀJ)⁻¹ from the column-scaled Jacobian `scaled` and its columns' `norms`:
/// (JᵀJ)⁻¹ = D⁻¹ (SᵀS)⁻¹ D⁻¹ with S the scaled Jacobian. When a direction is not seen by
/// the data, the variable that dominates it gets an infinite variance and the others the
/// covariance they have with it held (conditional on it), from the rest of the matrix.
fn covariance(scaled: &DMatrix<f64>, norms: &[f64], s2: f64) -> DMatrix<f64> {
    let (n, p) = scaled.shape();
    let mut keep: Vec<usize> = (0..p).collect();
    let mut cov = DMatrix::from_element(p, p, f64::INFINITY);
    while !keep.is_empty() {
        let sub = DMatrix::from_fn(n, keep.len(), |i, j| scaled[(i, keep[j])]);
        let sv = sub.clone().svd(false, true);
        let (lo, hi) = sv
            .singular_values
            .iter()
            .fold((f64::INFINITY, 0.0f64), |a, &s| (a.0.min(s), a.1.max(s)));
        if hi / lo < CONDITION_MAX {
            if let Some(inv) = (sub.transpose() * &sub).try_inverse() {
                for (a, &i) in keep.iter().enumerate() {
                    for (b, &j) in keep.iter().enumerate() {
                        cov[(i, j)] = s2 * inv[(a, b)] / (norms[i] * norms[j]);
                    }
                }
            }
            break;
        }
        // drop the variable that dominates the smallest singular direction
        let vt = sv.v_t.as_ref();
        let imin = sv.singular_values.iter().enumerate().fold(0, |b, (i, &s)| {
            if s < sv.singular_values[b] { i } else { b }
        });
        let worst = (0..keep.len()).fold(0, |b, j| match vt {
            Some(vt) if vt[(imin, j)].abs() > vt[(imin, b)].abs() => j,
            _ => b,
        });
        keep.remove(worst);
    }
    cov
}

/// cov_ij / √(cov_ii cov_jj), clamped to [−1, 1]; 1 on the diagonal, NaN where not finite.
fn correlation(cov: &DMatrix<f64>) -> DMatrix<f64> {
    let p = cov.nrows();
    let mut corr = DMatrix::from_element(p, p, f64::NAN);
    for i in 0..p {
        for j in 0..p {
            let c = cov[(i, j)] / (cov[(i, i)] * cov[(j, j)]).sqrt();
            corr[(i, j)] = if i == j {
                1.0
            } else if c.is_finite() {
                c.clamp(-1.0, 1.0)
            } else {
                f64::NAN
            };
        }
    }
    corr
}

/// The 0.975 quantile of Student's t with `dof` degrees of freedom: tabulated up to 10, the
/// Cornish–Fisher expansion in 1/ν beyond (error below 1e-4 from ν = 11).
pub fn t975(dof: usize) -> f64 {
    const TABLE: [f64; 10] = [
        12.706_204_736_174_7,
        4.302_652_729_749_46,
        3.182_446_305_283_71,
        2.776_445_105_197_79,
        2.570_581_835_636_31,
        2.446_911_851_144_97,
        2.364_624_251_592_78,
        2.306_004_135_204_17,
        2.262_157_162_798_2,
        2.228_138_851_986_27,
    ];
    match dof {
        0 => f64::NAN,
        1..=10 => TABLE[dof - 1],
        _ => {
            let z: f64 = 1.959_963_984_540_054;
            let v = dof as f64;
            let (z3, z5, z7) = (z.powi(3), z.powi(5), z.powi(7));
            z + (z3 + z) / (4.0 * v)
                + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v)
                + (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * v.powi(3))
                + (79.0 * z.powi(9) + 776.0 * z7 + 1482.0 * z5 - 1920.0 * z3 - 945.0 * z)
                    / (92160.0 * v.powi(4))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_quantiles_match_the_tables() {
        for (dof, t) in [
            (1, 12.706),
            (2, 4.303),
            (3, 3.182),
            (4, 2.776),
            (5, 2.571),
            (6, 2.447),
            (10, 2.228),
            (30, 2.042),
            (1000, 1.962),
        ] {
            assert!(
                (t975(dof) - t).abs() < 1.5e-3,
                "{dof}: {} vs {t}",
                t975(dof)
            );
        }
    }

    /// A straight line y = a + b x: the covariance is the textbook s² (XᵀX)⁻¹; a column
    /// repeated is flagged as not identifiable.
    #[test]
    fn line_fit_covariance_and_a_repeated_column() {
        let x = [0.0, 1.0, 2.0, 3.0];
        let jac = DMatrix::from_fn(4, 2, |i, j| if j == 0 { 1.0 } else { x[i] });
        let r = [0.1, -0.1, -0.1, 0.1];
        let u = uncertainty(&jac, &r);
        // XᵀX = [[4, 6], [6, 14]], det 20: inverse [[0.7, -0.3], [-0.3, 0.2]]; s² = 0.04/2
        assert!((u.covariance[(0, 0)] - 0.02 * 0.7).abs() < 1e-12);
        assert!((u.covariance[(0, 1)] + 0.02 * 0.3).abs() < 1e-12);
        assert!(u.condition < 10.0);
        let jac = DMatrix::from_fn(4, 2, |_, _| 1.0);
        let u = uncertainty(&jac, &r);
        assert!(u.condition > CONDITION_MAX);
        // one of the two is dropped (infinite variance), the other has the variance it has
        // with its twin held: s²/4
        let (a, b) = (u.covariance[(0, 0)], u.covariance[(1, 1)]);
        assert!(a.is_infinite() != b.is_infinite(), "{a} {b}");
        assert!((a.min(b) - 0.02 / 4.0).abs() < 1e-12, "{a} {b}");
    }
}
