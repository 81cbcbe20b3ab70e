//! The event loop's background threads, one a computation ([`Work`]): each started at its
//! first request, and again at the first request after it was found gone (a panic in its job,
//! [`crate::tui::background::Background::try_recv`]). The loop hands them the effects that
//! are theirs and collects their news as actions, a worker gone as `Action::WorkerStopped`
//! with why; `update` then stops asking it until `R` or a new request (src/tui/app/stopped.rs).

use super::action::Action;
use super::background::{Background, Stopped, Work};
use super::effect::Effect;
use super::worker::Worker;
use crate::tui::views::fit::worker::FitWorker;
use crate::tui::views::map::worker::MapWorker;
use crate::tui::views::models::state::ModelsRequest;
use crate::tui::views::oblique::worker::ObliqueMapWorker;

/// A worker the loop reads news from without blocking.
pub trait Thread {
    type News;
    /// News if some is waiting, or why the thread is gone.
    fn news(&mut self) -> Result<Option<Self::News>, Stopped>;
}

impl<J: super::worker::Job> Thread for Worker<J> {
    type News = super::worker::Reply<J>;
    fn news(&mut self) -> Result<Option<Self::News>, Stopped> {
        self.try_recv()
    }
}

impl Thread for FitWorker {
    type News = crate::tui::views::fit::worker::FitReply;
    fn news(&mut self) -> Result<Option<Self::News>, Stopped> {
        self.try_recv()
    }
}

impl<J: Send + 'static, R: Send + 'static> Thread for Background<J, R> {
    type News = R;
    fn news(&mut self) -> Result<Option<R>, Stopped> {
        self.try_recv()
    }
}

/// The threads: COR-vs-speed sweeps, the models view's calibrations, the fits, the map's
/// passes, the oblique view's map; `None` before the first request and once found gone.
#[derive(Default)]
pub struct Workers {
    pub sweeps: Option<Worker>,
    pub models: Option<Worker<ModelsRequest>>,
    pub fits: Option<FitWorker>,
    pub maps: Option<MapWorker>,
    pub oblique: Option<ObliqueMapWorker>,
}

impl Workers {
    /// Hand `effect` to its worker, started first when there is none; `None` once handed (or
    /// nothing to hand: an empty list for no thread), else the action saying it could not
    /// start. Other effects are not the workers': handed nowhere.
    pub fn hand(&mut self, effect: Effect) -> Option<Action> {
        let (work, failed) = match effect {
            Effect::Compute(requests) if requests.is_empty() && self.sweeps.is_none() => {
                return None;
            }
            Effect::Compute(requests) => (
                Work::Sweeps,
                started(&mut self.sweeps, Worker::spawn).map(|w| w.want(&requests)),
            ),
            Effect::ComputeModels(requests) if requests.is_empty() && self.models.is_none() => {
                return None;
            }
            Effect::ComputeModels(requests) => (
                Work::Models,
                started(&mut self.models, Worker::spawn).map(|w| w.want(&requests)),
            ),
            Effect::Fit(request) => (
                Work::Fit,
                started(&mut self.fits, FitWorker::spawn).map(|w| w.want(request)),
            ),
            Effect::Map(job) => (
                Work::Map,
                started(&mut self.maps, Worker::spawn).map(|w| w.want(&[job])),
            ),
            Effect::ObliqueMap(job) => (
                Work::ObliqueMap,
                started(&mut self.oblique, Worker::spawn).map(|w| w.want(&[*job])),
            ),
            _ => return None,
        };
        let why = failed.err()?;
        Some(Action::WorkerStopped { work, why })
    }

