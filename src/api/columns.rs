//! `bouncelab.impacts`' rows written straight into its answer's columns, in two passes (issue
//! 30 item 5). The first pass ([`first_pass`]) answers every element the cheap paths answer —
//! the linear law's closed forms, eight at a time in lanes ([`lanes::summaries`]), and under
//! Hertz and the elastic–plastic law the Hertz table (below yield) — and says which elements
//! are left and by which path ([`Unanswered::elements`], for `work::check_elements`); the
//! second ([`Unanswered::answer`]) runs those, once the work limit allows them. Each row is the
//! one [`super::impact_rows`] gives, bit for bit (tests/physics/rows_columns.rs).

use super::BallError;
use super::rows::{ImpactRow, Rest, flattening_si_row, row_from, si_row, solver_row, table_row};
use crate::analysis::work::Elements;
use crate::map::fast::Summary;
use crate::map::fast::lanes;
use crate::model::contact::ContactLaw;
use crate::model::params::{ImpactParams, Normalized, ParamError};
use crate::solver::SolveError;

/// A ball and its normalized groups.
type Ball = (ImpactParams, Normalized);
use rayon::prelude::*;

mod stoppable;
pub use stoppable::first_pass_stoppable;

/// Elements a task of the first pass takes: a multiple of the lanes' eight, small enough that
/// both cores share 10⁴ elements, large enough that rayon's split costs nothing per element.
const CHUNK: usize = 512;

/// The answer's columns, one entry an element (the arrays of `bouncelab.impacts`' dict).
pub struct Columns<'a> {
    /// The COR e.
    pub cor: &'a mut [f64],
    /// Peak force F_m, N.
    pub max_force: &'a mut [f64],
    /// Contact time t_f, s (NaN: the ball stays at the wall).
    pub contact_time: &'a mut [f64],
    /// Peak indentation z_m, m.
    pub max_indentation: &'a mut [f64],
    /// Permanent indentation z_f, m.
    pub permanent_indentation: &'a mut [f64],
    /// Whether the ball leaves the wall.
    pub rebound: &'a mut [bool],
}

impl Columns<'_> {
    /// Elements: the columns' common length (the shortest, should they differ).
    pub fn len(&self) -> usize {
        [
            self.cor.len(),
            self.max_force.len(),
            self.contact_time.len(),
            self.max_indentation.len(),
            self.permanent_indentation.len(),
            self.rebound.len(),
        ]
        .into_iter()
        .min()
        .unwrap_or(0)
    }

    /// Whether there are no elements.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn put(&mut self, k: usize, row: &ImpactRow) {
        self.cor[k] = row.cor;
        self.max_force[k] = row.max_force;
        self.contact_time[k] = row.contact_time;
        self.max_indentation[k] = row.max_indentation;
        self.permanent_indentation[k] = row.permanent_indentation;
        self.rebound[k] = row.rebound;
    }

    /// The columns in pieces of [`CHUNK`] elements, to fill in parallel (rayon's zip of the
    /// six columns' chunks).
    fn chunks(&mut self) -> impl IndexedParallelIterator<Item = Columns<'_>> {
        let n = self.len();
        (
            self.cor[..n].par_chunks_mut(CHUNK),
            self.max_force[..n].par_chunks_mut(CHUNK),
            self.contact_time[..n].par_chunks_mut(CHUNK),
            self.max_indentation[..n].par_chunks_mut(CHUNK),
            self.permanent_indentation[..n].par_chunks_mut(CHUNK),
            self.rebound[..n].par_chunks_mut(CHUNK),
        )
            .into_par_iter()
            .map(|(cor, f, t, z, z_f, rebound)| Columns {
                cor,
                max_force: f,
                contact_time: t,
                max_indentation: z,
                permanent_indentation: z_f,
                rebound,
            })
    }
}

/// What the first pass left: the elements it did not answer, in order, with the path that
/// will, and the first element that failed there (a ball that is not one, or a linear-law
/// impact no path answers) with its error: no element after it is left to run.
pub struct Unanswered {
    law: ContactLaw,
    n: usize,
    left: Vec<(usize, Rest)>,
    failed: Option<(usize, BallError)>,
}

/// What one task of the first pass left.
struct Part {
    left: Vec<(usize, Rest)>,
    failed: Option<(usize, BallError)>,
}

/// The first pass over the balls `params(0) … params(n − 1)`, `n` the columns' length, on
/// all cores: each ball checked (a [`BallError::Param`] naming the field), each row the cheap
/// paths answer written into `out` — on the linear law every row, as [`super::impact_row`]
/// gives it with the closed forms in lanes (a flattening ball's closed form, the exact
/// solver where neither answers), under Hertz and the elastic–plastic law the Hertz table's
/// (`rows::table_row`) — and the others left to [`Unanswered::answer`].
pub fn first_pass<F>(law: ContactLaw, params: &F, out: &mut Columns<'_>) -> Unanswered
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let n = out.len();
    let parts: Vec<Part> = out
        .chunks()
        .enumerate()
        .map(|(c, mut cols)| match law {
            ContactLaw::Linear => linear_part(c * CHUNK, params, &mut cols),
            _ => table_part(c * CHUNK, law, params, &mut cols),
        })
        .collect();
    // the chunks in order, each one's first failure its lowest index: the first found is the
    // first of all, and no element after it is left to run
    let mut unanswered = Unanswered {
        law,
        n,
        left: Vec::new(),
        failed: None,
    };
    for part in parts {
        if unanswered.failed.is_some() {
            break;
        }
        let stop = part.failed.as_ref().map_or(usize::MAX, |(i, _)| *i);
        let before = part.left.into_iter().take_while(|(i, _)| *i < stop);
        unanswered.left.extend(before);
        unanswered.failed = part.failed;
    }
    unanswered
}

