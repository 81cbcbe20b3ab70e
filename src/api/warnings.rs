//! What the caller should know about an answer, carried with it (docs/guarantees.md, "Warnings
//! travel with the answer"): the JSON `warnings` array of run, sweep velocity, drop and peers,
//! a `warning:` line in text, and the explorer's readout.

use super::map_reach::cell_indentation;
use super::reach::reach;
use super::{Ball, BallError};
use crate::solver::ImpactResponse;
use crate::text::{number, short, sig};

/// The energy audit (docs/model.md §8) must close to this fraction of the impact energy; a
/// larger residual means the numbers were not computed to their promised accuracy.
pub const ENERGY_RESIDUAL_MAX: f64 = 1e-6;

/// `w` said of `who` among several balls: named after its "outside calibration:" (the
/// prefix every filter of calibration warnings reads, issue 52), else before it. `collide`'s
/// partner ("outside calibration: the partner (golf): impact speed …") and a figure of
/// several balls ("outside calibration: golf: impact speeds …") say theirs so.
///
/// ```
/// use bouncelab::api::warning_of;
/// assert_eq!(warning_of("golf", "outside calibration: impact speed 9 m/s"),
///            "outside calibration: golf: impact speed 9 m/s");
/// assert_eq!(warning_of("golf", "peak indentation 30 mm"), "golf: peak indentation 30 mm");
/// ```
pub fn warning_of(who: &str, w: &str) -> String {
    const OUTSIDE: &str = "outside calibration: ";
    match w.strip_prefix(OUTSIDE) {
        Some(rest) => format!("{OUTSIDE}{who}: {rest}"),
        None => format!("{who}: {w}"),
    }
}

/// The cells of a dimensional `map` whose peak indentation passes `radius` (m): each cell's
/// z_m from its peak force through the loading branch, which the map's cells share (λ and ζ
/// move K_r and c, never m, K_p, K_h, z_p or v0; `Contact::loading_indentation`). One
/// warning naming how many cells and the largest z_m; `None` when none passes, for a
/// normalized map, or with no radius known (NaN). tests/cli/answer_warnings.rs.
pub fn map_indentation_warning(map: &crate::map::Map, radius: f64) -> Option<String> {
    let spec = &map.spec;
    if spec.normalized || !radius.is_finite() {
        return None;
    }
    let z_m = cell_indentation(spec);
    let (past, deepest) = map
        .cells()
        .iter()
        .flatten()
        .map(|c| z_m(c.max_force))
        .filter(|&z| z > radius)
        .fold((0usize, f64::NAN), |(n, deepest), z| {
            (n + 1, deepest.max(z))
        });
    (past > 0).then(|| {
        format!(
            "peak indentation exceeds the ball's radius {} mm in {} of {} cells (up to {} mm): \
             outside the model's range there (the contact laws assume a deformation small \
             against the ball)",
            sig(radius * 1e3, 4),
            past,
            map.cells().len(),
            sig(deepest * 1e3, 4)
        )
    })
}

impl Ball {
    /// The ball's radius, m (its preset's measured radius; NaN for a ball that is no preset).
    pub fn radius(&self) -> f64 {
        self.measured.as_ref().map_or(f64::NAN, |m| m.radius)
    }

