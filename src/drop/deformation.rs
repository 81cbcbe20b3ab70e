//! The static standards: a ball squeezed between two plates under a load, its forward
//! deflection judged against a window (docs/drop.md, "Standards"; the model's static chain,
//! docs/model.md §11). Listed by `bouncelab standards` after the impact standards and run by
//! `bouncelab drop --standard NAME`, as the COR tests are: the drop's bounces are the ball's,
//! the verdict is the static test's.

use super::DropBall;
use super::G;
use super::standards::Verdict;
use crate::analysis::statics::{StaticDeflection, static_deflection};
use crate::model::contact::ContactLaw;
use serde::Serialize;

/// One governing body's deformation test and its windows (m of the diameter's shortening).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DeformationStandard {
    /// Short name for `--standard`.
    pub name: &'static str,
    /// The governing body and the test.
    pub title: &'static str,
    /// What is measured: `{"kind": "static", "load_kg", "peak_m"}`.
    pub test: StaticTest,
    /// What squeezes the ball.
    pub surface: &'static str,
    /// [lo, hi] of the forward deflection (m): the verdict's window.
    pub window: [Option<f64>; 2],
    /// [lo, hi] of the return deflection (m) where the rules give one: reported beside the
    /// verdict, not judged (docs/drop.md says why).
    pub return_window: Option<[f64; 2]>,
    /// Where the numbers come from (docs/drop.md cites each in full).
    pub source: &'static str,
    /// What could not be confirmed from a public source, if anything.
    pub unconfirmed: Option<&'static str>,
    /// The embedded presets that pass this standard.
    pub balls: &'static [&'static str],
}

/// The load and the return test's peak.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename = "static")]
pub struct StaticTest {
    /// The load between the plates, kg (its weight bears on each contact).
    pub load_kg: f64,
    /// The diameter's shortening before the return reading, m.
    pub peak_m: f64,
}

/// 18 lb in kg, the ITF deformation tests' load as the rules print it (8.165 kg).
pub const ITF_LOAD_KG: f64 = 8.165;

/// Every static standard, in the order `bouncelab standards` lists them.
pub const DEFORMATION_STANDARDS: [DeformationStandard; 1] = [DeformationStandard {
    name: "itf-deformation",
    title: "ITF tennis ball (Type 2), forward deformation",
    test: StaticTest {
        load_kg: ITF_LOAD_KG,
        peak_m: crate::analysis::statics::ITF_RETURN_PEAK,
    },
    surface: "two flat rigid plates",
    window: [Some(5.59e-3), Some(7.37e-3)],
    return_window: Some([8.00e-3, 10.80e-3]),
    source: "ITF Rules of Tennis, Appendix I: forward deformation 0.220–0.290 in (0.559–0.737 \
             cm) and return deformation 0.315–0.425 in (0.800–1.080 cm) at 18 lb (8.165 kg); \
             the return read after a 1 in compression (Lindsey, Tennis Warehouse University, \
             2021)",
    unconfirmed: Some(
        "the plates' speed (the model's static chain is quasi-static) and the pre-compression \
         the ITF gives the ball before the test",
    ),
    balls: &["tennis"],
}];

/// The static standard called `name`, if there is one.
pub fn find(name: &str) -> Option<&'static DeformationStandard> {
    DEFORMATION_STANDARDS.iter().find(|s| s.name == name)
}

impl DeformationStandard {
    /// The model's static answer for `ball` under this test's load and peak.
    pub fn deflection(&self, ball: &DropBall, law: ContactLaw) -> StaticDeflection {
        static_deflection(&ball.params, law, self.test.load_kg * G, self.test.peak_m)
    }

    /// Whether the static answer `s` is this test's: its load and peak, to 1e-3.
    pub fn is_test_of(&self, s: &StaticDeflection) -> bool {
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-3 * b.abs();
        near(s.force / G, self.test.load_kg) && near(s.peak, self.test.peak_m)
    }

    /// The warning of a return deflection outside the rules' return window (reported, not
    /// judged: the verdict is the forward deflection's). The tennis preset's linear law with
    /// Eq. 20's z_p flattens only just at the 1 in peak, so it returns almost its forward
    /// deflection (docs/presets.md, tennis; docs/drop.md, "Standards").
    pub fn return_warning(&self, s: &StaticDeflection) -> Option<String> {
        let [lo, hi] = self.return_window?;
        let d = s.return_.as_ref().ok()?.diameter();
        if (lo..=hi).contains(&d) {
            return None;
        }
        let mm = |v: f64| format!("{:.2}", v * 1e3);
        Some(format!(
            "the return deflection after a {} mm compression, {} mm, is outside the rules' \
             window {}–{} mm ({}; reported, not judged: the verdict is the forward \
             deflection's): the model's unloading from that peak returns too little \
             (docs/presets.md says why and what would fit it)",
            mm(self.test.peak_m),
            mm(d),
            mm(lo),
            mm(hi),
            self.name
        ))
    }

    /// The verdict on the forward deflection of the diameter (`None`: the model gives none, a
    /// ball without a recoil spring).
    pub fn judge(&self, ball: &DropBall) -> Option<Verdict> {
        let d = self.deflection(ball, ball.law).forward.ok()?.diameter();
        Some(Verdict::of(self.name, self.window, d))
    }
}
