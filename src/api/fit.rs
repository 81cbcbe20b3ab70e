//! Fitting several parameters of a ball at once to measurements — a force–time trace, a COR
//! table, drop tests — as `bouncelab fit --trace/--cor-table/--drops` does (docs/fitting.md),
//! with the checks of the data that are not the files' (drop heights, the air) made here once.

use super::{Ball, BallError};
use crate::analysis::fit::{FitData, MultiFit, Param, fit_watched};
use crate::measured::{Air, CorPoint, Flight, drop_to_cor, drops_to_points};
use crate::text::number;

/// A finite positive number, or an error naming `field` (quantities the model's parameters do
/// not cover: drop heights, drag).
fn positive(field: &'static str, value: f64) -> Result<(), BallError> {
    if value.is_finite() && value > 0.0 {
        return Ok(());
    }
    Err(BallError::Invalid {
        field,
        value,
        reason: "must be a positive number".into(),
    })
}

impl Ball {
    /// The parameters `free` (default: what the data can pin, [`Param::defaults`]) fitted to
    /// `data` under the ball's law, the others held: values, standard errors, 95 % intervals
    /// and correlations ([`MultiFit`]), by bounded Levenberg–Marquardt from several starts.
    ///
    /// ```
    /// use bouncelab::{Ball, analysis::fit::FitData, measured::CorPoint};
    /// let ball = Ball::from_preset("superball")?;
    /// // the model's own COR at three speeds: the fit returns the preset's K_r and z_p
    /// let rows = ball.sweep_velocity(&[1.0, 3.0, 6.0])?;
    /// let points: Vec<CorPoint> = rows.iter().map(|r| CorPoint::new(r.v0, r.cor)).collect();
    /// let f = ball.fit(FitData::Cor(&points), None)?;
    /// assert_eq!(f.fitted[0].name, "k_r");
    /// assert!((f.fitted[0].value / ball.params.k_r - 1.0).abs() < 1e-4);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn fit(&self, data: FitData<'_>, free: Option<&[Param]>) -> Result<MultiFit, BallError> {
        self.fit_watched(data, free, &crate::analysis::work::Unwatched)
    }

    /// [`Ball::fit`], each model run reported to `watch`, which may stop it
    /// (`MultiFitError::Interrupted`): the Python package's Ctrl-C.
    pub fn fit_watched(
        &self,
        data: FitData<'_>,
        free: Option<&[Param]>,
        watch: &dyn crate::analysis::work::Watch,
    ) -> Result<MultiFit, BallError> {
        let free = match free {
            Some(f) => f.to_vec(),
            None => match data {
                FitData::Trace(_) => Param::defaults(true, 0, self.law),
                FitData::Cor(points) => Param::defaults(false, points.len(), self.law),
            },
        };
        Ok(fit_watched(&self.params, self.law, data, &free, watch)?)
    }

    /// The warnings of the ball fitted to data taken at `speeds` (m/s), `fitted` this ball's
    /// parameters after the fit ([`Ball::warnings`]: its indentation or centre past the
    /// radius, an energy balance that does not close), at the fastest speed, where it presses
    /// deepest (z_m and α_max grow with v0: the impact energy does), each line naming it.
    /// `[]` when nothing; a run that has no answer says so.
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("superball")?;
    /// let fast = bouncelab::ImpactParams { k_r: 187687.0, ..ball.params };
    /// let w = ball.fitted_warnings(&fast, &[30.0, 45.0]);
    /// assert!(w[0].starts_with("the fitted ball at v0 = 45 m/s (the fastest of the data): peak indentation"));
    /// assert!(ball.fitted_warnings(&ball.params, &[3.12]).is_empty());
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn fitted_warnings(&self, fitted: &crate::ImpactParams, speeds: &[f64]) -> Vec<String> {
        let v0 = speeds.iter().copied().fold(f64::NAN, f64::max);
        if !v0.is_finite() {
            return Vec::new();
        }
        let ball = Ball {
            params: crate::ImpactParams { v0, ..*fitted },
            // the fitted ball is calibrated by the data it was fitted to, not by the record of
            // the preset it started from (`fit --save` writes the new record)
            calibration: None,
            ..self.clone()
        };
        let several = speeds.iter().any(|&v| v != v0);
        let at = format!(
            "the fitted ball at v0 = {} m/s{}",
            number(v0),
            if several {
                " (the fastest of the data)"
            } else {
                ""
            }
        );
        match ball.impact() {
            Ok(r) => ball
                .warnings(&r)
                .into_iter()
                .map(|w| format!("{at}: {w}"))
                .collect(),
            Err(e) => vec![format!(
                "{at} has no answer to check against its radius: {e}"
            )],
        }
    }

    /// Every warning of a fit from this ball to data at `speeds` (m/s) that gave `fit`: its
    /// fitted ball's ([`Ball::fitted_warnings`]), then the record's of the parameters it held
    /// ([`Ball::held_warning`]; at the fitted impact speed where `v0` was free). One place for
    /// the command line's `fit` and the Python package's `fit_*`, whose answers agree
    /// (python/tests/test_parity.py).
    ///
    /// ```
    /// use bouncelab::{Ball, analysis::fit::{FitData, Param}, measured::CorPoint};
    /// let ball = Ball::from_preset("tennis")?;
    /// let points = [CorPoint::new(20.0, 0.6), CorPoint::new(25.0, 0.55)];
    /// // K_r alone: the record's K_p, c and z_p are held at 20–25 m/s, far past its 6.906
    /// let fit = ball.fit(FitData::Cor(&points), Some(&[Param::KR]))?;
    /// let w = ball.fit_warnings(&fit, &[20.0, 25.0]);
    /// assert!(w.iter().any(|l| l.starts_with("outside calibration: impact speeds 20–25 m/s")));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn fit_warnings(&self, fit: &MultiFit, speeds: &[f64]) -> Vec<String> {
        let free: Vec<Param> = fit
            .fitted
            .iter()
            .filter_map(|e| Param::parse(e.name))
            .collect();
        let at = match free.contains(&Param::V0) {
            true => vec![fit.params.v0],
            false => speeds.to_vec(),
        };
        let mut w = self.fitted_warnings(&fit.params, speeds);
        w.extend(self.held_warning(&free, &at));
        w
    }

    /// Whether a fit of `free` to data with a trace (`trace`) fits the trace's impact speed
    /// too, [`Param::V0`] added to `free`: no speed was given (`v0_given` false) and `free`
    /// does not name it. Such a trace is not known to be taken at the preset's speed: held
    /// there, a trace made at twice it gave K_r 43 k against a truth of 90 k with a tight
    /// interval (issue 52; tests/cli/calibration.rs, `a_trace_without_v0_fits_its_speed`).
    /// The fit's warnings then say so first ([`Ball::speed_fitted_warning`]). One rule for
    /// the command line's `fit --force-time` (alone and joint) and Python's `fit_trace`.
    ///
    /// ```
    /// use bouncelab::{Ball, analysis::fit::Param};
    /// let mut free = vec![Param::KP, Param::C, Param::KR];
    /// assert!(!Ball::free_trace_speed(&mut free, true, true)); // a speed given: held
    /// assert!(Ball::free_trace_speed(&mut free, true, false));
    /// assert_eq!(free, [Param::KP, Param::C, Param::KR, Param::V0]);
    /// assert!(!Ball::free_trace_speed(&mut free, true, false)); // named already
    /// ```
    pub fn free_trace_speed(free: &mut Vec<Param>, trace: bool, v0_given: bool) -> bool {
        let fitted = trace && !v0_given && !free.contains(&Param::V0);
        if fitted {
            free.push(Param::V0);
        }
        fitted
    }

    /// The first warning of a fit whose trace's speed [`Ball::free_trace_speed`] freed,
    /// naming this ball's speed the fit started from.
    ///
    /// ```
    /// let w = bouncelab::Ball::from_preset("superball")?.speed_fitted_warning();
    /// assert!(w.starts_with("no --v0 given: the trace's impact speed was fitted (as --free v0)"));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn speed_fitted_warning(&self) -> String {
        format!(
            "no --v0 given: the trace's impact speed was fitted (as --free v0), starting from \
             the preset's {} m/s; give --v0 to hold a measured one",
            crate::text::short(self.params.v0, 4)
        )
    }

    /// The warnings of the single-COR fit (K_r alone, at this ball's v0) that gave `fitted`:
    /// [`Ball::fit_warnings`] for one free K_r — the command line's `fit --cor` and Python's
    /// `fit_cor` alike.
    pub fn cor_fit_warnings(&self, fitted: &crate::ImpactParams) -> Vec<String> {
        let v0 = self.params.v0;
        let mut w = self.fitted_warnings(fitted, &[v0]);
        w.extend(self.held_warning(&[Param::KR], &[v0]));
        w
    }

    /// "outside calibration: …" for a fit from this ball to data at `speeds` (m/s) that frees
    /// `free` and holds the rest: the parameters held are the record's, which vouches for them
    /// at its own speeds and conditions only — `run`'s warning at the data's speeds
    /// ([`Ball::speeds_warning`]), as `fit --cor-temperature` (its springs) and a batch (its
    /// lot's) give it. `None` within the record, without one, and for a fit that frees every
    /// parameter of its law (K_p or K_h, c, K_r, and z_p but under the Hertz law, which has no
    /// flattening): its ball is the data's.
    ///
    /// ```
    /// use bouncelab::analysis::fit::Param;
    /// let b = bouncelab::Ball::from_preset("tennis")?;
    /// let w = b.held_warning(&[Param::KR], &[60.0]).unwrap();
    /// assert!(w.starts_with("outside calibration: impact speed 60 m/s, the ball was fitted at 6.906 m/s"));
    /// assert_eq!(b.held_warning(&[Param::KR], &[6.906]), None);
    /// assert_eq!(b.held_warning(&[Param::KP, Param::C, Param::KR, Param::ZP], &[60.0]), None);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn held_warning(&self, free: &[Param], speeds: &[f64]) -> Option<String> {
        let lo = speeds.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = speeds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        let frees = |p: Param| free.contains(&p);
        let every = (frees(Param::KP) || frees(Param::KH))
            && frees(Param::C)
            && frees(Param::KR)
            && (frees(Param::ZP) || self.law == crate::ContactLaw::Hertz);
        if every {
            return None;
        }
        self.speeds_warning(lo, hi)
    }

    /// Drop tests as a COR table: each (drop height, rebound height) pair (m) checked and
    /// turned into an impact speed and a COR by this ball's flight ([`drop_to_cor`]), in
    /// vacuum or through `air` (drag on the preset's measured radius); each row weighed by
    /// its rebound height's reading, with the reading's precision unknown
    /// ([`Ball::drops_to_cor_read`] with `None`).
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("tennis")?;
    /// let pts = ball.drops_to_cor(&[(2.54, 1.44)], None)?;
    /// assert!((pts[0].cor - (1.44_f64 / 2.54).sqrt()).abs() < 1e-12); // e = √(R/H) in vacuum
    /// let e = ball.drops_to_cor(&[(1.0, 2.0)], None).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid rebound_height: 2 (must lie in [0, the drop height 1])");
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn drops_to_cor(
        &self,
        drops: &[(f64, f64)],
        air: Option<Air>,
    ) -> Result<Vec<CorPoint>, BallError> {
        self.drops_to_cor_read(drops, air, None)
    }

    /// [`Ball::drops_to_cor`] with what is known of how the rebound heights were read. A
    /// height read to ±σ_R gives e = u(R)/v0 an error σ_e = σ_R ∂e/∂R
    /// (`measured::cor_per_rebound_height`; in vacuum 1/(2√(RH)), nine times larger from
    /// 0.2 m than from 1.8 m): fitted with equal weights, such drops gave 95 % intervals that
    /// covered K_r and z_p about two times in three (tests/analysis/fit_drop_coverage.rs,
    /// docs/fitting.md). With `rebound_sd` = σ_R (m)
    /// each row's `cor_sd` is σ_e, and the fit judges the scatter by χ²; without it each row's
    /// `cor_sd_relative` is ∂e/∂R and the scale comes from the misses
    /// ([`drops_to_points`]).
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("tennis")?;
    /// let pts = ball.drops_to_cor_read(&[(0.2, 0.1), (1.8, 0.9)], None, Some(0.003))?;
    /// // the same COR, its error nine times larger from the lower drop
    /// let (low, high) = (pts[0].cor_sd.unwrap(), pts[1].cor_sd.unwrap());
    /// assert!((low / high - 9.0).abs() < 1e-9);
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn drops_to_cor_read(
        &self,
        drops: &[(f64, f64)],
        air: Option<Air>,
        rebound_sd: Option<f64>,
    ) -> Result<Vec<CorPoint>, BallError> {
        if let Some(a) = air {
            positive("drag_coefficient", a.drag_coefficient)?;
            positive("air_density", a.density)?;
        }
        if let Some(sd) = rebound_sd {
            positive("rebound_height_sd", sd)?;
        }
        for &(h, r) in drops {
            positive("drop_height", h)?;
            if !(0.0..=h).contains(&r) {
                return Err(BallError::Invalid {
                    field: "rebound_height",
                    value: r,
                    reason: format!("must lie in [0, the drop height {}]", number(h)),
                });
            }
        }
        let radius = self.measured.as_ref().map_or(f64::NAN, |m| m.radius);
        let flight = Flight::new(self.params.mass, radius, air);
        for (i, &(h, r)) in drops.iter().enumerate() {
            let (v0, cor) = drop_to_cor(h, r, &flight);
            check_corrected(i, drops.len(), (h, r), v0, cor)?;
        }
        Ok(drops_to_points(drops, &flight, rebound_sd))
    }
}

