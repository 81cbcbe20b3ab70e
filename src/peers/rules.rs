//! The published closed-form rules that turn a requested COR e into a damping, and the closed
//! forms of the COR that some models have (docs/peers.md §3). Rules return the normalized
//! damping of laws.rs: ζ (Kelvin–Voigt), α (Tsuji), χ (Hunt–Crossley family).

use super::PeerModel;
use serde::Serialize;
use std::f64::consts::PI;
use std::fmt;

/// How a damping was chosen for a requested COR.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Rule {
    /// Root find on the model's own impact (calibrate.rs).
    Exact,
    /// Logarithmic decrement of the linear oscillator: ζ = −ln e / √(π² + ln² e). Exact for
    /// Kelvin–Voigt with tension; for Tsuji, the form LIGGGHTS and Chrono (Hertz, material
    /// properties) and LAMMPS (`damping coeff_restitution`) use: α = √5 · ζ (export.rs).
    LogDecrement,
    /// Hunt & Crossley (1975), J. Appl. Mech. 42: 440–445: χ = 3(1 − e)/2, from their
    /// e = 1 − (2/3) α v0 with χ = α v0 (they write λ = α K_h, α in s/m).
    HuntCrossley,
    /// Lankarani & Nikravesh (1990), J. Mech. Des. 112: 369–376: χ = 3(1 − e²)/4
    /// (their D = 3 K (1 − e²)/(4 v0), i.e. χ/v0 = D/K).
    LankaraniNikravesh,
    /// Flores, Machado, Silva & Martins (2011), Multibody Syst. Dyn. 25: 357–375:
    /// χ = 8(1 − e)/(5 e).
    Flores,
    /// Gonthier, McPhee, Lange & Piedbœuf (2004), Multibody Syst. Dyn. 11: 209–233:
    /// χ = (1 − e²)/e (their d = (1 − e²)/(e v0) per unit K_h).
    Gonthier,
}

impl Rule {
    /// Its name in the output (text, JSON, CSV): `exact`, `log-decrement`, …
    pub fn name(self) -> &'static str {
        match self {
            Rule::Exact => "exact",
            Rule::LogDecrement => "log-decrement",
            Rule::HuntCrossley => "hunt-crossley",
            Rule::LankaraniNikravesh => "lankarani-nikravesh",
            Rule::Flores => "flores",
            Rule::Gonthier => "gonthier",
        }
    }

    /// The rules published for `model`, exact first.
    pub fn for_model(model: PeerModel) -> &'static [Rule] {
        match model {
            PeerModel::KelvinVoigt | PeerModel::KelvinVoigtNoTension | PeerModel::Tsuji => {
                &[Rule::Exact, Rule::LogDecrement]
            }
            PeerModel::HuntCrossley => &[
                Rule::Exact,
                Rule::HuntCrossley,
                Rule::LankaraniNikravesh,
                Rule::Flores,
                Rule::Gonthier,
            ],
        }
    }
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The log-decrement damping ratio ζ(e) = −ln e / √(π² + ln² e); e in (0, 1].
pub fn log_decrement(e: f64) -> f64 {
    let l = e.ln();
    if l == 0.0 {
        return 0.0; // not −0 at e = 1
    }
    -l / (PI * PI + l * l).sqrt()
}

/// The normalized damping an approximate rule gives for COR `e` in (0, 1]; `None` for
/// `Rule::Exact` (calibrate.rs) or a rule not published for the model.
pub fn approximate(model: PeerModel, rule: Rule, e: f64) -> Option<f64> {
    use PeerModel::*;
    match (model, rule) {
        (KelvinVoigt | KelvinVoigtNoTension, Rule::LogDecrement) => Some(log_decrement(e)),
        // LIGGGHTS/Chrono: γ_n = 2√(5/6) β √(S_n m), S_n = 2E*√(Rδ), K_h = (4/3)E*√R, so
        // η = 2√(5/6) β √(1.5 K_h m) = √5 β √(m K_h)
        (Tsuji, Rule::LogDecrement) => Some(5f64.sqrt() * log_decrement(e)),
        (HuntCrossley, Rule::HuntCrossley) => Some(1.5 * (1.0 - e)),
        (HuntCrossley, Rule::LankaraniNikravesh) => Some(0.75 * (1.0 - e * e)),
        (HuntCrossley, Rule::Flores) => Some(8.0 * (1.0 - e) / (5.0 * e)),
        (HuntCrossley, Rule::Gonthier) => Some((1.0 - e * e) / e),
        _ => None,
    }
}

