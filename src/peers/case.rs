//! The bounce an export is for (issue 52 item 8, docs/peers.md §5 "The case asked"): the
//! normal model of every code is calibrated at the normal speed v·sinθ of that bounce (the
//! normal contact sees nothing else), a pair's at its closing speed; and since the codes'
//! spheres are solid (κ = I/(m R²) = 2/5, `model::materials::SOLID_INERTIA_FACTOR`) while a
//! ball may not be (a tennis ball's 0.6105), every snippet states both κ and bouncelab's own
//! answer for the bounce at the code's κ, so that a user can check the paste against it (652
//! against 427 rad/s out for the tennis ball at 30 m/s and 16° with μ 0.6: the difference is
//! κ's, not the export's).

use serde::Serialize;
use std::fmt::Write;

/// The bounce asked for and what bouncelab says of it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExportCase {
    /// The incoming speed |v|, m/s (a pair's: the closing speed, the partner at rest).
    pub speed: f64,
    /// θ between the path and the surface, degrees (90: head-on).
    pub angle_deg: f64,
    /// The incoming spin ω, rad/s.
    pub spin: f64,
    /// v·sinθ, m/s: the speed the normal model is calibrated at (the export's `v0`).
    pub normal_speed: f64,
    /// The partner of a pair (`--pair`): the speeds are closing speeds.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pair: Option<String>,
    /// The codes' sphere's κ, 0.4 (solid).
    pub inertia_factor_code: f64,
    /// The ball's κ.
    pub inertia_factor_ball: f64,
    /// bouncelab's answer for this bounce at the code's κ.
    pub answer: CaseAnswer,
}

/// bouncelab's own bounce (the Christoforou–Yigit normal model and the export's tangential
/// one, or none), SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseAnswer {
    /// The κ it was run at (the code's).
    pub inertia_factor: f64,
    /// v_x out, m/s.
    pub vx_out: f64,
    /// v_y out (normal, away from the surface), m/s.
    pub vy_out: f64,
    /// ω out, rad/s.
    pub spin_out: f64,
    /// e_y = v_y,out / v_y,in.
    pub cor_normal: f64,
    /// ω out at the ball's own κ, where it differs from the code's (with a tangential model).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin_out_ball_kappa: Option<f64>,
    /// v_x out at the ball's own κ, likewise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vx_out_ball_kappa: Option<f64>,
}

impl ExportCase {
    /// The comment lines a snippet carries; `c` opens a comment, `end` closes it; `target`
    /// is the COR the export is calibrated to, said beside the answer's where they differ.
    pub fn lines(&self, out: &mut String, c: &str, end: &str, target: f64) {
        let who = if self.pair.is_some() {
            "the pair's closing speed"
        } else {
            "the bounce"
        };
        let _ = if self.angle_deg < 90.0 {
            writeln!(
                out,
                "{c} calibrated for {who} at v = {} m/s, θ = {}°, ω = {} rad/s: the normal model at \
                 the normal speed v·sinθ = {} m/s{end}",
                num(self.speed),
                num(self.angle_deg),
                num(self.spin),
                num(self.normal_speed)
            )
        } else {
            writeln!(
                out,
                "{c} calibrated for {who} at v = {} m/s head-on: the COR holds at this speed \
                 only (export again with --v0 for another){end}",
                num(self.speed)
            )
        };
        let _ = writeln!(
            out,
            "{c} the code's sphere is solid: κ = I/(m R²) = {}; this ball's κ = {}{end}",
            num(self.inertia_factor_code),
            num(self.inertia_factor_ball)
        );
        let a = &self.answer;
        let _ = writeln!(
            out,
            "{c} bouncelab for this bounce at κ = {}: v_x,out = {} m/s, v_y,out = {} m/s, \
             ω_out = {} rad/s (e_y = {}){end}",
            num(a.inertia_factor),
            short(a.vx_out),
            short(a.vy_out),
            short(a.spin_out),
            short(a.cor_normal)
        );
        // a target of the user's (`--cor`, a measured COR, the curve's mean) is not the
        // model's e_y at this speed: the code will bounce at the target, bouncelab at e_y
        if short(target) != short(a.cor_normal) {
            let _ = writeln!(
                out,
                "{c} this export's target COR {} is not bouncelab's e_y = {} for this bounce: \
                 the code's v_y,out will be {} m/s, bouncelab's {} m/s{end}",
                short(target),
                short(a.cor_normal),
                short(target * self.normal_speed),
                short(a.vy_out)
            );
        }
        if let (Some(w), Some(vx)) = (a.spin_out_ball_kappa, a.vx_out_ball_kappa) {
            let _ = writeln!(
                out,
                "{c} (at the ball's own κ = {}: v_x,out = {} m/s, ω_out = {} rad/s){end}",
                num(self.inertia_factor_ball),
                short(vx),
                short(w)
            );
        }
    }
}

/// A number in a comment line: six digits as the text answers give them (15, not
/// 14.999999999999998: v·sinθ of 30 m/s at 30°); comments are read, not pasted (issue 52).
fn num(x: f64) -> String {
    crate::text::given(x, 6)
}

/// Six significant digits: what a paste is checked to.
fn short(x: f64) -> String {
    crate::text::sig(x, 6)
}