impl Unanswered {
    /// The elements by the path that answers them: the work limit's count
    /// (`work::check_elements`).
    pub fn elements(&self) -> Elements {
        let past_yield = self
            .left
            .iter()
            .filter(|(_, r)| *r == Rest::PastYield)
            .count();
        Elements {
            n: self.n,
            off_table: self.left.len() - past_yield,
            past_yield,
        }
    }

    /// The rows the first pass left, on all cores, written into `out` (the same columns):
    /// `Ok` with every row there, else the first failing element and its error.
    pub fn answer<F>(self, params: &F, out: &mut Columns<'_>) -> Result<(), (usize, BallError)>
    where
        F: Fn(usize) -> ImpactParams + Sync,
    {
        let law = self.law;
        // each chunk's rows in a Vec of its own: one Vec of all the rows would grow as
        // rayon's pieces arrive, each growth paging fresh memory and moving the rows (perf:
        // 6 % of a past-yield element's time in the kernel's page clearing)
        let rows: Vec<Vec<_>> = self
            .left
            .par_chunks(LEFT_CHUNK)
            .map(|chunk| left_rows(chunk, law, params))
            .collect();
        for (&(i, _), row) in self.left.iter().zip(rows.into_iter().flatten()) {
            out.put(i, &row.map_err(|e| (i, BallError::Solve(e)))?);
        }
        self.failed.map_or(Ok(()), Err)
    }
}

/// Elements the second pass hands to one core at a time: enough to keep the Taylor steps'
/// lanes full (`solver::taylor::batch`), few enough to share the work between the cores.
const LEFT_CHUNK: usize = 64;

/// The rows of the elements `left` (indices), each as [`row_from`] gives it: under the Hertz
/// and elastic–plastic laws [`crate::solver::table::summaries`] (the table, else the Taylor
/// steps in lanes: `row_from`'s bits) then `run`'s solver where they do not answer.
fn left_rows<F>(
    left: &[(usize, Rest)],
    law: ContactLaw,
    params: &F,
) -> Vec<Result<ImpactRow, SolveError>>
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let balls: Vec<ImpactParams> = left.iter().map(|&(i, _)| params(i)).collect();
    let norm: Vec<_> = balls.iter().map(ImpactParams::normalized).collect();
    if law == ContactLaw::Linear {
        let rows = balls.iter().zip(&norm);
        return rows.map(|(p, n)| row_from(p, n, law, None)).collect();
    }
    let fast = past_the_table(left, &norm, law);
    balls
        .iter()
        .zip(fast)
        .map(|(p, s)| match s.and_then(|s| si_row(p, s)) {
            Some(row) => Ok(row),
            None => solver_row(p, law),
        })
        .collect()
}

/// [`crate::solver::table::summaries`] of `norm`, the elements of `left`, the same bits
/// without asking the table again where the first pass found the impact past yield
/// ([`Rest::PastYield`]: the table's branch is `None` there, for `rows::table_row` and
/// `solver::table::summary` read it alike): those go to the Taylor steps in lanes at once,
/// and one at a time with more steps where a phase is too stiff for those
/// ([`crate::solver::taylor::stiff_summary`], as `summaries` does).
fn past_the_table(
    left: &[(usize, Rest)],
    norm: &[Normalized],
    law: ContactLaw,
) -> Vec<Option<crate::solver::taylor::Summary>> {
    let past = |k: &usize| left[*k].1 == Rest::PastYield;
    let (yielded, rest): (Vec<usize>, Vec<usize>) = (0..left.len()).partition(past);
    let pick = |ks: &[usize]| ks.iter().map(|&k| norm[k]).collect::<Vec<_>>();
    let mut out = vec![None; left.len()];
    let taylor = crate::solver::taylor::batch::summaries(&pick(&yielded), law);
    let stiff = |(s, &k): (Option<_>, &usize)| {
        s.or_else(|| crate::solver::taylor::stiff_summary(&norm[k], law))
    };
    let taylor: Vec<_> = taylor.into_iter().zip(&yielded).map(stiff).collect();
    let table = crate::solver::table::summaries(&pick(&rest), law);
    for (k, s) in yielded
        .into_iter()
        .zip(taylor)
        .chain(rest.into_iter().zip(table))
    {
        out[k] = s;
    }
    out
}

/// The ball `p` checked, with its normalized groups.
fn checked(p: &ImpactParams) -> Result<crate::model::params::Normalized, ParamError> {
    p.validate().map(|()| p.normalized())
}

