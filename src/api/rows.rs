//! Many impacts at array speed (issue 30 item 5, Python's `bouncelab.impacts`): each row the
//! answer `run` gives for its parameters, without the report's extras (history, energy
//! budget, warnings), so that a linear-law row costs the closed form of [`crate::map::fast`].

use super::BallError;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveError, SolveOptions, simulate};
use rayon::prelude::*;

/// One impact's numbers, SI: what `bouncelab run` reports under the same names.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactRow {
    /// The COR e.
    pub cor: f64,
    /// Peak force F_m, N.
    pub max_force: f64,
    /// Contact time t_f, s (NaN: the ball stays at the wall).
    pub contact_time: f64,
    /// Peak indentation z_m, m.
    pub max_indentation: f64,
    /// Permanent indentation z_f, m (0 without flattening).
    pub permanent_indentation: f64,
    /// Whether the ball leaves the wall.
    pub rebound: bool,
}

/// The impact of `p` under `law`, as `run` solves it: on the linear law the closed form while
/// the ball does not flatten (F̄_m ≤ z̄_p; then z_m = F_m / K_p, the contact being the spring
/// K_p, docs/model.md §3, and no permanent indentation), else the solver with its default
/// options. tests/rows.rs holds the two paths to each other.
pub fn impact_row(p: &ImpactParams, law: ContactLaw) -> Result<ImpactRow, SolveError> {
    if law == ContactLaw::Linear {
        let n = p.normalized();
        if let Some(s) = crate::map::fast::summary(n.lambda, n.zeta)
            && s.max_force <= n.zp_bar
            && s.cor > 0.0
        {
            let w0 = p.omega0();
            let max_force = s.max_force * p.mass * p.v0 * w0;
            return Ok(ImpactRow {
                cor: s.cor,
                max_force,
                contact_time: s.contact_time / w0,
                max_indentation: max_force / p.k_p,
                permanent_indentation: 0.0,
                rebound: true,
            });
        }
    }
    let r = simulate(p, law, &SolveOptions::default())?;
    Ok(ImpactRow {
        cor: r.cor,
        max_force: r.max_force,
        contact_time: r.contact_time.unwrap_or(f64::NAN),
        max_indentation: r.max_indentation,
        permanent_indentation: r.permanent_indentation,
        rebound: r.rebound,
    })
}

/// The rows of the balls `params(0) … params(n − 1)` on all cores, each ball checked first
/// (a [`BallError::Param`] naming the field) and solved by [`impact_row`]; on failure the
/// first failing index and its error, whatever the threads did (the rows are scanned again
/// in order to find it). The caller applies the work limit
/// ([`crate::analysis::work::check_samples`]).
pub fn impact_rows<F>(
    n: usize,
    law: ContactLaw,
    params: F,
) -> Result<Vec<ImpactRow>, (usize, BallError)>
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let one = |i: usize| -> Result<ImpactRow, BallError> {
        let p = params(i);
        p.validate().map_err(BallError::Param)?;
        impact_row(&p, law).map_err(BallError::Solve)
    };
    let rows: Result<Vec<ImpactRow>, ()> = (0..n)
        .into_par_iter()
        .map(|i| one(i).map_err(|_| ()))
        .collect();
    rows.map_err(|()| {
        (0..n)
            .find_map(|i| one(i).err().map(|e| (i, e)))
            .unwrap_or((0, BallError::NoValue("a failing row")))
    })
}
