//! The one work limit of every command ([`crate::analysis::work`], the library's, so that the
//! library's sweeps and the Python package apply the same), checked before any work; long
//! work shows progress and stops on Ctrl-C.
//!
//! The sweeps run in chunks through [`zeta_rows`] and [`velocity_rows`]: between chunks a
//! progress bar on stderr moves (only when stderr is a terminal, and only for work worth
//! watching) and a SIGINT or SIGTERM is noticed: the command then ends with [`Interrupted`]
//! (exit 130) before any file is written, so nothing partial is left; a second signal ends the
//! process at once. (tests/cli/cli_progress_pty.rs.)

use crate::analysis::sweep::{VelocityPoint, ZetaPoint, cor_vs_velocity, cor_vs_zeta};
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use std::io::IsTerminal;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

pub use crate::analysis::work::{LIMIT, cost};

/// Refuse `impacts` impacts under `law` beyond the limit (exit 2); `what` says how they were
/// asked for ("500 λ values × 20000 points").
pub fn check(impacts: usize, law: ContactLaw, what: &str) -> anyhow::Result<()> {
    Ok(crate::analysis::work::check(impacts, law, what)?)
}

/// The command was stopped by SIGINT or SIGTERM: exit 130, nothing written.
#[derive(Debug)]
pub struct Interrupted;

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("interrupted: nothing was written")
    }
}

impl std::error::Error for Interrupted {}

/// Work below this (in linear-law impacts) ends too soon for a bar to help.
const SHOW_FROM: u64 = 20_000;
/// Impacts solved between two looks at the bar and the signal flag.
const CHUNK: usize = 64;

static FLAG: std::sync::OnceLock<Arc<AtomicBool>> = std::sync::OnceLock::new();

/// Whether a SIGINT or SIGTERM came since long work began: the command then publishes no file
/// (`figure::commit` asks, after the work and before the renames).
pub fn interrupted() -> bool {
    FLAG.get().is_some_and(|f| f.load(Ordering::Relaxed))
}

/// [`Interrupted`] once a SIGINT or SIGTERM came: the look between the phases of work that
/// has none of its own (reading a measured file, drawing a figure), so that no phase but the
/// one under way runs after the signal (issue 54 item 6, tests/cli/signals_prompt.rs).
pub fn stop_if_interrupted() -> anyhow::Result<()> {
    if interrupted() {
        return Err(Interrupted.into());
    }
    Ok(())
}

/// Set by SIGINT or SIGTERM once this was called; the atomic writer looks at it too, so a
/// signal mid-write stops the staging and its temporaries go ([`crate::atomic::stop_on`]).
pub fn interrupt_flag() -> Arc<AtomicBool> {
    FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        #[cfg(unix)]
        // SIGHUP (the terminal closed) and SIGQUIT stop the work as SIGTERM does, nothing
        // written (issue 54 item 6)
        for sig in [
            signal_hook::consts::SIGINT,
            signal_hook::consts::SIGTERM,
            signal_hook::consts::SIGHUP,
            signal_hook::consts::SIGQUIT,
        ] {
            // the second signal ends the process at once (the first is only noted)
            let _ = signal_hook::flag::register_conditional_shutdown(sig, 130, flag.clone());
            let _ = signal_hook::flag::register(sig, flag.clone());
        }
        crate::atomic::stop_on(flag.clone());
        crate::measured::stop_on(flag.clone());
        flag
    })
    .clone()
}

/// Ctrl-Z (SIGTSTP) stops a command as its default action does, also where the kernel
/// discards it: a process group none of whose parents is in its session (a command run as a
/// session's leader in a pty — the review's terminal — or whose shell has gone: issue 54 item
/// 6, Ctrl-Z did not suspend command-line work). A thread waits for SIGTSTP and stops the
/// process by SIGSTOP, which nothing discards; SIGCONT (`fg`) resumes the work where it was.
/// The command keeps no terminal state to restore (the progress bar is redrawn as it goes).
/// tests/cli/suspend_pty.rs.
pub fn stop_on_tstp() {
    #[cfg(unix)]
    if let Ok(mut signals) = signal_hook::iterator::Signals::new([signal_hook::consts::SIGTSTP]) {
        let _ = std::thread::Builder::new()
            .name("tstp".into())
            .spawn(move || {
                for _ in signals.forever() {
                    let _ = signal_hook::low_level::raise(signal_hook::consts::SIGSTOP);
                }
            });
    }
}

/// The watch of the library's long work ([`crate::analysis::work::Watch`], a fit's model
/// runs): a counter on stderr on a terminal, and Ctrl-C (SIGINT) or SIGTERM stops the work.
pub struct Watcher {
    flag: Arc<AtomicBool>,
    bar: indicatif::ProgressBar,
}

impl Watcher {
    /// Counting steps named `unit` ("model runs") on a terminal.
    pub fn new(unit: &str) -> Watcher {
        let flag = interrupt_flag();
        let bar = if std::io::stderr().is_terminal() {
            let template = format!("{{spinner}} {{pos}} {unit}, {{elapsed}} (Ctrl-C stops)");
            let style = indicatif::ProgressStyle::with_template(&template)
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner());
            indicatif::ProgressBar::new_spinner().with_style(style)
        } else {
            indicatif::ProgressBar::hidden()
        };
        Watcher { flag, bar }
    }
}

