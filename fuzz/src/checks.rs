//! What the fuzz targets check, shared with the main crate's `tests/physics/fuzz_regressions.rs`, which
//! includes this file with `#[path]`: a regression input is replayed through exactly the
//! checks that found it, on the stable toolchain, by `cargo test`.
//!
//! Every check panics on a violation; libFuzzer reports a panic as a crash. Only the public
//! API is used, and only fields that exist on every branch of the solver.

use arbitrary::{Arbitrary, Unstructured};
use bouncelab::catalog::parse_preset_bytes;
use bouncelab::preset::{ParamSource, Preset, PresetError};
use bouncelab::solver::{ImpactResponse, Method, SolveOptions};
use bouncelab::{ContactLaw, ImpactParams};

// the solver's contract, for both targets: a file beside this one (`#[path]` keeps it there
// when tests/physics/fuzz_regressions.rs includes this file)
#[path = "contract.rs"]
pub mod contract;
use contract::{check_simulate, check_simulate_normalized};

/// The file name preset errors are reported against.
pub const ORIGIN: &str = "fuzz.toml";

// ------------------------------------------------------------------------------------------
// preset_toml

/// Bytes of a would-be preset file → the catalog's UTF-8 check and `Preset::parse`; on success
/// everything a preset feeds: derived parameters, both parameter sets, validation, a run.
pub fn check_preset_bytes(data: &[u8]) {
    match parse_preset_bytes(data.to_vec(), ORIGIN) {
        Err(e) => check_preset_error(&e, data),
        Ok(preset) => check_preset(&preset),
    }
}

/// A preset error is one non-empty line that names `fuzz.toml:LINE:COLUMN`, and that line and
/// column exist in the input (the column may be one past the line's end).
fn check_preset_error(e: &PresetError, data: &[u8]) {
    let shown = e.to_string();
    check_one_line(&e.message, &shown);
    assert_eq!(e.origin, ORIGIN, "{shown:?}");
    let Some((line, col)) = e.position else {
        panic!("a preset error without line:column: {shown:?}");
    };
    assert_eq!(
        shown,
        format!("{ORIGIN}:{line}:{col}: {}", e.message),
        "the display form"
    );
    let lines: Vec<&[u8]> = data.split(|&b| b == b'\n').collect();
    assert!(
        line >= 1 && line <= lines.len(),
        "line {line} of {}: {shown:?}",
        lines.len()
    );
    // a column counts characters; bytes are an upper bound (and all there is past bad UTF-8)
    let width = lines[line - 1].len();
    assert!(
        col >= 1 && col <= width + 1,
        "column {col} of a {width}-byte line: {shown:?}"
    );
}

/// An error message: not empty, and one line: no line break and no other control character
/// (an escape sequence would reach the terminal), so that `bouncelab: error: …` stays one
/// line.
fn check_one_line(message: &str, shown: &str) {
    assert!(!message.trim().is_empty(), "an empty message: {shown:?}");
    assert!(
        !shown.chars().any(char::is_control),
        "a message with a line break or control character: {shown:?}"
    );
}

fn check_preset(preset: &Preset) {
    let _ = preset.derived();
    let opts = SolveOptions::default().with_samples(16).with_energy();
    for source in [ParamSource::Adopted, ParamSource::Materials] {
        let params = preset.params_from(source);
        if source == preset.parameters {
            assert!(
                same_params(&params, &preset.params()),
                "params() is the chosen set"
            );
        }
        if source == ParamSource::Adopted {
            // a parsed preset with parameters = "adopted" has every adopted field
            assert!(
                preset.parameters != ParamSource::Adopted
                    || (params.k_p.is_finite() && params.damping.is_finite()),
                "adopted set incomplete: {params:?}"
            );
        }
        check_simulate(&params, preset.law, &opts);
    }
}

fn same_params(a: &ImpactParams, b: &ImpactParams) -> bool {
    let bits =
        |p: &ImpactParams| [p.mass, p.k_p, p.damping, p.k_r, p.z_p, p.k_h, p.v0].map(f64::to_bits);
    bits(a) == bits(b)
}

// ------------------------------------------------------------------------------------------
// solver_inputs

/// One number of a solver input: any bit pattern, a value spread evenly over the decades
/// 1e-15 … 1e15 the parameters may take, or one of the edge values (so that the fuzzer reaches
/// valid inputs and the boundaries as often as garbage).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Num {
    Raw(f64),
    Decades(u16),
    Edge(u8),
}

const EDGES: [f64; 20] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    f64::MIN_POSITIVE,
    5e-324,
    f64::MAX,
    f64::MIN,
    1e-15,
    1e15,
    1.000_000_000_000_000_2e15,
    9.999_999_999_999_999e-16,
    1e6,
    1e-6,
    0.5,
    2.0,
    1e-3,
];

impl Num {
    pub fn value(self) -> f64 {
        match self {
            Num::Raw(x) => x,
            Num::Decades(u) => 10f64.powf(-15.0 + 30.0 * f64::from(u) / f64::from(u16::MAX)),
            Num::Edge(i) => EDGES[usize::from(i) % EDGES.len()],
        }
    }
}

