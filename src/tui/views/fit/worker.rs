//! A background thread for the explorer's fits (`f`): a fit solves the model hundreds of
//! times, which in a debug build takes seconds, so it runs here while the keys go on acting.
//! Only the latest fit asked for is run: one asked before it and not yet started is dropped,
//! and one running stops at its next model run once a later one is asked for (its answer
//! would be superseded anyway, `App` keeps the id of the latest). While a fit runs its
//! progress comes back every [`PROGRESS_EVERY`] (model runs done and seconds: the work
//! budget's `Watch`, issue 29 item 13), then its outcome, each as `Action::FitReady`.

use crate::analysis::work::Watch;
use crate::tui::background::{Background, Stopped};
use crate::tui::views::fit::state::{self as measured, FitNews, FitProgress, FitRequest};
use std::cell::Cell;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, Sender};
use std::time::{Duration, Instant};

/// How often a running fit reports its progress: often enough for a counter that moves, far
/// less often than the loop's 40 ms wake while a fit is out (src/tui/event.rs).
pub const PROGRESS_EVERY: Duration = Duration::from_millis(100);

/// News of a fit: the id of its request and its progress or outcome.
pub type FitReply = (u64, FitNews);

pub struct FitWorker {
    thread: Background<FitRequest, FitReply>,
    /// The id of the latest fit asked for: a running fit of another id stops.
    latest: Arc<AtomicU64>,
}

impl FitWorker {
    pub fn spawn() -> std::io::Result<FitWorker> {
        let latest = Arc::new(AtomicU64::new(0));
        let seen = Arc::clone(&latest);
        let thread = Background::spawn("fit", move |inbox, outbox| serve(inbox, outbox, &seen))?;
        Ok(FitWorker { thread, latest })
    }

    /// Run `request`'s fit; should the thread be gone, `try_recv` says so.
    pub fn want(&self, request: FitRequest) {
        self.latest.store(request.id, Ordering::Relaxed);
        self.thread.send(request);
    }

    /// News of a fit if some is waiting, or why the thread is gone.
    pub fn try_recv(&mut self) -> Result<Option<FitReply>, Stopped> {
        self.thread.try_recv()
    }
}

/// The watch of one fit on the worker: its progress to the loop every [`PROGRESS_EVERY`], and
/// a stop once a later fit is asked for.
struct Reporter<'a> {
    id: u64,
    outbox: &'a Sender<FitReply>,
    latest: &'a AtomicU64,
    start: Instant,
    last: Cell<Instant>,
}

impl Watch for Reporter<'_> {
    fn step(&self, done: u64) -> bool {
        let now = Instant::now();
        if now.duration_since(self.last.get()) >= PROGRESS_EVERY {
            self.last.set(now);
            let p = FitProgress {
                runs: done,
                seconds: now.duration_since(self.start).as_secs_f64(),
            };
            // a closed channel: the explorer is gone, the answer is nobody's
            let _ = self.outbox.send((self.id, FitNews::Progress(p)));
        }
        self.latest.load(Ordering::Relaxed) == self.id
    }
}

fn serve(inbox: &Receiver<FitRequest>, outbox: &Sender<FitReply>, latest: &AtomicU64) {
    while let Ok(mut request) = inbox.recv() {
        // the latest of those waiting
        while let Ok(later) = inbox.try_recv() {
            request = later;
        }
        let start = Instant::now();
        let watch = Reporter {
            id: request.id,
            outbox,
            latest,
            start,
            last: Cell::new(start),
        };
        let outcome = measured::run_watched(&request, &watch);
        if outbox.send((request.id, FitNews::Done(outcome))).is_err() {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::{CorTable, Data};
    use crate::preset::Preset;
    use crate::tui::views::fit::state::{Loaded, request};
    use std::sync::mpsc;
    use std::thread;
    use std::time::{Duration, Instant};

    /// A running fit goes on while it is the latest asked for and stops at its next model
    /// run once another is; its progress goes out at most every PROGRESS_EVERY.
    #[test]
    fn the_reporter_stops_a_superseded_fit_and_reports_progress() {
        let (outbox, replies) = mpsc::channel();
        let latest = AtomicU64::new(3);
        let long_ago = Instant::now() - 2 * PROGRESS_EVERY;
        let r = Reporter {
            id: 3,
            outbox: &outbox,
            latest: &latest,
            start: long_ago,
            last: Cell::new(long_ago),
        };
        assert!(r.step(10));
        assert!(r.step(11), "no report so soon after the last");
        let Ok((3, FitNews::Progress(p))) = replies.try_recv() else {
            panic!("no progress report")
        };
        assert_eq!(p.runs, 10);
        assert!(p.seconds >= PROGRESS_EVERY.as_secs_f64() * 2.0);
        assert!(replies.try_recv().is_err());
        latest.store(4, Ordering::Relaxed);
        assert!(!r.step(12), "a later fit asked for stops this one");
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
