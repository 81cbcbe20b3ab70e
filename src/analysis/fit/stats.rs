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

pub fn uncertainty(jac: &DMatrix<f64>, residuals: &[f64]) -> Uncertainty {
    let (n, p) = jac.shape();
    let dof = n.saturating_sub(p);
    let s2 = if dof > 0 {
        residuals.iter().map(|r| r * r).sum::<f64>() / dof as f64
    } else {
        f64::NAN
    };
    // scale columns to unit norm so the condition number is about the parameters' roles,
    // not their units
    let norms: Vec<f64> = (0..p).map(|j| jac.column(j).norm().max(1e-300)).collect();
    let mut scaled = jac.clone();
    for j in 0..p {
        scaled.column_mut(j).scale_mut(1.0 / norms[j]);
    }
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
    // (JᵀJ)⁻¹ = D⁻¹ (SᵀS)⁺ D⁻¹ with S the scaled Jacobian; the pseudo-inverse drops directions
    // the data do not see (their variance is reported as infinite below)
    let sts = scaled.transpose() * &scaled;
    let inv = sts.clone().try_inverse().filter(|_| smax / smin < 1e14);
    let mut cov = DMatrix::from_element(p, p, f64::INFINITY);
    if let Some(inv) = inv {
        for i in 0..p {
            for j in 0..p {
                cov[(i, j)] = s2 * inv[(i, j)] / (norms[i] * norms[j]);
            }
        }
    }
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
    Uncertainty {
        covariance: cov,
        correlation: corr,
        t975: t975(dof),
        condition: smax / smin,
        weakest,
    }
}

/// The 0.975 quantile of Student's t with `dof` degrees of freedom: exact for 1 and 2, the
/// Cornish–Fisher expansion in 1/ν beyond (error below 2e-4 from ν = 3; 12.706, 4.303, 3.182,
/// 2.776, 2.571 … 1.960 in the tables).
pub fn t975(dof: usize) -> f64 {
    match dof {
        0 => f64::NAN,
        1 => 12.706_204_736_174_7,
        2 => 4.302_652_729_749_464,
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
        assert!(u.condition > CONDITION_MAX && u.covariance[(0, 0)].is_infinite());
    }
}
