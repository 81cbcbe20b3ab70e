//! The front door for code: a [`Ball`] — a preset, the normalized ball, or parameters you give
//! — and what you ask of it: [one impact](Ball::impact), [its force history](Ball::impact_history),
//! [COR against speed](Ball::sweep_velocity), [the recoil spring that gives a measured
//! COR](Ball::fit_cor). The ζ sweep of the paper's Figs. 2–3, which runs the normalized ball,
//! is [`sweep_zeta`].
//!
//! A `Ball` is what the command line runs: `bouncelab run --preset golf --v0 3` is
//! `Ball::from_preset("golf")?.with_v0(3.0)?.impact()?`, and every check and every error
//! message ([`BallError`]) is the command line's, word for word.
//!
//! ```
//! use bouncelab::{Ball, ContactLaw};
//!
//! let golf = Ball::from_preset("golf")?.with_v0(3.0)?;
//! let r = golf.impact()?;
//! assert!((r.cor - 0.8404).abs() < 1e-4);
//!
//! // the same ball on the elastic–plastic law
//! let r = golf.with_law(ContactLaw::ElasticPlastic).impact()?;
//! assert!(r.rebound && r.cor < 1.0);
//! # Ok::<(), bouncelab::BallError>(())
//! ```

use crate::analysis::fit::{Fit, fit_k_r};
use crate::catalog::{Catalog, Entry};
use crate::drop::{DropRun, DropSetup};
use crate::model::contact::ContactLaw;
use crate::model::params::{Field, ImpactParams, check_positive, validate_lambda_zeta};
use crate::preset::{Measured, ParamSource};
use crate::solver::{ImpactResponse, SolveOptions, simulate};

/// Most history samples [`Ball::impact_history`] takes (as `run --samples`).
pub const MAX_SAMPLES: usize = 100_000;

/// A ball ready to simulate: its parameters (SI units), its contact law and where they came
/// from.
///
/// Build one with [`Ball::from_preset`] (an embedded preset), [`Ball::from_catalog`] (embedded
/// or user presets), [`Ball::normalized`] (λ and ζ alone) or [`Ball::from_params`] (your own
/// numbers), change it with the `with_*` methods, and ask it for an [`impact`](Ball::impact).
/// The constructors and `with_*` methods check every parameter; the fields are public so that
/// a caller can read them (and change them at will: [`Ball::impact`] checks them again).
#[derive(Debug, Clone, PartialEq)]
pub struct Ball {
    /// Preset name; `None` for the normalized ball and for a ball given by its parameters.
    pub name: Option<String>,
    /// `"embedded"`, a preset file's path, `"normalized"` or `"parameters"`.
    pub origin: String,
    /// Which parameter set: `"adopted"`, `"materials"`, `"normalized"` or `"given"`.
    pub source: &'static str,
    /// The parameters, SI units.
    pub params: ImpactParams,
    /// The contact law.
    pub law: ContactLaw,
    /// What was measured, for comparison (presets only).
    pub measured: Option<Measured>,
    /// The preset's description (empty for other balls).
    pub description: String,
    /// A fitted preset's `[fit]` table, on its adopted set and law: the source of
    /// [`Ball::intervals`] (`None` for every other ball).
    pub fit: Option<crate::preset::FitTable>,
    /// The preset material's Poisson ratio ν (`None` for other balls): the default tangential
    /// stiffness of an oblique impact, Mindlin's K_t = 2(1 − ν)/(2 − ν) K_p.
    pub poisson_ratio: Option<f64>,
    /// The preset's `[calibration]` record: the speeds its parameters hold over (`None` for
    /// other balls and presets without one; [`Ball::calibration_warning`]).
    pub calibration: Option<crate::preset::Calibration>,
    /// What the caller changed from the preset (`mass`, `radius`, `k_p`, `c`, `k_r`, `z_p`,
    /// `lambda`, `zeta`), in that order: the JSON `ball.overrides`.
    pub overrides: Vec<String>,
    /// The conditions the ball is at (temperature, gauge pressure, atmosphere): its
    /// calibration record's, or those [`Ball::at_conditions`] set; every answer states them.
    pub conditions: crate::conditions::Conditions,
    /// The published flight model a shot of it flies on, its preset's
    /// ([`crate::preset::Preset::flight_model`]); `None`: none, the assumed smooth sphere.
    pub flight_model: Option<crate::flight::Published>,
}

