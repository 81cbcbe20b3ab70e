//! Two-body impacts through [`Ball`]: a ball against a target of finite mass, moving, with a
//! surface that gives ([`crate::target`], docs/targets.md), as `bouncelab collide` and `bat`.

use super::{Ball, BallError};
use crate::model::contact::ContactLaw;
use crate::solver::Method;
use crate::target::bat::{self, BatRun};
use crate::target::{Collision, Target, collide};
use serde::Serialize;

/// One two-body impact as the command line reports it: the ball, the target and the answer
/// (whose fields sit at the top level of the JSON: `cor`, `apparent_cor`, `ball_speed_out`, …).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CollisionReport {
    /// The ball's preset name (`None` for a ball that is no preset).
    pub ball: Option<String>,
    /// The ball as every JSON answer names it (docs/cli.md, "The ball object"): `ball_record`,
    /// for `ball` was already this report's preset name, a string, and stays one.
    pub ball_record: super::BallRecord,
    /// The ball's contact law.
    pub law: ContactLaw,
    /// The ball's mass m (kg).
    pub ball_mass: f64,
    /// The ball's speed toward the target before the impact (m/s).
    pub ball_speed: f64,
    /// What it hit, and whether it is rigid (the JSON `target`; its mass, speed, K_s and c_s
    /// read through it as a [`Target`]'s).
    pub target: super::TargetRecord,
    /// The answer, SI.
    #[serde(flatten)]
    pub collision: Collision,
    /// Ball on ball: the pair's effective mass m_eff = m1 m2/(m1 + m2) as DEM codes use it
    /// (kg; the reduced mass).
    pub effective_mass: Option<f64>,
    /// Ball on ball: the pair's effective radius R_eff = R1 R2/(R1 + R2) (m).
    pub effective_radius: Option<f64>,
    /// Ball on ball: the partner, named as the answer's ball is (the JSON `pair`, absent
    /// otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pair: Option<super::Partner>,
    /// What the caller should know about this answer: the ball's peak indentation, or its own
    /// compression α = z + y, beyond its radius ([`super::Reach::warning`]); `[]` when nothing.
    pub warnings: Vec<String>,
}