    /// Every worker's news waiting, as actions; a worker found gone as
    /// `Action::WorkerStopped`, its slot emptied for the next request to start another.
    pub fn news(&mut self) -> Vec<Action> {
        let mut out = Vec::new();
        collect(&mut self.sweeps, Work::Sweeps, &mut out, |(r, c)| {
            Action::SpeedReady(r, c)
        });
        collect(&mut self.models, Work::Models, &mut out, |(r, c)| {
            Action::ModelsReady(r, c)
        });
        collect(&mut self.fits, Work::Fit, &mut out, |(id, news)| {
            Action::FitReady(id, news)
        });
        collect(
            &mut self.maps,
            Work::Map,
            &mut out,
            |(job, map)| match map {
                Ok(map) => Action::MapPass {
                    generation: job.generation,
                    map: Box::new(map),
                },
                // a map's refinement has no refusal of its own (`Job for MapJob`)
                Err(why) => Action::WorkerStopped {
                    work: Work::Map,
                    why,
                },
            },
        );
        collect(
            &mut self.oblique,
            Work::ObliqueMap,
            &mut out,
            |(job, map)| Action::ObliqueMapReady {
                generation: job.generation,
                map: Box::new(map),
            },
        );
        out
    }
}

/// The worker in `slot`, started by `spawn` when there is none; why not when its thread
/// cannot start (reported as a worker that stopped).
pub fn started<W>(
    slot: &mut Option<W>,
    spawn: fn() -> std::io::Result<W>,
) -> Result<&mut W, String> {
    if slot.is_none() {
        let w = spawn().map_err(|e| format!("its thread could not start: {e}"))?;
        *slot = Some(w);
    }
    Ok(slot.as_mut().expect("started just above"))
}

/// `slot`'s news onto `out` as `action`s, then `WorkerStopped` if its thread is gone (the
/// slot emptied).
fn collect<T: Thread>(
    slot: &mut Option<T>,
    work: Work,
    out: &mut Vec<Action>,
    action: impl Fn(T::News) -> Action,
) {
    let Some(thread) = slot else { return };
    loop {
        match thread.news() {
            Ok(Some(news)) => out.push(action(news)),
            Ok(None) => return,
            Err(Stopped(why)) => {
                *slot = None;
                return out.push(Action::WorkerStopped { work, why });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    /// A gone worker's slot: the news say so once, the slot empties, and the next request
    /// starts a new thread that answers.
    #[test]
    fn a_worker_gone_is_reported_once_and_the_next_request_starts_another() {
        let mut slot = Some(
            Background::<u32, u32>::spawn("test-gone", |inbox, _| {
                let _ = inbox.recv();
                panic!("test: the first job kills me");
            })
            .unwrap(),
        );
        slot.as_ref().unwrap().send(1);
        let start = Instant::now();
        let mut out = Vec::new();
        while out.is_empty() {
            assert!(start.elapsed() < Duration::from_secs(60), "no news");
            collect(&mut slot, Work::Map, &mut out, |n| {
                Action::Tick(f64::from(n))
            });
            std::thread::sleep(Duration::from_millis(2));
        }
        let why = "it panicked: test: the first job kills me".to_string();
        let stopped = Action::WorkerStopped {
            work: Work::Map,
            why,
        };
        assert_eq!(out, [stopped]);
        assert!(slot.is_none());
        collect(&mut slot, Work::Map, &mut out, |n| {
            Action::Tick(f64::from(n))
        });
        assert_eq!(out.len(), 1, "reported once");
        fn echo() -> std::io::Result<Background<u32, u32>> {
            Background::spawn("test-echo", |inbox, outbox| {
                while let Ok(n) = inbox.recv() {
                    let _ = outbox.send(n + 1);
                }
            })
        }
        started(&mut slot, echo).unwrap().send(41);
        let w = slot.as_mut().unwrap();
        let start = Instant::now();
        let answer = loop {
            if let Some(n) = w.try_recv().unwrap() {
                break n;
            }
            assert!(start.elapsed() < Duration::from_secs(60), "no answer");
            std::thread::sleep(Duration::from_millis(2));
        };
        assert_eq!(answer, 42);
    }

    /// An empty list for a worker not started starts none; effects not the workers' are
    /// handed nowhere.
    #[test]
    fn nothing_to_hand_starts_nothing() {
        let mut w = Workers::default();
        assert_eq!(w.hand(Effect::Compute(Vec::new())), None);
        assert_eq!(w.hand(Effect::ComputeModels(Vec::new())), None);
        assert_eq!(w.hand(Effect::ListPresets), None);
        assert!(w.sweeps.is_none() && w.models.is_none());
        assert!(w.news().is_empty());
    }
}
