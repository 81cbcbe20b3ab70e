//! A ball ready to simulate, named, with what was measured on it: what the command line runs,
//! the figures draw and the explorer exports.

use crate::model::contact::ContactLaw;
use crate::model::params::ImpactParams;
use crate::preset::{Measured, ParamSource, Preset};

/// A ball: the parameters the model runs on, its contact law, and what was measured.
#[derive(Debug, Clone, PartialEq)]
pub struct Ball {
    /// The preset's name (`"ball"` for the normalized ball).
    pub name: String,
    /// Which parameter set `params` is: "adopted", "materials", "modified" (λ or ζ moved in
    /// the explorer) or "normalized".
    pub source: String,
    /// The parameters, SI units.
    pub params: ImpactParams,
    /// The contact law.
    pub law: ContactLaw,
    /// What was measured (presets only).
    pub measured: Option<Measured>,
}

impl Ball {
    /// Preset `p` on its parameter set `source`, with contact law `law`.
    pub fn from_preset(p: &Preset, source: ParamSource, law: ContactLaw) -> Ball {
        Ball {
            name: p.name.clone(),
            source: source.name().into(),
            params: p.params_from(source),
            law,
            measured: Some(p.measured.clone()),
        }
    }

    /// "adopted parameters, linear law" (a figure's title names the ball)
    pub fn describe(&self) -> String {
        format!("{} parameters, {} law", self.source, self.law)
    }

    /// The measured values apply only at the speed they were measured at.
    pub fn measured_at(&self, v0: f64) -> Option<&Measured> {
        self.measured
            .as_ref()
            .filter(|m| (m.v0 - v0).abs() <= 1e-9 * m.v0)
    }
}
