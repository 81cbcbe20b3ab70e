//! A fast summary of one impact under any law by Taylor-series integration (issue 30 items 1
//! and 2): COR, F̄_m, τ_f, z̄_m, z̄_f and ȳ at separation, no history, no energy audit.
//!
//! Each phase of docs/model.md §3 is a smooth system with a polynomial right-hand side once
//! the 3/2 power is written with s = √((z̄ − z̄₀)/b) and time with dτ = s dσ (`power`): the
//! Hertz loading, the elastic–plastic unloading. The linear branches (`linear`) are linear
//! systems in τ. Series of order 28 on the 3/2-power phases (`POWER_LEN`), 24 on the
//! elastic–plastic straight stretch (`linear::STRETCH_LEN`) and 20 on the linear law's
//! branches and in the Hertz table's reference (`poly::ORDER`) step from phase event to
//! phase event; the events
//! (the turn z̄' = 0, yield z̄ = z̄_p, separation F̄ = 0) are the roots of the step's series, so
//! no step is repeated and no event is passed.
//!
//! **Hertz scale.** Under the Hertz law F̄ = κ z̄^{3/2} scales out exactly: with
//! L = κ^{−2/5}, z̄ = L ẑ and τ = L t̂ the force is ẑ^{3/2}/L, the speeds are unchanged, and
//! the system is the same with λ̂ = λL², ζ̂ = ζ/L and κ̂ = 1 (docs/model.md §5), so the states
//! are of order 1 whatever the speed. The elastic–plastic law keeps ẑ_p = z̄_p/L and its
//! straight stretch has slope L².
//!
//! **Domain.** A stiff phase (a weak dashpot, ζ̂ large, or a stiff recoil spring against it)
//! needs steps of the order of its fastest rate, which a Taylor method (explicit) cannot
//! stretch: where the rate times the contact time exceeds `STIFF`, and wherever the run
//! needs more than `MAX_STEPS` steps (creeps, no rebound) or reloads after unloading began,
//! `summary` returns `None` and the caller runs the adaptive solver (or the exact one).
//! tests/physics/taylor.rs holds the answers to the adaptive solver's over the property tests' domain.

pub mod batch;
mod fused;
mod linear;
pub mod plastic;
mod poly;
mod power;
mod rules;
mod stages;

use crate::model::contact::{Contact, ContactLaw};
use crate::model::params::Normalized;

/// One impact's summary in normalized units (docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// The COR e (Eq. 6).
    pub cor: f64,
    /// F̄_m.
    pub max_force: f64,
    /// τ_f.
    pub contact_time: f64,
    /// z̄_m.
    pub max_indentation: f64,
    /// z̄_f (Eq. 18).
    pub permanent_indentation: f64,
    /// ȳ at separation.
    pub element_displacement: f64,
    /// Taylor steps taken.
    pub steps: usize,
}

/// Most steps of one impact; past them the adaptive solver answers.
const MAX_STEPS: usize = 160;
/// Largest stiffness 2ζ̂(k + λ̂) · τ̂ the Taylor steps take on (k the contact's stiffness, τ̂
/// the contact time's scale): an explicit step cannot much exceed the inverse of the fastest
/// rate, so past it the steps would run out anyway, and the adaptive solver's stiff cascade
/// is the one to use.
const STIFF: f64 = 60.0;
/// Longest contact followed, in the phase's time unit.
const TAU_MAX: f64 = 1e3;

/// The 3/2-power phases' series length in [`summary`]: order 28, not the reference's 20
/// (`poly::ORDER`). A step's cost grows about linearly with the order (the Cauchy products'
/// O(n²) is not yet the larger part at 20: the evaluations, the step rule and the loop's
/// overhead are) while the steps fall as ε^{−1/n}: by callgrind over five Hertz impacts
/// (BENCHMARKS.md, "ep6"), an impact costs 126 000 instructions at order 20 (ε 1e-17),
/// 109 000 at 28, 101 000 at 28 with ε 1e-16, 92 000 at 28 with [`POWER_EPS`] 1e-15, and more
/// again at 32. The reference ([`hertz_reference`], from which the Hertz table is built)
/// keeps order 20 and ε 1e-17, so the table's nodes are unchanged.
const POWER_LEN: usize = 29;
/// The 3/2-power phases' truncation per step in [`summary`], relative to the state's scale:
/// 1e-15, some ten steps of it 1e-14 at most, far inside the 1e-12 at which tests/physics/taylor.rs
/// holds the steps to the adaptive solver at rtol 1e-14
/// (`taylor_meets_the_reference_at_a_thousand_points`).
const POWER_EPS: f64 = 1e-15;
/// The 3/2-power phases' rules in [`summary`]: [`POWER_EPS`], the quick step rule and roots,
/// fused sums (`rules::Rules`, `fused`); the reference keeps `rules::Rules::REFERENCE`.
const POWER_RULES: rules::Rules = rules::Rules {
    eps: POWER_EPS,
    sums: rules::Sums::Fused,
};

