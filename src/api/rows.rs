//! Many impacts at array speed (issue 30 item 5, Python's `bouncelab.impacts`): each row the
//! answer `run` gives for its parameters, without the report's extras (history, energy
//! budget, warnings), so that a linear-law row costs the closed form of [`crate::map::fast`].

use super::BallError;
use crate::map::fast::Summary;
use crate::map::fast::lanes::{self, LANES};
use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::{ImpactParams, Normalized};
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
/// K_p, docs/model.md §3, and no permanent indentation) and the flattening's closed form when
/// it does (both to 1e-12 of `run`); under Hertz the Hertz table, then the Taylor steps
/// (within 1e-9 of their reference and of `run` at its solver's stated precision,
/// docs/numerics.md); under the elastic–plastic law the same (`solver::table::summary`: the
/// Hertz table below yield, the Taylor steps past it); else the solver with its default
/// options. tests/physics/rows.rs holds each path to `run`.
pub fn impact_row(p: &ImpactParams, law: ContactLaw) -> Result<ImpactRow, SolveError> {
    let n = p.normalized();
    let fast = if law == ContactLaw::Linear {
        crate::map::fast::summary(n.lambda, n.zeta)
    } else {
        None
    };
    row_from(p, &n, law, fast)
}

/// [`impact_row`] of `p`, whose normalized groups are `n`, with the closed form's answer for
/// it given (`None`: none, or not the linear law).
pub(super) fn row_from(
    p: &ImpactParams,
    n: &Normalized,
    law: ContactLaw,
    fast: Option<Summary>,
) -> Result<ImpactRow, SolveError> {
    if law == ContactLaw::Linear {
        if let Some(s) = fast
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
        let flattens = fast.is_none_or(|s| s.max_force > n.zp_bar);
        if let Some(row) = flattens.then(|| flattening_row(p, n)).flatten() {
            return Ok(row);
        }
    }
    if matches!(law, ContactLaw::Hertz | ContactLaw::ElasticPlastic)
        && let Some(row) = power_law_row(p, n, law)
    {
        return Ok(row);
    }
    solver_row(p, law)
}

/// The row of `p` from `run`'s solver with its default options (no fast path).
pub(super) fn solver_row(p: &ImpactParams, law: ContactLaw) -> Result<ImpactRow, SolveError> {
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

/// A Hertz or elastic–plastic row from `solver::table::summary` (the Hertz table — under the
/// elastic–plastic law where the impact stays below yield — else the Taylor steps), SI as
/// `run` converts (F = F̄ m v0 ω0, t = τ/ω0, z = z̄ v0/ω0, z_f too); `None` where neither
/// answers or the ball does not leave (then `simulate`). Not `run`'s bits: the table is
/// within 1e-9 of its reference, the Taylor steps without step limit, and both of the
/// adaptive solver `run` takes at that solver's stated precision (docs/numerics.md;
/// tests/physics/rows.rs `a_hertz_row_is_the_tables_answer`,
/// `an_elastic_plastic_row_is_the_fast_paths_answer`).
fn power_law_row(p: &ImpactParams, n: &Normalized, law: ContactLaw) -> Option<ImpactRow> {
    si_row(p, crate::solver::table::summary(n, law)?)
}

/// The row of `p` from the normalized summary `s` of its Hertz or elastic–plastic impact,
/// SI as `run` converts (F = F̄ m v0 ω0, t = τ/ω0, z = z̄ v0/ω0, z_f too); `None` where the
/// ball does not leave (then `simulate`).
pub(super) fn si_row(p: &ImpactParams, s: crate::solver::taylor::Summary) -> Option<ImpactRow> {
    if s.cor <= 0.0 {
        return None;
    }
    let w0 = p.omega0();
    Some(ImpactRow {
        cor: s.cor,
        max_force: s.max_force * p.mass * p.v0 * w0,
        contact_time: s.contact_time / w0,
        max_indentation: s.max_indentation * p.v0 / w0,
        permanent_indentation: s.permanent_indentation * p.v0 / w0,
        rebound: true,
    })
}

/// What answers a Hertz or elastic–plastic element the Hertz table does not
/// (`table_row`): the work limit counts it by that path (`work::Elements`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rest {
    /// An elastic–plastic impact whose Hertz impact the table holds but which reaches yield
    /// (within `taylor::plastic::YIELD_MARGIN`): the Taylor steps answer.
    PastYield,
    /// Outside the table, or a table answer without a rebound: the Taylor steps or the
    /// adaptive solver answer.
    Whole,
}

