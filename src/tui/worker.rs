//! The explorer's one background-worker type (issue 55 item 1): a thread that runs the latest
//! jobs asked for, one at a time, drops those the user has moved past (between two steps of a
//! job), and sends back what a job has so far and its answer. Every view's computation is a
//! [`Job`] on it: the COR-vs-speed sweeps (`Action::SpeedReady`; in some corners of the
//! parameter space — λ ≈ 0, ζ ≫ 1, a nonlinear law — a sweep takes seconds even in release
//! builds), the models view's calibrations
//! ([`crate::tui::views::models::state::ModelsRequest`], `Action::ModelsReady`), the fits
//! (src/tui/views/fit/worker.rs), the map's passes (src/tui/views/map/worker.rs) and the
//! oblique view's map (src/tui/views/oblique/worker.rs).

use crate::tui::background::{Background, Stopped};
use crate::tui::views::sweeps::speed::{SpeedCurve, SpeedRequest};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, TryRecvError};

/// Work a [`Worker`] does: equal jobs give equal results, so the job is its result's key.
pub trait Job: Clone + PartialEq + Send + 'static {
    type Output: Send + 'static;
    /// The thread's name, after [`crate::tui::background::THREAD_PREFIX`].
    const NAME: &'static str = "sweeps";
    /// The job, asking `go_on` between its steps (`None` when it said stop), handing
    /// `partial` what it has so far between them when it can (a coarse COR-vs-speed curve, a
    /// map's pass, a fit's progress); a job with nothing to show early ignores `partial`.
    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        partial: &mut dyn FnMut(Self::Output),
    ) -> Option<Result<Self::Output, String>>;

    /// [`Job::run_refining`] with nothing shown early.
    fn run_while(&self, go_on: &mut dyn FnMut() -> bool) -> Option<Result<Self::Output, String>> {
        self.run_refining(go_on, &mut |_| {})
    }
}

impl Job for SpeedRequest {
    type Output = SpeedCurve;

    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        partial: &mut dyn FnMut(SpeedCurve),
    ) -> Option<Result<SpeedCurve, String>> {
        SpeedRequest::run_refining(self, go_on, partial)
    }
}

/// Work handed to the worker that `update` calls off once it is stale (the ball or the view
/// changed): it sets `cancel`, and the job stops at its next step. `generation` counts the
/// view's hand-outs, so that an answer of an older one is known as stale. Two are the same
/// job when they are the same hand-out: the generation and the flag, whatever the work.
#[derive(Debug, Clone)]
pub struct Cancellable<W> {
    pub generation: u64,
    pub work: W,
    pub cancel: Arc<AtomicBool>,
}

impl<W> Cancellable<W> {
    /// Whether the job is to go on: `update` has not called it off and `go_on` (the worker:
    /// no newer list that leaves it out) still wants it.
    pub fn wanted(&self, go_on: &mut dyn FnMut() -> bool) -> bool {
        !self.cancel.load(Ordering::Relaxed) && go_on()
    }
}

impl<W> PartialEq for Cancellable<W> {
    fn eq(&self, other: &Cancellable<W>) -> bool {
        self.generation == other.generation && Arc::ptr_eq(&self.cancel, &other.cancel)
    }
}

/// A view's side of its [`Cancellable`] jobs: how many it handed out, the flag of the one out
/// at the worker, and why the worker's thread stopped (then nothing is handed out again until
/// `R` or another job, src/tui/app/stopped.rs).
#[derive(Debug, Clone, Default)]
pub struct JobState {
    /// Counts the jobs made: an answer of an older one is stale.
    pub generation: u64,
    /// The flag of the job out at the worker, if one is.
    pub out: Option<Arc<AtomicBool>>,
    /// Why the worker's thread stopped, if it did.
    pub stopped: Option<String>,
}

impl JobState {
    /// Stop the job out at the worker, if any.
    pub fn cancel(&mut self) {
        if let Some(flag) = self.out.take() {
            flag.store(true, Ordering::Relaxed);
        }
    }

    /// A new job replaces the old: the one out is stopped, a stop of the old forgotten, and
    /// answers of the old are stale from now.
    pub fn renew(&mut self) {
        self.cancel();
        self.stopped = None;
        self.generation += 1;
    }

    /// `work` handed out as the current job, its flag kept to cancel it by.
    pub fn hand_out<W>(&mut self, work: W) -> Cancellable<W> {
        let cancel = Arc::new(AtomicBool::new(false));
        self.out = Some(Arc::clone(&cancel));
        Cancellable {
            generation: self.generation,
            work,
            cancel,
        }
    }
}

/// A finished job and what it was for.
pub type Reply<J = SpeedRequest> = (J, Result<<J as Job>::Output, String>);

pub struct Worker<J: Job = SpeedRequest> {
    thread: Background<Vec<J>, Reply<J>>,
    sent: Vec<J>,
}

impl<J: Job> Worker<J> {
    pub fn spawn() -> std::io::Result<Worker<J>> {
        Ok(Worker {
            thread: Background::spawn(J::NAME, serve)?,
            sent: Vec::new(),
        })
    }

    /// Ask for exactly these sweeps: what was asked before and is not among them is dropped.
    pub fn want(&mut self, requests: &[J]) {
        if requests != self.sent.as_slice() {
            self.sent = requests.to_vec();
            // should the thread be gone, `try_recv` says so
            self.thread.send(self.sent.clone());
        }
    }

    /// A reply if one is waiting, or why the thread is gone ([`Background::try_recv`]).
    pub fn try_recv(&mut self) -> Result<Option<Reply<J>>, Stopped> {
        self.thread.try_recv()
    }
}

