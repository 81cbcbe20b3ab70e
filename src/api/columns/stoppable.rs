//! Both passes of `bouncelab.impacts` in blocks, a stop flag read between them (issue 54
//! item 6: Ctrl-C on 10⁷ elements took 3.1 s, the passes running whole): a block of the first
//! pass is some milliseconds on the closed forms or the table, a piece of the second at most
//! [`PIECE`] elements the solvers answer. python/tests/test_interrupt_latency.py.

use super::{Columns, Unanswered, first_pass};
use crate::api::BallError;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;

/// Elements of a first-pass block: 64 of its tasks (`CHUNK`), some 4 ms of linear-law
/// closed forms on one core (0.13 µs an element, BENCHMARKS.md).
const BLOCK: usize = 64 * super::CHUNK;
/// Elements of a second-pass piece: 16 of its tasks (`LEFT_CHUNK`), at most some 0.2 s on
/// two cores where every one runs the adaptive solver (≈ 0.35 ms).
const PIECE: usize = 16 * super::LEFT_CHUNK;

/// [`first_pass`] block by block, `stop()` read after each: `None` once it says stop. The
/// same rows and the same [`Unanswered`] as one pass (`first_pass` answers each element on
/// its own, and its failure is the lowest index's: the blocks are taken in order, none after
/// a failure).
pub fn first_pass_stoppable<F>(
    law: ContactLaw,
    params: &F,
    out: &mut Columns<'_>,
    stop: &dyn Fn() -> bool,
) -> Option<Unanswered>
where
    F: Fn(usize) -> ImpactParams + Sync,
{
    let n = out.len();
    let mut all = Unanswered {
        law,
        n,
        left: Vec::new(),
        failed: None,
    };
    let mut start = 0;
    while start < n && all.failed.is_none() {
        let end = (start + BLOCK).min(n);
        let mut block = Columns {
            cor: &mut out.cor[start..end],
            max_force: &mut out.max_force[start..end],
            contact_time: &mut out.contact_time[start..end],
            max_indentation: &mut out.max_indentation[start..end],
            permanent_indentation: &mut out.permanent_indentation[start..end],
            rebound: &mut out.rebound[start..end],
        };
        let part = first_pass(law, &|i| params(start + i), &mut block);
        all.left
            .extend(part.left.into_iter().map(|(i, r)| (start + i, r)));
        all.failed = part.failed.map(|(i, e)| (start + i, e));
        if stop() {
            return None;
        }
        start = end;
    }
    Some(all)
}

impl Unanswered {
    /// [`Unanswered::answer`] piece by piece, `stop()` read after each: `None` once it says
    /// stop; else the same rows and the same result.
    pub fn answer_stoppable<F>(
        self,
        params: &F,
        out: &mut Columns<'_>,
        stop: &dyn Fn() -> bool,
    ) -> Option<Result<(), (usize, BallError)>>
    where
        F: Fn(usize) -> ImpactParams + Sync,
    {
        for piece in self.left.chunks(PIECE) {
            let part = Unanswered {
                law: self.law,
                n: self.n,
                left: piece.to_vec(),
                failed: None,
            };
            if let Err(e) = part.answer(params, out) {
                return Some(Err(e));
            }
            if stop() {
                return None;
            }
        }
        Some(self.failed.map_or(Ok(()), Err))
    }
}
