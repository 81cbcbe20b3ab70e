//! A Monte Carlo sample's impact ([`super::mc`]): `bouncelab run`'s answer, four balls at once.
//!
//! On the linear law the closed form runs in lanes ([`lanes::summary4`], to 1e-12 of the exact
//! solver) where it answers and the ball does not flatten (z̄_m ≤ z̄_p), the flattening closed
//! form in lanes where it flattens ([`lanes::flattening_lanes4`]); the rest, rare, takes
//! `run`'s other paths one ball at a time. The normalized groups and the SI scales of the four
//! balls are computed side by side in `f64x4`: the operations of
//! [`ImpactParams::normalized`] and [`ImpactParams::omega0`] in the same order, each a single
//! IEEE operation (×, /, √) correctly rounded in a SIMD lane as in a scalar register, so the
//! same bits as one ball at a time (`group_draws_are_the_crates_generator_sample_by_sample`
//! compares a group's samples with [`impact`]'s, which pads a ball to four copies).

use crate::map::fast::Summary;
use crate::map::fast::lanes::{self, LANES};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveError, SolveOptions, simulate};
use wide::f64x4;

/// One sample's answer; `contact_time` NaN where the ball stays at the wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// The COR e.
    pub cor: f64,
    /// Peak force F_m, N.
    pub max_force: f64,
    /// Contact time t_f, s (NaN: no rebound).
    pub contact_time: f64,
}

impl Outcome {
    /// The normalized summary `s` of the ball `p` in SI, as the Monte Carlo scales it:
    /// F = F̄ m v0 ω0, t = τ/ω0.
    pub fn in_si(p: &ImpactParams, s: &Summary) -> Outcome {
        let w0 = p.omega0();
        Outcome {
            cor: s.cor,
            max_force: s.max_force * p.mass * p.v0 * w0,
            contact_time: s.contact_time / w0,
        }
    }
}

/// One impact as `bouncelab run` solves it (COR, F_m, t_f): [`impacts`]' lane 0 with `p` in
/// every lane, so that a ball's answer is the same alone as in any group of four.
pub fn impact(p: &ImpactParams, law: ContactLaw) -> Result<Outcome, SolveError> {
    let [one, ..] = impacts(&[Some(*p); LANES], law);
    one.expect("a ball has its impact")
}

/// The impacts of up to four checked balls (`None`: no ball, no answer) as `bouncelab run`
/// solves them: on the linear law the closed form in lanes ([`lanes::summary4`], to 1e-12 of
/// the exact solver) where it answers and the ball does not flatten (z̄_m ≤ z̄_p), the
/// flattening closed form in lanes ([`lanes::flattening_lanes4`], to 1e-12 of the scalar
/// `map::fast::flattening`) where it flattens and the lanes answer, SI by F = F̄ m v0 ω0 and
/// t = τ/ω0; else `one_by_one`.
pub fn impacts(
    balls: &[Option<ImpactParams>; LANES],
    law: ContactLaw,
) -> [Option<Result<Outcome, SolveError>>; LANES] {
    if law != ContactLaw::Linear {
        return balls
            .each_ref()
            .map(|p| p.as_ref().map(|p| one_by_one(p, law)));
    }
    // a missing ball is NaN in every field: the lanes give it no answer
    let field = |f: fn(&ImpactParams) -> f64| {
        f64x4::new(balls.each_ref().map(|p| p.as_ref().map_or(f64::NAN, f)))
    };
    let (m, k_p, c) = (field(|p| p.mass), field(|p| p.k_p), field(|p| p.damping));
    let (k_r, z_p, v0) = (field(|p| p.k_r), field(|p| p.z_p), field(|p| p.v0));
    // ImpactParams::omega0 and ::normalized's λ, ζ and z̄_p, operation for operation
    let w0 = (k_p / m).sqrt();
    let lambda = k_r / k_p;
    let zeta = (m * k_p).sqrt() / (f64x4::splat(2.0) * c);
    let zp_bar = z_p * w0 / v0;
    let fast = lanes::summary4(lambda.to_array(), zeta.to_array());
    let zp_bar = zp_bar.to_array();
    // the balls that flatten (or that the summary leaves), four at a time in lanes too
    let flattens = |k: usize| !matches!(fast[k], Some(s) if s.max_force <= zp_bar[k]);
    let flat = if (0..LANES).any(|k| balls[k].is_some() && flattens(k)) {
        lanes::flattening_lanes4(lambda.to_array(), zeta.to_array(), zp_bar)
    } else {
        [None; LANES]
    };
    let pick = |f: fn(&Summary) -> f64| f64x4::new(fast.map(|s| s.as_ref().map_or(f64::NAN, f)));
    let max_force = (pick(|s| s.max_force) * m * v0 * w0).to_array();
    let contact_time = (pick(|s| s.contact_time) / w0).to_array();
    std::array::from_fn(|k| {
        let p = balls[k].as_ref()?;
        Some(match (fast[k], flat[k]) {
            (Some(s), _) if s.max_force <= zp_bar[k] => Ok(Outcome {
                cor: s.cor,
                max_force: max_force[k],
                contact_time: contact_time[k],
            }),
            (_, Some(s)) => Ok(Outcome::in_si(p, &s)),
            _ => one_by_one(p, law),
        })
    })
}

