//! A 3-parameter (K_p, c, K_r) linear-law fit to a 2 000-sample force–time trace with noise
//! and an unknown time offset, against the same fit in SciPy (`least_squares` over
//! `solve_ivp`, benches/fit_scipy.py) timed in the same run; prints both medians and the ratio.
//! Run: `cargo bench --bench fit` (the SciPy side needs python3 with numpy and scipy).

mod common;
// the trace read between the solver's samples, as the fit tests read it
#[path = "../tests/support/fit_common/force.rs"]
mod force;
// the trace's ball, the fit's start and the noise, as tests/fit_memory.rs fits them
#[path = "../tests/support/fit_common/bench_ball.rs"]
mod bench_ball;

use bench_ball::{normals, start, truth};
use bouncelab::ContactLaw;
use bouncelab::analysis::fit::{FitData, Param, fit};
use bouncelab::measured::Trace;
use bouncelab::{SolveOptions, simulate};
use common::{median, quick};
use std::process::Command;
use std::time::Instant;

/// The parameters the fit frees.
const FREE: [Param; 3] = [Param::KP, Param::C, Param::KR];

/// 2 000 samples 5 µs apart, contact from 0.8123 ms, noise 1 N (a fixed pseudo-random
/// sequence, so both sides fit the same numbers), baseline 0.3 N; as CSV text.
fn trace_csv() -> String {
    dense_csv(2000, 5e-6)
}

/// `rows` samples `dt` apart from −1.7 ms, otherwise as [`trace_csv`].
fn dense_csv(rows: usize, dt: f64) -> String {
    let r = simulate(
        &truth(),
        ContactLaw::Linear,
        &SolveOptions::default().with_samples(20_001),
    )
    .unwrap();
    let h = &r.history;
    let tf = *h.t.last().unwrap();
    let mut normal = normals(12345);
    let mut text = String::from("time_s,force_N\n");
    for i in 0..rows {
        let t = -1.7e-3 + i as f64 * dt;
        let f = force::force_at(h, tf, t - 0.8123e-3);
        text.push_str(&format!("{t:e},{:e}\n", f + 0.3 + normal()));
    }
    text
}

/// Dense traces over the same 10 ms (issue 30, item 4: binned to the model's resolution):
/// parse and fit timed apart, medians of `runs`.
fn dense(rows: usize, runs: usize) {
    let csv = dense_csv(rows, 1e-2 / rows as f64);
    let (mut parse, mut fits) = (Vec::new(), Vec::new());
    let mut last = None;
    for _ in 0..runs {
        let t0 = Instant::now();
        let trace = Trace::parse(&csv).unwrap();
        parse.push(t0.elapsed().as_secs_f64());
        let t1 = Instant::now();
        let f = fit(&start(), ContactLaw::Linear, FitData::Trace(&trace), &FREE).unwrap();
        fits.push(t1.elapsed().as_secs_f64());
        last = Some(f);
    }
    let f = last.unwrap();
    println!(
        "dense trace, {rows} rows: parse median {:.1} ms, fit median {:.1} ms over {runs} runs, {} iterations, rms {:.4} N, peak memory of the process so far {}",
        median(parse) * 1e3,
        median(fits) * 1e3,
        f.iterations,
        f.rms_residual,
        peak_memory()
    );
    for e in &f.fitted {
        println!("  {} = {:.6e} ± {:.2e}", e.name, e.value, e.std_error);
    }
}

/// The process's peak resident memory (Linux: VmHWM in /proc/self/status).
fn peak_memory() -> String {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .map(|l| l["VmHWM:".len()..].trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into())
}

fn main() {
    let runs = |n: usize| if quick() { 1 } else { n };
    dense(10_000, runs(21));
    dense(100_000, runs(5));
    dense(999_999, runs(5));
    let csv = trace_csv();
    let trace = Trace::parse(&csv).unwrap();
    let start = start();
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..runs(31) {
        let t0 = Instant::now();
        let f = fit(&start, ContactLaw::Linear, FitData::Trace(&trace), &FREE).unwrap();
        times.push(t0.elapsed().as_secs_f64());
        last = Some(f);
    }
    let f = last.unwrap();
    let ours = median(times);
    println!(
        "bouncelab fit (k_p, c, k_r, t0, baseline) to 2000 samples: median {:.2} ms over 31 runs, {} iterations",
        ours * 1e3,
        f.iterations
    );
    for e in &f.fitted {
        println!("  {} = {:.6e} ± {:.2e}", e.name, e.value, e.std_error);
    }
    println!(
        "  time_offset = {:.6e} s, rms {:.4} N",
        f.time_offset.as_ref().unwrap().value,
        f.rms_residual
    );

    let dir = std::env::temp_dir().join(format!("bouncelab-fit-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("trace.csv");
    std::fs::write(&path, &csv).unwrap();
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/benches/fit_scipy.py");
    let out = Command::new("python3")
        .arg(script)
        .arg(&path)
        .arg(if quick() { "1" } else { "5" })
        .output();
    let _ = std::fs::remove_dir_all(&dir);
    let Some(out) = common::scipy_output(out) else {
        return;
    };
    let text = String::from_utf8_lossy(&out.stdout);
    print!("{text}");
    if let Some(m) = text
        .split("median_s ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|s| s.parse::<f64>().ok())
    {
        println!("ratio (scipy / bouncelab): {:.0}x", m / ours);
    }
}
