//! One named background thread and its two channels: jobs in, replies out. The explorer's one
//! worker type ([`crate::tui::worker::Worker`]: the sweeps', the models', the fits', the
//! (λ, ζ) map's and the oblique map's jobs, issue 55 item 1) serves on one; what a thread
//! needs — spawning it, reading replies without blocking, and telling "nothing yet" from "the
//! thread is gone" (a panic in a job), with the panic's message — is here. The event loop
//! reports a thread gone as `Action::WorkerStopped` and starts a new one at the next request
//! (src/tui/event.rs).

use crate::fault::Fault;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread::{self, JoinHandle};

/// Every worker thread's name starts so ("bouncelab-sweeps", "bouncelab-map", …): the panic
/// hook of [`quiet_worker_panics`] knows them by it.
pub const THREAD_PREFIX: &str = "bouncelab-";

/// Which of the explorer's background computations: one worker thread each.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Work {
    /// The sweeps view's COR-vs-speed sweeps.
    Sweeps,
    /// The models view's calibrations.
    Models,
    /// The fit (`f`).
    Fit,
    /// The map view's passes.
    Map,
    /// The oblique view's (θ, μ) map.
    ObliqueMap,
}

impl Work {
    /// What the user sees computed: "the COR-vs-speed sweep stopped: …".
    pub fn name(self) -> &'static str {
        match self {
            Work::Sweeps => "the COR-vs-speed sweep",
            Work::Models => "the models' calibration",
            Work::Fit => "the fit",
            Work::Map => "the map's refinement",
            Work::ObliqueMap => "the (θ, μ) map",
        }
    }
}

/// Why a worker's thread is gone: "it panicked: <the panic's message>", or that it ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Stopped(pub String);

/// A thread serving jobs `J` and answering `R`s.
pub struct Background<J, R> {
    jobs: Sender<J>,
    replies: Receiver<R>,
    /// Joined once the thread is found gone, for its panic's message.
    thread: Option<JoinHandle<()>>,
}

impl<J: Send + 'static, R: Send + 'static> Background<J, R> {
    /// Start the thread `name` (after [`THREAD_PREFIX`]) running `serve` on the jobs' inbox
    /// and the replies' outbox; it ends when `serve` returns (its inbox closed once this is
    /// dropped, or its outbox gone) or panics.
    pub fn spawn<F>(name: &str, serve: F) -> std::io::Result<Background<J, R>>
    where
        F: FnOnce(&Receiver<J>, &Sender<R>) + Send + 'static,
    {
        let (jobs, inbox) = mpsc::channel();
        let (outbox, replies) = mpsc::channel();
        let faulty = fault_this_thread();
        let thread = thread::Builder::new()
            .name(format!("{THREAD_PREFIX}{name}"))
            .spawn(move || {
                if faulty && inbox.recv().is_ok() {
                    panic!(
                        "{}: test fault injected at a worker's first job",
                        Fault::PanicInWorker.name()
                    );
                }
                serve(&inbox, &outbox)
            })?;
        Ok(Background {
            jobs,
            replies,
            thread: Some(thread),
        })
    }

    /// Hand the thread `job`. A send fails only when the thread is gone, which
    /// [`Background::try_recv`] then says, with why.
    pub fn send(&self, job: J) {
        let _ = self.jobs.send(job);
    }

    /// A reply, if one is waiting (`Ok(None)`: nothing yet); once the thread is gone and every
    /// reply it sent has been read, why it is gone.
    pub fn try_recv(&mut self) -> Result<Option<R>, Stopped> {
        match self.replies.try_recv() {
            Ok(r) => Ok(Some(r)),
            Err(TryRecvError::Empty) => Ok(None),
            Err(TryRecvError::Disconnected) => Err(self.why_gone()),
        }
    }

