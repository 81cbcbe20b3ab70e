//! One normal impact of a [`Ball`] on a surface (docs/surfaces.md §1), as `bouncelab run
//! --surface` runs it: on the rigid plate today's impact, unchanged; on a surface that gives or
//! moves, the ball against that surface at rest (docs/targets.md), reported as an impact.

use super::{Ball, BallError, MAX_SAMPLES};
use crate::oblique::normal_response;
use crate::solver::{History, ImpactResponse};
use crate::target::{Target, collide, history};

impl Ball {
    /// This ball's impact at its v0 on `surface` (at rest), with `samples` history samples
    /// (0: none; else 2 … [`MAX_SAMPLES`]). On a rigid, immovable surface it is
    /// [`Ball::impact`] (or [`Ball::impact_history`]) itself. Elsewhere its COR is the ball's
    /// rebound over its arrival (the apparent COR, = e for a fixed surface), its history the
    /// chain's (the displacement is the ball's relative to the surface, α = z + y + s), and it
    /// carries no energy audit.
    pub fn impact_on(&self, surface: &Target, samples: usize) -> Result<ImpactResponse, BallError> {
        let rigid = surface.is_rigid() && surface.mass == f64::INFINITY && surface.speed == 0.0;
        if rigid {
            return match samples {
                0 => self.impact(),
                n => self.impact_history(n),
            };
        }
        if samples != 0 && !(2..=MAX_SAMPLES).contains(&samples) {
            return Err(BallError::Samples(samples));
        }
        let v = self.params.v0;
        let w0 = self.params.omega0();
        if samples == 0 {
            let c = collide(&self.params, self.law, surface, v, None)?;
            return Ok(normal_response(&self.params, self.law, &c, w0));
        }
        let h = history(&self.params, self.law, surface, v, samples)?;
        let mut r = normal_response(&self.params, self.law, &h.collision, w0);
        r.history = History {
            t: h.t,
            force: h.force,
            indentation: h.indentation,
            displacement: h.displacement,
        };
        Ok(r)
    }
}

/// A surface's line for a text header (the command line's, and the explanations the Python
/// package gives): "surface steel-plate (rigid, immovable)", or with its K_s, c_s, moving
/// mass and μ, and the quantities given over the surface's own.
pub fn surface_label<S: AsRef<str>>(
    name: &str,
    (stiffness, damping, mass): (f64, f64, f64),
    friction: Option<f64>,
    overrides: &[S],
) -> String {
    let human = crate::text::human;
    let mut parts = Vec::new();
    if stiffness.is_infinite() {
        parts.push("rigid".to_string());
    } else {
        parts.push(format!("K_s {} N/m", human(stiffness, 4)));
        parts.push(format!("c_s {} kg/s", human(damping, 4)));
    }
    if mass.is_infinite() {
        parts.push("immovable".into());
    } else {
        parts.push(format!("M {} kg", human(mass, 4)));
    }
    if let Some(mu) = friction {
        parts.push(format!("μ {}", human(mu, 4)));
    }
    let over = if overrides.is_empty() {
        String::new()
    } else {
        let given: Vec<&str> = overrides.iter().map(AsRef::as_ref).collect();
        format!("; given: {}", given.join(", "))
    };
    format!("surface {name} ({}{over})", parts.join(", "))
}
