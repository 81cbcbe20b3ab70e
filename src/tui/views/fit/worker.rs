//! A background thread for the explorer's fits (`f`): a fit solves the model hundreds of
//! times, which in a debug build takes seconds, so it runs here while the keys go on acting.
//! Only the latest fit asked for is run: one asked before it and not yet started is dropped
//! (its answer would be superseded anyway, `App` keeps the id of the latest). Each finished
//! fit comes back as `Action::FitReady`.

use crate::tui::views::fit::state::{self as measured, FitOutcome, FitRequest};
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread;

/// A finished fit: the id of its request and the outcome.
pub type FitReply = (u64, Result<FitOutcome, String>);

pub struct FitWorker {
    jobs: Sender<FitRequest>,
    replies: Receiver<FitReply>,
}

impl FitWorker {
    pub fn spawn() -> std::io::Result<FitWorker> {
        let (jobs, inbox) = mpsc::channel();
        let (outbox, replies) = mpsc::channel();
        thread::Builder::new()
            .name("bouncelab-fit".into())
            .spawn(move || serve(&inbox, &outbox))?;
        Ok(FitWorker { jobs, replies })
    }

    pub fn want(&self, request: FitRequest) {
        // a send fails only when the thread is gone; the pane then keeps saying "fitting…"
        let _ = self.jobs.send(request);
    }

    pub fn try_recv(&self) -> Option<FitReply> {
        self.replies.try_recv().ok()
    }
}

fn serve(inbox: &Receiver<FitRequest>, outbox: &Sender<FitReply>) {
    while let Ok(mut request) = inbox.recv() {
        // the latest of those waiting
        while let Ok(later) = inbox.try_recv() {
            request = later;
        }
        if outbox.send((request.id, measured::run(&request))).is_err() {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measured::{CorTable, Data};
    use crate::preset::Preset;
    use crate::tui::views::fit::state::{Loaded, request};
    use std::time::{Duration, Instant};

    #[test]
    fn a_fit_comes_back_with_its_id() {
        let ball = Preset::embedded()[0].clone();
        let table = CorTable::parse("v0,cor\n1,0.8\n2,0.75\n3,0.7\n").unwrap();
        let loaded = Loaded {
            path: "t.csv".into(),
            label: "t.csv".into(),
            data: Data::Cor(table),
        };
        let r = request(7, &loaded, &ball.params(), ball.law).unwrap();
        let w = FitWorker::spawn().unwrap();
        w.want(r.clone());
        let start = Instant::now();
        let (id, outcome) = loop {
            if let Some(reply) = w.try_recv() {
                break reply;
            }
            assert!(start.elapsed() < Duration::from_secs(120), "no reply");
            thread::sleep(Duration::from_millis(5));
        };
        assert_eq!(id, 7);
        assert_eq!(outcome, measured::run(&r));
    }
}
