//! The sweeps of the front door: COR against ζ on the normalized ball ([`sweep_zeta`]) and
//! against the impact speed for a ball ([`Ball::sweep_velocity`]), within the work limit and
//! in chunks a [`work::Watch`] sees (the Python package's Ctrl-C).

use super::{Ball, BallError};
use crate::analysis::sweep::{VelocityPoint, ZetaPoint, cor_vs_velocity, cor_vs_zeta};
use crate::analysis::work;
use crate::model::contact::ContactLaw;
use crate::model::params::validate_lambda_zeta;

impl Ball {
    /// COR, peak force, contact time and permanent indentation at each speed (m/s), as
    /// `bouncelab sweep velocity` (Fig. 4). The speeds run in parallel, within the command
    /// line's work limit ([`work::check`]: 10⁶ linear-law impacts, 25 000 on the other laws).
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("superball")?;
    /// let rows = ball.sweep_velocity(&[1.0, 3.0, 9.0])?;
    /// assert_eq!(rows.len(), 3);
    /// assert!(rows[2].cor < rows[0].cor); // flattening costs energy at speed
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn sweep_velocity(&self, speeds: &[f64]) -> Result<Vec<VelocityPoint>, BallError> {
        self.sweep_velocity_watched(speeds, &work::Unwatched)
    }

    /// [`Ball::sweep_velocity`] in chunks, `watch` told between them ([`work::Watch`]: the
    /// Python package's Ctrl-C); the same rows. An empty list is refused.
    pub fn sweep_velocity_watched(
        &self,
        speeds: &[f64],
        watch: &dyn work::Watch,
    ) -> Result<Vec<VelocityPoint>, BallError> {
        let n = speeds.len();
        if n == 0 {
            return Err(BallError::NoValue("speeds"));
        }
        work::check(n, self.law, &format!("{n} speeds"))?;
        let chunk = work::chunk(self.law);
        in_chunks(speeds, chunk, watch, |c| {
            Ok(cor_vs_velocity(&self.params, self.law, c)?)
        })
    }

    /// The warning of one `row` of this ball's speed sweep: its reach past the radius
    /// ([`super::Reach::warning`], the ball at the row's speed), as `run` warns of it — the
    /// command line's `sweep velocity` rows and Python's `sweep_velocity` alike.
    pub fn velocity_row_warning(&self, row: &VelocityPoint) -> Option<String> {
        let params = crate::ImpactParams {
            v0: row.v0,
            ..self.params
        };
        let method = match self.law {
            ContactLaw::Linear => crate::solver::Method::Exact,
            _ => crate::solver::Method::Numeric,
        };
        let duration = row.contact_time.unwrap_or(f64::INFINITY);
        let z_m = row.max_indentation;
        let radius = self.radius();
        super::reach(&params, self.law, method, z_m, duration, radius)?.warning(radius)
    }

    /// Every warning of a `sweep velocity` row: [`Ball::velocity_row_warning`], then the
    /// row's speed against the ball's calibration record ([`Ball::calibration_warning`]).
    pub fn velocity_row_warnings(&self, row: &VelocityPoint) -> Vec<String> {
        self.velocity_row_warning(row)
            .into_iter()
            .chain(self.calibration_warning(row.v0))
            .collect()
    }
}

/// COR, F̄_m and τ_f against ζ for each λ, on the normalized ball without flattening (the
/// paper's Figs. 2–3), as `bouncelab sweep zeta`: rows grouped by λ in the order given, the
/// points run in parallel. Each λ is checked first, and the work limit ([`work::check`]),
/// as on the command line.
///
/// ```
/// use bouncelab::{ContactLaw, analysis::sweep::log_space};
/// let rows = bouncelab::sweep_zeta(&[0.0, 1.0], &log_space(0.01, 100.0, 5), ContactLaw::Linear)?;
/// assert_eq!(rows.len(), 10);
/// // λ = 0 (Maxwell): no rebound from ζ = 1 on
/// assert_eq!(rows[2].zeta, 1.0);
/// assert_eq!(rows[2].cor, 0.0);
/// assert!(rows[7].cor > 0.0);
/// # Ok::<(), bouncelab::BallError>(())
/// ```
pub fn sweep_zeta(
    lambdas: &[f64],
    zetas: &[f64],
    law: ContactLaw,
) -> Result<Vec<ZetaPoint>, BallError> {
    sweep_zeta_watched(lambdas, zetas, law, &work::Unwatched)
}

/// [`sweep_zeta`] in chunks, `watch` told between them ([`work::Watch`]: the Python
/// package's Ctrl-C); the same rows.
pub fn sweep_zeta_watched(
    lambdas: &[f64],
    zetas: &[f64],
    law: ContactLaw,
    watch: &dyn work::Watch,
) -> Result<Vec<ZetaPoint>, BallError> {
    if lambdas.is_empty() {
        return Err(BallError::NoValue("lambda"));
    }
    if zetas.is_empty() {
        return Err(BallError::NoValue("zeta"));
    }
    for &l in lambdas {
        validate_lambda_zeta(l, 0.0)?;
    }
    let (nl, nz) = (lambdas.len(), zetas.len());
    let what = format!("{nl} λ values × {nz} points");
    work::check(nl.saturating_mul(nz), law, &what)?;
    let mut rows = Vec::with_capacity(nl * nz);
    let mut done = 0;
    for &l in lambdas {
        rows.extend(in_chunks(zetas, work::chunk(law), watch, |c| {
            Ok(cor_vs_zeta(&[l], c, law)?)
        })?);
        done += 1;
        if !watch.step(done) {
            return Err(BallError::Interrupted);
        }
    }
    Ok(rows)
}

/// `f` over `items` in chunks of `chunk`, `watch` told after each (and stopping the work).
fn in_chunks<T, R>(
    items: &[T],
    chunk: usize,
    watch: &dyn work::Watch,
    mut f: impl FnMut(&[T]) -> Result<Vec<R>, BallError>,
) -> Result<Vec<R>, BallError> {
    let mut out = Vec::with_capacity(items.len());
    for (i, c) in items.chunks(chunk.max(1)).enumerate() {
        out.extend(f(c)?);
        if !watch.step(i as u64 + 1) {
            return Err(BallError::Interrupted);
        }
    }
    Ok(out)
}