mod batch;
mod batch_failure;
mod batch_reading;
mod batch_report;
mod calibration;
mod collide;
mod collide_pair;
mod columns;
mod conditions;
mod conditions_blame;
mod conditions_words;
mod court;
mod entry;
mod error;
mod fit;
mod intervals;
mod judged;
mod map_reach;
mod mc;
mod mc_temperature;
mod moved;
mod oblique;
mod oblique_fit;
mod reach;
mod report;
mod rows;
mod shift;
mod shot;
mod shot_after;
mod shot_mc;
mod shot_net;
mod shot_row;
mod standard_ball;
mod standard_conditions;
mod standards;
mod statics;
mod summary;
mod surface;
mod surface_used;
mod surface_warnings;
mod sweep;
mod vouched;
mod warnings;
pub use batch::{BallOutcome, BatchSetup, quantity as batch_quantity};
pub use batch_failure::FitFailure;
pub use batch_report::{
    BatchReport, BatchSummary, BatchUnanswered, StandardRef, unfitted_by_reason,
};
pub use calibration::{BallRecord, changed_params};
pub use collide::CollisionReport;
pub use collide_pair::{Partner, TargetRecord};
pub use columns::{Columns, Unanswered, first_pass, first_pass_stoppable};
pub use conditions::{ConditionsSpec, recorded as recorded_conditions, standard_leak};
pub use court::{CourtCalibration, ITF_ANGLE, ITF_SPEED};
pub use entry::{Overrides, PresetRow};
pub use error::BallError;
pub use intervals::{Intervals, bands, fit_table, holds, intervals};
pub use judged::{
    CourtMeasured, LeakVerdict, StaticTestReport, court_measured, judge_leak, leak_test_conditions,
    pressure_loss_test, static_test_report,
};
pub use map_reach::{MapReach, map_displacement_warning, map_radius_note, map_reach};
pub use mc::{McReport, MonteCarlo};
pub use oblique::{CourtPace, ObliqueSpec, SOLID_INERTIA_FACTOR};
pub use oblique_fit::{ObliqueFitReport, is_data_error as is_oblique_data_error};
pub use reach::{
    Reach, centre_bounds, displacement_warning, indentation_warning, peak_displacement, reach,
};
pub use report::{BallHeader, Energy, FitReport, ImpactReport, MeasuredAt};
pub use rows::{ImpactRow, Rest, impact_row, impact_rows};
pub use shot::{ShotBounce, ShotEnd, ShotReport, ShotSpec};
pub use shot_after::AfterBounceError;
pub use shot_mc::{
    NetMc, SHOT_MC_END_QUANTITIES, SHOT_MC_QUANTITIES, ShotMcReport, ShotMcSpec, ShotSpread, Spread,
};
pub use shot_net::{Net, NetReport, TENNIS_NET_HEIGHT};
pub use shot_row::SHOT_QUANTITIES;
pub use standard_conditions::test_words;
pub use standards::{
    ConditionsEntry, PressureLossEntry, PressureLossTest, StandardEntry, not_a_drop_standard,
    standards,
};
pub use statics::{ITF_RETURN_PEAK, ReturnReading, StaticReading, StaticReport};
pub use summary::{ImpactOutcome, ImpactSummary};
pub use surface::surface_label;
pub use surface_used::{SurfaceError, SurfaceUsed};
pub use sweep::{sweep_zeta, sweep_zeta_watched};
pub use warnings::{ENERGY_RESIDUAL_MAX, map_indentation_warning, warning_of};

