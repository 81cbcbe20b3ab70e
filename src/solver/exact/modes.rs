//! The time scales of a phase's modes: how far the search for its events may step, and after
//! when no event can come.

use crate::solver::propagator::Roots;

/// The time scales of a phase's modes, worked out once per phase.
#[derive(Clone, Copy)]
pub(super) struct Modes {
    /// (|s|, Re s, part of an oscillating pair) for each mode that enters z̄: modes with s = 0
    /// (λ = 0) carry w1 = w3... in the (z̄, ᾱ', ȳ) state they have no z̄ component at all.
    live: [(f64, f64, bool); 3],
    count: usize,
    /// Smallest |Re s| among them.
    slowest: f64,
    /// The time after which no event can come (see `settle_time`), if any.
    pub(super) settle: Option<f64>,
}

impl Modes {
    pub(super) fn new(roots: &Roots) -> Self {
        let all = roots.all();
        // |s| as √(norm²): hypot's overflow care is not needed at these magnitudes
        let norms = all.map(|s| s.norm_sqr().sqrt());
        let mut live = [(0.0, 0.0, false); 3];
        let mut count = 0;
        for (i, s) in all.iter().enumerate() {
            // The zero root of λ = 0 is not a mode. Every other is, however slow: the recoil
            // spring's relaxation (s ≈ −2ζλ, fifteen decades below the dashpot's rate at
            // λ = 3.1e-12) is what pushes the ball back out, and a phase may settle only once
            // it has decayed (tests/physics/solver_agreement.rs, `creeps_match_a_40_digit_reference`;
            // tests/physics/closed_forms.rs, `largest_lambda_and_zeta_still_rebound`, for a complex
            // pair). Following a slow mode is cheap: the step doubles with τ.
            let oscillation = i > 0 && roots.q < 0.0;
            if norms[i] > 0.0 {
                live[count] = (norms[i], s.re, oscillation);
                count += 1;
            }
        }
        let slowest = live[..count]
            .iter()
            .map(|m| m.1.abs())
            .fold(f64::INFINITY, f64::min);
        let mut modes = Modes {
            live,
            count,
            slowest,
            settle: None,
        };
        modes.settle = modes.settle_time();
        modes
    }

    /// Step length at τ. Modes with e^{Re s τ} < e^{−36} are gone. An oscillating pair limits
    /// the step to one time constant (a quarter period at most). A fastest mode that is real
    /// only decays: a monotone exponential plus what the slower modes do over one of their own
    /// time constants has a monotone derivative, so at most one extremum per step (which
    /// `crossing_in` checks), and the step may double with τ up to the next mode's time
    /// constant. Never past two time constants of the slowest mode: the Newton form sums terms
    /// that do not all decay, and over a longer step their cancellation would eat the relative
    /// precision of a state that has.
    pub(super) fn step(&self, tau: f64) -> f64 {
        let mut first: Option<(f64, bool)> = None; // fastest alive: (|s|, oscillating)
        let mut second: f64 = 0.0; // |s| of the next fastest alive, other than its pair
        for &(norm, re, osc) in &self.live[..self.count] {
            if re * tau < -36.0 {
                continue;
            }
            match first {
                Some((n, o)) if norm > n => {
                    if !(o && osc) {
                        second = second.max(n);
                    }
                    first = Some((norm, osc));
                }
                Some((n, o)) => {
                    if !(o && osc && norm == n) {
                        second = second.max(norm);
                    }
                }
                None => first = Some((norm, osc)),
            }
        }
        let h = match first {
            None => tau.max(1.0),
            // 1.5 time constants < a quarter period (π/2b ≥ π/2|s|): one extremum at most
            Some((n, true)) => 1.5 / n,
            Some((n, false)) if second > 0.0 => (1.0 / n).max(tau).min(1.0 / second),
            Some((n, false)) => (1.0 / n).max(tau),
        };
        if self.slowest > 0.0 && self.slowest.is_finite() {
            h.min(2.0 / self.slowest)
        } else {
            h
        }
    }

    /// The time after which no event can come: the slowest mode is real and every other has
    /// decayed relative to it by e^{−70}, or it has itself fallen below e^{−600} (the faster
    /// ones then underflow to exact zeros, which must not read as crossings). `None` while an
    /// oscillation dominates the tail.
    fn settle_time(&self) -> Option<f64> {
        let live = &self.live[..self.count];
        let &(_, slow, complex) = live.iter().max_by(|a, b| a.1.total_cmp(&b.1))?;
        if complex {
            return None;
        }
        let floor = 600.0 / slow.abs();
        // The next mode is any other faster than the slowest by more than the slowest's own
        // rounding: two slow modes of a creep are told apart however far the fast one lies
        // (λ = 1e-9, ζ = 3000: −6.2e-6 and −1.6e-4 beside −1.7e5; tests/physics/solver_agreement.rs,
        // `soft_spring_release_is_a_rebound_for_both`). Counting a near-double root as two
        // only makes the settle time later: safe.
        let next = live
            .iter()
            .map(|m| m.1)
            .filter(|&re| re < slow - 1e-9 * slow.abs())
            .fold(f64::NEG_INFINITY, f64::max);
        if next.is_finite() {
            Some((70.0 / (slow - next)).min(floor))
        } else {
            Some(floor)
        }
    }
}
