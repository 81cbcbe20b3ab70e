//! The time of a 10⁵-point ζ sweep (λ = 1, ζ log-spaced over 0.01 … 100, linear law), for the
//! comparison with the Python bindings in BENCHMARKS.md (`python/examples/sweep_timing.py`
//! times the same sweep): `cargo run --release --example sweep_timing [POINTS [RUNS]]`.

use bouncelab::analysis::sweep::log_space;
use bouncelab::{ContactLaw, sweep_zeta};
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let points: usize = args.first().map_or(Ok(100_000), |s| s.parse())?;
    let runs: usize = args.get(1).map_or(Ok(7), |s| s.parse())?;
    let zetas = log_space(0.01, 100.0, points);
    let mut times = Vec::with_capacity(runs);
    let mut sum = 0.0;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let rows = sweep_zeta(&[1.0], &zetas, ContactLaw::Linear)?;
        times.push(start.elapsed().as_secs_f64());
        sum += rows.iter().map(|r| r.cor).sum::<f64>();
    }
    times.sort_by(f64::total_cmp);
    println!(
        "rust: {points} points, {} runs: median {:.1} ms, min {:.1} ms (Σe = {sum:.6})",
        times.len(),
        times[times.len() / 2] * 1e3,
        times[0] * 1e3
    );
    Ok(())
}