/// Which entry point, with its raw inputs.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Entry {
    /// `simulate` on dimensional parameters.
    Dimensional {
        mass: Num,
        k_p: Num,
        damping: Num,
        k_r: Num,
        z_p: Num,
        k_h: Num,
        v0: Num,
    },
    /// `simulate_normalized(λ, ζ)`.
    Normalized { lambda: Num, zeta: Num },
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Law {
    Linear,
    ElasticPlastic,
    Hertz,
}

/// `SolveOptions::method`; `Both` runs the linear law with each solver and compares them.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum MethodChoice {
    Auto,
    Exact,
    Numeric,
    Both,
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct SolverInput {
    pub entry: Entry,
    pub law: Law,
    pub method: MethodChoice,
    /// History samples, taken modulo 65.
    pub samples: u8,
    pub energy: bool,
}

/// Most history samples asked for (the CLI asks 400; the checks need only a few).
pub const MAX_SAMPLES: usize = 64;

/// Decode fuzzer bytes as the `solver_inputs` target does (`arbitrary`'s take-rest form).
pub fn decode_solver_input(data: &[u8]) -> Option<SolverInput> {
    SolverInput::arbitrary_take_rest(Unstructured::new(data)).ok()
}

pub fn check_solver_bytes(data: &[u8]) {
    if let Some(input) = decode_solver_input(data) {
        check_solver_input(&input);
    }
}

pub fn check_solver_input(input: &SolverInput) {
    let law = match input.law {
        Law::Linear => ContactLaw::Linear,
        Law::ElasticPlastic => ContactLaw::ElasticPlastic,
        Law::Hertz => ContactLaw::Hertz,
    };
    let mut opts =
        SolveOptions::default().with_samples(usize::from(input.samples) % (MAX_SAMPLES + 1));
    if input.energy {
        opts = opts.with_energy();
    }
    let methods: &[Option<Method>] = match input.method {
        MethodChoice::Auto => &[None],
        MethodChoice::Exact => &[Some(Method::Exact)],
        MethodChoice::Numeric => &[Some(Method::Numeric)],
        MethodChoice::Both => &[Some(Method::Exact), Some(Method::Numeric)],
    };
    let mut results = Vec::new();
    for &method in methods {
        let opts = SolveOptions { method, ..opts };
        results.push(match input.entry {
            Entry::Dimensional {
                mass,
                k_p,
                damping,
                k_r,
                z_p,
                k_h,
                v0,
            } => {
                let params = ImpactParams {
                    mass: mass.value(),
                    k_p: k_p.value(),
                    damping: damping.value(),
                    k_r: k_r.value(),
                    z_p: z_p.value(),
                    k_h: k_h.value(),
                    v0: v0.value(),
                };
                check_simulate(&params, law, &opts)
            }
            Entry::Normalized { lambda, zeta } => {
                check_simulate_normalized(lambda.value(), zeta.value(), law, &opts)
            }
        });
    }
    if let [Some(exact), Some(numeric)] = results.as_slice() {
        check_agreement(exact, numeric);
    }
}

/// Below this λ the numerical solver is known to go wrong at large ζ, so the two are not
/// compared there: its state carries ᾱ and ȳ, both of order 1/√λ, and the contact indentation
/// z̄ = ᾱ − ȳ is their small difference; from λ ≈ 1e-7 and ζ ≳ 1e2 its events come out wrong
/// or it stops unresolved and reports no rebound (the exact solver carries z̄ itself).
pub const AGREEMENT_MIN_LAMBDA: f64 = 1e-6;

/// Likewise below this z̄_p: the unloading slope F_m/(z_m − z_f) ~ 1/√(2 z̄_p) makes the run so
/// stiff that the numerical solver runs out of steps and reports no rebound (an unresolved run,
/// which the solver is to report as an error).
pub const AGREEMENT_MIN_ZP_BAR: f64 = 1e-6;

/// The exact and the numerical solver on the same linear-law impact: same outcome, and the
/// same COR to well within what either promises (1e-8 on ordinary cases; the stiff Radau5
/// path about 1e-7).
fn check_agreement(exact: &ImpactResponse, numeric: &ImpactResponse) {
    if exact.normalized.lambda < AGREEMENT_MIN_LAMBDA
        || exact.normalized.zp_bar < AGREEMENT_MIN_ZP_BAR
    {
        return;
    }
    // near "no rebound" (e of order the integrator's rest threshold) the two may decide
    // differently; both then say the ball barely leaves
    if exact.rebound != numeric.rebound {
        assert!(
            exact.cor.max(numeric.cor) < 1e-6,
            "exact and numeric disagree on the rebound: {exact:?} vs {numeric:?}"
        );
        return;
    }
    assert!(
        (exact.cor - numeric.cor).abs() <= 1e-5,
        "exact COR {} vs numeric {}",
        exact.cor,
        numeric.cor
    );
}
