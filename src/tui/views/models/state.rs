//! The models view's numbers: the field's contact models calibrated to the current ball
//! (`crate::peers::calibrate::compare`, the same call as `bouncelab peers`), the
//! Christoforou–Yigit COR against speed, and Hunt–Crossley with α fixed. A calibration with
//! its sweep takes tens of milliseconds in debug builds, so it runs on a background
//! [`crate::tui::worker::Worker`] and comes back as `Action::ModelsReady`; a request the user has
//! moved past is abandoned between two speeds and its late answer dropped.

use crate::analysis::sweep::log_space;
use crate::figure::explorer::models::ModelsData;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::peers::calibrate::{self, christoforou_yigit_cor};
use crate::peers::rules::Rule;
use crate::peers::{PeerBall, PeerModel, cor};
use crate::tui::compute::HISTORY_SAMPLES;
use crate::tui::worker::Job;

/// Points of the COR-vs-speed sweep, log-spaced over v0/10 … 10 v0.
pub const MODELS_SPEEDS: usize = 25;

/// What the models view is computed for: the ball (m, R, v0, k, K_h), its parameters and law
/// for the Christoforou–Yigit curve, and the COR the peers are calibrated to. Two equal
/// requests give the same data, so the request is the data's key.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelsRequest {
    pub ball: PeerBall,
    pub params: ImpactParams,
    pub law: ContactLaw,
    /// The Christoforou–Yigit model's COR at v0 (the explorer's run).
    pub target: f64,
}

impl ModelsRequest {
    /// The request for a ball of `radius` (m) with these parameters, calibrated to `target`.
    pub fn new(params: &ImpactParams, law: ContactLaw, radius: f64, target: f64) -> Self {
        ModelsRequest {
            ball: PeerBall::from_params(params, radius),
            params: *params,
            law,
            target,
        }
    }

    /// The speeds of the COR-vs-speed sweep.
    pub fn speeds(&self) -> Vec<f64> {
        let (lo, hi) = crate::figure::peers::default_range(&self.params);
        log_space(lo, hi, MODELS_SPEEDS)
    }

    /// The whole computation.
    pub fn run(&self) -> Result<ModelsData, String> {
        Job::run_while(self, &mut || true).expect("never abandoned")
    }
}

impl Job for ModelsRequest {
    type Output = ModelsData;

    /// The calibrations first, then the sweep one speed at a time, asking `go_on` before each;
    /// nothing to show before the whole.
    fn run_refining(
        &self,
        go_on: &mut dyn FnMut() -> bool,
        _partial: &mut dyn FnMut(ModelsData),
    ) -> Option<Result<ModelsData, String>> {
        let err = |e: &dyn std::fmt::Display| Some(Err(e.to_string()));
        if !go_on() {
            return None;
        }
        let rows = match calibrate::compare(&self.ball, self.target, HISTORY_SAMPLES) {
            Ok(r) => r,
            Err(e) => return err(&e),
        };
        let chi = rows
            .iter()
            .find(|c| c.model == PeerModel::HuntCrossley && c.rule == Rule::Exact)
            .map_or(0.0, |c| c.damping);
        let alpha = chi / self.ball.v0;
        let (mut cy_speed, mut hc_fixed) = (Vec::new(), Vec::new());
        for v in self.speeds() {
            if !go_on() {
                return None;
            }
            match christoforou_yigit_cor(&self.params, self.law, v) {
                Ok(e) => cy_speed.push((v, e)),
                Err(e) => return err(&e),
            }
            match cor(PeerModel::HuntCrossley, alpha * v) {
                Ok(e) => hc_fixed.push((v, e)),
                Err(e) => return err(&e),
            }
        }
        Some(Ok(ModelsData {
            target: self.target,
            v0: self.ball.v0,
            rows,
            cy_speed,
            hc_alpha: alpha,
            hc_fixed,
        }))
    }
}

/// The models view's bookkeeping in the explorer's state: the data held, for which request,
/// and the request out on the worker.
#[derive(Debug, Clone, Default)]
pub struct Models {
    /// The request the held answer is for, and the answer (an error in one line).
    pub held: Option<(ModelsRequest, Result<ModelsData, String>)>,
    /// The request the view needs and has no answer for.
    pub wanted: Option<ModelsRequest>,
    /// The request last handed to the worker.
    pub asked: Option<ModelsRequest>,
    /// Why the worker's thread stopped, while `held`'s error is that stop (`R` asks again).
    pub stopped: Option<String>,
}

impl Models {
    /// The data for `current`, when held (not a previous ball's).
    pub fn for_request(&self, current: Option<&ModelsRequest>) -> Option<&ModelsData> {
        match (&self.held, current) {
            (Some((r, Ok(d))), Some(c)) if r == c => Some(d),
            _ => None,
        }
    }

    /// The error the calibration for `current` ended with, if it did.
    pub fn error_for(&self, current: Option<&ModelsRequest>) -> Option<&str> {
        match (&self.held, current) {
            (Some((r, Err(e))), Some(c)) if r == c => Some(e),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Preset;

    #[test]
    fn a_calibration_can_be_abandoned_between_speeds() {
        let p = Preset::embedded()[0].params();
        let req = ModelsRequest::new(&p, ContactLaw::Linear, 0.0254, 0.75);
        let mut asked = 0;
        assert!(
            Job::run_while(&req, &mut || {
                asked += 1;
                asked < 4
            })
            .is_none()
        );
        assert_eq!(asked, 4);
    }

    #[test]
    fn the_peers_reach_the_target_and_the_sweep_spans_two_decades() {
        let p = Preset::embedded()[1].params();
        let req = ModelsRequest::new(&p, ContactLaw::Linear, 0.021, 0.6);
        let d = req.run().unwrap();
        for model in PeerModel::ALL {
            let e = d.exact(model).unwrap().response.cor;
            assert!((e - 0.6).abs() < 1e-6, "{model}: {e}");
        }
        assert_eq!(d.cy_speed.len(), MODELS_SPEEDS);
        let (first, last) = (d.cy_speed[0].0, d.cy_speed[MODELS_SPEEDS - 1].0);
        assert!((last / first - 100.0).abs() < 1e-9);
        // α fixed: the calibration holds at v0 only, the COR falls with speed
        assert!(d.hc_fixed[0].1 > 0.6 && d.hc_fixed[MODELS_SPEEDS - 1].1 < 0.6);
    }
}
