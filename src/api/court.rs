//! A court calibrated to a measured (μ, e) pair at the ITF court pace test (docs/oblique.md
//! §6, docs/surfaces.md): the surface's give that makes this ball's vertical COR at the test
//! (30 m/s at 16°: v_y = 30 sin 16°) the measured e.
//!
//! One number cannot fix two: e alone does not separate K_s from c_s. The calibration holds
//! K_s (the ball's own K_p unless given: an ASSUMPTION, said in every answer) and solves c_s on
//! the branch from the elastic surface (c_s = 0, where a spring in series returns what it
//! stores and e is highest) to the most dissipative one (the minimum of e over c_s); along it
//! e falls monotonically, so the answer is unique. Outside that branch's range the e asked for
//! is out of reach (an error with the range: exit 2).

use super::{Ball, BallError};
use crate::target::{Target, collide};
use serde::Serialize;

/// The ITF court pace test's speed (m/s) and angle (degrees), ITF CS 01/02.
pub const ITF_SPEED: f64 = 30.0;
/// The test's angle to the surface, degrees.
pub const ITF_ANGLE: f64 = 16.0;

/// A surface calibrated to a measured e at the ITF test.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CourtCalibration {
    /// The e asked for.
    pub surface_cor: f64,
    /// K_s held, N/m.
    pub stiffness: f64,
    /// c_s solved, kg/s.
    pub damping: f64,
    /// The e the calibrated surface gives at the test (the ball's rebound over arrival).
    pub cor: f64,
    /// The e reachable at this K_s, [lowest, highest].
    pub reachable: [f64; 2],
    /// What was assumed.
    pub assumption: String,
}

impl Ball {
    /// `court`'s answer, the command line's and Python's: the ITF court pace of this ball on
    /// `surface` (its K_s, c_s, M, K_t and c_t; μ `friction`, κ `inertia_factor` or the
    /// ball's), by [`Ball::court_pace_on`], with the words saying what it was computed on
    /// ("the model's bounce of … at 30 m/s and 16° without spin on surface …"); its warnings
    /// end with a ball that is not the test's ([`Ball::not_standards_ball`]).
    pub fn court_pace_on_surface(
        &self,
        friction: f64,
        inertia_factor: Option<f64>,
        surface: &super::SurfaceUsed,
    ) -> Result<(super::CourtPace, String), BallError> {
        let computed_on = format!(
            "the model's bounce of {} at 30 m/s and 16° without spin on {}",
            self.label(),
            surface.label()
        );
        let m = &surface.mechanics;
        let tangential = (m.tangential_stiffness, inertia_factor, m.tangential_damping);
        let mut pace = self.court_pace_on(friction, tangential, &m.target())?;
        pace.warnings.extend(surface.court_warnings());
        let standard = &crate::oblique::court::ITF_COURT_PACE;
        pace.warnings.extend(self.not_standards_ball(
            standard.name,
            "fires",
            standard.balls,
            "the rating judges the court with another ball",
        ));
        Ok((pace, computed_on))
    }

    /// The normal speed of the ITF court test, v sin θ as `oblique` takes it.
    pub fn itf_normal_speed() -> f64 {
        ITF_SPEED * ITF_ANGLE.to_radians().sin()
    }

    /// This ball's vertical COR at the ITF test on a surface of K_s, c_s and mass M at rest
    /// (its rebound over its arrival).
    fn itf_cor(&self, stiffness: f64, damping: f64, mass: f64) -> Result<f64, BallError> {
        let t = Target {
            stiffness,
            damping,
            mass,
            ..Target::wall()
        };
        let vy = Ball::itf_normal_speed();
        Ok(collide(&self.params, self.law, &t, vy, None)?.apparent_cor)
    }

    /// The surface (K_s held at `stiffness`, else this ball's K_p; its moving mass `mass`, ∞
    /// for a fixed one) whose c_s makes this ball's vertical COR at the ITF test `cor` (to
    /// 1e-10); an error with the reachable range when no c_s does.
    pub fn calibrate_court(
        &self,
        cor: f64,
        stiffness: Option<f64>,
        mass: f64,
    ) -> Result<CourtCalibration, BallError> {
        let bad = |field, value, reason: String| BallError::Invalid {
            field,
            value,
            reason,
        };
        if !(cor.is_finite() && cor > 0.0 && cor < 1.0) {
            return Err(bad("surface_cor", cor, "must lie in (0, 1)".into()));
        }
        let k = stiffness.unwrap_or(self.params.k_p);
        if !(k.is_finite() && k > 0.0) {
            return Err(bad(
                "surface_stiffness",
                k,
                "a calibrated surface needs a finite K_s > 0".into(),
            ));
        }
        let e = |c: f64| self.itf_cor(k, c, mass);
        let (c_min, e_min) = self.least_cor(k, mass)?;
        let e_top = e(0.0)?;
        let range = [e_min, e_top];
        if !(cor >= e_min && cor <= e_top) {
            return Err(bad(
                "surface_cor",
                cor,
                format!(
                    "out of reach: at the ITF test (30 m/s, 16°) this ball's e on a surface of \
                     K_s = {} N/m reaches {}–{} (c_s from 0 to {} kg/s); give another \
                     --surface-stiffness",
                    crate::text::short(k, 6),
                    crate::text::short(e_min, 5),
                    crate::text::short(e_top, 5),
                    crate::text::short(c_min, 4)
                ),
            ));
        }
        // bisection on the falling branch [0, c_min]: e(0) ≥ cor ≥ e(c_min)
        let (mut lo, mut hi) = (0.0, c_min);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if e(mid)? > cor {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-13 * hi {
                break;
            }
        }
        let damping = 0.5 * (lo + hi);
        Ok(CourtCalibration {
            surface_cor: cor,
            stiffness: k,
            damping,
            cor: e(damping)?,
            reachable: range,
            assumption: if stiffness.is_some() {
                "K_s as given; c_s solved on the branch below the elastic surface".into()
            } else {
                "K_s ASSUMED equal to the ball's K_p (e alone does not separate K_s from c_s); \
                 c_s solved on the branch below the elastic surface"
                    .into()
            },
        })
    }

    /// Where e(c_s) is least at K_s = `k`: a scan over c_s on a log grid spanning the
    /// surface's relaxation times around the contact's (√(m K_p) × 10⁻³ … 10⁴), then golden
    /// section on log c_s in the scan's best bracket.
    fn least_cor(&self, k: f64, mass: f64) -> Result<(f64, f64), BallError> {
        let scale = (self.params.mass * self.params.k_p).sqrt();
        let at = |x: f64| self.itf_cor(k, scale * 10f64.powf(x), mass);
        let n = 43;
        let xs: Vec<f64> = (0..n)
            .map(|i| -3.0 + 7.0 * i as f64 / (n - 1) as f64)
            .collect();
        let mut es = Vec::with_capacity(n);
        for &x in &xs {
            es.push(at(x)?);
        }
        let best = (0..n)
            .min_by(|&a, &b| es[a].total_cmp(&es[b]))
            .expect("a grid");
        let (mut a, mut b) = (xs[best.saturating_sub(1)], xs[(best + 1).min(n - 1)]);
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..60 {
            let (x1, x2) = (b - g * (b - a), a + g * (b - a));
            if at(x1)? < at(x2)? {
                b = x2;
            } else {
                a = x1;
            }
        }
        let x = 0.5 * (a + b);
        Ok((scale * 10f64.powf(x), at(x)?))
    }
}