/// ȳ' = 2ζ(F̄ − λȳ) in the units of the run.
#[derive(Debug, Clone, Copy)]
struct Sys {
    lambda: f64,
    zeta: f64,
}

/// The state where a phase starts or ends.
#[derive(Debug, Clone, Copy)]
struct Point {
    tau: f64,
    z: f64,
    /// ᾱ'
    v: f64,
    y: f64,
}

impl Point {
    /// First touch at unit speed: nothing indented, the element at rest.
    const FIRST_TOUCH: Point = Point {
        tau: 0.0,
        z: 0.0,
        v: 1.0,
        y: 0.0,
    };
}

/// The steps left to an impact, and its longest contact.
#[derive(Debug, Clone, Copy)]
struct Budget {
    steps: usize,
    taken: usize,
    tau_max: f64,
}

impl Budget {
    fn new() -> Budget {
        Budget::with_steps(MAX_STEPS)
    }
    fn with_steps(steps: usize) -> Budget {
        Budget {
            steps,
            taken: 0,
            tau_max: TAU_MAX,
        }
    }
    /// One step, or `None` when none is left.
    fn take(&mut self) -> Option<()> {
        if self.taken >= self.steps {
            return None;
        }
        self.taken += 1;
        Some(())
    }
}

/// The impact of the normalized ball `n` under `law`, or `None` outside the Taylor steps'
/// domain (see the module's introduction), where the caller runs the adaptive solver. The
/// linear law is taken only where the ball flattens (F̄_m > z̄_p: `map::fast` answers the
/// rest in closed form).
pub fn summary(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    let ok = |x: f64| x.is_finite() && x >= 0.0;
    if !(ok(n.lambda) && ok(n.zeta) && n.kappa.is_finite() && n.kappa > 0.0 && n.zp_bar > 0.0) {
        return None;
    }
    match law {
        ContactLaw::Linear => linear_flattening(n),
        ContactLaw::Hertz | ContactLaw::ElasticPlastic => power_law(n, law),
    }
}

/// The Hertz and elastic–plastic laws in the Hertz scale, one step after another
/// (`stages::PowerImpact`).
fn power_law(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    power_run(stages::PowerImpact::new(n, law)?)
}

/// The Hertz or elastic–plastic impact of `n` by the Taylor steps of [`summary`] with no
/// stiffness cut and at most `max_steps` steps: a stiff impact's reference, independent of
/// the implicit steps that answer it on the fast path (`solver::stiff`), as
/// [`hertz_reference`] is the Hertz table's. A stiff phase takes steps about a seventh of its
/// stiffness 2ζ̂(k + λ̂)·τ̂, so thousands where `summary` stops at 60. `None` for the linear
/// law, or where the steps run out.
pub fn unbounded(n: &Normalized, law: ContactLaw, max_steps: usize) -> Option<Summary> {
    if law == ContactLaw::Linear {
        return None;
    }
    let budget = Budget::with_steps(max_steps);
    power_run(stages::PowerImpact::within(n, law, f64::INFINITY, budget)?)
}

/// [`stiff_summary`]'s stiffness cut: past it a stiff impact's steps (a seventh to a fifth of
/// the stiffness) would cost more than the adaptive solver's stiff cascade. The
/// elastic–plastic map's stiff corner (λ, ζ ∈ [1, 100], tennis) reaches 7·10⁴.
const FAR_STIFF: f64 = 1.5e5;

/// The Hertz or elastic–plastic impact of `n` where [`summary`] leaves a phase too stiff for
/// its steps (issue 54 item 10): the same steps, as many as the stiffness needs (its fifth and
/// a margin), up to `FAR_STIFF`. An explicit step cannot outrun the dashpot's rate
/// 2ζ̂(k + λ̂), but each of these keeps its truncation below `POWER_EPS` whatever the rate, so
/// the answer keeps its precision, and the steps, some hundreds to thousands, cost less than the
/// adaptive solver's DOPRI5 held to its stability limit (the cascade's check of a stiff run,
/// `numeric::checked_run`). tests/physics/map_stiff.rs holds it to an independent implicit
/// integration (`solver::stiff::summary`) to 1e-9. `None` outside that band (within
/// [`summary`]'s cut it has answered or refused for another reason) or where the steps run out.
pub fn stiff_summary(n: &Normalized, law: ContactLaw) -> Option<Summary> {
    if law == ContactLaw::Linear {
        return None;
    }
    let stiffness = stages::PowerImpact::stiffness(n, law)?;
    if stiffness <= STIFF || stiffness > FAR_STIFF {
        return None;
    }
    let budget = Budget::with_steps((stiffness / 5.0) as usize + MAX_STEPS);
    power_run(stages::PowerImpact::within(n, law, FAR_STIFF, budget)?)
}

