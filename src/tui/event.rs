//! The event loop: wait for an event, drain whatever else is queued (zero-timeout poll), apply
//! it all, recompute once, draw once — a held key never builds a backlog. After a resize the
//! terminal is asked to announce its pending input again (`rearm_input`): crossterm's reader
//! can drop a key that arrives with a resize. The loop also
//! carries out the effects `update` returns: COR-vs-speed sweeps go to a worker thread (while
//! one is out, the loop also wakes to collect it), fits (`f`) to the fit worker likewise, an
//! export (`e`) and a saved preset (`s`) are written here and a measured file (`o`) read, and
//! each outcome goes back to `update` as an action.

use super::action::{self, Action};
use super::app::{App, Effect};
use super::export;
use super::save;
use super::workers::Workers;
use crate::catalog;
use crate::fault::Fault;
use ratatui::DefaultTerminal;
use ratatui::crossterm::event;
use std::time::{Duration, Instant};

/// How often to look for a finished sweep while one is running.
const SWEEP_POLL: Duration = Duration::from_millis(40);
/// How often to look for a pass of the map while one is being refined: a pass of a
/// 200 × 60 screen's map takes some milliseconds.
const MAP_POLL: Duration = Duration::from_millis(5);
/// Frame period of the drop view's animation (about 30 frames a second).
const FRAME: Duration = Duration::from_millis(33);
/// How often an idle loop wakes to see whether a resumed suspension wants the screen redrawn
/// whole (crate::signals).
const IDLE: Duration = Duration::from_millis(100);

pub fn run(terminal: &mut DefaultTerminal, app: &mut App) -> anyhow::Result<()> {
    let mut worker = Workers::default();
    // test-only (see `crate::fault`): tests/tui/tui_pty.rs checks that the terminal is restored
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
        let animating = app.animating();
        let next = if event::poll(wait(app))? {
            Some(event::read()?)
        } else {
            None
        };
        if crate::signals::take_redraw() {
            // back from Ctrl-Z or SIGTSTP on a cleared screen: a blank frame makes the next
            // one draw every cell (Terminal::clear would ask the terminal for the cursor)
            terminal.draw(|f| f.render_widget(ratatui::widgets::Clear, f.area()))?;
            dirty = true;
        }
        // a resize, too, needs a new frame
        dirty |= apply_queued(next, app, &mut effects, panic_on_key)?;
        if app.should_quit() {
            return Ok(());
        }
        // the animation's clock: real time since the last frame, counted only while the
        // animation was already playing (not the idle wait before `d` or a replay)
        let now = Instant::now();
        if animating && app.animating() {
            effects.extend(app.apply(Action::Tick(now.duration_since(clock).as_secs_f64())));
            dirty = true;
        }
        clock = now;
        let news = worker.news();
        if news
            .iter()
            .any(|a| matches!(a, Action::WorkerStopped { .. }))
        {
            // a panic on one of rayon's threads under a worker restored the terminal (ratatui's
            // hook: crate::tui::background::quiet_worker_panics): take it back, redraw whole
            super::resume_all();
            terminal.draw(|f| f.render_widget(ratatui::widgets::Clear, f.area()))?;
        }
        for action in news {
            effects.extend(app.apply(action));
            dirty = true;
        }
        if dirty {
            effects.extend(app.refresh());
        }
    }
    Ok(())
}

/// How long to wait for an event: briefly while a map's passes come in, a frame while the drop
/// animates, longer while a sweep, calibration or fit is out, else [`IDLE`].
fn wait(app: &App) -> Duration {
    let waiting =
        !app.speed_requests().is_empty() || app.models_request().is_some() || app.fitting();
    if app.map_pending() || app.oblique_pending() {
        MAP_POLL
    } else if app.animating() {
        FRAME
    } else if waiting {
        SWEEP_POLL
    } else {
        IDLE
    }
}

/// Apply `next` and every event queued behind it (zero-timeout polls; after a resize the
/// terminal is asked to announce pending input again, [`rearm_input`]), until none is left,
/// the explorer quits or an effect must be answered before the next key
/// ([`Effect::answered_before_next_key`]); whether any came.
fn apply_queued(
    mut next: Option<event::Event>,
    app: &mut App,
    effects: &mut Vec<Effect>,
    panic_on_key: bool,
) -> std::io::Result<bool> {
    let (mut any, mut resized) = (false, false);
    while let Some(ev) = next {
        any = true;
        resized |= matches!(ev, event::Event::Resize(..));
        if panic_on_key && matches!(ev, event::Event::Key(_)) {
            panic!(
                "{}: test fault injected at a key press",
                Fault::PanicInLoop.name()
            );
        }
        if is_suspend(&ev) {
            // raw mode delivers Ctrl-Z as a key: suspend as the shell's SIGTSTP would
            crate::signals::suspend();
        } else if let Some(a) = action::from_event(&ev, app.mode()) {
            effects.extend(app.apply(a));
        }
        if app.should_quit() {
            break;
        }
        if effects.iter().any(Effect::answered_before_next_key) {
            // the keys behind it stay queued for the loop's next turn, after the answer
            if resized {
                rearm_input();
            }
            break;
        }
        next = if event::poll(Duration::ZERO)? {
            Some(event::read()?)
        } else if std::mem::take(&mut resized) {
            rearm_input();
            event::poll(Duration::ZERO)?.then(event::read).transpose()?
        } else {
            None
        };
    }
    Ok(any)
}

