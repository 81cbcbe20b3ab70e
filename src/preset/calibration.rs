//! The `[calibration]` record of a preset (docs/presets.md, "The calibration record"): the
//! tests and data its parameters were fitted to, and the range of impact speed over which they
//! hold. Every answer outside that range says so (`crate::api`, "outside calibration").

use super::error::Bad;
use super::outputs::Output;
use crate::text::{number, short};
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// How far past an end of the range a speed may lie and still count as inside it, relative:
/// the ends are written to four figures (6.906 m/s for the ITF drop, whose first impact the
/// drop's flight gives as 6.9057… m/s), so a speed within 1e-3 of an end is the same speed.
pub const SPEED_SLACK: f64 = 1e-3;

/// What a ball's parameters were fitted to and where they hold. SI units, °C.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Calibration {
    /// The lowest impact speed the parameters hold at, m/s.
    pub speed_min: f64,
    /// The highest impact speed the parameters hold at, m/s (≥ `speed_min`).
    pub speed_max: f64,
    /// The temperature of the tests, °C, where known.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature: Option<f64>,
    /// The ball's inflation (gauge) pressure in the tests, Pa, where it matters.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure: Option<f64>,
    /// The temperature shift of the dashpot (`[calibration.temperature_shift]`, docs/model.md
    /// §10.4), for a solid ball whose CORs against temperature were fitted; `None`: the
    /// parameters hold at `temperature` alone.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub temperature_shift: Option<TemperatureShift>,
    /// The data sets fitted, one or more.
    pub data: Vec<CalibrationData>,
    /// Set by the caller, never read from a file: what a ball runs that is not the recorded
    /// model ("the materials set", "the hertz law"): the record is of the preset's own set
    /// and law, so it does not vouch for the answer (`crate::api::Ball::speeds_warning`).
    #[serde(skip)]
    pub other_model: Option<String>,
}

/// Arrhenius's shift of the dashpot, c(T) = c · exp[(E_a/R)(1/T − 1/T_ref)] (docs/model.md
/// §10.4): the preset's own c holds at `reference`; `--temperature T` moves it by the factor.
/// The springs are kept (a COR against temperature cannot tell a spring's shift from the
/// dashpot's).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TemperatureShift {
    /// The activation energy E_a, J/mol (`fit --cor-temperature`).
    pub activation_energy: f64,
    /// The temperature the preset's c holds at, °C.
    pub reference: f64,
    /// Where E_a comes from: the data it was fitted or solved from.
    pub source: String,
    /// The lowest and highest temperature of those data, °C: the span the shift holds over
    /// (beyond it the answer says the shift is extrapolated, and refuses it where the COR
    /// would turn back; docs/model.md §10.4). `None` in a record written before spans were
    /// kept: then only `reference` is known to hold.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub span: Option<[f64; 2]>,
}

/// One data set a ball was fitted to.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CalibrationData {
    /// The standard or the publication (or the data file) it comes from.
    pub source: String,
    /// What was fitted to it, in words ("COR", "peak force", "rebound height", …).
    #[serde(default)]
    pub quantities: String,
    /// The impact speeds of the data, m/s (empty when the data give heights).
    #[serde(default)]
    pub speeds: Vec<f64>,
    /// The drop heights of the data, m (empty when the data give speeds).
    #[serde(default)]
    pub heights: Vec<f64>,
    /// The loads of a static test between two plates, kg (empty for impacts, and for a static
    /// test whose record does not give them: written only when known).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub loads: Vec<f64>,
    /// Which outputs of an answer the set measured, by their JSON keys (`cor`, `max_force`,
    /// `contact_time`, `max_indentation`, `permanent_indentation`, `deflection_m`): what it
    /// vouches for. `None` when the record does not say (a user preset written before the
    /// field): it then makes no claim, and no answer names an output as not measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outputs: Option<Vec<Output>>,
}

impl CalibrationData {
    /// Whether the set is a static test: loads, or neither speeds nor heights (a record
    /// written before loads were kept).
    pub fn is_static(&self) -> bool {
        !self.loads.is_empty() || (self.speeds.is_empty() && self.heights.is_empty())
    }
}

impl Calibration {
    /// The outputs its data sets measured, each once, in [`Output::ALL`]'s order; `None` when
    /// a set does not say which (the record then makes no claim about its outputs).
    pub fn outputs(&self) -> Option<Vec<Output>> {
        let mut all: Vec<Output> = Vec::new();
        for d in &self.data {
            all.extend(d.outputs.as_ref()?);
        }
        all.sort();
        all.dedup();
        Some(all)
    }

