//! The sweeps view's COR against impact speed (Fig. 4): what a sweep is computed for, the
//! curve, and the sweep run coarse to fine so a slow one shows its shape early (on the
//! background worker, `tui::worker`). SI units throughout.

use crate::analysis::sweep::{VelocityPoint, cor_vs_velocity, lin_space};
use crate::figure::ticks::nice_ceil;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::solver::{SolveOptions, simulate_normalized};

/// Points of the COR-vs-speed sweep.
pub const SPEED_POINTS: usize = 40;

/// What a COR-vs-speed sweep (Fig. 4) is computed for. Two equal requests give the same
/// curve, so the request is the curve's key.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedRequest {
    /// The ball; v0 is replaced by `v_max`: the sweep does not depend on it otherwise.
    pub params: ImpactParams,
    pub law: ContactLaw,
    /// The sweep runs over (0, v_max] (m/s).
    pub v_max: f64,
    /// Speed at which the linear law starts to flatten (m/s), when the ball can flatten.
    pub v_flat: Option<f64>,
}

/// COR against impact speed for one ball (Fig. 4).
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedCurve {
    pub request: SpeedRequest,
    /// In order of speed.
    pub points: Vec<VelocityPoint>,
    /// Some of the speeds only: the sweep is still being refined ([`SpeedRequest::run_refining`]).
    pub refining: bool,
}

/// The sweep's speeds (indices into [`SpeedRequest::speeds`]) in the order they are computed:
/// the ends and every 13th first (4 points: the curve's shape), then every 6th, every 3rd, and
/// the rest — each group a coarse curve the next refines. Every index once.
pub fn refinement_levels(n: usize) -> Vec<Vec<usize>> {
    let mut done = vec![false; n];
    let mut levels = Vec::new();
    for stride in [13, 6, 3, 1] {
        let mut level: Vec<usize> = (0..n).step_by(stride).collect();
        if stride > 1 && n > 0 {
            level.push(n - 1);
        }
        level.retain(|&i| !std::mem::replace(&mut done[i], true));
        if !level.is_empty() {
            levels.push(level);
        }
    }
    levels
}

/// Speed at which the ball starts to flatten under the linear law. Below flattening the peak
/// indentation scales with v0 (z_m = z̄_m(λ, ζ) v0/ω0, docs/model.md §5), so z_m = z_p at
/// v = z_p ω0 / z̄_m. `None` when the ball cannot flatten (z_p = ∞).
pub fn flattening_speed(params: &ImpactParams) -> Option<f64> {
    if !params.z_p.is_finite() {
        return None;
    }
    let n = params.normalized();
    let r = simulate_normalized(
        n.lambda,
        n.zeta,
        ContactLaw::Linear,
        &SolveOptions::default(),
    )
    .ok()?;
    let v = params.z_p * params.omega0() / r.max_indentation;
    (v.is_finite() && v > 0.0).then_some(v)
}

impl SpeedRequest {
    /// The sweep for `params` and `law`, up to a speed that shows the flattening drop, the
    /// measured speed and the current one: v_max = max(2.5 v_flat, 1.5 v_measured, 1.2 v0),
    /// rounded up, at most 100 m/s. Costs one exact linear run (for v_flat).
    pub fn new(params: &ImpactParams, law: ContactLaw, measured_v0: f64) -> SpeedRequest {
        let v_flat = flattening_speed(params);
        let want = [
            2.5 * v_flat.unwrap_or(0.0),
            1.5 * measured_v0,
            1.2 * params.v0,
        ]
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
        let v_max = nice_ceil(want).min(100.0);
        SpeedRequest {
            params: ImpactParams {
                v0: v_max,
                ..*params
            },
            law,
            v_max,
            v_flat,
        }
    }

    pub fn speeds(&self) -> Vec<f64> {
        lin_space(self.v_max / SPEED_POINTS as f64, self.v_max, SPEED_POINTS)
    }

    /// The whole sweep.
    pub fn run(&self) -> Result<SpeedCurve, String> {
        self.run_while(|| true).expect("never abandoned")
    }

    /// The sweep one speed at a time, asking `go_on` before each; `None` when it said stop.
    /// (Some corners — λ ≈ 0, ζ ≫ 1 with a nonlinear law — take tens of ms a point.)
    pub fn run_while(&self, go_on: impl FnMut() -> bool) -> Option<Result<SpeedCurve, String>> {
        self.run_refining(go_on, |_| {})
    }