/// Have the terminal announce the input it holds again. crossterm's Unix reader waits on the
/// terminal and on its SIGWINCH pipe together, edge-triggered (mio), and when both are ready
/// at once it returns the resize and drops the terminal's readiness: a key typed with a resize
/// stays unread until the next key comes (issue 28: after a burst of resizes, `q` was lost;
/// tests/tui/tui_exit_pty.rs, `a_key_typed_while_the_explorer_draws_a_resize_is_not_lost`).
/// Setting the terminal's attributes, even unchanged, wakes its readers (Linux's line
/// discipline does so on every change of settings), which gives crossterm a new edge for the
/// pending key; with nothing pending nothing is announced.
fn rearm_input() {
    #[cfg(unix)]
    {
        use rustix::termios::{OptionalActions, tcgetattr, tcsetattr};
        use std::io::IsTerminal;
        // the terminal crossterm reads: stdin when it is one, else the controlling terminal
        let tty = if std::io::stdin().is_terminal() {
            None
        } else {
            std::fs::File::open("/dev/tty").ok()
        };
        let fd = match &tty {
            Some(file) => std::os::fd::AsFd::as_fd(file),
            None => rustix::stdio::stdin(),
        };
        if let Ok(settings) = tcgetattr(fd) {
            let _ = tcsetattr(fd, OptionalActions::Now, &settings);
        }
    }
}

/// Ctrl-Z, pressed.
fn is_suspend(ev: &event::Event) -> bool {
    use event::{KeyCode, KeyEventKind, KeyModifiers};
    matches!(ev, event::Event::Key(k) if k.code == KeyCode::Char('z')
        && k.modifiers.contains(KeyModifiers::CONTROL)
        && k.kind == KeyEventKind::Press)
}

/// Carry out `effects`, and those the answers to them bring, until none is left.
fn carry_out(mut effects: Vec<Effect>, app: &mut App, worker: &mut Workers) {
    while !effects.is_empty() {
        for effect in std::mem::take(&mut effects) {
            let answer = match effect {
                Effect::Compute(_)
                | Effect::ComputeModels(_)
                | Effect::Fit(_)
                | Effect::Map(_)
                | Effect::ObliqueMap(_) => match worker.hand(effect) {
                    Some(stopped) => stopped,
                    None => continue,
                },
                Effect::Export(request) => match export::write(&request, &export::dir_from_env()) {
                    Ok(files) => Action::Exported { files },
                    Err(msg) => Action::ExportFailed { msg },
                },
                Effect::ListPresets => {
                    let (entries, error) = super::picker::list();
                    Action::PresetsListed(entries, error)
                }
                Effect::ListSurfaces => {
                    let (entries, error) = super::surface::list();
                    Action::SurfacesListed(entries, error)
                }
                Effect::Save(request) => {
                    save::write(&request, catalog::user_presets_dir().as_deref())
                }
                Effect::SaveSession {
                    path,
                    text,
                    replace,
                } => write_session(path, text, replace),
                Effect::Copy(text) => {
                    super::clipboard::copy(&text);
                    continue;
                }
                Effect::LoadMeasured(path) => match crate::tui::views::fit::state::load(&path) {
                    Ok(data) => Action::MeasuredLoaded { path, data },
                    Err(msg) => Action::MeasuredFailed { msg },
                },
            };
            effects.extend(app.update(answer));
        }
    }
}

/// `S`'s file written in one piece (src/atomic.rs): saved; or it exists and was not to be
/// replaced (the app asks); or why not, the system's reason included ("cannot write
/// /x/s.toml: Permission denied (os error 13)").
fn write_session(path: std::path::PathBuf, text: String, replace: bool) -> Action {
    let mut out = crate::atomic::Outputs::new(replace);
    match out.text(&path, &text).and_then(|()| out.commit()) {
        Ok(_) => Action::SessionSaved(path),
        Err(e) if e.exists => Action::SessionExists { path, text },
        Err(e) => Action::SessionFailed {
            why: format!("{e}: {}", e.error),
            path,
        },
    }
}