    /// A record over the speeds `speeds` (at least one) of one data set.
    pub fn over(data: CalibrationData, speeds: &[f64]) -> Calibration {
        let min = speeds.iter().copied().fold(f64::INFINITY, f64::min);
        let max = speeds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Calibration {
            speed_min: min,
            speed_max: max,
            temperature: None,
            pressure: None,
            temperature_shift: None,
            data: vec![data],
            other_model: None,
        }
    }

    /// Whether the impact speed `v` (m/s) lies in the range, to [`SPEED_SLACK`].
    pub fn holds_at(&self, v: f64) -> bool {
        v >= self.speed_min * (1.0 - SPEED_SLACK) && v <= self.speed_max * (1.0 + SPEED_SLACK)
    }

    /// The range as text: "1.47 m/s only" or "1.2–6.9 m/s".
    pub fn range_text(&self) -> String {
        if self.speed_min == self.speed_max {
            format!("{} m/s only", short(self.speed_min, 4))
        } else {
            format!(
                "{}–{} m/s",
                short(self.speed_min, 4),
                short(self.speed_max, 4)
            )
        }
    }

    /// The static loads of the record's static tests (kg) as `[min, max]`, with their
    /// sources; `None` when no static test gives its loads.
    pub fn load_range(&self) -> Option<([f64; 2], String)> {
        let tests: Vec<&CalibrationData> =
            self.data.iter().filter(|d| !d.loads.is_empty()).collect();
        let loads = tests.iter().flat_map(|d| d.loads.iter().copied());
        let lo = loads.clone().fold(f64::INFINITY, f64::min);
        let hi = loads.fold(f64::NEG_INFINITY, f64::max);
        let sources: Vec<&str> = tests.iter().map(|d| d.source.as_str()).collect();
        (!tests.is_empty()).then(|| ([lo, hi], sources.join("; ")))
    }

    /// The sources, "; "-separated.
    pub fn sources(&self) -> String {
        let s: Vec<&str> = self.data.iter().map(|d| d.source.as_str()).collect();
        s.join("; ")
    }

    /// `[calibration]` as TOML, numbers in their round-trip form.
    pub(super) fn write(&self, out: &mut String) {
        let list = |v: &[f64]| {
            let items: Vec<String> = v.iter().map(|x| format!("{x:?}")).collect();
            format!("[{}]", items.join(", "))
        };
        let string = |s: &str| toml::Value::String(s.to_string()).to_string();
        out.push_str("\n[calibration]\n");
        let _ = writeln!(out, "speed_min = {:?}  # m/s", self.speed_min);
        let _ = writeln!(out, "speed_max = {:?}  # m/s", self.speed_max);
        if let Some(t) = self.temperature {
            let _ = writeln!(out, "temperature = {t:?}  # °C");
        }
        if let Some(p) = self.pressure {
            let _ = writeln!(out, "pressure = {p:?}  # Pa, gauge");
        }
        if let Some(s) = &self.temperature_shift {
            out.push_str("\n[calibration.temperature_shift]\n");
            let _ = writeln!(
                out,
                "activation_energy = {:?}  # J/mol",
                s.activation_energy
            );
            let _ = writeln!(out, "reference = {:?}  # °C", s.reference);
            if let Some([lo, hi]) = s.span {
                let _ = writeln!(out, "span = [{lo:?}, {hi:?}]  # °C, the data's");
            }
            let _ = writeln!(out, "source = {}", string(&s.source));
        }
        for d in &self.data {
            out.push_str("\n[[calibration.data]]\n");
            let _ = writeln!(out, "source = {}", string(&d.source));
            let _ = writeln!(out, "quantities = {}", string(&d.quantities));
            let _ = writeln!(out, "speeds = {}  # m/s", list(&d.speeds));
            let _ = writeln!(out, "heights = {}  # m", list(&d.heights));
            if !d.loads.is_empty() {
                let _ = writeln!(out, "loads = {}  # kg", list(&d.loads));
            }
            if let Some(o) = &d.outputs {
                let keys: Vec<String> = o.iter().map(|o| string(o.key())).collect();
                let _ = writeln!(out, "outputs = [{}]", keys.join(", "));
            }
        }
    }
}

fn bad(table: &'static str, layer: Option<usize>, key: &'static str, message: String) -> Bad {
    Bad {
        table,
        layer,
        key,
        message,
    }
}

fn positive(layer: Option<usize>, key: &'static str, v: f64) -> Result<(), Bad> {
    let table = if layer.is_some() {
        "calibration.data"
    } else {
        "calibration"
    };
    if v.is_finite() && v > 0.0 && v < 1e15 {
        Ok(())
    } else {
        let msg = format!("must be a positive finite number, got {}", number(v));
        Err(bad(table, layer, key, msg))
    }
}

