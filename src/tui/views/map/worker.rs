//! A background thread for the map view: it refines the map it was handed pass by pass (each
//! pass on all cores, through [`Map::refine_until`]) and sends every finished pass back, so
//! the screen grows finer while the keys stay free. A job stops inside its pass once `update`
//! sets its cancel flag (the ball or the view changed); the thread then waits for the next.

use crate::map::Map;
use crate::tui::background::Background;
use crate::tui::views::map::state::MapJob;
use std::sync::atomic::Ordering;
use std::sync::mpsc::{Receiver, Sender};

/// A finished pass: the map's generation and the map with that pass in.
pub type Reply = (u64, Map);

/// The map's thread: hand it a job (one `update` has not cancelled already) with `send`; should
/// the thread be gone, `try_recv` says why.
pub type MapWorker = Background<MapJob, Reply>;

/// Start the map's thread.
pub fn spawn() -> std::io::Result<MapWorker> {
    Background::spawn("map", serve)
}

fn serve(inbox: &Receiver<MapJob>, outbox: &Sender<Reply>) {
    while let Ok(mut job) = inbox.recv() {
        while !job.cancel.load(Ordering::Relaxed) {
            match job.map.refine_until(&job.cancel) {
                Some(pass) if pass.complete => {
                    if outbox.send((job.generation, job.map.clone())).is_err() {
                        return;
                    }
                }
                Some(_) | None => break,
            }
        }
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
            map: Map::new(spec),
            cancel: Arc::new(AtomicBool::new(cancel)),
        }
    }

    /// Every pass comes back, the last one complete; a cancelled job sends nothing.
    #[test]
    fn passes_come_back_until_complete_and_a_cancelled_job_is_silent() {
        let mut w = spawn().unwrap();
        w.send(job(1, true));
        w.send(job(2, false));
        let start = Instant::now();
        loop {
            if let Some((generation, map)) = w.try_recv().unwrap() {
                assert_eq!(generation, 2, "the cancelled job sent a pass");
                if map.is_complete() {
                    break;
                }
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no reply");
            thread::sleep(Duration::from_millis(2));
        }
    }
}
