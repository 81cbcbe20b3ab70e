//! Whether a fit answered (docs/fitting.md, "Did the fit answer?"): every free parameter
//! pinned by the data, exact solves verified, the trace's impulse consistent with the setup,
//! and a test of whether the model can follow the data at all.

use super::Estimate;
pub use super::result::{LACK_OF_FIT_P, LackOfFit};
use crate::measured::TraceSummary;
use statrs::distribution::{ChiSquared, ContinuousCDF, Normal};

/// A free parameter whose 95 % interval spans more than this factor (hi/lo) is not pinned by
/// the data: the fit names a value but the data would take anything across two decades.
pub const PIN_RATIO: f64 = 100.0;

/// An exact solve (as many data as parameters) must reproduce its target to this relative
/// miss, or the target is out of the model's reach.
pub const EXACT_MISS: f64 = 1e-9;

/// A measured peak force or contact time more than this factor from the starting ball's is
/// out of the fit's reach (the search moves each parameter ±5 decades: a contact time
/// ∝ 1/√K moves 2.5).
pub const SCALE_MAX: f64 = 1e3;

/// Wald–Wolfowitz runs test of the signs of `r` in order (zeros skipped); `None` below 20
/// signs, where the normal approximation is not to be trusted. Mean runs μ = 2n₊n₋/n + 1,
/// variance (μ − 1)(μ − 2)/(n − 1); p = Φ(z) for too few runs.
pub fn runs_test(r: &[f64]) -> Option<LackOfFit> {
    let signs: Vec<bool> = r.iter().filter(|v| **v != 0.0).map(|v| *v > 0.0).collect();
    let n = signs.len() as f64;
    let pos = signs.iter().filter(|s| **s).count() as f64;
    let neg = n - pos;
    if signs.len() < 20 || pos == 0.0 || neg == 0.0 {
        return None;
    }
    let runs = 1.0 + signs.windows(2).filter(|w| w[0] != w[1]).count() as f64;
    let mu = 2.0 * pos * neg / n + 1.0;
    let var = (mu - 1.0) * (mu - 2.0) / (n - 1.0);
    if var <= 0.0 {
        return None;
    }
    let z = (runs - mu) / var.sqrt();
    let p = Normal::standard().cdf(z);
    Some(LackOfFit {
        test: "runs",
        statistic: z,
        p_value: p,
    })
}

/// χ² = Σ r² of residuals already divided by their standard deviations, at `dof` degrees of
/// freedom; p = P(χ²_dof ≥ χ²). `None` without a degree of freedom.
pub fn chi2_test(r: &[f64], dof: usize) -> Option<LackOfFit> {
    if dof == 0 {
        return None;
    }
    let chi2: f64 = r.iter().map(|v| v * v).sum();
    let p = ChiSquared::new(dof as f64).ok()?.sf(chi2);
    Some(LackOfFit {
        test: "chi2",
        statistic: chi2,
        p_value: p,
    })
}

/// Whether the data pin an estimate: with residuals left, a finite interval spanning at most
/// [`PIN_RATIO`]; an exact solve (no residual) pins what it verified, but not a parameter the
/// data do not see (its variance infinite: `stats::uncertainty` dropped its direction, the
/// fit's "not identifiable" warning) — any value of it solves the data as well. Never a
/// value on the search's bound.
pub fn pinned(e: &Estimate, dof: usize, on_bound: bool) -> bool {
    if on_bound || !e.value.is_finite() {
        return false;
    }
    if dof == 0 {
        return e.std_error != f64::INFINITY;
    }
    let [lo, hi] = e.ci95;
    lo.is_finite() && hi.is_finite() && lo > 0.0 && hi / lo <= PIN_RATIO
}

/// Whether `x` sits on (within 1e-6 of) the box `[lo, hi]` it was searched in.
pub fn on_bound(x: f64, lo: f64, hi: f64) -> bool {
    let tol = 1e-6 * (hi - lo).abs().max(1.0);
    x - lo <= tol || hi - x <= tol
}

/// The restitution a force pulse implies at the given speed and mass: I = m v0 (1 + e)
/// (docs/model.md §2, the impulse of the contact force is the change of momentum), and its
/// standard error from the noise, σ_I = noise · √(n) · Δt over the n samples of the pulse.
pub fn implied_cor(s: &TraceSummary, mass: f64, v0: f64, dt: f64) -> (f64, f64) {
    let samples = ((s.t_end - s.t_start) / dt).max(1.0);
    let sd_impulse = s.noise * samples.sqrt() * dt;
    (s.impulse / (mass * v0) - 1.0, sd_impulse / (mass * v0))
}