impl Ball {
    /// An embedded preset (`superball`, `golf`, `baseball`, …) on the parameter set and contact
    /// law its file names. No file is read: user presets are [`Ball::from_catalog`]'s.
    ///
    /// ```
    /// let b = bouncelab::Ball::from_preset("superball")?;
    /// assert_eq!(b.params.mass, 0.0374);
    /// assert_eq!(b.params.v0, 3.12); // the speed Cross measured at
    /// let err = bouncelab::Ball::from_preset("cricket").unwrap_err();
    /// assert!(err.to_string().starts_with("unknown preset 'cricket' (available: superball,"));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn from_preset(name: &str) -> Result<Ball, BallError> {
        Ball::from_catalog(&Catalog::embedded(), name)
    }

    /// A preset from a catalog: `Catalog::load(catalog::user_presets_dir().as_deref(), None)?`
    /// holds the user's presets as well as the embedded ones, as the command line sees them.
    pub fn from_catalog(catalog: &Catalog, name: &str) -> Result<Ball, BallError> {
        Ball::from_entry(catalog.get(name)?, None, None, None)
    }

    /// A catalog entry with the command line's `--params`, `--law` and `--v0` applied (each
    /// `None` keeps the preset's), every parameter checked. A bad `v0` is named as such; any
    /// other parameter out of its domain is the preset's, and the error names the preset.
    /// [`Ball::from_entry_with`] takes parameter overrides too.
    pub fn from_entry(
        entry: &Entry,
        source: Option<ParamSource>,
        law: Option<ContactLaw>,
        v0: Option<f64>,
    ) -> Result<Ball, BallError> {
        Ball::from_entry_with(entry, source, law, v0, &Overrides::default())
    }

    /// The normalized ball, m = K_p = v0 = 1, set by λ and ζ alone (and z̄_p = z_p ω0/v0 for
    /// flattening; `None` for none), as `bouncelab run --normalized`.
    ///
    /// ```
    /// use bouncelab::{Ball, ContactLaw};
    /// // Maxwell's ball (λ = 0) keeps no energy from ζ = 1 on: e = 0
    /// let r = Ball::normalized(0.0, 1.5, None, ContactLaw::Linear)?.impact()?;
    /// assert_eq!((r.cor, r.rebound), (0.0, false));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn normalized(
        lambda: f64,
        zeta: f64,
        zp_bar: Option<f64>,
        law: ContactLaw,
    ) -> Result<Ball, BallError> {
        validate_lambda_zeta(lambda, zeta)?;
        if let Some(z) = zp_bar {
            check_positive(Field::ZpBar, z)?;
        }
        let params = ImpactParams::from_normalized(lambda, zeta, zp_bar.unwrap_or(f64::INFINITY));
        params.validate()?;
        Ok(Ball::unnamed("normalized", "normalized", params, law))
    }

    /// A ball given by its parameters, SI units (checked: the first bad field is named).
    ///
    /// ```
    /// use bouncelab::{Ball, ContactLaw, ImpactParams};
    /// let k_h = ImpactParams::k_h_matching(5.45e4, 4e-3); // Eq. 16
    /// let p = ImpactParams { mass: 0.0374, k_p: 5.45e4, damping: 140.0, k_r: 7.08e4,
    ///                        z_p: 4e-3, k_h, v0: 3.12 };
    /// let r = Ball::from_params(p, ContactLaw::Linear)?.impact()?;
    /// assert!((r.cor - 0.7506).abs() < 1e-4);
    /// let bad = ImpactParams { mass: -1.0, ..p };
    /// assert_eq!(Ball::from_params(bad, ContactLaw::Linear).unwrap_err().to_string(),
    ///            "invalid mass: -1 (must not be negative)");
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn from_params(params: ImpactParams, law: ContactLaw) -> Result<Ball, BallError> {
        params.validate()?;
        Ok(Ball::unnamed("parameters", "given", params, law))
    }

    /// A ball of no preset (checked parameters): no name, no measurements, no fit, the
    /// conditions recorded as none; `origin` and `source` say where its parameters came from.
    fn unnamed(origin: &str, source: &'static str, params: ImpactParams, law: ContactLaw) -> Ball {
        Ball {
            name: None,
            origin: origin.into(),
            source,
            params,
            law,
            measured: None,
            description: String::new(),
            fit: None,
            poisson_ratio: None,
            calibration: None,
            overrides: Vec::new(),
            conditions: recorded_conditions(None),
            flight_model: None,
        }
    }

    /// "superball (embedded, adopted parameters)", "normalized ball (m = K_p = v0 = 1)" or
    /// "ball given by its parameters".
    pub fn label(&self) -> String {
        match &self.name {
            Some(n) => format!("{n} ({}, {} parameters)", self.origin, self.source),
            None if self.source == "normalized" => "normalized ball (m = K_p = v0 = 1)".into(),
            None => "ball given by its parameters".into(),
        }
    }

    /// The same ball at another impact speed (m/s). On a preset, a parameter that the new speed
    /// puts out of its domain (z̄_p = z_p ω0/v0) is named as the preset's.
    pub fn with_v0(mut self, v0: f64) -> Result<Ball, BallError> {
        self.params.v0 = v0;
        self.params.validate().map_err(|error| match &self.name {
            Some(name) if error.field != Field::V0 => BallError::Preset {
                name: name.clone(),
                source: self.source,
                error,
            },
            _ => BallError::Param(error),
        })?;
        Ok(self)
    }

    /// The same ball on another contact law.
    pub fn with_law(mut self, law: ContactLaw) -> Ball {
        self.law = law;
        self
    }

    /// The same ball with λ = K_r/K_p changed: K_r moves, m and K_p stay (Eq. 24).
    pub fn with_lambda(self, lambda: f64) -> Result<Ball, BallError> {
        self.with_lambda_zeta(Some(lambda), None)
    }

    /// The same ball with ζ = √(m K_p)/(2c) changed: c moves, m and K_p stay (Eq. 24).
    pub fn with_zeta(self, zeta: f64) -> Result<Ball, BallError> {
        self.with_lambda_zeta(None, Some(zeta))
    }

    /// λ and/or ζ changed at once (`None` keeps it), as `run --lambda L --zeta Z`.
    pub fn with_lambda_zeta(
        mut self,
        lambda: Option<f64>,
        zeta: Option<f64>,
    ) -> Result<Ball, BallError> {
        set_lambda_zeta(&mut self.params, lambda, zeta)?;
        for (name, given) in [("lambda", lambda.is_some()), ("zeta", zeta.is_some())] {
            if given && !self.overrides.iter().any(|o| o == name) {
                self.overrides.push(name.to_string());
            }
        }
        Ok(self)
    }

    /// λ = K_r/K_p.
    pub fn lambda(&self) -> f64 {
        self.params.normalized().lambda
    }

    /// ζ = √(m K_p)/(2c).
    pub fn zeta(&self) -> f64 {
        self.params.normalized().zeta
    }

    /// One impact: COR, peak force, contact time, indentations and the energy budget (no
    /// history), as `bouncelab run`.
    pub fn impact(&self) -> Result<ImpactResponse, BallError> {
        self.impact_with(&SolveOptions::default().with_energy())
    }

    /// One impact with the force, indentation and displacement sampled at `samples` evenly
    /// spaced times over the contact (2 … [`MAX_SAMPLES`]), as `bouncelab run --history`.
    ///
    /// ```
    /// let r = bouncelab::Ball::from_preset("superball")?.impact_history(400)?;
    /// let h = &r.history;
    /// assert_eq!((h.t.len(), h.force.len()), (400, 400));
    /// assert_eq!(h.force[0], 0.0); // F(0) = 0
    /// assert!((h.t[399] - r.contact_time.unwrap()).abs() < 1e-15); // s: sampled up to t_f
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn impact_history(&self, samples: usize) -> Result<ImpactResponse, BallError> {
        if !(2..=MAX_SAMPLES).contains(&samples) {
            return Err(BallError::Samples(samples));
        }
        self.impact_with(&SolveOptions::default().with_samples(samples).with_energy())
    }

    /// One impact with the solver options given (tolerance, method, history, energy audit).
    pub fn impact_with(&self, opts: &SolveOptions) -> Result<ImpactResponse, BallError> {
        Ok(simulate(&self.params, self.law, opts)?)
    }

    /// The recoil spring K_r (and λ) that makes the model's COR equal a measured one, holding
    /// m, K_p, c (so ζ), z_p and v0, as `bouncelab fit --cor E` (docs/model.md §4).
    ///
    /// ```
    /// let ball = bouncelab::Ball::from_preset("superball")?;
    /// let fit = ball.fit_cor(0.75)?;
    /// assert!((fit.cor - 0.75).abs() < 1e-12);
    /// assert!((fit.k_r - 70447.5).abs() < 0.1); // N/m; the paper adopted 70800
    /// let err = ball.fit_cor(0.1).unwrap_err(); // below what λ = 0 gives at this ζ
    /// assert!(err.to_string().starts_with("cor 0.1 is out of reach at ζ = 0.1612"));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn fit_cor(&self, cor: f64) -> Result<Fit, BallError> {
        Ok(fit_k_r(&self.params, self.law, cor)?)
    }

    /// Drop the ball onto a rigid plate and follow its bounces — flight under gravity and
    /// drag, each impact solved at its own speed — as `bouncelab drop` (docs/drop.md). The
    /// drag area is the preset's measured radius (a ball that is not a preset has none: give it
    /// a [`DropSetup`] without air, or use [`crate::drop::drop`] with a radius).
    ///
    /// ```
    /// use bouncelab::{Ball, drop::DropSetup};
    /// let ball = Ball::from_preset("tennis")?;
    /// let run = ball.drop_test(&DropSetup::new(2.54))?; // 100 in, the ITF's drop
    /// let first = &run.bounces[0];
    /// assert!(first.rebound_height > 1.0 && first.rebound_height < 2.54);
    /// assert!(run.bounces.windows(2).all(|w| w[1].rebound_height < w[0].rebound_height));
    /// # Ok::<(), bouncelab::BallError>(())
    /// ```
    pub fn drop_test(&self, setup: &DropSetup) -> Result<DropRun, BallError> {
        Ok(crate::drop::drop(&self.drop_ball(), setup)?)
    }

    /// [`Ball::drop_test`], each bounce reported to `watch`, which may stop it
    /// ([`BallError::Interrupted`]): Python's Ctrl-C.
    pub fn drop_test_watched(
        &self,
        setup: &DropSetup,
        watch: &dyn crate::analysis::work::Watch,
    ) -> Result<DropRun, BallError> {
        crate::drop::drop_watched(&self.drop_ball(), setup, watch)?.ok_or(BallError::Interrupted)
    }
}

