//! Fit the recoil spring K_r to a measured COR: `cargo run --example fit_cor [PRESET COR [V0]]`
//! (default: the superball's measured e = 0.75 at 3.12 m/s). Then check the fit by running
//! the fitted ball, and show how the fitted K_r moves with the COR measured.

mod common;

use bouncelab::{Ball, BallError};

fn main() -> std::process::ExitCode {
    common::exit(run())
}

fn run() -> Result<(), BallError> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let preset = args.first().map_or("superball", String::as_str);
    let cor: f64 = args.get(1).map_or(0.75, |s| s.parse().unwrap_or(f64::NAN));
    let mut ball = Ball::from_preset(preset)?;
    if let Some(v0) = args.get(2) {
        ball = ball.with_v0(v0.parse().unwrap_or(f64::NAN))?;
    }
    let fit = ball.fit_cor(cor)?;
    println!(
        "{} at v0 = {} m/s, ζ = {:.4}",
        ball.label(),
        ball.params.v0,
        fit.zeta
    );
    println!(
        "measured e = {cor}: K_r = {:.1} N/m (λ = {:.4}); the preset has K_r = {:.1} N/m",
        fit.k_r, fit.lambda, ball.params.k_r
    );
    // the fitted ball gives the measured COR back
    let check = ball.clone().with_lambda(fit.lambda)?.impact()?;
    println!("model e at the fit: {:.12}", check.cor);
    assert!(
        (check.cor - cor).abs() < 1e-9,
        "the fit does not reproduce the COR"
    );
    for e in [cor - 0.02, cor + 0.02] {
        match ball.fit_cor(e) {
            Ok(f) => println!(
                "  e = {e:.2} → K_r = {:.1} N/m (λ = {:.4})",
                f.k_r, f.lambda
            ),
            Err(err) => println!("  e = {e:.2} → {err}"),
        }
    }
    Ok(())
}
