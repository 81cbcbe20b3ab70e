//! Correlated spreads of a Monte Carlo (docs/scale.md, "Correlated parameters"): a
//! correlation matrix R over the varied parameters (`--correlate k_p:c=0.5,…`, or a fitted
//! preset's own, `--vary fit`) and its Cholesky factor L (R = L Lᵀ, nalgebra's). A sample
//! draws independent standard normals z, one per varied parameter as without correlation,
//! and uses y = L z: y is standard normal with correlation R. `normal` and `lognormal` take
//! y for their normal variate, so the normal's parameters have correlation R exactly (the
//! lognormal's, that of their logarithms); `uniform` takes U = 2Φ(y) − 1 (a Gaussian copula:
//! the uniforms' rank correlation is (6/π) asin(R/2)).

use super::mc_spec::{McError, Spread, Varied};
use nalgebra::DMatrix;

/// A correlation matrix over a spec's varied parameters (in the spec's order) and its
/// Cholesky factor.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlation {
    /// R, row-major, n × n: symmetric, unit diagonal, positive definite.
    pub matrix: Vec<Vec<f64>>,
    /// The pairs as given, (first, second, ρ), for the reports.
    pub pairs: Vec<(Varied, Varied, f64)>,
    /// L, lower triangular, row-major: R = L Lᵀ.
    lower: Vec<Vec<f64>>,
}

impl Correlation {
    /// R over `vary` with the off-diagonal `pairs` set (the rest 0), checked positive
    /// definite by its Cholesky factorization.
    pub fn new(vary: &[Spread], pairs: Vec<(Varied, Varied, f64)>) -> Result<Correlation, McError> {
        let n = vary.len();
        let index = |v: Varied| vary.iter().position(|s| s.what == v);
        let mut r = DMatrix::<f64>::identity(n, n);
        let mut set = vec![vec![false; n]; n];
        for &(a, b, rho) in &pairs {
            let name = || format!("{}:{}", a.name(), b.name());
            let (Some(i), Some(j)) = (index(a), index(b)) else {
                return Err(McError::Correlate(format!(
                    "{} names a parameter not in --vary",
                    name()
                )));
            };
            if i == j {
                return Err(McError::Correlate(format!(
                    "{} correlates a parameter with itself",
                    name()
                )));
            }
            if !(rho.is_finite() && (-1.0..=1.0).contains(&rho)) {
                return Err(McError::Correlate(format!(
                    "{} = {rho}: a correlation lies in [-1, 1]",
                    name()
                )));
            }
            if set[i][j] {
                return Err(McError::Correlate(format!("{} given twice", name())));
            }
            (set[i][j], set[j][i]) = (true, true);
            (r[(i, j)], r[(j, i)]) = (rho, rho);
        }
        let matrix: Vec<Vec<f64>> = (0..n)
            .map(|i| (0..n).map(|j| r[(i, j)]).collect())
            .collect();
        let chol = r.cholesky().ok_or_else(|| {
            McError::Correlate(
                "the correlation matrix is not positive definite (no set of parameters can be \
                 correlated so): weaken the correlations"
                    .into(),
            )
        })?;
        let l = chol.l();
        let lower = (0..n)
            .map(|i| (0..n).map(|j| l[(i, j)]).collect())
            .collect();
        Ok(Correlation {
            matrix,
            pairs,
            lower,
        })
    }

    /// y = L z over the first `n` entries of `z`, in place (L lower triangular: from the
    /// last row up, each row reads only entries not yet overwritten).
    pub fn apply(&self, z: &mut [f64]) {
        let n = self.lower.len();
        for i in (0..n).rev() {
            z[i] = (0..=i).map(|j| self.lower[i][j] * z[j]).sum();
        }
    }
}

/// `k_p:c=0.5,k_p:k_r=-0.2`: pairs of varied parameters and their correlations.
pub fn parse_correlate(text: &str) -> Result<Vec<(Varied, Varied, f64)>, McError> {
    let mut out = Vec::new();
    for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let syntax = || McError::Correlate(format!("'{item}' is not A:B=RHO (e.g. k_p:c=0.5)"));
        let (names, rho) = item.split_once('=').ok_or_else(syntax)?;
        let (a, b) = names.split_once(':').ok_or_else(syntax)?;
        let param = |s: &str| Varied::parse(s).ok_or_else(|| McError::Unknown(s.trim().into()));
        let rho = rho.trim().parse::<f64>().map_err(|_| syntax())?;
        out.push((param(a)?, param(b)?, rho));
    }
    if out.is_empty() {
        return Err(McError::Correlate("no pair given".into()));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::mc::parse_vary;

    #[test]
    fn cholesky_of_a_pair() {
        let vary = parse_vary("k_p=5%,c=5%,k_r=1%").unwrap();
        let c = Correlation::new(&vary, parse_correlate("k_r:k_p=0.6").unwrap()).unwrap();
        assert_eq!(c.matrix[0][2], 0.6);
        // L = [[1,0,0],[0,1,0],[0.6,0,0.8]]: y₂ = 0.6 z₀ + 0.8 z₂
        let mut z = [1.0, 2.0, 3.0];
        c.apply(&mut z);
        assert_eq!(z[..2], [1.0, 2.0]);
        assert!((z[2] - (0.6 + 0.8 * 3.0)).abs() < 1e-15, "{z:?}");
    }

    #[test]
    fn refused_one_line_each() {
        let vary = parse_vary("k_p=5%,c=5%,k_r=5%").unwrap();
        let bad = |t: &str| Correlation::new(&vary, parse_correlate(t)?).map(|_| ());
        // ρ(k_p,c) = ρ(k_p,k_r) = 0.9 and ρ(c,k_r) = −0.9 is no correlation matrix
        let e = bad("k_p:c=0.9,k_p:k_r=0.9,c:k_r=-0.9").unwrap_err();
        assert!(e.to_string().contains("not positive definite"), "{e}");
        let e = bad("k_p:m=0.5").unwrap_err();
        assert!(e.to_string().contains("not in --vary"), "{e}");
        assert!(
            bad("k_p:c=1.5")
                .unwrap_err()
                .to_string()
                .contains("[-1, 1]")
        );
        assert!(
            bad("k_p:c=0.5,c:k_p=0.2")
                .unwrap_err()
                .to_string()
                .contains("twice")
        );
        assert!(
            bad("k_p:k_p=0.5")
                .unwrap_err()
                .to_string()
                .contains("itself")
        );
        assert!(bad("k_p=0.5").unwrap_err().to_string().contains("A:B=RHO"));
        assert!(matches!(bad("k_q:c=0.5"), Err(McError::Unknown(_))));
    }
}
