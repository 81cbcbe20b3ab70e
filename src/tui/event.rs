//! The event loop: wait for an event, drain whatever else is queued (zero-timeout poll), apply
//! it all, recompute once, draw once — a held key never builds a backlog. The loop also
//! carries out the effects `update` returns: COR-vs-speed sweeps go to a worker thread (while
//! one is out, the loop also wakes to collect it), an export (`e`) and a saved preset (`s`)
//! are written here, and each outcome goes back to `update` as an action.

use super::action::{self, Action};
use super::app::{App, Effect};
use super::export;
use super::save;
use super::worker::Worker;
use crate::catalog;
use crate::fault::Fault;
use ratatui::DefaultTerminal;
use ratatui::crossterm::event;
use std::time::{Duration, Instant};

/// How often to look for a finished sweep while one is running.
const SWEEP_POLL: Duration = Duration::from_millis(40);
/// Frame period of the drop view's animation (about 30 frames a second).
const FRAME: Duration = Duration::from_millis(33);

pub fn run(terminal: &mut DefaultTerminal, app: &mut App) -> anyhow::Result<()> {
    let mut worker = Worker::spawn()?;
    // test-only (see `crate::fault`): tests/tui_pty.rs checks that the terminal is restored
    // after a panic in here
    let panic_on_key = Fault::PanicInLoop.active();
    let size = terminal.size()?;
    let mut effects = app.update(Action::Resize(size.width, size.height));
    let mut dirty = true;
    let mut clock = Instant::now();
    while !app.should_quit() {
        carry_out(std::mem::take(&mut effects), app, &mut worker);
        if dirty {
            terminal.draw(|frame| frame.render_widget(&*app, frame.area()))?;
            dirty = false;
        }
        let waiting = !app.speed_requests().is_empty();
        let animating = app.animating();
        let wait = if animating { FRAME } else { SWEEP_POLL };
        let mut next = if !(waiting || animating) || event::poll(wait)? {
            Some(event::read()?)
        } else {
            None
        };
        while let Some(ev) = next {
            if panic_on_key && matches!(ev, event::Event::Key(_)) {
                panic!(
                    "{}: test fault injected at a key press",
                    Fault::PanicInLoop.name()
                );
            }
            dirty = true; // a resize, too, needs a new frame
            if let Some(a) = action::from_event(&ev, app.mode()) {
                effects.extend(app.apply(a));
            }
            if app.should_quit() {
                return Ok(());
            }
            next = if event::poll(Duration::ZERO)? {
                Some(event::read()?)
            } else {
                None
            };
        }
        // the animation's clock: real time since the last frame, counted only while the
        // animation was already playing (not the idle wait before `d` or a replay)
        let now = Instant::now();
        if animating && app.animating() {
            effects.extend(app.apply(Action::Tick(now.duration_since(clock).as_secs_f64())));
            dirty = true;
        }
        clock = now;
        while let Some((request, result)) = worker.try_recv() {
            effects.extend(app.apply(Action::SpeedReady(request, result)));
            dirty = true;
        }
        if dirty {
            effects.extend(app.refresh());
        }
    }
    Ok(())
}

/// Carry out `effects`, and those the answers to them bring, until none is left.
fn carry_out(mut effects: Vec<Effect>, app: &mut App, worker: &mut Worker) {
    while !effects.is_empty() {
        for effect in std::mem::take(&mut effects) {
            let answer = match effect {
                Effect::Compute(requests) => {
                    worker.want(&requests);
                    continue;
                }
                Effect::Export(request) => match export::write(&request, &export::dir_from_env()) {
                    Ok(files) => Action::Exported { files },
                    Err(msg) => Action::ExportFailed { msg },
                },
                Effect::ListPresets => {
                    let (entries, error) = super::picker::list();
                    Action::PresetsListed(entries, error)
                }
                Effect::Save(request) => {
                    save::write(&request, catalog::user_presets_dir().as_deref())
                }
            };
            effects.extend(app.update(answer));
        }
    }
}