/// Positive speeds with `speed_min ≤ speed_max`, a temperature a test is taken at
/// (−50 … 100 °C), a positive pressure, at least one data set, each with a source free of
/// control characters and positive speeds and heights.
pub(super) fn check(c: &Option<Calibration>) -> Result<(), Bad> {
    let Some(c) = c else { return Ok(()) };
    positive(None, "speed_min", c.speed_min)?;
    positive(None, "speed_max", c.speed_max)?;
    if c.speed_max < c.speed_min {
        let msg = format!(
            "{} is below speed_min {}",
            number(c.speed_max),
            number(c.speed_min)
        );
        return Err(bad("calibration", None, "speed_max", msg));
    }
    if let Some(t) = c.temperature
        && !(t.is_finite() && (-50.0..=100.0).contains(&t))
    {
        let msg = format!("must lie in [-50, 100] °C, got {}", number(t));
        return Err(bad("calibration", None, "temperature", msg));
    }
    if let Some(p) = c.pressure {
        positive(None, "pressure", p)?;
    }
    if let Some(s) = &c.temperature_shift {
        check_shift(s)?;
    }
    if c.data.is_empty() {
        let msg = "names no data set ([[calibration.data]] with its source)".into();
        return Err(bad("calibration", None, "data", msg));
    }
    for (i, d) in c.data.iter().enumerate() {
        let at = Some(i);
        for (key, text) in [("source", &d.source), ("quantities", &d.quantities)] {
            if let Some((j, ch)) = crate::sanitize::first_control(text, &[]) {
                let msg = format!(
                    "holds a control character, U+{:04X} (character {})",
                    ch as u32,
                    j + 1
                );
                return Err(bad("calibration.data", at, key, msg));
            }
        }
        if d.source.trim().is_empty() {
            let msg = "must name the standard or publication".into();
            return Err(bad("calibration.data", at, "source", msg));
        }
        for &v in &d.speeds {
            positive(at, "speeds", v)?;
        }
        for &h in &d.heights {
            positive(at, "heights", h)?;
        }
        for &l in &d.loads {
            positive(at, "loads", l)?;
        }
        check_outputs(at, d.outputs.as_deref().unwrap_or_default())?;
    }
    Ok(())
}

/// Each output named once (the names themselves are checked as the TOML is read: an unknown
/// one is refused at its value, naming the choices).
fn check_outputs(at: Option<usize>, outputs: &[Output]) -> Result<(), Bad> {
    for (i, o) in outputs.iter().enumerate() {
        if outputs[..i].contains(o) {
            let msg = format!("names `{}` twice", o.key());
            return Err(bad("calibration.data", at, "outputs", msg));
        }
    }
    Ok(())
}

/// A shift's activation energy finite and within ±1 MJ/mol (the glass transitions of rubbers
/// reach a few hundred kJ/mol), its reference and its span's ends temperatures a test is
/// taken at (the span's in order), its source named and free of control characters.
fn check_shift(s: &TemperatureShift) -> Result<(), Bad> {
    const TABLE: &str = "calibration.temperature_shift";
    let e = s.activation_energy;
    if !(e.is_finite() && e.abs() <= 1e6) {
        let msg = format!(
            "must be a finite energy within ±1e6 J/mol, got {}",
            number(e)
        );
        return Err(bad(TABLE, None, "activation_energy", msg));
    }
    let test_temperature = |key, t: f64| {
        if t.is_finite() && (-50.0..=100.0).contains(&t) {
            return Ok(());
        }
        let msg = format!("must lie in [-50, 100] °C, got {}", number(t));
        Err(bad(TABLE, None, key, msg))
    };
    test_temperature("reference", s.reference)?;
    if let Some([lo, hi]) = s.span {
        test_temperature("span", lo)?;
        test_temperature("span", hi)?;
        if hi < lo {
            let msg = format!("[{}, {}] is not in order", number(lo), number(hi));
            return Err(bad(TABLE, None, "span", msg));
        }
    }
    if let Some((j, ch)) = crate::sanitize::first_control(&s.source, &[]) {
        let msg = format!(
            "holds a control character, U+{:04X} (character {})",
            ch as u32,
            j + 1
        );
        return Err(bad(TABLE, None, "source", msg));
    }
    if s.source.trim().is_empty() {
        let msg = "must name the data the shift was fitted to".into();
        return Err(bad(TABLE, None, "source", msg));
    }
    Ok(())
}
