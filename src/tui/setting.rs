//! What the model runs on, as the undo stack keeps it.

use super::param::Param;
use crate::api::ConditionsSpec;
use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::Preset;
use crate::target::Target;

/// What the model runs on: the ball, its parameters (SI) and the contact law. The undo stack
/// holds these.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// Index into the explorer's presets.
    pub preset: usize,
    pub params: ImpactParams,
    pub law: ContactLaw,
    /// The ball's radius R (m): the preset's, or typed in the form (`m`); the run is outside
    /// the model's validity once z_m or α_max exceeds it.
    pub radius: f64,
    /// Whether the ball flattens as an elastomer (p0 = E z_p/R, Eq. 20), which ties its
    /// contact modulus to K_p: K_p = 2π E z_p (the form's E field).
    pub elastomer: bool,
    /// The target the ball meets, typed in the form (the wall until M, v_t, K_s or c_s is):
    /// its mass M (kg; ∞: today's wall) and speed toward the ball v_t (m/s) make the run the
    /// pair's, the reduced ball at the closing speed (docs/targets.md §2); its stiffness K_s
    /// (N/m; ∞: rigid) and the damping in parallel with it c_s (kg/s), the pair's run on a
    /// compliant target (docs/targets.md).
    pub target: Target,
    /// The inflation pressure and temperature typed in the form (issue 56), as `--pressure`
    /// and `--temperature` take them (`None`: the record's); `params` are the ball's at them
    /// (src/tui/physical/conditions.rs). The other fields of the spec stay `None`.
    pub conditions: ConditionsSpec,
    /// The pressure and temperature the preset's record states (`None` where it states none):
    /// what the form shows where none is typed.
    pub record: ConditionsSpec,
    /// The surface chosen in the surface picker (`G`, issue 53 item 6), as its file gives it
    /// (`None`: none chosen, the wall until a target is typed). Its normal give is the target
    /// above when chosen; the form may then move K_s, c_s, M off it (`y` writes them as
    /// overrides of it).
    pub surface: Option<crate::target::surface::Surface>,
    /// The tangential dashpot c_t (kg/s) in parallel with K_t (`None`: none), the chosen
    /// surface's (`oblique --tangential-damping`; docs/oblique.md §1).
    pub tangential_damping: Option<f64>,
}

/// The record's pressure (Pa) and temperature (°C) of `preset`, where it states them.
pub fn record(preset: &Preset) -> ConditionsSpec {
    let c = preset.calibration.as_ref();
    ConditionsSpec {
        pressure: c.and_then(|c| c.pressure),
        temperature: c.and_then(|c| c.temperature),
        ..ConditionsSpec::default()
    }
}

impl Setting {
    pub fn from_preset(index: usize, preset: &Preset) -> Setting {
        Setting {
            preset: index,
            params: preset.params(),
            law: preset.law,
            radius: preset.measured.radius,
            elastomer: preset.material.kind == crate::preset::MaterialKind::Elastomer,
            target: Target::wall(),
            conditions: ConditionsSpec::default(),
            record: record(preset),
            surface: None,
            tangential_damping: None,
        }
    }

    /// The parameters the run is made on: the ball's against the wall, else the reduced ball
    /// m* = m/(1 + m/M) at the closing speed v0 + v_t (docs/targets.md §2: a rigid target).
    pub fn run_params(&self) -> ImpactParams {
        if self.target.mass == f64::INFINITY && self.target.speed == 0.0 {
            return self.params;
        }
        let p = &self.params;
        ImpactParams {
            mass: p.mass / (1.0 + p.mass / self.target.mass),
            v0: p.v0 + self.target.speed,
            ..*p
        }
    }

    pub fn get(&self, p: Param) -> f64 {
        p.get(&self.params)
    }
}
