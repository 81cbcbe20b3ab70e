//! A background thread for the COR-vs-speed sweeps: in some corners of the parameter space
//! (λ ≈ 0, ζ ≫ 1, nonlinear law: the ball sinks into the dashpot) a sweep takes seconds even in
//! release builds. The explorer stays responsive meanwhile, and a sweep the user has moved past
//! is abandoned between two speeds. Results come back as `Action::SpeedReady`. The models
//! view's calibrations ([`super::models::ModelsRequest`]) run on a second worker of the same
//! kind and come back as `Action::ModelsReady`.

use super::compute::{SpeedCurve, SpeedRequest};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread;

/// Work a [`Worker`] does: equal jobs give equal results, so the job is its result's key.
pub trait Job: Clone + PartialEq + Send + 'static {
    type Output: Send + 'static;
    /// The job, asking `go_on` between its steps; `None` when it said stop.
    fn run_while(&self, go_on: &mut dyn FnMut() -> bool) -> Option<Result<Self::Output, String>>;
}

impl Job for SpeedRequest {
    type Output = SpeedCurve;
    fn run_while(&self, go_on: &mut dyn FnMut() -> bool) -> Option<Result<SpeedCurve, String>> {
        SpeedRequest::run_while(self, go_on)
    }
}

/// A finished job and what it was for.
pub type Reply<J = SpeedRequest> = (J, Result<<J as Job>::Output, String>);

pub struct Worker<J: Job = SpeedRequest> {
    jobs: Sender<Vec<J>>,
    replies: Receiver<Reply<J>>,
    sent: Vec<J>,
}

impl<J: Job> Worker<J> {
    pub fn spawn() -> std::io::Result<Worker<J>> {
        let (jobs, inbox) = mpsc::channel();
        let (outbox, replies) = mpsc::channel();
        thread::Builder::new()
            .name("bouncelab-sweeps".into())
            .spawn(move || serve(&inbox, &outbox))?;
        Ok(Worker {
            jobs,
            replies,
            sent: Vec::new(),
        })
    }

    /// Ask for exactly these sweeps: what was asked before and is not among them is dropped.
    pub fn want(&mut self, requests: &[J]) {
        if requests != self.sent.as_slice() {
            self.sent = requests.to_vec();
            // a send fails only when the thread is gone; the explorer then waits in vain for a
            // sweep, which its title says
            let _ = self.jobs.send(self.sent.clone());
        }
    }

    pub fn try_recv(&self) -> Option<Reply<J>> {
        self.replies.try_recv().ok()
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
            continue;
        }
        let request = queue.remove(0);
        let mut latest = None;
        let mut gone = false;
        let result = request.run_while(&mut || {
            loop {
                match inbox.try_recv() {
                    Ok(q) => latest = Some(q),
                    Err(TryRecvError::Empty) => break,
                    Err(TryRecvError::Disconnected) => {
                        gone = true;
                        break;
                    }
                }
            }
            !gone
                && latest
                    .as_ref()
                    .is_none_or(|q: &Vec<_>| q.contains(&request))
        });
        if gone {
            return;
        }
        if let Some(q) = latest {
            let finished = result.is_some();
            queue = q
                .into_iter()
                .filter(|r| !(finished && *r == request))
                .collect();
        }
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
    use std::time::{Duration, Instant};

    fn wait(w: &Worker) -> Reply {
        let start = Instant::now();
        loop {
            if let Some(r) = w.try_recv() {
                return r;
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reply");
            thread::sleep(Duration::from_millis(5));
        }
    }

    #[test]
    fn replies_with_the_latest_wanted_sweeps() {
        let p = Preset::embedded()[0].params();
        let a = SpeedRequest::new(&p, ContactLaw::Linear, 3.12);
        let b = SpeedRequest::new(&p, ContactLaw::Hertz, 3.12);
        let mut w = Worker::spawn().unwrap();
        w.want(std::slice::from_ref(&a));
        w.want(std::slice::from_ref(&b));
        let (req, curve) = wait(&w);
        // `a` may have finished before `b` was asked for; `b` always comes
        let (req, curve) = if req == a { wait(&w) } else { (req, curve) };
        assert_eq!(req, b);
        assert_eq!(curve.unwrap(), b.run().unwrap());
    }
}
