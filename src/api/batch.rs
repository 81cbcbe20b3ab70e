//! A batch of balls, one fit and one verdict each (docs/batch.md): each ball's data fitted
//! from this ball as the start (as `bouncelab fit` fits one file), the fitted ball run through
//! the standard's own test, and the summary over the batch against the standard's window.
//! What `bouncelab batch` writes and `bouncelab.batch` returns.

use super::Ball;
use super::batch_failure::{FitFailure, failure};
use crate::analysis::fit::verdict::no_answer_reasons;
use crate::analysis::fit::{FitData, MultiFit, Param};
use crate::drop::standards::{Standard, Test};
use crate::measured::{Air, Data, Flight};
use serde::Serialize;

/// What a batch asks of every ball.
#[derive(Debug, Clone, Copy)]
pub struct BatchSetup<'a> {
    /// The standard each fitted ball is judged against.
    pub standard: &'static Standard,
    /// The parameters fitted (`None`: what each ball's data can pin, [`Param::defaults`]).
    pub free: Option<&'a [Param]>,
    /// The air of the drop tests, fitted and judged alike (`None`: vacuum).
    pub air: Option<Air>,
    /// The standard deviation of a rebound height's reading, m (`--rebound-height-sd`, as
    /// `fit`'s; `None`: unknown, the scale taken from the readings' scatter).
    pub rebound_sd: Option<f64>,
}

/// One ball of a batch: its fit and its verdict, or why it has none (`error`). SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BallOutcome {
    /// The ball's id.
    pub id: String,
    /// The batch line its rows begin at.
    pub line: usize,
    /// "drop test", "COR table" or "force-time trace".
    pub data: &'static str,
    /// Data points fitted.
    pub points: usize,
    /// The parameters fitted.
    pub free: Vec<&'static str>,
    /// The fitted ball's K_p (N/m), c (kg/s), K_r (N/m), z_p (m).
    pub k_p: Option<f64>,
    /// Damping c, kg/s.
    pub c: Option<f64>,
    /// Recoil stiffness K_r, N/m.
    pub k_r: Option<f64>,
    /// Flattening threshold z_p, m.
    pub z_p: Option<f64>,
    /// Whether the fit answered: converged, every free parameter pinned (docs/fitting.md).
    pub identified: bool,
    /// The fitted ball's COR at the standard's impact speed.
    pub cor: Option<f64>,
    /// What the standard measures, on the fitted ball: the rebound height (m, in the
    /// standard's convention) or the COR.
    pub measured: Option<f64>,
    /// `PASS` or `FAIL`; `None` without a fit.
    pub verdict: Option<&'static str>,
    /// Distance to the nearer bound of the window, positive inside.
    pub margin: Option<f64>,
    /// `measured`'s 95 % interval from the fit's covariance, carried through the standard's
    /// test by the delta method (docs/batch.md); `None` where the fit leaves no degree of
    /// freedom (one drop, or a value per free parameter: the data themselves).
    pub measured_ci95: Option<[f64; 2]>,
    /// What the fit warns of.
    pub warnings: Vec<String>,
    /// Why the ball has no verdict: its data could not be fitted, and were not taken at the
    /// standard's condition (so no reading of its own judges it).
    pub error: Option<String>,
    /// What the verdict is on: `measurement` (the ball's own readings at the standard's
    /// condition, `api::batch_reading`) or `model` (the fitted ball run
    /// through the standard's test); `None` without a verdict.
    pub verdict_from: Option<&'static str>,
    /// Readings at the standard's condition (drops from its height, CORs at its speed).
    pub readings: usize,
    /// The fitted ball's value in the standard's test (beside a verdict from the
    /// measurement, what the model makes of it); `None` without a fit.
    pub model_measured: Option<f64>,
    /// Why the fit gave no answer, where the ball's verdict stands on its measurement.
    pub fit_error: Option<String>,
    /// The kind of `fit_error` (or of `error`), as the text's summary groups the balls.
    #[serde(skip)]
    pub fit_failure: Option<FitFailure>,
}