/// The linear-law rows of the elements `first …` of `out`: every ball's λ and ζ into the
/// lanes at once ([`lanes::summaries`], [`lanes::summary4`]'s bits; a ball that is not one
/// enters as NaN, a lane whose answer is dropped), then each row from its lane's answer.
fn linear_part<F>(first: usize, params: &F, out: &mut Columns<'_>) -> Part
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let len = out.len();
    let balls: Vec<_> = (first..first + len)
        .map(|i| {
            let p = params(i);
            checked(&p).map(|n| (p, n))
        })
        .collect();
    let (lambda, zeta): (Vec<f64>, Vec<f64>) = balls
        .iter()
        .map(|b| {
            b.as_ref()
                .map_or((f64::NAN, f64::NAN), |(_, n)| (n.lambda, n.zeta))
        })
        .unzip();
    let mut fast = vec![None; len];
    lanes::summaries(&lambda, &zeta, &mut fast);
    let flat = flattening_lanes(&balls, &fast);
    let mut failed = None;
    for (k, ((ball, s), f)) in balls.into_iter().zip(fast).zip(flat).enumerate() {
        let row = ball.map_err(BallError::Param).and_then(|(p, n)| {
            // a flattening ball's row from its lane's answer (`row_from` would ask
            // `flattening_one`, the same bits); where none or no rebound, `row_from` again
            f.and_then(|s| flattening_si_row(&p, &n, s))
                .map_or_else(|| row_from(&p, &n, ContactLaw::Linear, s), Ok)
                .map_err(BallError::Solve)
        });
        match row {
            Ok(row) => out.put(k, &row),
            Err(e) => {
                failed.get_or_insert((first + k, e));
            }
        }
    }
    Part {
        left: Vec::new(),
        failed,
    }
}

/// The flattening closed form's answers for the balls that flatten (as `row_from` decides:
/// no summary without flattening, or its peak past z̄_p), eight at a time in lanes
/// ([`lanes::flattenings`], issue 30 item 2: each lane bit for bit the lone cell's
/// [`lanes::flattening_one`] that `row_from` takes, tests/physics/rows_columns.rs); `None` for the
/// others and where the closed form does not answer.
fn flattening_lanes(
    balls: &[Result<Ball, ParamError>],
    fast: &[Option<Summary>],
) -> Vec<Option<Summary>> {
    let flattens = |k: usize| match &balls[k] {
        Ok((_, n)) => fast[k].is_none_or(|s| s.max_force > n.zp_bar),
        Err(_) => false,
    };
    let which: Vec<usize> = (0..balls.len()).filter(|&k| flattens(k)).collect();
    let mut out = vec![None; balls.len()];
    if which.is_empty() {
        return out;
    }
    let norm: Vec<&Normalized> = which
        .iter()
        .filter_map(|&k| balls[k].as_ref().ok().map(|(_, n)| n))
        .collect();
    let col = |f: fn(&Normalized) -> f64| -> Vec<f64> { norm.iter().map(|n| f(n)).collect() };
    let mut found = vec![None; which.len()];
    lanes::flattenings(
        &col(|n| n.lambda),
        &col(|n| n.zeta),
        &col(|n| n.zp_bar),
        &mut found,
    );
    for (&k, s) in which.iter().zip(found) {
        out[k] = s;
    }
    out
}

/// The Hertz or elastic–plastic rows of the elements `first …` of `out` the Hertz table
/// answers (`rows::table_row`); the others left, with their path.
fn table_part<F>(first: usize, law: ContactLaw, params: &F, out: &mut Columns<'_>) -> Part
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let mut part = Part {
        left: Vec::new(),
        failed: None,
    };
    for k in 0..out.len() {
        let i = first + k;
        let p = params(i);
        match checked(&p) {
            Err(e) => {
                part.failed.get_or_insert((i, BallError::Param(e)));
            }
            Ok(n) => match table_row(&p, &n, law) {
                Ok(row) => out.put(k, &row),
                Err(rest) => part.left.push((i, rest)),
            },
        }
    }
    part
}

impl<'a> Columns<'a> {
    /// The answer's names of the five number columns, in the order [`Columns::from_slices`]
    /// takes them (the keys of `bouncelab.impacts`' dict, with `rebound`).
    pub const NUMBERS: [&'static str; 5] = [
        "cor",
        "max_force",
        "contact_time",
        "max_indentation",
        "permanent_indentation",
    ];

    /// The columns over the five number slices in the order of [`Columns::NUMBERS`] and the
    /// rebound slice: the one place the six are put together (Python's `impacts` and
    /// tests/physics/rows_columns.rs each built them by hand).
    pub fn from_slices(numbers: [&'a mut [f64]; 5], rebound: &'a mut [bool]) -> Columns<'a> {
        let [
            cor,
            max_force,
            contact_time,
            max_indentation,
            permanent_indentation,
        ] = numbers;
        Columns {
            cor,
            max_force,
            contact_time,
            max_indentation,
            permanent_indentation,
            rebound,
        }
    }
}
