//! The conditions each standard tests its ball at — temperature and inflation pressure, as its
//! rules state them or that they state none (docs/drop.md, "Conditions") — and the FIFA
//! 72-hour pressure-loss test. Kept beside [`super::standards`], keyed by the standard's name,
//! so that a standard added there without conditions here reads "not stated" rather than
//! failing to build.

use serde::Serialize;

/// The temperature and pressure a standard tests its ball at.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TestConditions {
    /// The standard's name (`super::standards::Standard::name`).
    pub standard: &'static str,
    /// The test's temperature, °C, with its tolerance [nominal, ±]; `None` where the rule
    /// states none (in the sources used).
    pub temperature_c: Option<[f64; 2]>,
    /// The ball's gauge pressure, Pa, as [lo, hi]; `None` where the rule states none.
    pub pressure_gauge_pa: Option<[f64; 2]>,
    /// Where these come from, or that the rule states none.
    pub source: &'static str,
}

/// 1 psi, Pa (NIST SP 811, B.8), for the pressures printed in psi.
const PSI: f64 = crate::conditions::pressure::PSI;

/// A WSF squash ball's conditions at its test temperature `$c` (°C): the standard `wsf-$c`,
/// conditioned to `$c`, not pressurized.
macro_rules! squash {
    ($c:literal) => {
        TestConditions {
            standard: concat!("wsf-", $c),
            temperature_c: Some([$c as f64, 0.0]),
            pressure_gauge_pa: None,
            source: concat!(
                "World Squash Federation, Specifications for Squash Balls: the ball conditioned \
                 to ",
                $c,
                " °C (no tolerance stated in the sources used); a squash ball is not \
                 pressurized"
            ),
        }
    };
}

/// Every standard's conditions that a source states (docs/drop.md, "Conditions").
pub const TEST_CONDITIONS: [TestConditions; 7] = [
    TestConditions {
        standard: "itf",
        temperature_c: Some([20.0, 2.0]),
        pressure_gauge_pa: None,
        source: "ITF Technical booklet (2015), Part A §1.1, the Controlled Environment: \
                 20 ± 2 °C, 60 ± 5 % RH, 102 ± 3 kPa atmosphere; the ball's own pressure is \
                 not specified (the rules test its deformation and rebound)",
    },
    fifa(
        "fifa-quality",
        "FIFA Quality Programme for Footballs as licensees publish it (derbystar.de, \
         \"FIFA Quality Pro\"): 0.8 bar, 20 °C; the ± 2 °C is the pressure-loss test's",
    ),
    fifa(
        "fifa-quality-pro",
        "FIFA Quality Programme for Footballs as licensees publish it (derbystar.de, \
         \"FIFA Quality Pro\"): 0.8 bar, 20 °C; the ± 2 °C is the pressure-loss test's",
    ),
    TestConditions {
        standard: "fiba",
        temperature_c: None,
        pressure_gauge_pa: Some([7.5 * PSI, 8.5 * PSI]),
        source: "FIBA Official Basketball Rules, Basketball Equipment (2020), section 2: the \
                 ball is inflated so that it rebounds in the window (no number); 7.5–8.5 psi is \
                 the range printed on size-7 balls; no temperature is stated",
    },
    squash!(23),
    squash!(45),
    fifa(
        "fifa-pressure-loss",
        "FIFA Quality Programme for Footballs, loss of pressure, as licensees publish it \
         (derbystar.de): inflated to 0.8 bar, kept 72 h at 20 ± 2 °C",
    ),
];

/// A FIFA test's conditions: 0.8 bar at 20 ± 2 °C (the Quality Programme's classes and its
/// pressure-loss test alike), as `source` words it.
const fn fifa(standard: &'static str, source: &'static str) -> TestConditions {
    TestConditions {
        standard,
        temperature_c: Some([20.0, 2.0]),
        pressure_gauge_pa: Some([80_000.0, 80_000.0]),
        source,
    }
}

/// The conditions of the standard `name`: its entry, or one that says the rule states none
/// (ITTF's, MLB's, the NCAA's and the softball classes' in the sources used).
pub fn of(name: &str) -> TestConditions {
    TEST_CONDITIONS
        .iter()
        .find(|c| c.standard == name)
        .copied()
        .unwrap_or(TestConditions {
            standard: "",
            temperature_c: None,
            pressure_gauge_pa: None,
            source: "the rule, in the sources used (docs/drop.md), states no temperature and no \
                     pressure",
        })
}

/// A pressure-loss test: a ball inflated to `pressure` and kept `hours` at `temperature` may
/// lose at most `max_loss` of its gauge pressure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PressureLoss {
    /// Short name for `--standard`.
    pub name: &'static str,
    /// The body and the test.
    pub title: &'static str,
    /// The gauge pressure at the start, Pa.
    pub pressure: f64,
    /// The temperature it is kept at, °C.
    pub temperature: f64,
    /// How long, h.
    pub hours: f64,
    /// The largest fraction of the gauge pressure it may lose.
    pub max_loss: f64,
    /// The embedded presets this is the ball's own test.
    pub balls: &'static [&'static str],
    /// Where the numbers come from.
    pub source: &'static str,
    /// What could not be confirmed from a public source.
    pub unconfirmed: &'static str,
}

/// FIFA's 72-hour test: at most 20 % lost (Quality Pro; 25 % for Quality) from 0.8 bar at
/// 20 °C (docs/model.md §10.3).
pub const PRESSURE_LOSS: [PressureLoss; 1] = [PressureLoss {
    name: "fifa-pressure-loss",
    title: "FIFA Quality Pro football, loss of pressure over 72 h",
    pressure: 80_000.0,
    temperature: 20.0,
    hours: 72.0,
    max_loss: 0.20,
    balls: &["football"],
    source: "FIFA Quality Programme for Footballs, loss of pressure (≤ 20 % in 72 h for \
             Quality Pro, ≤ 25 % for Quality), as published by licensed makers (derbystar.de, \
             \"FIFA Quality Pro\")",
    unconfirmed: "FIFA's own test manual is not public: the limit is as licensed makers \
                  publish it",
}];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_entry_names_a_standard() {
        for c in TEST_CONDITIONS {
            let known = super::super::standards::find(c.standard).is_ok()
                || PRESSURE_LOSS.iter().any(|p| p.name == c.standard);
            assert!(known, "{}", c.standard);
        }
        assert_eq!(of("mlb").temperature_c, None);
        assert_eq!(of("itf").temperature_c, Some([20.0, 2.0]));
    }

    /// FIBA's range in pascals: 7.5 psi = 51 710.68 Pa, 8.5 psi = 58 605.44 Pa (NIST SP 811).
    #[test]
    fn fiba_pressures_in_pascals() {
        let [lo, hi] = of("fiba").pressure_gauge_pa.unwrap();
        assert!((lo - 51_710.679_7).abs() < 1e-3, "{lo}");
        assert!((hi - 58_605.437_0).abs() < 1e-3, "{hi}");
    }
}