impl BallOutcome {
    fn new(id: &str, line: usize, data: &'static str) -> BallOutcome {
        BallOutcome {
            id: id.to_string(),
            line,
            data,
            points: 0,
            free: Vec::new(),
            k_p: None,
            c: None,
            k_r: None,
            z_p: None,
            identified: false,
            cor: None,
            measured: None,
            verdict: None,
            margin: None,
            measured_ci95: None,
            warnings: Vec::new(),
            error: None,
            verdict_from: None,
            readings: 0,
            model_measured: None,
            fit_error: None,
            fit_failure: None,
        }
    }
}

/// The range what a standard measures can take: a COR lies in [0, 1], a rebound height at
/// or above the plate, [0, ∞) (the lot mean's interval is clipped to it: analysis::batch_stats).
pub fn quantity_range(s: &Standard) -> [f64; 2] {
    match s.test {
        Test::Drop { .. } => [0.0, f64::INFINITY],
        Test::Cor { .. } => [0.0, 1.0],
    }
}

/// The name and unit of what a standard measures: `rebound_height` (m) or `cor`.
pub fn quantity(s: &Standard) -> (&'static str, &'static str) {
    match s.test {
        Test::Drop { .. } => ("rebound_height", "m"),
        Test::Cor { .. } => ("cor", ""),
    }
}

impl Ball {
    /// Ball `id` of a batch (its rows from `line`): `data` fitted from this ball, and the
    /// ball judged by `setup.standard` — on its own readings where it was tested at the
    /// standard's condition (`api::batch_reading`; the fitted ball's value beside them),
    /// else on the fitted ball run through the standard's test. Never fails: a ball without a
    /// verdict says why in its `error`; a ball whose verdict stands on its readings but whose
    /// fit gave no answer says why in its `fit_error`.
    ///
    /// ```
    /// use bouncelab::{Ball, api::BatchSetup, drop::standards, measured::parse_any};
    /// let tennis = Ball::from_preset("tennis")?;
    /// let setup = BatchSetup {
    ///     standard: standards::find("itf").unwrap(),
    ///     free: None,
    ///     air: None,
    ///     rebound_sd: None,
    /// };
    /// // one drop at the standard's own height: the verdict is on that rebound
    /// let data = parse_any("drop_height_m,rebound_height_m\n2.54,1.40\n").unwrap();
    /// let o = tennis.judge_in_batch("A1", 2, &data, &setup);
    /// assert_eq!((o.verdict, o.verdict_from), (Some("PASS"), Some("measurement")));
    /// assert_eq!(o.measured, Some(1.40));
    /// // and the fitted ball gives it back (in vacuum, K_r alone)
    /// assert!((o.model_measured.unwrap() - 1.40).abs() < 1e-6, "{o:?}");
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn judge_in_batch(
        &self,
        id: &str,
        line: usize,
        data: &Data,
        setup: &BatchSetup<'_>,
    ) -> BallOutcome {
        let mut o = BallOutcome::new(id, line, data.kind());
        // the rows given (a fit that answers counts the values it fitted)
        o.points = match data {
            Data::Trace(t) => t.time.len(),
            Data::Cor(t) => t.points.len(),
            Data::Drop(d) => d.drops.len(),
        };
        let reading = super::batch_reading::reading(self, data, setup);
        if let Some(r) = &reading {
            o.readings = r.count;
            o.cor = Some(r.cor);
            verdict_on_reading(setup.standard, r, &mut o);
        }
        let fitted = match self.fit_and_judge(data, setup, &mut o) {
            Ok(fitted) => fitted,
            Err((kind, e)) => {
                o.fit_failure = Some(kind);
                match reading {
                    Some(_) => o.fit_error = Some(e),
                    None => o.error = Some(e),
                }
                return o;
            }
        };
        if reading.is_none() {
            // the verdict from the model: its interval from the fit's covariance
            o.measured = o.model_measured;
            o.verdict_from = Some("model");
            o.verdict = Some(fitted.verdict.verdict);
            o.margin = Some(fitted.verdict.margin);
            if let Some((fitted, table)) = fitted.band {
                match measured_band(&fitted, setup, &table) {
                    Ok(ci) => o.measured_ci95 = Some(ci),
                    // the verdict stands; its interval is missing, and the ball says why
                    Err(e) => o.warnings.push(format!(
                        "no 95 % interval for the measured value: the standard's test failed \
                         on the ball moved within its fit's uncertainty ({e})"
                    )),
                }
            }
        }
        if let Some(ci) = o.measured_ci95 {
            o.warnings.extend(unsure(setup.standard, &o, ci));
        }
        o
    }

