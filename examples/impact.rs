//! One impact of an embedded preset, printed: `cargo run --example impact [PRESET [V0]]`
//! (default: the golf ball at 3 m/s).

mod common;

use bouncelab::{Ball, BallError};

fn main() -> std::process::ExitCode {
    common::exit(run())
}

fn run() -> Result<(), BallError> {
    let mut args = std::env::args().skip(1);
    let preset = args.next().unwrap_or_else(|| "golf".into());
    let v0 = match args.next() {
        Some(v) => v.parse().unwrap_or(f64::NAN), // not a number: refused as "invalid v0"
        None => 3.0,
    };
    let ball = Ball::from_preset(&preset)?.with_v0(v0)?;
    let r = ball.impact()?;
    println!(
        "{}, {} law, v0 = {} m/s",
        ball.label(),
        ball.law,
        ball.params.v0
    );
    println!("  λ = K_r/K_p          {:.4}", ball.lambda());
    println!("  ζ = √(m K_p)/(2c)    {:.4}", ball.zeta());
    println!("  COR e                {:.4}", r.cor);
    println!("  peak force F_m       {:.1} N", r.max_force);
    match r.contact_time {
        Some(t) => println!("  contact time t_f     {:.3} ms", t * 1e3),
        None => println!("  no rebound (the ball stays at the wall)"),
    }
    println!("  peak indentation z_m {:.3} mm", r.max_indentation * 1e3);
    println!(
        "  permanent flat z_f   {:.3} mm",
        r.permanent_indentation * 1e3
    );
    if let Some(e) = r.energy {
        println!(
            "  energy: {:.4} J in, {:.4} J out; dashpot {:.4} J, contact {:.4} J, spring {:.4} J",
            e.initial_kinetic, e.final_kinetic, e.dashpot, e.contact, e.spring
        );
    }
    Ok(())
}
