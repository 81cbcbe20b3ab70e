//! Memory of a dense trace fit (issue 30 item 4: a million rows in ≤ 100 MB), counted by the
//! allocator rather than read off the resident set, which other processes' pages and the
//! allocator's caching blur on a shared machine: every byte the reader and the fit allocate,
//! the highest total in use at once.

#[path = "support/fit_common/force.rs"]
mod force;
// the ball of benches/fit.rs and its fit's start
#[path = "support/fit_common/bench_ball.rs"]
mod bench_ball;

use bench_ball::{start, truth};
use bouncelab::analysis::fit::{FitData, Param, fit};
use bouncelab::measured::Trace;
use bouncelab::{ContactLaw, SolveOptions, simulate};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the bytes in use and their peak.
struct Counting;

static IN_USE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

fn grew(bytes: usize) {
    let now = IN_USE.fetch_add(bytes, Ordering::SeqCst) + bytes;
    PEAK.fetch_max(now, Ordering::SeqCst);
}

// SAFETY: every call is passed on to `System` unchanged; the counters only watch.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's layout, as `System` requires
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from `alloc`/`realloc` above with this layout
        unsafe { System.dealloc(ptr, layout) };
        IN_USE.fetch_sub(layout.size(), Ordering::SeqCst);
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: as for `dealloc`, and `new_size` is the caller's
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            // a moving realloc holds both blocks for a moment
            grew(new_size);
            IN_USE.fetch_sub(layout.size(), Ordering::SeqCst);
        }
        p
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// benches/fit.rs's dense trace as CSV text: `rows` samples over 10 ms, contact from
/// 0.8123 ms after −1.7 ms, baseline 0.3 N, noise of ±1 N from a fixed sequence.
fn csv(rows: usize) -> String {
    let opts = SolveOptions::default().with_samples(20_001);
    let h = simulate(&truth(), ContactLaw::Linear, &opts)
        .unwrap()
        .history;
    let tf = *h.t.last().unwrap();
    let mut state = 12345u64;
    let mut text = String::from("time_s,force_N\n");
    let dt = 1e-2 / rows as f64;
    for i in 0..rows {
        let t = -1.7e-3 + i as f64 * dt;
        let f = force::force_at(&h, tf, t - 0.8123e-3);
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let noise = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0;
        text.push_str(&format!("{t:e},{:e}\n", f + 0.3 + noise));
    }
    text
}

/// Bytes a row may take beside the text: the 100 MB goal for the most rows a file may hold
/// (999 999), less the text the command line holds while it reads (25–45 MB), with room.
const PER_ROW: usize = 55;

#[test]
fn a_dense_trace_is_read_and_fitted_in_at_most_55_bytes_a_row() {
    // 100 000 rows: the memory grows with the rows alone (bins, history and work are a few
    // thousand samples), and a million rows would take a minute to read in a debug build.
    // Measured 32.0 bytes a row read (time, force, line, column) and 40.6 read and fitted (the
    // model at every row for the report) — at a million rows 40.6 MB beside the text
    let rows = 100_000;
    let text = csv(rows);
    let before = IN_USE.load(Ordering::SeqCst);
    PEAK.store(before, Ordering::SeqCst);
    let trace = Trace::parse(&text).unwrap();
    let read = PEAK.load(Ordering::SeqCst) - before;
    let start = start();
    let free = [Param::KP, Param::C, Param::KR];
    let f = fit(&start, ContactLaw::Linear, FitData::Trace(&trace), &free).unwrap();
    let all = PEAK.load(Ordering::SeqCst) - before;
    assert!(f.identified, "{f:?}");
    let per_row = |bytes: usize| bytes as f64 / rows as f64;
    eprintln!(
        "{} bytes of text; {:.1} bytes a row read, {:.1} read and fitted",
        text.len(),
        per_row(read),
        per_row(all)
    );
    assert!(all <= PER_ROW * rows, "{:.1} bytes a row", per_row(all));
}
