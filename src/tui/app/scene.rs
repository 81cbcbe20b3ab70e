//! What the charts are drawn from: the state's results and display choices as a
//! [`Scene`], plain data the figure builders (`crate::figure::explorer`) take. The screen and
//! the export both build their figures from it.

use super::App;
use crate::figure::explorer::{MODIFIED, Pinned, Scene, SpeedSweep, ZetaSweep};
use crate::figure::paper::Ball;
use crate::preset::Preset;
use crate::tui::compute::{ZetaCurve, reference_curves};
use crate::tui::setting::Setting;
use crate::tui::views::sweeps::speed::SpeedCurve;

fn zeta(c: &ZetaCurve) -> ZetaSweep<'_> {
    ZetaSweep {
        lambda: c.lambda,
        points: &c.points,
    }
}

fn speed(c: &SpeedCurve) -> SpeedSweep<'_> {
    SpeedSweep {
        points: &c.points,
        v_flat: c.request.v_flat,
        v_max: c.request.v_max,
        refining: c.refining,
    }
}

/// A preset as a ball of the paper's charts, with what was measured.
fn ball(p: &Preset) -> Ball {
    Ball {
        name: p.name.clone(),
        source: p.parameters.name().into(),
        params: p.params(),
        law: p.law,
        measured: Some(p.measured.clone()),
    }
}

/// Whether `setting` keeps the λ and ζ of `preset` (v0 is shown on its own).
fn preset_lambda_zeta(preset: &Preset, setting: &Setting) -> bool {
    let base = preset.params().normalized();
    let now = setting.params.normalized();
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs());
    same(base.lambda, now.lambda) && same(base.zeta, now.zeta)
}

impl App {
    /// The scene of the current state.
    pub fn scene(&self) -> Scene<'_> {
        let preset = self.preset();
        let mut current = ball(preset);
        current.params = self.setting.params;
        current.law = self.setting.law;
        if !preset_lambda_zeta(preset, &self.setting) {
            current.source = MODIFIED.into();
        }
        // the measurements are of the record's conditions, against its wall: not drawn beside
        // a ball at others or on a target (the readout does not compare them either, as `run`
        // withholds them and `collide` has none)
        let elsewhere = self.setting.target != crate::target::Target::wall();
        if (!self.setting.conditions.is_empty() || elsewhere)
            && let Some(m) = current.measured.as_mut()
        {
            (m.cor, m.max_force, m.contact_time) = (None, None, None);
        }
        let pending = self.speed_requests().iter().map(|r| r.v_max);
        Scene {
            ball: current,
            balls: self.presets.iter().map(ball).collect(),
            run: self.run.as_ref(),
            references: reference_curves().iter().map(zeta).collect(),
            zeta: self.zeta.as_ref().map(zeta),
            speed: self.sweeps.curve.as_ref().map(speed),
            speed_pending: pending.reduce(f64::max),
            speed_stopped: self.sweeps.stopped.as_deref(),
            pinned: self
                .pins
                .iter()
                .enumerate()
                .map(|(i, g)| Pinned {
                    number: i + 1,
                    ball: self.presets[g.setting.preset].name.clone(),
                    params: g.setting.params,
                    law: g.setting.law,
                    run: g.run.as_ref(),
                    zeta: g.zeta.as_ref().map(zeta),
                    speed: g.speed.as_ref().map(speed),
                })
                .collect(),
            measured: &self.fit.overlays,
            models: self.models(),
            models_pending: self.models.wanted.is_some(),
            target: self.target_motion.as_ref(),
        }
    }
}