impl crate::analysis::work::Watch for Watcher {
    fn step(&self, done: u64) -> bool {
        if crate::fault::Fault::SlowWork.active() {
            // test-only (crate::fault): slow enough for a test to signal mid-work
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        self.bar.set_position(done);
        !self.flag.load(Ordering::Relaxed)
    }
}

impl Drop for Watcher {
    fn drop(&mut self) {
        self.bar.finish_and_clear();
    }
}

/// Run `work` over `items` in chunks, with a bar and the interruption check between them.
fn chunked<T: Sync, R>(
    items: &[T],
    unit_cost: u64,
    mut work: impl FnMut(&[T]) -> anyhow::Result<Vec<R>>,
) -> anyhow::Result<Vec<R>> {
    let flag = interrupt_flag();
    let total = items.len() as u64;
    let bar = if std::io::stderr().is_terminal() && total * unit_cost >= SHOW_FROM {
        let style = indicatif::ProgressStyle::with_template(
            "{bar:40} {pos}/{len} impacts, {eta} left (Ctrl-C stops)",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
        indicatif::ProgressBar::new(total).with_style(style)
    } else {
        indicatif::ProgressBar::hidden()
    };
    let mut out = Vec::with_capacity(items.len());
    for chunk in items.chunks(CHUNK) {
        if flag.load(Ordering::Relaxed) {
            bar.finish_and_clear();
            return Err(Interrupted.into());
        }
        out.extend(work(chunk)?);
        bar.inc(chunk.len() as u64);
    }
    bar.finish_and_clear();
    Ok(out)
}

/// [`cor_vs_zeta`] with progress and interruption; the same rows in the same order.
pub fn zeta_rows(
    lambdas: &[f64],
    zetas: &[f64],
    law: ContactLaw,
) -> anyhow::Result<Vec<ZetaPoint>> {
    let grid: Vec<(f64, f64)> = lambdas
        .iter()
        .flat_map(|&l| zetas.iter().map(move |&z| (l, z)))
        .collect();
    chunked(&grid, cost(law), |chunk| {
        // a chunk may span two λ: one call per λ run within it
        let mut rows = Vec::with_capacity(chunk.len());
        for run in chunk.chunk_by(|a, b| a.0.to_bits() == b.0.to_bits()) {
            let z: Vec<f64> = run.iter().map(|p| p.1).collect();
            rows.extend(cor_vs_zeta(&[run[0].0], &z, law)?);
        }
        Ok(rows)
    })
}

/// [`cor_vs_velocity`] with progress and interruption; the same rows in the same order.
pub fn velocity_rows(
    params: &ImpactParams,
    law: ContactLaw,
    speeds: &[f64],
) -> anyhow::Result<Vec<VelocityPoint>> {
    chunked(speeds, cost(law), |chunk| {
        cor_vs_velocity(params, law, chunk).map_err(anyhow::Error::from)
    })
}

/// The design map ([`crate::map::compute`]) pass by pass on all cores, with the bar over its
/// cells; a SIGINT or SIGTERM stops the pass under way (each cell looks at the flag) and the
/// command ends with [`Interrupted`].
pub fn map(spec: crate::map::MapSpec) -> anyhow::Result<crate::map::Map> {
    let progress = Progress::new(spec.cells() as u64, cost(spec.law) as f64, "cells");
    let mut map = crate::map::Map::new(spec);
    while let Some(pass) = map.refine_until(&progress.flag) {
        if !pass.complete {
            progress.check()?;
        }
        progress.advance(pass.evaluated as u64);
    }
    progress.check()?;
    progress.finish();
    Ok(map)
}

/// Long work its caller does in steps (the Monte Carlo's blocks of samples): the bar of
/// [`velocity_rows`] on stderr and the same Ctrl-C check between steps.
pub struct Progress {
    flag: Arc<AtomicBool>,
    bar: indicatif::ProgressBar,
}

impl Progress {
    /// `total` units of `unit_cost` linear-law impacts each, named `unit` on the bar.
    pub fn new(total: u64, unit_cost: f64, unit: &str) -> Progress {
        let flag = interrupt_flag();
        let worth = total as f64 * unit_cost >= SHOW_FROM as f64;
        let bar = if std::io::stderr().is_terminal() && worth {
            let template =
                format!("{{bar:40}} {{pos}}/{{len}} {unit}, {{eta}} left (Ctrl-C stops)");
            let style = indicatif::ProgressStyle::with_template(&template)
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar());
            indicatif::ProgressBar::new(total).with_style(style)
        } else {
            indicatif::ProgressBar::hidden()
        };
        Progress { flag, bar }
    }

    /// Before a step: [`Interrupted`] once a SIGINT or SIGTERM came.
    pub fn check(&self) -> anyhow::Result<()> {
        if self.flag.load(Ordering::Relaxed) {
            self.bar.finish_and_clear();
            return Err(Interrupted.into());
        }
        Ok(())
    }

    /// After a step of `n` units.
    pub fn advance(&self, n: u64) {
        self.bar.inc(n);
    }

    /// The work is done: the bar goes.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
