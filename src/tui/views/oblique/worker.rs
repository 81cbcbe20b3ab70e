//! The oblique view's (angle, μ) map as a job of the explorer's one worker type
//! ([`crate::tui::worker::Worker`]): the worker computes the map it was handed (all cores) and
//! sends it back; a job whose cancel flag `update` set (the ball, spin or view changed) stops
//! between angles and sends nothing, and of a burst of jobs only the newest is computed.

use crate::tui::views::oblique::map::{self, MapJob, ObliqueMap};
use crate::tui::worker::{Job, Worker};

/// A finished map: the job it was for and the map, or why there is none.
pub type Reply = crate::tui::worker::Reply<MapJob>;

/// The oblique map's thread: hand it a job with `want`.
pub type ObliqueMapWorker = Worker<MapJob>;

impl Job for MapJob {
    type Output = ObliqueMap;
    const NAME: &'static str = "oblique-map";

    /// The whole map or nothing: no pass to show early.
    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        _partial: &mut dyn FnMut(ObliqueMap),
    ) -> Option<Result<ObliqueMap, String>> {
        if !self.wanted(go_on) {
            return None;
        }
        map::compute(&self.work, &self.cancel)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tui::views::oblique::map::MapSpec;
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    use std::thread;
    use std::time::{Duration, Instant};

    #[test]
    fn a_job_comes_back_and_a_cancelled_one_does_not() {
        let mut w = ObliqueMapWorker::spawn().unwrap();
        let spec = MapSpec {
            ball: crate::Ball::from_preset("tennis").unwrap(),
            spin: 0.0,
            tangential_stiffness: None,
            inertia_factor: None,
        };
        let job = |generation, cancel| MapJob {
            generation,
            work: spec.clone(),
            cancel: Arc::new(AtomicBool::new(cancel)),
        };
        w.want(&[job(1, true)]);
        w.want(&[job(2, false)]);
        let start = Instant::now();
        let (job, map) = loop {
            if let Some(reply) = w.try_recv().unwrap() {
                break reply;
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reply");
            thread::sleep(Duration::from_millis(5));
        };
        assert_eq!(job.generation, 2);
        assert_eq!(map.unwrap().cells.len(), 90 * 50);
        thread::sleep(Duration::from_millis(200));
        assert!(w.try_recv().unwrap().is_none());
    }
}
