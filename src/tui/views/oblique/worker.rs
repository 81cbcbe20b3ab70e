//! A background thread for the oblique view's (angle, μ) map: it computes the map it was
//! handed (all cores) and sends it back; a job whose cancel flag `update` set (the ball, spin
//! or view changed) stops between angles and sends nothing.

use crate::tui::views::oblique::map::{self, MapJob, ObliqueMap};
use std::sync::atomic::Ordering;
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;

/// A finished map: its generation and the map, or why there is none.
pub type Reply = (u64, Result<ObliqueMap, String>);

pub struct ObliqueMapWorker {
    jobs: Sender<MapJob>,
    replies: Receiver<Reply>,
}

impl ObliqueMapWorker {
    pub fn spawn() -> std::io::Result<ObliqueMapWorker> {
        let (jobs, inbox) = mpsc::channel();
        let (outbox, replies) = mpsc::channel();
        thread::Builder::new()
            .name("bouncelab-oblique-map".into())
            .spawn(move || serve(&inbox, &outbox))?;
        Ok(ObliqueMapWorker { jobs, replies })
    }

    pub fn want(&self, job: MapJob) {
        // a send fails only when the thread is gone; the map then says it is computing
        let _ = self.jobs.send(job);
    }

    pub fn try_recv(&self) -> Option<Reply> {
        self.replies.try_recv().ok()
    }
}

fn serve(inbox: &Receiver<MapJob>, outbox: &Sender<Reply>) {
    while let Ok(mut job) = inbox.recv() {
        // only the newest job is worth computing
        while let Ok(newer) = inbox.try_recv() {
            job = newer;
        }
        if job.cancel.load(Ordering::Relaxed) {
            continue;
        }
        if let Some(answer) = map::compute(&job.spec, &job.cancel)
            && outbox.send((job.generation, answer)).is_err()
        {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::views::oblique::map::MapSpec;
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    use std::time::Duration;

    #[test]
    fn a_job_comes_back_and_a_cancelled_one_does_not() {
        let w = ObliqueMapWorker::spawn().unwrap();
        let spec = MapSpec {
            ball: crate::Ball::from_preset("tennis").unwrap(),
            spin: 0.0,
            tangential_stiffness: None,
            inertia_factor: None,
        };
        let job = |generation, cancel| MapJob {
            generation,
            spec: spec.clone(),
            cancel: Arc::new(AtomicBool::new(cancel)),
        };
        w.want(job(1, true));
        w.want(job(2, false));
        let (generation, map) = w.replies.recv_timeout(Duration::from_secs(60)).unwrap();
        assert_eq!(generation, 2);
        assert_eq!(map.unwrap().cells.len(), 90 * 50);
        assert!(w.replies.recv_timeout(Duration::from_millis(200)).is_err());
    }
}