/// The COR a rule's input `e_in` produces, inverted: the `e_in` that makes the rule return
/// the damping `d` (for codes that take a COR and apply a rule, export.rs). `None` when no
/// e_in in (0, 1] reaches `d`.
pub fn rule_input_for(model: PeerModel, rule: Rule, d: f64) -> Option<f64> {
    let f = |e: f64| approximate(model, rule, e).unwrap_or(f64::NAN) - d;
    // every rule decreases from +∞ or its value at e → 0 to 0 at e = 1
    let (lo, hi) = (1e-12, 1.0);
    let (flo, fhi) = (f(lo), f(hi));
    if !(flo >= 0.0 && fhi <= 0.0) {
        return None;
    }
    Some(crate::solver::roots::brent(f, lo, hi, flo, fhi, 1e-15))
}

/// Kelvin–Voigt with tension: e = exp(−π ζ / √(1 − ζ²)) for ζ < 1, 0 (no rebound) beyond.
pub fn kelvin_voigt_cor(zeta: f64) -> f64 {
    if zeta < 1.0 {
        (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp()
    } else {
        0.0
    }
}

/// Kelvin–Voigt clipped at F ≥ 0: the force k δ + η δ̇ of the free oscillation vanishes at
/// ω_d t = 2 arccos ζ, where the speed is exactly v0 e^{−ζ ω t} (the cosine terms combine
/// to −1), so e = exp(−2ζ arccos ζ / √(1 − ζ²)); for ζ > 1 the same with arccosh and
/// √(ζ² − 1); e = e^{−2} at ζ = 1 (cf. Schwager & Pöschel 2007, Granular Matter 9: 465).
pub fn kelvin_voigt_no_tension_cor(zeta: f64) -> f64 {
    let g = if (zeta - 1.0).abs() < 1e-6 {
        // both branches → 1 + (1 − ζ)/3 + O((1 − ζ)²) near ζ = 1
        1.0 + (1.0 - zeta) / 3.0
    } else if zeta < 1.0 {
        zeta.acos() / (1.0 - zeta * zeta).sqrt()
    } else {
        zeta.acosh() / (zeta * zeta - 1.0).sqrt()
    };
    (-2.0 * zeta * g).exp()
}

/// The Hunt–Crossley family's COR from the first integral of x'' = −x^{3/2}(1 + χ x'):
/// H = x'/χ − ln(1 + χ x')/χ² + (2/5) x^{5/2} is constant, so between x = 0 at x' = 1 and at
/// x' = −e: χ(1 + e) + ln(1 − χ e) − ln(1 + χ) = 0 (the relation behind Hunt & Crossley's and
/// Lankarani & Nikravesh's approximations; independent of the 3/2 power). Solved for
/// u = χ e in (0, 1): −u − ln(1 − u) = χ − ln(1 + χ).
pub fn hunt_crossley_cor(chi: f64) -> f64 {
    if chi == 0.0 {
        return 1.0;
    }
    let target = chi - chi.ln_1p();
    let g = |u: f64| -u - (-u).ln_1p() - target;
    let hi = 1.0 - f64::EPSILON;
    if g(hi) <= 0.0 {
        // χ ≳ 35: u is within rounding of 1, e = 1/χ to double precision
        return hi / chi;
    }
    let u = crate::solver::roots::brent(g, 0.0, hi, g(0.0), g(hi), 1e-16);
    u / chi
}