    /// The warnings of an impact `r` of this ball: an indentation or its centre's displacement
    /// beyond its radius ([`super::Reach::warning`]), an energy balance that does not close.
    ///
    /// ```
    /// let b = bouncelab::Ball::from_preset("superball")?;
    /// assert!(b.warnings(&b.impact()?).is_empty());
    /// let fast = b.with_v0(45.0)?;
    /// let w = fast.warnings(&fast.impact()?);
    /// assert!(w[0].starts_with("peak indentation 31.05 mm exceeds the ball's radius 21.55 mm"));
    /// // a soft spring: the centre sinks 35 mm while the contact takes 0.13 mm
    /// let soft = bouncelab::Ball::from_preset("superball")?.with_lambda_zeta(Some(0.001), Some(10.0))?;
    /// let w = soft.warnings(&soft.impact()?);
    /// assert!(w[0].starts_with("peak displacement of the ball's centre α_max 34.97 mm"));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn warnings(&self, r: &ImpactResponse) -> Vec<String> {
        let (z_m, radius) = (r.max_indentation, self.radius());
        let mut w: Vec<String> = reach(&self.params, r.law, r.method, z_m, r.duration, radius)
            .and_then(|how| how.warning(radius))
            .into_iter()
            .collect();
        if let Some(e) = &r.energy {
            let residual = e.relative_residual();
            if residual.abs() > ENERGY_RESIDUAL_MAX {
                w.push(format!(
                    "the energy balance closes only to {} of the impact energy",
                    sig(residual.abs(), 2)
                ));
            }
        }
        // last: the warnings before it are read by position (tests/cli/answer_warnings.rs)
        w.extend(self.calibration_warning(self.params.v0));
        w
    }

    /// The warnings of an impact `r` of this ball on `surface` (`run`, Python's `run`):
    /// [`Ball::warnings`], then the surface's ([`super::SurfaceUsed::warnings`]).
    pub fn warnings_on(&self, r: &ImpactResponse, surface: &super::SurfaceUsed) -> Vec<String> {
        let mut w = self.warnings(r);
        w.extend(surface.warnings());
        w
    }

    /// The warnings of a drop test `run` of this ball: those of its first impact, the
    /// fastest (the later ones only slow down), then the later bounces' that leave the ball's
    /// record ([`Ball::later_bounces_warning`]).
    pub fn drop_warnings(&self, run: &crate::drop::DropRun) -> Result<Vec<String>, BallError> {
        let Some(first) = run.bounces.first() else {
            return Ok(Vec::new());
        };
        let ball = self.clone().with_v0(first.v_in)?;
        let mut warnings = ball.warnings(&ball.impact()?);
        let speeds: Vec<f64> = run.bounces.iter().map(|b| b.v_in).collect();
        warnings.extend(self.later_bounces_warning(&speeds));
        Ok(warnings)
    }

    /// The warnings of a drop test `run` judged by a standard, the same from the command line
    /// and Python (`bouncelab drop --standard`, `drop(standard=…)`): the first impact's
    /// ([`Ball::drop_warnings`]) — without its impact-speed calibration warning where the
    /// standard is judged at its own speed or load and the bounces are only shown from the
    /// default height (`height_given` false: their speed is not the verdict's) —, a static
    /// standard's (`statics`: its deflection's warnings and the rules' return window), then
    /// the standard's own test against the record when it is another impact
    /// (tests/cli/cli_static.rs), then a ball that is not the standard's
    /// ([`Ball::standard_ball_warning`]); last the `surface` dropped on
    /// ([`super::SurfaceUsed::warnings`]: its rigidity assumed) and, judged by an impact
    /// standard, a surface not the standard's ([`super::SurfaceUsed::off_standard_warning`]).
    pub fn judged_drop_warnings(
        &self,
        run: &crate::drop::DropRun,
        height_given: bool,
        standard: Option<&crate::drop::standards::Standard>,
        statics: Option<(
            &crate::drop::deformation::DeformationStandard,
            &crate::analysis::statics::StaticDeflection,
        )>,
        surface: &super::SurfaceUsed,
    ) -> Result<Vec<String>, BallError> {
        let mut warnings = self.drop_warnings(run)?;
        let radius = self.drop_ball().radius;
        let shown_only =
            statics.is_some() || standard.is_some_and(|s| s.release_height(radius).is_none());
        if !height_given && shown_only {
            warnings.retain(|w| {
                !w.starts_with("outside calibration: impact speed")
                    && !w.starts_with("outside calibration: bounce")
            });
        }
        if let Some((d, s)) = statics {
            warnings.extend(self.static_warnings(s));
            if let Some(w) = d.return_warning(s).filter(|w| !warnings.contains(w)) {
                warnings.push(w);
            }
        }
        if let Some(w) = standard.and_then(|s| self.standard_calibration_warning(s))
            && !warnings.contains(&w)
        {
            warnings.push(w);
        }
        warnings.extend(standard.and_then(|s| self.standard_ball_warning(s)));
        warnings.extend(statics.and_then(|(d, _)| self.static_standard_ball_warning(d)));
        warnings.extend(surface.warnings());
        warnings.extend(standard.and_then(|s| surface.off_standard_warning(s)));
        Ok(warnings)
    }

    /// The warning of a drop through `air` (`None`: vacuum) of a ball fitted to drop tests
    /// taken in another air (its `[measured.drops]`; with a `[fit]` table, while no override
    /// moved a fitted parameter):
    /// its rebounds are not those the fit matched — a tennis ball fitted in vacuum to readings
    /// of 1.4625 m from 2.54 m rebounds 1.376 m through air (docs/fitting.md, "The air is
    /// stated"; tests/cli/cli_fit_air.rs). `None` when the airs agree or the ball has no drop fit.
    pub fn drop_air_warning(&self, air: Option<crate::measured::Air>) -> Option<String> {
        let fitted = self.measured.as_ref()?.drops?;
        if self
            .fit
            .as_ref()
            .is_some_and(|f| !super::holds(&self.params, f))
        {
            return None;
        }
        let (cd, rho) = air.map_or((0.0, 0.0), |a| (a.drag_coefficient, a.density));
        let same = |x: f64, y: f64| (x - y).abs() <= 1e-12 * x.abs().max(y.abs());
        let agree = if fitted.drag_coefficient == 0.0 {
            cd == 0.0
        } else {
            same(cd, fitted.drag_coefficient) && same(rho, fitted.air_density)
        };
        if agree {
            return None;
        }
        let how = |c: f64, rho: f64| {
            if c == 0.0 {
                "in vacuum".to_string()
            } else {
                format!("through air (C_d {}, {} kg/m³)", short(c, 4), short(rho, 4))
            }
        };
        let fix = if fitted.drag_coefficient == 0.0 {
            "--no-drag".to_string()
        } else {
            format!(
                "--drag-coefficient {} --air-density {}",
                number(fitted.drag_coefficient),
                number(fitted.air_density)
            )
        };
        Some(format!(
            "this ball was fitted to drops taken {}, and this drop falls {}: its rebounds are \
             not those the fit matched ({fix} drops it as the fit did)",
            how(fitted.drag_coefficient, fitted.air_density),
            how(cd, rho)
        ))
    }
}