/// The newest list of sweeps asked for in `inbox` (`None`: nothing new), and whether the
/// explorer is gone. Older lists are dropped unread: only the latest key's sweeps matter.
fn newest<J>(inbox: &Receiver<Vec<J>>) -> (Option<Vec<J>>, bool) {
    let mut latest = None;
    loop {
        match inbox.try_recv() {
            Ok(q) => latest = Some(q),
            Err(TryRecvError::Empty) => return (latest, false),
            Err(TryRecvError::Disconnected) => return (latest, true),
        }
    }
}

/// Whether to go on with `request` now that `latest` was asked for (`None`: nothing new).
pub fn still_wanted<J: PartialEq>(request: &J, latest: Option<&[J]>) -> bool {
    latest.is_none_or(|q| q.contains(request))
}

/// The sweeps left once `request` stopped (`finished`, or abandoned for a newer list):
/// the newest list when there is one — without `request` if it finished — else `queue`.
pub fn left_after<J: PartialEq>(
    queue: Vec<J>,
    request: &J,
    latest: Option<Vec<J>>,
    finished: bool,
) -> Vec<J> {
    match latest {
        Some(q) => q
            .into_iter()
            .filter(|r| !(finished && r == request))
            .collect(),
        None => queue,
    }
}

fn serve<J: Job>(inbox: &Receiver<Vec<J>>, outbox: &Sender<Reply<J>>) {
    let mut queue: Vec<J> = Vec::new();
    loop {
        if queue.is_empty() {
            match inbox.recv() {
                Ok(q) => queue = q,
                Err(_) => return,
            }
        }
        // a burst of keys leaves many lists: start on the newest
        let (latest, gone) = newest(inbox);
        if gone {
            return;
        }
        if let Some(q) = latest {
            queue = q;
        }
        let Some(request) = queue.first().cloned() else {
            continue;
        };
        queue.remove(0);
        let mut latest: Option<Vec<J>> = None;
        let mut gone = false;
        let result = request.run_refining(
            &mut || {
                let (newer, g) = newest(inbox);
                gone = g;
                if newer.is_some() {
                    latest = newer;
                }
                !gone && still_wanted(&request, latest.as_deref())
            },
            // a coarse curve early; a send fails only when the explorer is gone
            &mut |coarse| {
                let _ = outbox.send((request.clone(), Ok(coarse)));
            },
        );
        if gone {
            return;
        }
        queue = left_after(queue, &request, latest, result.is_some());
        if let Some(r) = result
            && outbox.send((request, r)).is_err()
        {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::contact::ContactLaw;
    use crate::preset::Preset;
    use std::sync::mpsc;
    use std::thread;
    use std::time::{Duration, Instant};

    fn wait(w: &mut Worker) -> Reply {
        let start = Instant::now();
        loop {
            if let Some(r) = w.try_recv().unwrap() {
                return r;
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reply");
            thread::sleep(Duration::from_millis(5));
        }
    }

    fn request(v0: f64) -> SpeedRequest {
        let p = Preset::embedded()[0].params();
        SpeedRequest::new(
            &crate::model::params::ImpactParams { v0, ..p },
            ContactLaw::Linear,
            3.12,
        )
    }

    /// Issue 18, defect 11: a sweep the user has moved past is dropped at the next point; one
    /// still wanted goes on; a finished one is not asked again; an abandoned one that is still
    /// in the newest list comes back in its place there.
    #[test]
    fn stale_sweeps_are_dropped_and_wanted_ones_kept() {
        let (a, b, c) = (request(3.0), request(30.0), request(60.0));
        assert_ne!(a, b);
        assert!(still_wanted(&a, None));
        assert!(!still_wanted(&a, Some(std::slice::from_ref(&b))));
        assert!(!still_wanted(&a, Some(&[])));
        assert!(still_wanted(&a, Some(&[b.clone(), a.clone()])));
        let queue = vec![c.clone()];
        assert_eq!(left_after(queue.clone(), &a, None, true), queue);
        let newer = Some(vec![b.clone(), c.clone()]);
        assert_eq!(
            left_after(queue.clone(), &a, newer, false),
            [b.clone(), c.clone()]
        );
        let again = Some(vec![a.clone(), b.clone()]);
        assert_eq!(
            left_after(queue.clone(), &a, again.clone(), true),
            std::slice::from_ref(&b)
        );
        assert_eq!(left_after(queue, &a, again, false), [a, b]);
    }

    /// Of a burst of lists only the newest is read; the rest are dropped unread.
    #[test]
    fn a_burst_leaves_only_the_newest_list() {
        let (tx, rx) = mpsc::channel();
        for v0 in 1..=30 {
            tx.send(vec![request(f64::from(v0))]).unwrap();
        }
        assert_eq!(newest(&rx), (Some(vec![request(30.0)]), false));
        assert_eq!(newest(&rx), (None, false));
        drop(tx);
        assert_eq!(newest(&rx), (None, true));
    }

    #[test]
    fn replies_with_the_latest_wanted_sweeps() {
        let p = Preset::embedded()[0].params();
        let a = SpeedRequest::new(&p, ContactLaw::Linear, 3.12);
        let b = SpeedRequest::new(&p, ContactLaw::Hertz, 3.12);
        let mut w = Worker::spawn().unwrap();
        w.want(std::slice::from_ref(&a));
        w.want(std::slice::from_ref(&b));
        // `a` may have finished (or sent coarse curves) before `b` was asked for; `b`'s
        // finished curve always comes, after its coarse ones
        let (req, curve) = loop {
            let (req, curve) = wait(&mut w);
            if req == b && !curve.as_ref().is_ok_and(|c| c.refining) {
                break (req, curve);
            }
        };
        assert_eq!(req, b);
        assert_eq!(curve.unwrap(), b.run().unwrap());
    }
}
