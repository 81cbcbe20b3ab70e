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
    /// Where the ball's reference values (its `measured` COR, F_m, t_f) come from, as the
    /// figures label them: Cross's measurements for the paper's three balls, the middle of
    /// its standard's window for the drop-test balls (their preset files say "Not measured"),
    /// plain "measured" for a user's preset. Known by content, not by name alone: a preset
    /// carries the embedded data only if its name and `[measured]` table are an embedded
    /// preset's (tests/figures/figure_numbers.rs).
    pub fn measured_label(&self) -> &'static str {
        // parsed once: the explorer draws Fig. 4 (and asks this) at every frame
        static EMBEDDED: std::sync::OnceLock<Vec<Preset>> = std::sync::OnceLock::new();
        let same = |p: &Preset| p.name == self.name && Some(&p.measured) == self.measured.as_ref();
        match EMBEDDED
            .get_or_init(Preset::embedded_all)
            .iter()
            .position(same)
        {
            Some(i) if i < crate::preset::PAPER_BALLS => "measured (Cross 1999)",
            Some(_) => "standard's mid-window",
            None => "measured",
        }
    }

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