/// The row of `p` (normalized groups `n`) under Hertz or the elastic–plastic law where the
/// Hertz table answers it — `solver::table::summary`'s first branch, the table under Hertz
/// and below yield under the elastic–plastic law (`taylor::plastic::below_yield`) — so
/// [`impact_row`]'s row bit for bit; else which path will ([`Rest`]).
pub(super) fn table_row(
    p: &ImpactParams,
    n: &Normalized,
    law: ContactLaw,
) -> Result<ImpactRow, Rest> {
    let hertz = (n.zp_bar > 0.0)
        .then(|| crate::solver::table::hertz(n))
        .flatten()
        .ok_or(Rest::Whole)?;
    let s = match law {
        ContactLaw::ElasticPlastic => {
            crate::solver::taylor::plastic::below_yield(n, hertz).ok_or(Rest::PastYield)?
        }
        _ => hertz,
    };
    si_row(p, s).ok_or(Rest::Whole)
}

/// The row of a linear-law ball that flattens (F̄_m > z̄_p), from the closed form on one lane
/// ([`crate::map::fast::lanes::flattening_one`]: the lanes' answer, as `first_pass` takes it
/// eight at a time, else the scalar closed form's; to 1e-12 of the exact solver,
/// tests/physics/map_flatten.rs, tests/physics/map_flatten_lanes.rs) by [`flattening_si_row`]. `None` where
/// the closed form does not answer or the ball does not leave: the solver answers.
fn flattening_row(p: &ImpactParams, n: &Normalized) -> Option<ImpactRow> {
    let s = crate::map::fast::lanes::flattening_one(n.lambda, n.zeta, n.zp_bar)?;
    flattening_si_row(p, n, s)
}

/// The flattening closed form's answer `s` for the ball `p` as a row, in SI as `run` scales
/// its answer (docs/model.md §5: force m v0 ω0, length v0/ω0, time 1/ω0): F_m = F̄_m m v0 ω0,
/// z_m = z̄_m v0/ω0 (F̄ = z̄ on loading), z_f from z̄_f by Eqs. 18–19 (the contact's
/// `permanent_indentation`, as the exact solver takes it). `None` where the ball does not
/// leave (e ≤ 0).
pub(super) fn flattening_si_row(p: &ImpactParams, n: &Normalized, s: Summary) -> Option<ImpactRow> {
    let zp_bar = n.zp_bar;
    let s = Some(s).filter(|s| s.cor > 0.0)?;
    let contact = Contact {
        law: ContactLaw::Linear,
        zp_bar,
        kappa: 1.0,
    };
    let w0 = p.omega0();
    let length = p.v0 / w0;
    Some(ImpactRow {
        cor: s.cor,
        max_force: s.max_force * (p.mass * p.v0 * w0),
        contact_time: s.contact_time / w0,
        max_indentation: s.max_force * length,
        permanent_indentation: contact.permanent_indentation(s.max_force) * length,
        rebound: true,
    })
}

/// The rows of balls `first … first + 3` (past `last`: `last` again, a copy the caller
/// drops), each checked, the linear law's closed forms four at once
/// ([`lanes::summary4`], to 1e-12 of [`crate::map::fast::summary`], or of the exact solver
/// where the scalar path's rounding bound refuses: tests/physics/map_lanes.rs).
fn four_rows<F>(
    first: usize,
    last: usize,
    law: ContactLaw,
    params: &F,
) -> [Result<ImpactRow, BallError>; LANES]
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let balls: [ImpactParams; LANES] = std::array::from_fn(|k| params((first + k).min(last)));
    let checked = balls.map(|p| p.validate().map(|()| p));
    let fast = if law == ContactLaw::Linear {
        let n = checked
            .each_ref()
            .map(|p| p.as_ref().ok().map(ImpactParams::normalized));
        let pick = |f: fn(&Normalized) -> f64| n.map(|n| n.as_ref().map_or(f64::NAN, f));
        lanes::summary4(pick(|n| n.lambda), pick(|n| n.zeta))
    } else {
        [None; LANES]
    };
    let mut fast = fast.into_iter();
    checked.map(|p| {
        let s = fast.next().flatten();
        let p = p.map_err(BallError::Param)?;
        row_from(&p, &p.normalized(), law, s).map_err(BallError::Solve)
    })
}

/// The rows of the balls `params(0) … params(n − 1)` on all cores, four at a time, each ball
/// checked first (a [`BallError::Param`] naming the field) and solved as [`impact_row`]
/// solves it, the closed forms in lanes (to 1e-12 of it); on failure the first failing index
/// and its error, whatever the threads did (the rows are kept in order). The caller applies
/// the work limit ([`crate::analysis::work::check_samples`]).
pub fn impact_rows<F>(
    n: usize,
    law: ContactLaw,
    params: F,
) -> Result<Vec<ImpactRow>, (usize, BallError)>
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    if n == 0 {
        return Ok(Vec::new());
    }
    let groups: Vec<[Result<ImpactRow, BallError>; LANES]> = (0..n.div_ceil(LANES))
        .into_par_iter()
        .map(|g| four_rows(g * LANES, n - 1, law, &params))
        .collect();
    let mut rows = Vec::with_capacity(n);
    for (i, r) in groups.into_iter().flatten().take(n).enumerate() {
        rows.push(r.map_err(|e| (i, e))?);
    }
    Ok(rows)
}
