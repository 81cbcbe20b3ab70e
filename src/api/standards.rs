//! Every governing body's test in one list, as `bouncelab standards --format json` writes it
//! and Python's `standards()` returns it: the ball standards with their test conditions, the
//! bat standards, the court pace, the pressure-loss tests, the static (deformation) standards
//! (docs/drop.md, "Standards", cites each source).

use crate::drop::conditions::{PRESSURE_LOSS, PressureLoss, of};
use crate::drop::deformation::{DEFORMATION_STANDARDS, DeformationStandard};
use crate::drop::standards::{STANDARDS, Standard};
use crate::oblique::court::{CourtStandard, ITF_COURT_PACE};
use crate::target::bat::{BAT_STANDARDS, BatStandard};
use serde::Serialize;

/// One entry of the list; each serializes as its own object (`test.kind` tells them apart).
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum StandardEntry {
    /// A ball standard (`test.kind` "drop" or "cor") and its test conditions.
    Ball {
        /// The standard, its fields at the object's top level.
        #[serde(flatten)]
        standard: Standard,
        /// Its test conditions.
        conditions: ConditionsEntry,
    },
    /// A bat standard (`test.kind` "bbcor").
    Bat(BatStandard),
    /// The court pace (`test.kind` "court-pace").
    Court(CourtStandard),
    /// A pressure-loss test (`test.kind` "pressure-loss").
    PressureLoss(PressureLossEntry),
    /// A static standard (`test.kind` "static", windows in m of the diameter).
    Deformation(DeformationStandard),
}

/// A standard's test conditions: `{temperature_c: [nominal, ±] | null, pressure_gauge_pa:
/// [lo, hi] | null, source}` (docs/drop.md, "Conditions").
#[derive(Debug, Clone, Copy, Serialize)]
pub struct ConditionsEntry {
    /// The test's temperature, °C, [nominal, ±].
    pub temperature_c: Option<[f64; 2]>,
    /// The ball's gauge pressure, Pa, [lo, hi].
    pub pressure_gauge_pa: Option<[f64; 2]>,
    /// Where these come from, or that the rule states none.
    pub source: &'static str,
}

impl ConditionsEntry {
    /// The conditions of the standard `name` ([`crate::drop::conditions::of`]).
    pub fn of(name: &str) -> ConditionsEntry {
        let c = of(name);
        ConditionsEntry {
            temperature_c: c.temperature_c,
            pressure_gauge_pa: c.pressure_gauge_pa,
            source: c.source,
        }
    }
}

/// A pressure-loss test laid out as the other standards: `test: {kind: "pressure-loss",
/// hours, pressure, temperature}`, `window: [null, max_loss]`.
#[derive(Debug, Clone, Serialize)]
pub struct PressureLossEntry {
    /// Short name for `--standard`.
    pub name: &'static str,
    /// The body and the test.
    pub title: &'static str,
    /// What is done to the ball.
    pub test: PressureLossTest,
    /// [no lower bound, the largest fraction of the gauge pressure it may lose].
    pub window: [Option<f64>; 2],
    /// Where the numbers come from.
    pub source: &'static str,
    /// What could not be confirmed from a public source.
    pub unconfirmed: &'static str,
    /// The embedded presets this is the ball's own test.
    pub balls: &'static [&'static str],
    /// Its test conditions.
    pub conditions: ConditionsEntry,
}

/// The `test` of a [`PressureLossEntry`]: kept `hours` at `temperature` (°C) from `pressure`
/// (Pa gauge).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PressureLossTest {
    /// "pressure-loss".
    pub kind: &'static str,
    /// How long, h.
    pub hours: f64,
    /// The gauge pressure at the start, Pa.
    pub pressure: f64,
    /// The temperature it is kept at, °C.
    pub temperature: f64,
}

impl From<&PressureLoss> for PressureLossEntry {
    fn from(p: &PressureLoss) -> PressureLossEntry {
        PressureLossEntry {
            name: p.name,
            title: p.title,
            test: PressureLossTest {
                kind: "pressure-loss",
                hours: p.hours,
                pressure: p.pressure,
                temperature: p.temperature,
            },
            window: [None, Some(p.max_loss)],
            source: p.source,
            unconfirmed: p.unconfirmed,
            balls: p.balls,
            conditions: ConditionsEntry::of(p.name),
        }
    }
}

/// Why `drop --standard name` (and Python's `drop(standard=name)`) takes no standard `name`:
/// a bat or court standard is named with the command that judges it (`bat`, `court`; both
/// are listed by `bouncelab standards`), any other name is unknown, listing every one `drop`
/// takes.
pub fn not_a_drop_standard(name: &str) -> String {
    let bat = BAT_STANDARDS.iter().find(|s| s.name == name);
    let bat = bat.map(|s| ("bat", s.title));
    let court = (ITF_COURT_PACE.name == name).then_some(("court", ITF_COURT_PACE.title));
    match bat.or(court) {
        Some((command, title)) => format!(
            "standard '{name}' ({title}) is not a drop test: it is judged by `bouncelab \
             {command}`"
        ),
        None => crate::drop::names::unknown(name),
    }
}

/// The list, in its order: ball standards, bat standards, the court pace, pressure-loss
/// tests, static standards.
pub fn standards() -> Vec<StandardEntry> {
    let balls = STANDARDS.iter().map(|s| StandardEntry::Ball {
        standard: *s,
        conditions: ConditionsEntry::of(s.name),
    });
    balls
        .chain(BAT_STANDARDS.iter().copied().map(StandardEntry::Bat))
        .chain([StandardEntry::Court(ITF_COURT_PACE)])
        .chain(
            PRESSURE_LOSS
                .iter()
                .map(|p| StandardEntry::PressureLoss(p.into())),
        )
        .chain(
            DEFORMATION_STANDARDS
                .iter()
                .copied()
                .map(StandardEntry::Deformation),
        )
        .collect()
}