/// [`impacts`] of each group of balls, the same answers: under the Hertz and elastic–plastic
/// laws every group's fast paths at once ([`crate::solver::table::summaries`]: the Hertz
/// table, else the Taylor steps several to a SIMD register, `one_by_one`'s bits), then
/// `run`'s solver where they do not answer; the linear law group by group.
pub fn impacts_of_groups(
    groups: &[[Option<ImpactParams>; LANES]],
    law: ContactLaw,
) -> Vec<[Option<Result<Outcome, SolveError>>; LANES]> {
    if law == ContactLaw::Linear {
        return groups.iter().map(|balls| impacts(balls, law)).collect();
    }
    let norm: Vec<_> = groups
        .iter()
        .flatten()
        .flatten()
        .map(ImpactParams::normalized)
        .collect();
    let mut fast = crate::solver::table::summaries(&norm, law).into_iter();
    let solve = |p: &ImpactParams, s: Option<crate::solver::taylor::Summary>| match s
        .filter(|t| t.cor > 0.0)
    {
        Some(t) => Ok(Outcome::in_si(p, &short(t))),
        None => solver_outcome(p, law),
    };
    groups
        .iter()
        .map(|balls| {
            balls
                .each_ref()
                .map(|p| Some(solve(p.as_ref()?, fast.next().flatten())))
        })
        .collect()
}

/// An impact the lanes do not answer: its fast path where one answers (`fast_one`), SI by
/// F = F̄ m v0 ω0 and t = τ/ω0, else `run`'s solver.
fn one_by_one(p: &ImpactParams, law: ContactLaw) -> Result<Outcome, SolveError> {
    if let Some(s) = fast_one(p, law) {
        return Ok(Outcome::in_si(p, &s));
    }
    solver_outcome(p, law)
}

/// The impact of `p` by `run`'s solver with its default options.
fn solver_outcome(p: &ImpactParams, law: ContactLaw) -> Result<Outcome, SolveError> {
    simulate(p, law, &SolveOptions::default()).map(|r| Outcome {
        cor: r.cor,
        max_force: r.max_force,
        contact_time: r.contact_time.unwrap_or(f64::NAN),
    })
}

/// The normalized summary of an impact the lanes do not answer, `None` where `run`'s solver
/// must: on the linear law (a flattening ball) the flattening closed form where it answers
/// (`map::fast::flattening`, tests/physics/map_flatten.rs), else the Taylor steps within their
/// domain (both to 1e-12 of the exact solver, tests/physics/taylor.rs); under the Hertz law the Hertz
/// table, else the Taylor steps (`solver::table::summary`: within 1e-9 of their reference,
/// the Taylor steps without step limit, and of the adaptive solver at its stated precision,
/// docs/numerics.md; `hertz_samples_take_the_table`); under the elastic–plastic law the same
/// dispatch (the Hertz table below yield, the Taylor steps past it, to 1e-9 of the adaptive
/// solver: tests/physics/taylor.rs; tests/cli/cli_mc.rs `elastic_plastic_samples_take_the_fast_path`).
fn fast_one(p: &ImpactParams, law: ContactLaw) -> Option<Summary> {
    let n = p.normalized();
    match law {
        // the scalar closed form, not `lanes::flattening_one`: a flattening ball comes here
        // only where the four lanes handed it back, and a lane of width one hands it back too
        // (the same bits, `None` included: tests/physics/map_flatten_lanes.rs), then asks this very
        // call — the same answer for a kernel's run more (tests/analysis/mc_flattening.rs; 3 797 against
        // 5 581 instructions on such a cell, BENCHMARKS.md "Ninth session")
        ContactLaw::Linear => crate::map::fast::flattening(n.lambda, n.zeta, n.zp_bar)
            .or_else(|| crate::solver::taylor::summary(&n, law).map(short)),
        // e > 0: a ball that leaves (the table and the steps answer only where it does)
        ContactLaw::Hertz | ContactLaw::ElasticPlastic => crate::solver::table::summary(&n, law)
            .filter(|t| t.cor > 0.0)
            .map(short),
    }
}

/// A Taylor summary's COR, F̄_m and τ_f.
fn short(t: crate::solver::taylor::Summary) -> Summary {
    Summary {
        cor: t.cor,
        max_force: t.max_force,
        contact_time: t.contact_time,
    }
}