/// Change λ and/or ζ of a ball's parameters (`None` keeps it): K_r and c move, m and K_p stay
/// (Eq. 24). Both values are checked first; then a K_r or c out of range is named by the λ or
/// ζ that gave it.
pub fn set_lambda_zeta(
    params: &mut ImpactParams,
    lambda: Option<f64>,
    zeta: Option<f64>,
) -> Result<(), BallError> {
    validate_lambda_zeta(lambda.unwrap_or(0.0), zeta.unwrap_or(0.0))?;
    let moved = params.with_lambda_zeta(lambda.unwrap_or(0.0), zeta.unwrap_or(1.0));
    if lambda.is_some() {
        params.k_r = moved.k_r;
    }
    if zeta.is_some() {
        params.damping = moved.damping;
    }
    // name what the caller gave when the K_r or c it gives is out of range
    params.validate().map_err(|e| {
        let given = match e.field {
            Field::KR => lambda.map(|l| (Field::Lambda, l, "K_r", "N/m")),
            Field::Damping => zeta.map(|z| (Field::Zeta, z, "c", "kg/s")),
            _ => None,
        };
        match given {
            Some((field, value, gives, unit)) => BallError::Derived {
                field,
                value,
                gives,
                derived: e.value,
                unit,
                reason: e.reason,
            },
            None => BallError::Param(e),
        }
    })
}

#[cfg(test)]
mod tests;
