//! The explorer's fits (`f`) on its one worker type ([`crate::tui::worker::Worker`]): a fit solves the model hundreds of
//! times, which in a debug build takes seconds, so it runs here while the keys go on acting.
//! Only the latest fit asked for is run: one asked before it and not yet started is dropped,
//! and one running stops at its next model run once a later one is asked for (its answer
//! would be superseded anyway, `App` keeps the id of the latest). While a fit runs its
//! progress comes back every [`PROGRESS_EVERY`] (model runs done and seconds: the work
//! budget's `Watch`, issue 29 item 13), then its outcome, each as `Action::FitReady`.

use crate::analysis::work::Watch;
use crate::tui::background::Stopped;
use crate::tui::views::fit::state::{self as measured, FitNews, FitProgress, FitRequest};
use crate::tui::worker::{Job, Worker};
use std::cell::{Cell, RefCell};
use std::time::{Duration, Instant};

/// How often a running fit reports its progress: often enough for a counter that moves, far
/// less often than the loop's 40 ms wake while a fit is out (src/tui/event.rs).
pub const PROGRESS_EVERY: Duration = Duration::from_millis(100);

/// News of a fit: the id of its request and its progress or outcome.
pub type FitReply = (u64, FitNews);

/// The fits' thread: the explorer's one worker type ([`Worker`], issue 55 item 1: the fit had
/// a thread and serving loop of its own) with a fit as its job, its news told by request id.
pub struct FitWorker {
    thread: Worker<PacedFit>,
    every: Duration,
}

/// A fit as the worker runs it: the request and how often its progress goes out.
#[derive(Debug, Clone, PartialEq)]
pub struct PacedFit {
    request: FitRequest,
    every: Duration,
}

impl FitWorker {
    /// The explorer's: progress every [`PROGRESS_EVERY`].
    pub fn spawn() -> std::io::Result<FitWorker> {
        FitWorker::spawn_reporting_every(PROGRESS_EVERY)
    }

    /// Progress at most every `every` (zero: after each model run, so that a test sees it
    /// whatever the build's speed: tests/tui/tui_heavy.rs, whose 200 000-row fit ends within
    /// one [`PROGRESS_EVERY`] when optimised).
    pub fn spawn_reporting_every(every: Duration) -> std::io::Result<FitWorker> {
        Ok(FitWorker {
            thread: Worker::spawn()?,
            every,
        })
    }

    /// Run `request`'s fit; should the thread be gone, `try_recv` says so.
    pub fn want(&mut self, request: FitRequest) {
        let every = self.every;
        self.thread.want(&[PacedFit { request, every }]);
    }

    /// News of a fit if some is waiting, or why the thread is gone.
    pub fn try_recv(&mut self) -> Result<Option<FitReply>, Stopped> {
        let reply = self.thread.try_recv()?;
        // a fit's refusal comes inside its outcome (`FitNews::Done`), never as the job's
        Ok(reply.map(|(paced, news)| {
            (
                paced.request.id,
                news.unwrap_or_else(|e| FitNews::from(Err(e))),
            )
        }))
    }
}

impl Job for PacedFit {
    type Output = FitNews;
    const NAME: &'static str = "fit";

    /// The fit, its progress to `partial` every `every`; it stops at its next
    /// model run once `go_on` says a later fit is asked for, and its outcome (then an
    /// "interrupted" error) still comes back: `App` keeps the id of the latest and drops it.
    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        partial: &mut dyn FnMut(FitNews),
    ) -> Option<Result<FitNews, String>> {
        let start = Instant::now();
        let watch = Reporter {
            go_on: RefCell::new(go_on),
            partial: RefCell::new(partial),
            start,
            last: Cell::new(start),
            every: self.every,
        };
        Some(Ok(FitNews::Done(measured::run_watched(
            &self.request,
            &watch,
        ))))
    }
}

/// The watch of one fit on the worker: its progress to the loop every `every`, and a stop
/// once a later fit is asked for.
struct Reporter<'a> {
    go_on: RefCell<&'a mut dyn FnMut() -> bool>,
    partial: RefCell<&'a mut dyn FnMut(FitNews)>,
    start: Instant,
    last: Cell<Instant>,
    every: Duration,
}

impl Watch for Reporter<'_> {
    fn step(&self, done: u64) -> bool {
        let now = Instant::now();
        if now.duration_since(self.last.get()) >= self.every {
            self.last.set(now);
            let p = FitProgress {
                runs: done,
                seconds: now.duration_since(self.start).as_secs_f64(),
            };
            (self.partial.borrow_mut())(FitNews::Progress(p));
        }
        (self.go_on.borrow_mut())()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::{CorTable, Data};
    use crate::preset::Preset;
    use crate::tui::views::fit::state::{Loaded, request};
    use std::thread;
    use std::time::{Duration, Instant};

    /// A running fit goes on while `go_on` says it is wanted and stops at its next model run
    /// once it is not; its progress goes out at most every PROGRESS_EVERY.
    #[test]
    fn the_reporter_stops_a_superseded_fit_and_reports_progress() {
        let mut news = Vec::new();
        let wanted_now = Cell::new(true);
        let mut go_on = || wanted_now.get();
        let mut partial = |n: FitNews| news.push(n);
        let long_ago = Instant::now() - 2 * PROGRESS_EVERY;
        let r = Reporter {
            go_on: RefCell::new(&mut go_on),
            partial: RefCell::new(&mut partial),
            start: long_ago,
            last: Cell::new(long_ago),
            every: PROGRESS_EVERY,
        };
        assert!(r.step(10));
        assert!(r.step(11), "no report so soon after the last");
        wanted_now.set(false);
        assert!(!r.step(12), "a later fit asked for stops this one");
        let [FitNews::Progress(p)] = news.as_slice() else {
            panic!("not one progress report: {news:?}")
        };
        assert_eq!(p.runs, 10);
        assert!(p.seconds >= PROGRESS_EVERY.as_secs_f64() * 2.0);
    }

    #[test]
    fn a_fit_comes_back_with_its_id() {
        let ball = Preset::embedded()[0].clone();
        let table = CorTable::parse("v0,cor\n1,0.8\n2,0.75\n3,0.7\n").unwrap();
        let loaded = Loaded {
            path: "t.csv".into(),
            label: "t.csv".into(),
            data: Data::Cor(table),
        };
        let r = request(7, &loaded, &ball.params(), ball.law).unwrap();
        let mut w = FitWorker::spawn().unwrap();
        w.want(r.clone());
        let start = Instant::now();
        let (id, outcome) = loop {
            if let Ok(Some((id, FitNews::Done(o)))) = w.try_recv() {
                break (id, o);
            }
            assert!(start.elapsed() < Duration::from_secs(120), "no reply");
            thread::sleep(Duration::from_millis(5));
        };
        assert_eq!(id, 7);
        assert_eq!(outcome, measured::run(&r));
    }
}
