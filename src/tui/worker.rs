//! A background thread for the COR-vs-speed sweeps: in some corners of the parameter space
//! (λ ≈ 0, ζ ≫ 1, nonlinear law: the ball sinks into the dashpot) a sweep takes seconds even in
//! release builds. The explorer stays responsive meanwhile, and a sweep the user has moved past
//! is abandoned between two speeds. Results come back as `Action::SpeedReady`.

use super::compute::{SpeedCurve, SpeedRequest};
use std::sync::mpsc::{self, Receiver, Sender, TryRecvError};
use std::thread;

/// A finished sweep and what it was for.
pub type Reply = (SpeedRequest, Result<SpeedCurve, String>);

pub struct Worker {
    jobs: Sender<Vec<SpeedRequest>>,
    replies: Receiver<Reply>,
    sent: Vec<SpeedRequest>,
}

impl Worker {
    pub fn spawn() -> std::io::Result<Worker> {
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
    pub fn want(&mut self, requests: &[SpeedRequest]) {
        if requests != self.sent.as_slice() {
            self.sent = requests.to_vec();
            // a send fails only when the thread is gone; the explorer then waits in vain for a
            // sweep, which its title says
            let _ = self.jobs.send(self.sent.clone());
        }
    }

    pub fn try_recv(&self) -> Option<Reply> {
        self.replies.try_recv().ok()
    }
}

fn serve(inbox: &Receiver<Vec<SpeedRequest>>, outbox: &Sender<Reply>) {
    let mut queue: Vec<SpeedRequest> = Vec::new();
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
        let result = request.run_while(|| {
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