    /// The thread has dropped its outbox, so it has returned or is unwinding: join it (at once,
    /// or as soon as its unwinding ends) for its panic's payload.
    fn why_gone(&mut self) -> Stopped {
        let why = match self.thread.take().map(JoinHandle::join) {
            Some(Err(payload)) => format!("it panicked: {}", panic_message(payload.as_ref())),
            Some(Ok(())) => "its thread ended".to_string(),
            None => "its thread is gone".to_string(),
        };
        Stopped(why)
    }

    /// A reply within `timeout` (tests wait for the thread this way).
    #[cfg(test)]
    pub fn recv_timeout(&self, timeout: std::time::Duration) -> Option<R> {
        self.replies.recv_timeout(timeout).ok()
    }
}

/// The text a panic was raised with (`panic!("…")` gives a `&str` or a `String`).
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".to_string()
    }
}

/// Keep the panics of the explorer's worker threads off the screen: over the hook in place
/// (ratatui's, which restores the terminal, then the default one, which prints), a hook that
/// passes every other thread's panic on and does nothing for a worker's — the explorer goes
/// on, and the view says that its computation stopped and why ([`Background::try_recv`]).
/// A panic in one of rayon's threads (a map pass runs on all cores) is not a worker's by
/// name: it restores the terminal as before, and the loop takes the screen back when the
/// worker it ended is reported (src/tui/event.rs).
pub fn quiet_worker_panics() {
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let worker = thread::current()
            .name()
            .is_some_and(|n| n.starts_with(THREAD_PREFIX));
        if !worker {
            previous(info);
        }
    }));
}

/// Whether the thread about to be spawned takes the test fault `panic-in-worker`: the first
/// worker spawned in a process with the fault on, and no other (its retry then works).
fn fault_this_thread() -> bool {
    static TAKEN: AtomicBool = AtomicBool::new(false);
    Fault::PanicInWorker.active() && !TAKEN.swap(true, Ordering::Relaxed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    /// Poll `b` as the event loop does until it answers something other than "nothing yet".
    fn poll<J: Send + 'static, R: Send + 'static>(b: &mut Background<J, R>) -> Result<R, Stopped> {
        let start = Instant::now();
        loop {
            match b.try_recv() {
                Ok(Some(r)) => return Ok(r),
                Ok(None) => assert!(start.elapsed() < Duration::from_secs(60), "no answer"),
                Err(s) => return Err(s),
            }
            thread::sleep(Duration::from_millis(2));
        }
    }

    /// A thread that panics at a job is told from one with nothing to say yet, with the
    /// panic's message; a reply sent before the panic is read first.
    #[test]
    fn a_panic_is_told_from_nothing_yet_with_its_message() {
        let mut b = Background::<u32, u32>::spawn("test-panics", |inbox, outbox| {
            while let Ok(n) = inbox.recv() {
                assert!(n < 3, "job {n} is too big");
                let _ = outbox.send(n * 10);
            }
        })
        .unwrap();
        assert_eq!(b.try_recv(), Ok(None));
        b.send(2);
        b.send(7);
        assert_eq!(poll(&mut b), Ok(20));
        assert_eq!(
            poll(&mut b),
            Err(Stopped("it panicked: job 7 is too big".into()))
        );
        b.send(1); // to a thread gone: quietly nothing
        assert_eq!(b.try_recv(), Err(Stopped("its thread is gone".into())));
    }

    #[test]
    fn a_thread_that_returns_has_ended() {
        let mut b = Background::<u32, u32>::spawn("test-returns", |_, _| {}).unwrap();
        assert_eq!(poll(&mut b), Err(Stopped("its thread ended".into())));
    }

    #[test]
    fn panic_messages_of_both_kinds() {
        let text = |p: Box<dyn std::any::Any + Send>| panic_message(p.as_ref());
        assert_eq!(text(Box::new("static")), "static");
        assert_eq!(text(Box::new(String::from("formatted 3"))), "formatted 3");
        assert_eq!(text(Box::new(3_u8)), "a panic without a message");
    }
}