/// A drop's corrected speed and COR must be a possible impact: finite, e ≤ 1, and a drag
/// correction no larger than the rebound measured (the rise in vacuum that the launch speed
/// would give, v²/2g, less the rebound, is what drag took): otherwise the drag correction, not
/// the ball, makes the number, and the row is refused.
fn check_corrected(
    row: usize,
    rows: usize,
    (h, r): (f64, f64),
    v0: f64,
    cor: f64,
) -> Result<(), BallError> {
    let launch = cor * v0;
    let correction = launch * launch / (2.0 * crate::drop::flight::G) - r;
    let what = match rows {
        1 => format!("the drop from {} m to {} m", number(h), number(r)),
        _ => format!(
            "drop {} of {rows}, {} m to {} m",
            row + 1,
            number(h),
            number(r)
        ),
    };
    let reason = if !(v0.is_finite() && cor.is_finite()) {
        format!("{what}: the drag correction gives no finite speed")
    } else if cor > 1.0 {
        format!(
            "{what}: corrected for drag it implies COR {} > 1; the drag correction is larger \
             than these heights allow (check --drag-coefficient and the heights)",
            crate::text::sig(cor, 4)
        )
    } else if correction > r {
        format!(
            "{what}: the drag correction ({} m) is larger than the rebound itself",
            crate::text::sig(correction, 3)
        )
    } else {
        return Ok(());
    };
    Err(BallError::Invalid {
        field: "rebound_height",
        value: r,
        reason,
    })
}