/// An impact's Taylor steps from first touch to its end.
fn power_run(mut impact: stages::PowerImpact) -> Option<Summary> {
    let mut c = [[0.0; POWER_LEN]; 4];
    let mut scratch = [[0.0; POWER_LEN]; 2];
    loop {
        if !next_series(&mut impact, &mut c, &mut scratch) {
            return None;
        }
        if let stages::Progress::Done(summary) = impact.feed(&c) {
            return summary;
        }
    }
}

/// The next Taylor step of `impact` (`stages::PowerImpact::take_step`) and its series into
/// `c`; false where there is none (steps or budget run out, a stiff phase).
#[inline]
fn next_series(impact: &mut stages::PowerImpact, c: &mut Series, scratch: &mut Scratch) -> bool {
    if !impact.take_step() {
        return false;
    }
    let coefs = power::Coefs::of(&impact.sys, &impact.phase.br);
    series_one(coefs, impact.phase.x, c, scratch);
    true
}

/// [`peak_displacement`]'s stiffness cut: 50 × [`STIFF`]. The steps it takes grow with the
/// stiffness (about a seventh of it, `solver::table::REFERENCE_STEPS`), so a stiffer phase than
/// [`summary`] takes on costs some hundreds of steps — still far below the adaptive solver's
/// 0.35 ms — and leaves none of a preset's map cells to it (tests/cli/answer_reach.rs).
const PEAK_STIFF: f64 = 50.0 * STIFF;
/// [`peak_displacement`]'s most steps: [`PEAK_STIFF`]'s seventh and margin.
const PEAK_STEPS: usize = 1_000;

/// The peak displacement ᾱ_max = max (z̄ + ȳ) of the ball's centre toward the wall (normalized,
/// z̄'s units) in the impact of `n` under the Hertz or elastic–plastic law, read where ᾱ' = 0
/// by the same Taylor steps as [`summary`] (`power::Phase::centre_turn`), stopping there: the
/// map's centre warning's exact read without the adaptive solver (issue 54 item 10: 0.35 ms a
/// cell by it). The centre turns after the indentation does (ᾱ' = z̄' + ȳ' and ȳ' > 0 while
/// F̄ rises: ȳ' = 2ζ(F̄ − λȳ) from ȳ = 0), so on the Hertz branch or on the elastic–plastic
/// unloading, never on the straight stretch. `None` where [`summary`] would be (the linear
/// law, a stiff phase, steps run out) or the centre does not turn before the ball leaves:
/// the caller then runs the adaptive solver. tests/cli/answer_reach.rs holds it to the
/// adaptive solver's α_max (`api::peak_displacement`) cell by cell.
pub fn peak_displacement(n: &Normalized, law: ContactLaw) -> Option<f64> {
    if law == ContactLaw::Linear {
        return None;
    }
    let budget = Budget::with_steps(PEAK_STEPS);
    let mut impact = stages::PowerImpact::within(n, law, PEAK_STIFF, budget)?;
    let mut c = [[0.0; POWER_LEN]; 4];
    let mut scratch = [[0.0; POWER_LEN]; 2];
    loop {
        if !next_series(&mut impact, &mut c, &mut scratch) {
            return None;
        }
        if let Some(alpha) = impact.phase.centre_turn(&c) {
            return Some(alpha * impact.scale());
        }
        if let stages::Progress::Done(_) = impact.feed(&c) {
            return None;
        }
    }
}

/// `power::series_of` for one impact, compiled with FMA where the CPU has it (an instruction
/// for each `mul_add`); elsewhere `mul_add` is the library's `fma`: the same bits, slower
/// (`batch`'s tests: `series_are_the_same_bits_without_fma_instructions`).
fn series_one(k: power::Coefs<f64>, x: [f64; 4], c: &mut Series, scratch: &mut Scratch) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU has FMA, the only feature the function enables
        return unsafe { series_fma(k, x, c, scratch) };
    }
    power::series_of(k, x, c, scratch)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn series_fma(k: power::Coefs<f64>, x: [f64; 4], c: &mut Series, scratch: &mut Scratch) {
    power::series_of(k, x, c, scratch)
}

/// A 3/2-power phase's series (s, ᾱ', ȳ, τ) in [`summary`].
type Series = [[f64; POWER_LEN]; 4];
/// `power::series_of`'s scratch.
type Scratch = [[f64; POWER_LEN]; 2];

