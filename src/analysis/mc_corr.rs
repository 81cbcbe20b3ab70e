//! Correlated spreads of a Monte Carlo (docs/scale.md, "Correlated parameters"): a
//! correlation matrix R over the varied parameters (`--correlate k_p:c=0.5,…`, or a fitted
//! preset's own, `--vary fit`) and its Cholesky factor L (R = L Lᵀ, nalgebra's). A sample
//! draws independent standard normals z, one per varied parameter as without correlation,
//! and uses y = L z: y is standard normal with correlation R. `normal` and `lognormal` take
//! y for their normal variate, so the normal's parameters have correlation R exactly (the
//! lognormal's, that of their logarithms); `uniform` takes U = 2Φ(y) − 1 (a Gaussian copula:
//! the uniforms' rank correlation is (6/π) asin(R/2)). The matrix and its factor are
//! [`super::mc_spec::Correlation`] (the spec holds it); this file reads `--correlate`.

use super::mc_spec::{McError, Varied};

/// `k_p:c=0.5,k_p:k_r=-0.2`: pairs of varied parameters and their correlations.
pub fn parse_correlate(text: &str) -> Result<Vec<(Varied, Varied, f64)>, McError> {
    let mut out = Vec::new();
    for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        let syntax = || McError::Correlate(format!("'{item}' is not A:B=RHO (e.g. k_p:c=0.5)"));
        let (names, rho) = item.split_once('=').ok_or_else(syntax)?;
        let (a, b) = names.split_once(':').ok_or_else(syntax)?;
        let param = |s: &str| Varied::parse(s).ok_or_else(|| McError::Unknown(s.trim().into()));
        // the command line's reader: a ρ of 1e-400 is refused, never read as 0
        let rho = crate::text::parse::read(rho).map_err(|_| syntax())?;
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
    use crate::analysis::mc::{Correlation, parse_vary};

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
