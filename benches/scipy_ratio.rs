//! bouncelab's 4 × 400 COR-vs-ζ sweep against the same sweep in SciPy's `solve_ivp` (RK45,
//! rtol 1e-10, terminal event at F = 0), timed in the same run; prints the ratio of medians
//! and the accuracy of both against the closed form at λ = 0 (Eq. 28) and against each other.
//! Run: `cargo bench --bench scipy_ratio` (needs python3 with numpy and scipy).

mod common;

use bouncelab::ContactLaw;
use bouncelab::analysis::sweep::{cor_vs_zeta, log_space};
use common::{median, quick};
use std::process::Command;
use std::time::Instant;

const LAMBDAS: [f64; 4] = [0.0, 0.4, 1.0, 1.3];

fn maxwell(zeta: f64) -> f64 {
    if zeta >= 1.0 {
        0.0
    } else {
        (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp()
    }
}

fn main() {
    let zetas = log_space(0.01, 100.0, 400);
    let mut times = Vec::new();
    let mut ours = Vec::new();
    // BENCH_QUICK=1 (`benches/figures.sh --quick`): a few runs each side, to check it runs
    let (runs, scipy_runs) = if quick() { (5, "1") } else { (101, "3") };
    for _ in 0..runs {
        let t0 = Instant::now();
        ours = cor_vs_zeta(&LAMBDAS, &zetas, ContactLaw::Linear).unwrap();
        times.push(t0.elapsed().as_secs_f64());
    }
    let ours_median = median(times);
    println!(
        "bouncelab sweep 4x400: median {:.3} ms over {runs} runs",
        ours_median * 1e3
    );

    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/benches/scipy_sweep.py");
    let run = Command::new("python3").args([script, scipy_runs]).output();
    let Some(out) = common::scipy_output(run) else {
        return;
    };
    let text = String::from_utf8_lossy(&out.stdout);
    let median_s = field(&text, "\"median_s\": ").expect("median_s in the script's output");
    let cors: Vec<f64> = text[text.find("\"cor\": [").unwrap() + 8..]
        .trim_end()
        .trim_end_matches("]}")
        .split(',')
        .map(|s| s.trim().parse().unwrap())
        .collect();
    println!(
        "scipy solve_ivp RK45 rtol 1e-10 sweep 4x400: median {median_s:.3} s over {scipy_runs} runs"
    );
    println!("ratio (scipy / bouncelab): {:.0}x", median_s / ours_median);

    let (mut ours_err, mut scipy_err, mut diff) = (0.0f64, 0.0f64, 0.0f64);
    for (i, row) in ours.iter().enumerate() {
        diff = diff.max((row.cor - cors[i]).abs());
        if row.lambda == 0.0 {
            ours_err = ours_err.max((row.cor - maxwell(row.zeta)).abs());
            scipy_err = scipy_err.max((cors[i] - maxwell(row.zeta)).abs());
        }
    }
    println!("max |e - closed form| at λ = 0: bouncelab {ours_err:.1e}, scipy {scipy_err:.1e}");
    println!("max |e_bouncelab - e_scipy| over all 1600 points: {diff:.1e}");
}

fn field(text: &str, key: &str) -> Option<f64> {
    let rest = &text[text.find(key)? + key.len()..];
    rest[..rest.find(',')?].trim().parse().ok()
}