    /// The ball fitted to `data` and run through the standard's test: the fit's values and
    /// warnings, the fitted ball's COR and value (`model_measured`, its verdict kept aside)
    /// in `o`; the fitted ball and its fit's covariance table where the fit leaves degrees of
    /// freedom. An error says why the fit or the test gave no answer, and of what kind.
    fn fit_and_judge(
        &self,
        data: &Data,
        setup: &BatchSetup<'_>,
        o: &mut BallOutcome,
    ) -> Result<Fitted, (FitFailure, String)> {
        let (f, speeds) = self.fit_batch_data(data, setup)?;
        o.points = f.points;
        o.free = f.fitted.iter().map(|e| e.name).collect();
        let p = &f.params;
        (o.k_p, o.c, o.k_r, o.z_p) = (Some(p.k_p), Some(p.damping), Some(p.k_r), Some(p.z_p));
        o.identified = f.identified;
        o.warnings.extend(f.warnings.iter().cloned());
        // the fitted ball where it presses deepest, as `bouncelab fit` warns of it
        o.warnings.extend(self.fitted_warnings(&f.params, &speeds));
        if !f.identified {
            let why = no_answer_reasons(f.converged, &f.not_pinned);
            return Err((
                FitFailure::NotFollowed,
                format!("the fit gave no answer: {}", why.join("; ")),
            ));
        }
        let fitted = Ball {
            params: f.params,
            ..self.clone()
        };
        let verdict = judge(&fitted, setup, o).map_err(|e| (FitFailure::TestFailed, e))?;
        Ok(Fitted {
            verdict,
            band: super::fit_table(&f).map(|t| (fitted, t)),
        })
    }

    /// The fit of one ball's data (drop tests through this ball's flight in `setup.air`), and
    /// the impact speeds of its data (a trace's: this ball's v0), as `bouncelab fit` takes
    /// them for [`Ball::fitted_warnings`].
    fn fit_batch_data(
        &self,
        data: &Data,
        setup: &BatchSetup<'_>,
    ) -> Result<(MultiFit, Vec<f64>), (FitFailure, String)> {
        let points = match data {
            Data::Trace(t) => {
                return self
                    .fit(FitData::Trace(t), setup.free)
                    .map(|f| (f, vec![self.params.v0]))
                    .map_err(failure);
            }
            Data::Cor(t) => t.points.clone(),
            Data::Drop(d) => {
                let pairs: Vec<(f64, f64)> = d.drops.iter().map(|d| (d.0, d.1)).collect();
                self.drops_to_cor_read(&pairs, setup.air, setup.rebound_sd)
                    .map_err(|e| (FitFailure::Other, e.to_string()))?
            }
        };
        let speeds = points.iter().map(|p| p.v0).collect();
        self.fit(FitData::Cor(&points), setup.free)
            .map(|f| (f, speeds))
            .map_err(failure)
    }
}

