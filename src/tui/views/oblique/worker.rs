//! A background thread for the oblique view's (angle, μ) map: it computes the map it was
//! handed (all cores) and sends it back; a job whose cancel flag `update` set (the ball, spin
//! or view changed) stops between angles and sends nothing.

use crate::tui::background::Background;
use crate::tui::views::oblique::map::{self, MapJob, ObliqueMap};
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Receiver, Sender};

/// A finished map: its generation and the map, or why there is none.
pub type Reply = (u64, Result<ObliqueMap, String>);

/// The oblique map's thread: hand it a job with `send`.
pub type ObliqueMapWorker = Background<MapJob, Reply>;

/// Start the oblique map's thread.
pub fn spawn() -> std::io::Result<ObliqueMapWorker> {
    Background::spawn("oblique-map", serve)
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
        let w = spawn().unwrap();
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
        w.send(job(1, true));
        w.send(job(2, false));
        let (generation, map) = w.recv_timeout(Duration::from_secs(60)).unwrap();
        assert_eq!(generation, 2);
        assert_eq!(map.unwrap().cells.len(), 90 * 50);
        assert!(w.recv_timeout(Duration::from_millis(200)).is_none());
    }
}
