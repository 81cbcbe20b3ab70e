//! The map view's job on the explorer's one worker type ([`crate::tui::worker::Worker`]): the
//! worker refines the map it was handed pass by pass (each pass on all cores, through
//! [`Map::refine_until`]) and sends every finished pass back, so the screen grows finer while the
//! keys stay free. A job stops inside its pass once `update` sets its cancel flag (the ball or the
//! view changed), and between passes once a newer job is asked for; the thread then takes the next.

use crate::map::Map;
use crate::tui::views::map::state::MapJob;
use crate::tui::worker::{Job, Worker};

/// A finished pass: the job it was for and the map with that pass in.
pub type Reply = crate::tui::worker::Reply<MapJob>;

/// The map's thread: hand it a job (one `update` has not cancelled already) with `want`;
/// should the thread be gone, `try_recv` says why.
pub type MapWorker = Worker<MapJob>;

impl Job for MapJob {
    type Output = Map;
    const NAME: &'static str = "map";

    /// Each pass but the last to `partial`, the last as the answer; `None` once cancelled
    /// (inside a pass) or superseded (between passes), or when the map was complete already.
    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        partial: &mut dyn FnMut(Map),
    ) -> Option<Result<Map, String>> {
        let mut map = self.work.clone();
        while self.wanted(go_on) {
            match map.refine_until(&self.cancel) {
                Some(pass) if pass.complete && map.is_complete() => return Some(Ok(map)),
                Some(pass) if pass.complete => partial(map.clone()),
                Some(_) | None => return None,
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::map::{Axis, MapSpec, Param, Scale};
    use crate::model::contact::ContactLaw;
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    use std::thread;
    use std::time::{Duration, Instant};

    fn job(generation: u64, cancel: bool) -> MapJob {
        let l = Axis::new(Param::Lambda, 0.1, 10.0, 20, Scale::Log).unwrap();
        let z = Axis::new(Param::Zeta, 0.01, 1.0, 30, Scale::Log).unwrap();
        let p = crate::preset::Preset::embedded()[0].params();
        let spec = MapSpec::dimensional(p, ContactLaw::Linear, l, z).unwrap();
        MapJob {
            generation,
            work: Map::new(spec),
            cancel: Arc::new(AtomicBool::new(cancel)),
        }
    }

    /// Every pass comes back, the last one complete; a cancelled job sends nothing.
    #[test]
    fn passes_come_back_until_complete_and_a_cancelled_job_is_silent() {
        let mut w = MapWorker::spawn().unwrap();
        w.want(&[job(1, true)]);
        w.want(&[job(2, false)]);
        let start = Instant::now();
        let mut passes = 0;
        loop {
            if let Some((job, map)) = w.try_recv().unwrap() {
                assert_eq!(job.generation, 2, "the cancelled job sent a pass");
                passes += 1;
                if map.unwrap().is_complete() {
                    break;
                }
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reply");
            thread::sleep(Duration::from_millis(2));
        }
        assert!(passes > 1, "one pass only: {passes}");
    }
}
