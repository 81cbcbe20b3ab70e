//! What the benches that time SciPy beside bouncelab share (`mod common;` in each): the median
//! of the timings, `BENCH_QUICK`, and the SciPy side's output or why it was skipped.

use std::process::Output;

/// The median of `v` (the upper one of an even count): the figure each side quotes.
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// `BENCH_QUICK=1` (`benches/figures.sh --quick`): each part once or a few times, to check
/// that it runs, not to quote.
pub fn quick() -> bool {
    std::env::var_os("BENCH_QUICK").is_some()
}

/// The SciPy script's output, or `None` with the reason printed (its last line of stderr and
/// how to install what it needs, or that there is no python3): a machine without SciPy
/// skips the comparison, never fails the bench.
pub fn scipy_output(run: std::io::Result<Output>) -> Option<Output> {
    match run {
        Ok(o) if o.status.success() => Some(o),
        Ok(o) => {
            let err = String::from_utf8_lossy(&o.stderr);
            println!(
                "scipy comparison skipped: {}",
                err.lines().last().unwrap_or("")
            );
            println!("(install with: pip install numpy scipy)");
            None
        }
        Err(e) => {
            println!("scipy comparison skipped: python3 not found ({e})");
            None
        }
    }
}