/// The standard's test on the fitted ball: the verdict, and the COR at the test's speed.
fn judge(ball: &Ball, setup: &BatchSetup<'_>, o: &mut BallOutcome) -> Result<ModelVerdict, String> {
    let s = setup.standard;
    let dball = ball.drop_ball();
    let v = s.judge(&dball, setup.air).map_err(|e| e.to_string())?;
    if !v.measured.is_finite() {
        return Err(format!(
            "{} reads heights at the top of the ball: the ball needs a radius (a preset's)",
            s.name
        ));
    }
    let cor = match s.test {
        Test::Drop { .. } => {
            let h = s.release_height(dball.radius).unwrap_or(f64::NAN);
            let speed = Flight::new(dball.params.mass, dball.radius, setup.air).fall_speed(h);
            crate::drop::impact(&dball, speed)
                .map_err(|e| e.to_string())?
                .cor
        }
        Test::Cor { .. } => v.measured,
    };
    // the fitted ball's COR at the standard's speed (beside a reading too, as before the
    // readings were judged)
    o.cor = Some(cor);
    o.model_measured = Some(v.measured);
    Ok(ModelVerdict {
        verdict: if v.pass { "PASS" } else { "FAIL" },
        margin: v.margin,
    })
}

/// The fitted ball's verdict in the standard's test.
struct ModelVerdict {
    verdict: &'static str,
    margin: f64,
}

/// A ball's fit that answered: the fitted ball's verdict, and the fitted ball with its fit's
/// covariance table where the fit leaves degrees of freedom.
struct Fitted {
    verdict: ModelVerdict,
    band: Option<(Ball, crate::preset::FitTable)>,
}

/// The verdict on the ball's own reading at the standard's condition.
fn verdict_on_reading(s: &Standard, r: &super::batch_reading::Reading, o: &mut BallOutcome) {
    let v = s.judge_value(r.value);
    o.measured = Some(r.value);
    o.measured_ci95 = r.ci95;
    o.verdict = Some(if v.pass { "PASS" } else { "FAIL" });
    o.margin = Some(v.margin);
    o.verdict_from = Some("measurement");
}

/// The 95 % interval of what the standard measures on `ball`, from the fit's covariance
/// `table` (`super::bands`: each fitted parameter moved, the standard's test run again).
fn measured_band(
    ball: &Ball,
    setup: &BatchSetup<'_>,
    table: &crate::preset::FitTable,
) -> Result<[f64; 2], crate::api::BallError> {
    let band = super::bands(&ball.params, table, |p| {
        let moved = Ball {
            params: *p,
            ..ball.clone()
        };
        Ok(vec![
            setup
                .standard
                .judge(&moved.drop_ball(), setup.air)?
                .measured,
        ])
    })?;
    Ok(band[0])
}

/// The warning of a verdict the ball's interval leaves open: a bound of the window inside
/// `ci` (the verdict would change within the fit's uncertainty).
fn unsure(s: &Standard, o: &BallOutcome, ci: [f64; 2]) -> Option<String> {
    let bound = s
        .window
        .into_iter()
        .flatten()
        .find(|&b| within_one(b, ci))?;
    let (_, unit) = quantity(s);
    let unit = if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    };
    Some(format!(
        "the window's bound {}{unit} lies within this ball's 95 % interval ({} … {}{unit}): \
         its {} is not sure at 95 %",
        crate::text::short(bound, 4),
        crate::text::short(ci[0], 4),
        crate::text::short(ci[1], 4),
        o.verdict.unwrap_or("verdict")
    ))
}

/// Whether a bound of `s`'s window lies strictly inside `ci`.
pub(super) fn within(s: &Standard, ci: [f64; 2]) -> bool {
    s.window.into_iter().flatten().any(|b| within_one(b, ci))
}

/// Whether `bound` lies strictly inside `ci`.
fn within_one(bound: f64, ci: [f64; 2]) -> bool {
    ci[0] < bound && bound < ci[1]
}
