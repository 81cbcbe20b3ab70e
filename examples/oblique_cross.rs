//! The tangential COR e_x = −v_c,out/v_c,in against the angle of incidence, the trend Cross
//! measured (Am. J. Phys. 70, 1093 (2002), "Grip-slip behavior of a bouncing ball"): a ball
//! that slides throughout at grazing incidence (e_x from −1 upward, along the closed form
//! −1 + μ(1 + e_y)(1 + 1/κ) tan θ), that reaches rolling (e_x = 0) and then grips, its
//! friction reversing, so that e_x turns positive at steeper incidence (docs/oblique.md §7).
//! `cargo run --example oblique_cross -- FILE.svg` writes the figure (and its CSV on stdout).

use bouncelab::Ball;
use bouncelab::figure::{Axis, Figure, Kind, Marker, Series, Style, svg};
use bouncelab::oblique::{Oblique, mindlin_ratio, solve};
use bouncelab::text::number as num;
use std::io::Write;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .unwrap_or("oblique-cross.svg".into());
    let mut out = std::io::stdout().lock();
    writeln!(out, "ball,mu,angle_deg,cor_tangential,slid_throughout")?;
    let mut series = Vec::new();
    let cases = [
        ("superball", 0.5, 0),
        ("tennis", 0.5, 1),
        ("tennis", 0.2, 2),
    ];
    for (name, mu, color) in cases {
        let ball = Ball::from_preset(name)?;
        let p = ball.params;
        let kappa = ball.inertia_factor();
        let k_t = mindlin_ratio(ball.poisson_ratio.unwrap_or(0.5)) * p.k_p;
        let (mut model, mut sliding) = (Vec::new(), Vec::new());
        for i in 0..=80 {
            let angle = 5.0 + i as f64;
            let o = Oblique::new(angle, 0.0, mu, k_t, kappa, ball.radius())?;
            let r = solve(&p, p.v0, &o, 0)?;
            let ex = r.cor_tangential.unwrap_or(f64::NAN);
            writeln!(out, "{name},{mu},{angle},{},{}", num(ex), r.slid_throughout)?;
            model.push((angle, ex));
            // sliding throughout, in closed form: e_x = −1 + μ(1 + e_y)(1 + 1/κ) tan θ
            let slide =
                -1.0 + mu * (1.0 + r.cor_normal) * (1.0 + 1.0 / kappa) * angle.to_radians().tan();
            if slide <= 0.2 {
                sliding.push((angle, slide));
            }
        }
        let label = format!("{name}, μ = {mu} (model)");
        series.push(
            Series::new(
                &label,
                &format!("{name}-{mu}"),
                Kind::Model,
                Style::Solid,
                color,
            )
            .with_points(model),
        );
        let label = format!("{name}, μ = {mu}: sliding throughout");
        let id = format!("{name}-{mu}-sliding");
        series.push(
            Series::new(
                &label,
                &id,
                Kind::Reference,
                Style::Markers(Marker::Circle),
                color,
            )
            .with_points(sliding),
        );
    }
    let fig = Figure::new(
        "Tangential COR against the angle of incidence".into(),
        "e_x = −v_c,out / v_c,in, no spin, each ball at its preset's speed; Cross (2002): \
         −1 sliding at grazing incidence, rising through 0 (rolling) to > 0 (grip)"
            .into(),
        Axis::linear("angle of incidence to the surface (°)", "angle_deg", 1.0)
            .with_range(0.0, 90.0),
        Axis::linear("e_x", "cor_tangential", 1.0).with_range(-1.0, 0.8),
        series,
    );
    std::fs::write(&path, svg::render(&fig)?)?;
    eprintln!("wrote {path}");
    Ok(())
}
