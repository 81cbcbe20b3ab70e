//! The published flight models (docs/flight.md §2): which one a ball flies on is its preset's
//! `aerodynamics` field (docs/presets.md), or the model named like the preset when the field
//! is absent; a ball with neither flies on [`Aero::assumed`].

use super::aero::{Aero, Decay, Drag, GOLF_LIFT, Lift};
use serde::{Deserialize, Serialize};

/// 1 mph in m/s (exact: 0.44704).
const MPH: f64 = 0.44704;

/// A ball kind with a published flight model: what a preset's `aerodynamics` names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Published {
    /// Cross & Lindsey's C_D, Štěpánek's C_L.
    Tennis,
    /// Nathan's calculator.
    Baseball,
    /// Jenkins et al.'s drag crisis, Smits & Smith's lift and decay.
    Golf,
}

impl Published {
    /// Every published model, in the order docs/flight.md §2 lists them.
    pub const ALL: [Published; 3] = [Published::Tennis, Published::Baseball, Published::Golf];

    /// The name a preset's `aerodynamics` writes: `"tennis"`, `"baseball"` or `"golf"`.
    pub fn name(self) -> &'static str {
        match self {
            Published::Tennis => "tennis",
            Published::Baseball => "baseball",
            Published::Golf => "golf",
        }
    }

    /// The model named `name` exactly (a preset without `aerodynamics` flies on the model
    /// named like it), `None` for any other name.
    pub fn named(name: &str) -> Option<Published> {
        Published::ALL.into_iter().find(|p| p.name() == name)
    }
}

impl Aero {
    /// The published model `model` in air of density `rho` (docs/flight.md §2).
    pub fn published(model: Published, rho: f64) -> Aero {
        let published = |drag, lift, decay, source| Aero {
            air_density: rho,
            drag,
            lift,
            decay,
            assumed: false,
            source,
        };
        match model {
            // Cross & Lindsey (2014): C_D = 0.507 ± 0.024 in free flight, independent of speed
            // and spin (15–30 m/s); Štěpánek (1988): C_L = 1/(2.022 + 0.981/S)
            Published::Tennis => published(
                Drag::Constant { cd: 0.507 },
                Lift::Rational {
                    c0: 0.981,
                    c1: 2.022,
                    c2: 1.0,
                },
                Decay::None,
                "C_D Cross & Lindsey 2014; C_L Stepanek 1988; no spin decay (none published found)",
            ),
            // Nathan's trajectory calculator: C_L = 1.120 S/(0.583 + 2.333 S), spin decaying
            // as exp(−(t/30 s)(|v|/100 mph)), C_D = 0.3008 + 0.0292 per 1000 rpm (its
            // spreadsheet's cd0 and cdspin, fitted to the 2015 Statcast batted balls)
            Published::Baseball => published(
                Drag::Spin {
                    cd0: 0.3008,
                    per_krpm: 0.0292,
                },
                Lift::Rational {
                    c0: 0.583,
                    c1: 2.333,
                    c2: 1.120,
                },
                Decay::PerMetre {
                    k: 1.0 / (30.0 * 100.0 * MPH),
                },
                "C_D, C_L and spin decay Nathan's calculator (2015 Statcast fit)",
            ),
            // Jenkins et al. (2018): 0.24 < C_D < 0.7 over 3·10⁴ < Re < 1.08·10⁵ (the dimpled
            // ball's crisis), plus Smits & Smith's (1994) spin term 0.18 S; their C_L(S) table;
            // spin loss 0.0004 (1/mph/s) × speed × spin
            Published::Golf => published(
                Drag::Crisis {
                    re_low: 3.0e4,
                    cd_low: 0.7,
                    re_high: 1.08e5,
                    cd_high: 0.24,
                    cd_per_spin: 0.18,
                },
                Lift::Table { points: &GOLF_LIFT },
                Decay::PerMetre { k: 0.0004 / MPH },
                "C_D Jenkins et al. 2018 (crisis) + 0.18 S, C_L(S) and spin decay Smits & Smith 1994",
            ),
        }
    }

    /// The model of a ball whose preset names `model` (docs/flight.md §2), or
    /// [`Aero::assumed`] for a ball with none, in air of density `rho`.
    pub fn for_ball(model: Option<Published>, rho: f64) -> Aero {
        model.map_or_else(|| Aero::assumed(rho), |m| Aero::published(m, rho))
    }
}
