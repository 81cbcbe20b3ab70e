//! COR against ζ for λ = 0, 0.4 and 1 (the paper's Fig. 2), as CSV on stdout — the columns of
//! `bouncelab sweep zeta`: `cargo run --example cor_vs_zeta [POINTS] > fig2.csv`
//! (default 41 points per λ, log-spaced from ζ = 0.01 to 100).

use bouncelab::analysis::sweep::log_space;
use bouncelab::text::number as num;
use bouncelab::{ContactLaw, sweep_zeta};
use std::io::{self, BufWriter, Write};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let points: usize = match std::env::args().nth(1) {
        Some(n) => n.parse()?,
        None => 41,
    };
    let zetas = log_space(0.01, 100.0, points);
    let rows = sweep_zeta(&[0.0, 0.4, 1.0], &zetas, ContactLaw::Linear)?;
    let mut out = BufWriter::new(io::stdout().lock());
    writeln!(
        out,
        "lambda,zeta,cor,max_force_normalized,contact_time_normalized"
    )?;
    for r in &rows {
        writeln!(
            out,
            "{},{},{},{},{}",
            num(r.lambda),
            num(r.zeta),
            num(r.cor),
            num(r.max_force_normalized),
            r.contact_time_normalized.map(num).unwrap_or_default()
        )?;
    }
    out.flush()?;
    Ok(())
}