/// Why a fit gave no answer, one reason each ("not converged", "z_p not pinned by the data");
/// empty when it answered. The command line's report and error and the explorer's message
/// all say it in these words.
pub fn no_answer_reasons(converged: bool, not_pinned: &[&str]) -> Vec<String> {
    let mut why = Vec::new();
    if !converged {
        why.push("not converged".to_string());
    }
    if !not_pinned.is_empty() {
        why.push(format!("{} not pinned by the data", not_pinned.join(", ")));
    }
    why
}

/// The judgement of a fit of a law to readings (`fit --cor-temperature`,
/// `fit --pressure-loss`): its lack-of-fit test on the `residuals` (each divided by its
/// standard deviation) — χ² at `dof` where every reading's deviation is `stated`, the runs
/// test otherwise — and why it gave no answer: not `converged`, or the test significant,
/// said as `misfit`.
pub fn judge_law(
    residuals: &[f64],
    dof: usize,
    stated: bool,
    converged: bool,
    misfit: &str,
) -> (Option<LackOfFit>, Vec<String>) {
    let lack_of_fit = if stated {
        chi2_test(residuals, dof)
    } else {
        runs_test(residuals)
    };
    let mut no_answer = no_answer_reasons(converged, &[]);
    if lack_of_fit.as_ref().is_some_and(LackOfFit::significant) {
        no_answer.push(misfit.to_string());
    }
    (lack_of_fit, no_answer)
}

/// The warning of a fit whose residuals are all zero with degrees of freedom left
/// (`MultiFit::no_scatter`): no standard error or interval is given.
pub const NO_SCATTER: &str = "the residuals are all zero: the data show no scatter to estimate \
                              the uncertainty from (no standard error or interval is given)";

/// The warnings every fit gives on how well its data pin it: no residual left to estimate
/// the uncertainty from (`dof` 0), and the parameter `weakest` not identifiable where the
/// column-scaled Jacobian's condition number passes `stats::CONDITION_MAX`, with `hint` —
/// what this kind of fit's user can do about it.
pub(super) fn pinning_warnings(
    dof: usize,
    u: &super::stats::Uncertainty,
    weakest: &str,
    hint: &str,
) -> Vec<String> {
    let mut w = Vec::new();
    if dof == 0 {
        w.push(
            "as many data as parameters: no residual is left to estimate the uncertainty".into(),
        );
    }
    if u.condition > super::stats::CONDITION_MAX {
        w.push(format!(
            "{weakest} is not identifiable from these data: the fit cannot tell it from the \
             other parameters (condition number {:.1e}); {hint}",
            u.condition
        ));
    }
    w
}

/// The warning of a fit that stopped after `iterations` without converging.
pub(super) fn not_converged(iterations: usize) -> String {
    format!("the fit stopped after {iterations} iterations without converging")
}

/// The free parameters (the first `fitted.len()` variables of `best`) the data do not pin,
/// with `quantities` fitted in all (a trace's start and baseline included); `no_scatter`
/// (`MultiFit::no_scatter`): judged as an exact solve (`MultiFit::exact`), on what the data
/// see.
pub(super) fn not_pinned(
    fitted: &[Estimate],
    best: &super::lm::Best,
    quantities: usize,
    no_scatter: bool,
) -> Vec<&'static str> {
    let dof = best.sol.residuals.len().saturating_sub(quantities);
    let dof = if no_scatter { 0 } else { dof };
    fitted
        .iter()
        .enumerate()
        .filter(|(j, e)| {
            let (x, lo, hi) = (best.sol.x[*j], best.lo[*j], best.hi[*j]);
            !pinned(e, dof, on_bound(x, lo, hi))
        })
        .map(|(_, e)| e.name)
        .collect()
}