impl Ball {
    /// This ball at its speed v0 against `target` (docs/targets.md): the pair's COR, the
    /// apparent COR, both outgoing speeds, peak force and contact time.
    ///
    /// ```
    /// use bouncelab::{Ball, target::Target};
    /// let golf = Ball::from_preset("golf")?;
    /// // the wall: today's impact
    /// let wall = golf.collide(&Target::wall())?;
    /// assert_eq!(wall.collision.cor, golf.impact()?.cor);
    /// // a club face of 0.2 kg at rest: the ball leaves faster than the club's share would say
    /// let face = golf.collide(&Target { mass: 0.2, ..Target::wall() })?;
    /// assert!(face.collision.apparent_cor < face.collision.cor);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn collide(&self, target: &Target) -> Result<CollisionReport, BallError> {
        self.collide_with(target, None)
    }

    /// [`Ball::collide`] with the solver forced: [`Method::Exact`] (a rigid target on the
    /// linear law, or a compliant one without flattening) or [`Method::Numeric`].
    pub fn collide_with(
        &self,
        target: &Target,
        method: Option<Method>,
    ) -> Result<CollisionReport, BallError> {
        let collision = collide(&self.params, self.law, target, self.params.v0, method)?;
        let warnings = self
            .collision_warning(target, self.params.v0, &collision)
            .into_iter()
            // the record is of impacts on a rigid plate: the closing speed is the impact's
            .chain(self.calibration_warning(collision.closing_speed));
        Ok(CollisionReport {
            ball: self.name.clone(),
            ball_record: self.record_json(),
            law: self.law,
            ball_mass: self.params.mass,
            ball_speed: self.params.v0,
            target: super::TargetRecord::body(*target),
            collision,
            effective_mass: None,
            effective_radius: None,
            pair: None,
            warnings: warnings.into_iter().collect(),
        })
    }

    /// Ball on ball, head-on: this ball at its v0 against `other` coming at `other_speed`,
    /// with the pair's m_eff and R_eff (the radii of the presets' measurements; `None` for a
    /// ball that is no preset). With `surface` rigid (`(f64::INFINITY, _)`, the default) both
    /// balls deform, their chains in series on this ball's law (`target::pair`,
    /// docs/targets.md §8): identical balls at ±v bounce as one off the wall at v. A surface
    /// given as K_s, c_s stands for the other ball's give instead: it is then a body of its
    /// mass behind that surface (docs/targets.md §7).
    pub fn collide_ball(
        &self,
        other: &Ball,
        other_speed: f64,
        surface: (f64, f64),
    ) -> Result<CollisionReport, BallError> {
        let target = Target {
            mass: other.params.mass,
            speed: other_speed,
            stiffness: surface.0,
            damping: surface.1,
        };
        let mut r = if target.is_rigid() {
            let (p1, p2) = (&self.params, &other.params);
            let collision = crate::target::pair::collide(p1, p2, self.law, p1.v0, other_speed)?;
            // the reach is read on the reduced single chain (ball 1 against a rigid m*, the
            // old model), not on the pair's run: an estimate (docs/targets.md §8)
            let warnings = self.collision_warning(&target, p1.v0, &collision);
            let calibration = self.pair_calibration_warnings(other, collision.closing_speed);
            let warnings: Vec<String> = warnings.into_iter().chain(calibration).collect();
            CollisionReport {
                ball: self.name.clone(),
                ball_record: self.record_json(),
                law: self.law,
                ball_mass: p1.mass,
                ball_speed: p1.v0,
                // no surface spring (stiffness ∞), yet not rigid: the partner's chain deforms
                target: super::TargetRecord {
                    target,
                    rigid: false,
                },
                collision,
                effective_mass: None,
                effective_radius: None,
                pair: None,
                warnings,
            }
        } else {
            self.collide(&target)?
        };
        let partner = super::Partner::of(self, other);
        r.effective_mass = Some(r.collision.reduced_mass);
        r.effective_radius = partner.effective_radius;
        r.pair = Some(partner);
        Ok(r)
    }

    /// The records' warnings of this ball meeting `other` head-on at the closing speed
    /// `closing` (m/s), this ball's then the partner's, named as the partner's. Each record is
    /// of impacts on a rigid plate: in the pair's centre-of-mass frame each ball meets the
    /// other at m_other·v_c/(m1 + m2), the wall impact's speed for two identical balls (v each
    /// at ±v) and for a wall (m_other → ∞). `collide --target-preset` and `peers --pair`.
    pub fn pair_calibration_warnings(&self, other: &Ball, closing: f64) -> Vec<String> {
        let total = self.params.mass + other.params.mass;
        let own = self.calibration_warning(other.params.mass * closing / total);
        let partner = other
            .calibration_warning(self.params.mass * closing / total)
            .map(|w| {
                let who = format!(
                    "the partner ({})",
                    other.name.as_deref().unwrap_or("a ball")
                );
                super::warning_of(&who, &w)
            });
        own.into_iter().chain(partner).collect()
    }

    /// The warnings of a bat's run `r` for this ball: its peak indentation, or its own
    /// compression, beyond its radius in the game impact or in the BBCOR test, each named;
    /// its record's range; last, a ball that is not the standard's (the verdict is then not
    /// the test's: tests/cli/cli_targets.rs, `bat_names_the_standards_ball`).
    pub fn bat_warnings(&self, r: &BatRun) -> Vec<String> {
        let standard = &bat::BAT_STANDARDS[0];
        let not_standard = self.not_standards_ball(
            standard.name,
            "fires",
            standard.balls,
            "the verdict judges the bat with another ball",
        );
        let at_rest = Target {
            speed: 0.0,
            ..r.bat
        };
        let game_speed = r.game.closing_speed - r.bat.speed;
        [
            ("game", &r.game, r.bat, game_speed),
            ("BBCOR test", &r.test, at_rest, r.test.closing_speed),
        ]
        .into_iter()
        .filter_map(|(what, c, target, speed)| {
            self.collision_warning(&target, speed, c)
                .map(|w| format!("{what}: {w}"))
        })
        // the game's and the test's closing speeds against the record, in one warning
        .chain(self.speeds_warning(
            r.game.closing_speed.min(r.test.closing_speed),
            r.game.closing_speed.max(r.test.closing_speed),
        ))
        .chain(not_standard)
        .collect()
    }

    /// The warning of `c`, this ball's collision at `ball_speed` with `target`: its peak
    /// indentation, else the ball's own compression α = z + y, beyond its radius. On a rigid
    /// target the relative motion is the ball's impact at the reduced mass and the closing
    /// speed (`target::collide`), whose α_max [`super::Reach::warning`] reads exactly; on a
    /// compliant one the ball's compression is the chain's minus the surface's deflection
    /// (docs/targets.md §2), read off 4 001 samples of the run (`target::history`: a value from
    /// below, as the explorer's), unless α ≤ v_c t_f (α'' ≤ 0) keeps it within the radius.
    fn collision_warning(&self, target: &Target, ball_speed: f64, c: &Collision) -> Option<String> {
        let radius = self.radius();
        let duration = c.contact_time.unwrap_or(f64::INFINITY);
        let reduced = crate::model::params::ImpactParams {
            mass: c.reduced_mass,
            v0: c.closing_speed,
            ..self.params
        };
        if target.is_rigid() || c.max_indentation > radius || c.closing_speed * duration <= radius {
            let z_m = c.max_indentation;
            return super::reach(&reduced, self.law, c.method, z_m, duration, radius)?
                .warning(radius);
        }
        let h = crate::target::history(&self.params, self.law, target, ball_speed, 4001);
        match h {
            Ok(h) => {
                let own = h.displacement.iter().zip(&h.deflection).map(|(a, s)| a - s);
                super::displacement_warning(own.fold(0.0, f64::max), radius)
            }
            Err(e) => Some(format!(
                "the ball's peak displacement could not be checked against its radius: {e}"
            )),
        }
    }

    /// A bat of effective mass `bat_mass` at the impact point (rigid, or with `surface` =
    /// (K_s, c_s)): the batted-ball speed at `ball_speed` against `bat_speed`, and the NCAA
    /// BBCOR test's pair COR at 136 mph onto the bat at rest, judged against ≤ 0.50
    /// (docs/targets.md §5).
    pub fn bat(
        &self,
        bat_mass: f64,
        speeds: (f64, f64),
        surface: (f64, f64),
    ) -> Result<BatRun, BallError> {
        Ok(bat::run(&self.params, self.law, bat_mass, speeds, surface)?)
    }
}
