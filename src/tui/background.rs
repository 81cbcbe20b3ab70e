//! One named background thread and its two channels: jobs in, replies out. The explorer's
//! workers (the sweeps' and models' `worker.rs`, the fits', the (λ, ζ) map's and the oblique
//! map's) each run their own serving loop on one; what they share — spawning the thread, a
//! send that fails quietly once the thread is gone, reading replies without blocking — is here.

use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;

/// A thread serving jobs `J` and answering `R`s.
pub struct Background<J, R> {
    jobs: Sender<J>,
    replies: Receiver<R>,
}

impl<J: Send + 'static, R: Send + 'static> Background<J, R> {
    /// Start the thread `name` running `serve` on the jobs' inbox and the replies' outbox; it
    /// ends when `serve` returns (its inbox closed once this is dropped, or its outbox gone).
    pub fn spawn<F>(name: &str, serve: F) -> std::io::Result<Background<J, R>>
    where
        F: FnOnce(&Receiver<J>, &Sender<R>) + Send + 'static,
    {
        let (jobs, inbox) = mpsc::channel();
        let (outbox, replies) = mpsc::channel();
        thread::Builder::new()
            .name(name.into())
            .spawn(move || serve(&inbox, &outbox))?;
        Ok(Background { jobs, replies })
    }

    /// Hand the thread `job`. A send fails only when the thread is gone; the view then keeps
    /// saying it is computing, which is all it can do.
    pub fn send(&self, job: J) {
        let _ = self.jobs.send(job);
    }

    /// A reply, if one is waiting.
    pub fn try_recv(&self) -> Option<R> {
        self.replies.try_recv().ok()
    }

    /// A reply within `timeout` (tests wait for the thread this way).
    #[cfg(test)]
    pub fn recv_timeout(&self, timeout: std::time::Duration) -> Option<R> {
        self.replies.recv_timeout(timeout).ok()
    }
}