    /// [`SpeedRequest::run_while`], coarse to fine ([`refinement_levels`]): after each level
    /// but the last, `partial` gets the curve so far (`refining: true`), so a slow sweep shows
    /// its shape early. The finished curve is the same as computing the speeds in order.
    pub fn run_refining(
        &self,
        mut go_on: impl FnMut() -> bool,
        mut partial: impl FnMut(SpeedCurve),
    ) -> Option<Result<SpeedCurve, String>> {
        let speeds = self.speeds();
        let mut found: Vec<Option<VelocityPoint>> = vec![None; speeds.len()];
        let levels = refinement_levels(speeds.len());
        let curve = |found: &[Option<VelocityPoint>], refining| SpeedCurve {
            request: self.clone(),
            points: found.iter().flatten().cloned().collect(),
            refining,
        };
        for (k, level) in levels.iter().enumerate() {
            for &i in level {
                if !go_on() {
                    return None;
                }
                match cor_vs_velocity(&self.params, self.law, &[speeds[i]]) {
                    Ok(p) => found[i] = p.into_iter().next(),
                    Err(e) => return Some(Err(e.to_string())),
                }
            }
            if k + 1 < levels.len() {
                partial(curve(&found, true));
            }
        }
        Some(Ok(curve(&found, false)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Preset;
    use crate::tui::compute::impact;

    #[test]
    fn flattening_speed_is_where_z_m_reaches_z_p() {
        let p = Preset::embedded()[0].params();
        let v = flattening_speed(&p).unwrap();
        let at = |v0| impact(&ImpactParams { v0, ..p }, ContactLaw::Linear).unwrap();
        assert!((at(v).max_indentation - p.z_p).abs() < 1e-9 * p.z_p.max(1.0));
        assert_eq!(at(0.99 * v).permanent_indentation, 0.0);
        assert!(at(1.1 * v).permanent_indentation > 0.0);
    }

    #[test]
    fn speed_curve_reaches_past_flattening() {
        for preset in Preset::embedded() {
            let p = preset.params();
            let req = SpeedRequest::new(&p, ContactLaw::Linear, preset.measured.v0);
            let c = req.run().unwrap();
            let v_flat = req.v_flat.unwrap();
            assert!(
                req.v_max >= 2.0 * v_flat && req.v_max <= 100.0,
                "{}",
                preset.name
            );
            assert!(
                c.points.last().unwrap().cor < c.points[0].cor - 0.02,
                "{}",
                preset.name
            );
            // the same as the library's sweep over the same speeds
            let whole = cor_vs_velocity(&p, ContactLaw::Linear, &req.speeds()).unwrap();
            assert_eq!(c.points, whole);
            // v0 matters only through v_max
            let slower = ImpactParams {
                v0: 0.5 * preset.measured.v0,
                ..p
            };
            assert_eq!(
                SpeedRequest::new(&slower, ContactLaw::Linear, preset.measured.v0),
                req
            );
            assert_ne!(
                SpeedRequest::new(&p, ContactLaw::Hertz, preset.measured.v0),
                req
            );
            if req.v_max < 100.0 {
                let faster = ImpactParams { v0: req.v_max, ..p };
                assert_ne!(
                    SpeedRequest::new(&faster, ContactLaw::Linear, preset.measured.v0),
                    req
                );
            }
        }
    }

    #[test]
    fn refinement_covers_every_speed_once_coarse_first() {
        let levels = refinement_levels(SPEED_POINTS);
        assert_eq!(levels[0], [0, 13, 26, 39]);
        let mut all: Vec<usize> = levels.concat();
        all.sort_unstable();
        assert_eq!(all, (0..SPEED_POINTS).collect::<Vec<_>>());
    }

    #[test]
    fn a_refined_sweep_shows_coarse_curves_then_the_whole_one() {
        let p = Preset::embedded()[0].params();
        let req = SpeedRequest::new(&p, ContactLaw::Linear, 3.12);
        let mut partials = Vec::new();
        let done = req
            .run_refining(|| true, |c| partials.push(c))
            .unwrap()
            .unwrap();
        assert_eq!(done, req.run().unwrap());
        assert!(!done.refining && done.points.len() == SPEED_POINTS);
        assert_eq!(partials.len(), refinement_levels(SPEED_POINTS).len() - 1);
        assert_eq!(partials[0].points.len(), 4);
        for c in &partials {
            assert!(c.refining);
            // in order of speed, each point one of the finished curve's
            assert!(c.points.windows(2).all(|w| w[0].v0 < w[1].v0));
            assert!(c.points.iter().all(|q| done.points.contains(q)));
        }
    }

    #[test]
    fn a_sweep_can_be_abandoned_between_points() {
        let p = Preset::embedded()[0].params();
        let req = SpeedRequest::new(&p, ContactLaw::Linear, 3.12);
        let mut asked = 0;
        assert!(
            req.run_while(|| {
                asked += 1;
                asked < 5
            })
            .is_none()
        );
        assert_eq!(asked, 5);
    }
}