/// The verdict on a finished fit: the lack-of-fit test, whether it answered, and the warnings
/// that say why not (naming the `--free` set the data can pin).
pub(super) fn judge(f: &mut super::result::MultiFit, lack: Option<LackOfFit>) {
    f.lack_of_fit = lack;
    if let Some(t) = lack.filter(LackOfFit::significant) {
        f.warnings.push(format!(
            "the model cannot follow these data: the residuals are systematic ({} test {} = \
             {}, p = {})",
            t.test,
            if t.test == "runs" { "z" } else { "χ²" },
            crate::text::sig(t.statistic, 3),
            crate::text::sig(t.p_value, 2)
        ));
    }
    f.identified = f.converged && f.not_pinned.is_empty();
    for name in &f.on_bound {
        let value = f
            .fitted
            .iter()
            .find(|e| e.name == *name)
            .map_or(f64::NAN, |e| e.value);
        f.warnings.push(format!(
            "{name} ran to the bound of its search ({}): the data ask for more than the model \
             gives with the rest of the ball held",
            crate::text::sig(value, 4)
        ));
    }
    if !f.not_pinned.is_empty() {
        let pinnable: Vec<&str> = f
            .fitted
            .iter()
            .map(|e| e.name)
            .filter(|n| !f.not_pinned.contains(n))
            .collect();
        f.warnings.push(format!(
            "the data do not pin {}: {}",
            f.not_pinned.join(", "),
            if pinnable.is_empty() {
                if f.fitted.len() == 1 {
                    "add data (more points, other speeds, forces or contact times)".to_string()
                } else {
                    "add data (other speeds, forces or contact times) or fit fewer parameters"
                        .to_string()
                }
            } else {
                format!("fit --free {} alone, or add data", pinnable.join(","))
            }
        ));
    }
}

/// Tests': that a fit judged by [`judge_law`] gave no answer for the lack of fit it found
/// (`no_answer` naming it).
#[cfg(test)]
#[track_caller]
pub(super) fn assert_refused_for_lack_of_fit(no_answer: &[String]) {
    assert!(
        no_answer.iter().any(|w| w.contains("lack of fit")),
        "{no_answer:?}"
    );
}

/// Tests': an estimate `got` within the relative `tol` of the `truth` it should give back.
#[cfg(test)]
#[track_caller]
pub(super) fn assert_recovered(got: f64, truth: f64, tol: f64) {
    assert!((got / truth - 1.0).abs() < tol, "{got} vs {truth}");
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Alternating signs: as many runs as possible, p near 1; a block of + then a block of −
    /// (a systematic miss): two runs, p tiny.
    #[test]
    fn runs_test_tells_noise_from_a_systematic_miss() {
        let alt: Vec<f64> = (0..40)
            .map(|i| if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        let t = runs_test(&alt).unwrap();
        assert!(t.p_value > 0.99 && !t.significant(), "{t:?}");
        let block: Vec<f64> = (0..40).map(|i| if i < 20 { 1.0 } else { -1.0 }).collect();
        let t = runs_test(&block).unwrap();
        // μ = 21, σ² = 20·19/39: z = (2 − 21)/3.1213 = −6.087
        assert!((t.statistic + 6.0873).abs() < 1e-3, "{t:?}");
        assert!(t.significant());
        assert!(runs_test(&block[..10]).is_none());
    }

    /// χ² of 10 unit residuals at 10 degrees of freedom is the median-ish value (p ≈ 0.44);
    /// residuals of 5σ are not noise.
    #[test]
    fn chi2_test_against_its_table() {
        let t = chi2_test(&[1.0; 10], 10).unwrap();
        // P(χ²₁₀ ≥ 10) = 0.44049
        assert!((t.p_value - 0.44049).abs() < 1e-4, "{t:?}");
        assert!(chi2_test(&[5.0; 10], 8).unwrap().significant());
        assert!(chi2_test(&[1.0], 0).is_none());
    }

    #[test]
    fn an_interval_over_two_decades_is_not_pinned() {
        let e = |lo: f64, hi: f64| Estimate {
            name: "k_r",
            unit: "N/m",
            // an exact solve has a value and no interval
            value: if lo.is_finite() {
                (lo * hi).sqrt()
            } else {
                1.0
            },
            std_error: 1.0,
            ci95: [lo, hi],
        };
        assert!(pinned(&e(1.0, 99.0), 3, false));
        assert!(!pinned(&e(1.0, 101.0), 3, false));
        assert!(!pinned(&e(2.6e-180, 2.8e183), 3, false));
        assert!(!pinned(&e(f64::NAN, f64::NAN), 3, false));
        assert!(pinned(&e(f64::NAN, f64::NAN), 0, false));
        assert!(!pinned(&e(1.0, 2.0), 3, true));
        // an exact solve does not pin a parameter its data do not see (infinite variance)
        let unseen = Estimate {
            std_error: f64::INFINITY,
            ..e(f64::NAN, f64::NAN)
        };
        assert!(!pinned(&unseen, 0, false));
    }
}