/// The Hertz loading (ẑ from 0 at unit speed, κ̂ = 1) until separation or yield at ẑ_p, by
/// series of order L − 1 by `rules`.
fn hertz_loading<const L: usize>(
    sys: &Sys,
    zp: f64,
    rules: rules::Rules,
    budget: &mut Budget,
) -> Option<power::Run> {
    let (hertz, start) = hertz_start();
    power::run::<L>(sys, &hertz, start, zp.sqrt(), false, rules, budget)
}

/// The Hertz branch in the Hertz scale (ẑ = s², F̂ = s³) and first touch on it at unit speed.
fn hertz_start() -> (power::Branch, Point) {
    let hertz = power::Branch {
        z0: 0.0,
        b: 1.0,
        a: 1.0,
    };
    (hertz, Point::FIRST_TOUCH)
}

/// The Hertz impact in the Hertz scale (κ̂ = 1, unit speed) at (λ̂, ζ̂), by the Taylor steps
/// with no stiffness cut and at most `max_steps` steps: the reference of the Hertz table
/// (`solver::table`). BENCHMARKS.md ("a stiff solver tried and withdrawn"): at a stiff cell,
/// (λ̂, ζ̂) = (30, 40), its e agrees with an independent Radau IIA to 4e-15. `None` when the
/// steps run out, the contact outlasts τ̂ = 10³, or λ̂, ζ̂ are not finite and ≥ 0.
pub fn hertz_reference(lambda_hat: f64, zeta_hat: f64, max_steps: usize) -> Option<Summary> {
    let ok = |x: f64| x.is_finite() && x >= 0.0;
    if !(ok(lambda_hat) && ok(zeta_hat)) {
        return None;
    }
    let sys = Sys {
        lambda: lambda_hat,
        zeta: zeta_hat,
    };
    let mut budget = Budget::with_steps(max_steps);
    let first =
        hertz_loading::<{ poly::LEN }>(&sys, f64::INFINITY, rules::Rules::REFERENCE, &mut budget)?;
    let power::End::Separated(end) = first.end else {
        return None;
    };
    let s = first.s_max;
    finish(end, s * s, s * s * s, 0.0, 1.0, &budget)
}

/// The linear law where the ball flattens: loading F̄ = z̄ to the turn, then the straight
/// unloading of Eq. 22 to z̄_f.
fn linear_flattening(n: &Normalized) -> Option<Summary> {
    let sys = Sys {
        lambda: n.lambda,
        zeta: n.zeta,
    };
    if 2.0 * sys.zeta * (1.0 + sys.lambda) * std::f64::consts::PI > STIFF {
        return None;
    }
    let mut budget = Budget::new();
    let load = linear::Branch {
        k: 1.0,
        z0: 0.0,
        f0: 0.0,
    };
    let linear::End::Turned(top) =
        linear::run::<{ poly::LEN }>(&sys, &load, Point::FIRST_TOUCH, None, &mut budget)?
    else {
        return None;
    };
    let z_m = top.z;
    if z_m <= n.zp_bar {
        return None;
    }
    let contact = Contact {
        law: ContactLaw::Linear,
        zp_bar: n.zp_bar,
        kappa: n.kappa,
    };
    let z_f = contact.permanent_indentation(z_m);
    if z_m.is_nan() || z_m <= z_f {
        return None;
    }
    let unload = linear::Branch {
        k: z_m / (z_m - z_f),
        z0: z_f,
        f0: 0.0,
    };
    // the stiffer unloading spring: its rate too must stay within the steps' reach
    if 2.0 * sys.zeta * (unload.k + sys.lambda) * std::f64::consts::PI / unload.k.sqrt() > STIFF {
        return None;
    }
    let linear::End::Separated(end) =
        linear::run::<{ poly::LEN }>(&sys, &unload, top, Some(z_m), &mut budget)?
    else {
        return None;
    };
    finish(end, z_m, z_m, z_f, 1.0, &budget)
}

/// The summary from the separation point, in the units of the run (scale `l`: z̄ = l ẑ,
/// τ = l t̂, F̄ = F̂/l).
fn finish(end: Point, z_m: f64, f_m: f64, z_f: f64, l: f64, budget: &Budget) -> Option<Summary> {
    let cor = (-end.v).clamp(0.0, 1.0);
    let s = Summary {
        cor,
        max_force: f_m / l,
        contact_time: end.tau * l,
        max_indentation: z_m * l,
        permanent_indentation: z_f * l,
        element_displacement: end.y * l,
        steps: budget.taken,
    };
    let finite = [s.cor, s.max_force, s.contact_time, s.max_indentation]
        .iter()
        .all(|x| x.is_finite());
    (finite && s.contact_time > 0.0).then_some(s)
}
