//! The exact flow of a compliant target on the linear law without flattening
//! (docs/targets.md §4). The state u = (ᾱ, ᾱ', ȳ, s̄) of the reduced ball obeys the linear
//! system u' = A u of docs/targets.md §2:
//!
//! ```text
//! ᾱ'' = −F̄,   ȳ' = 2ζ(F̄ − λȳ),   s̄' = 2ζ_s(F̄ − λ_s s̄),   F̄ = z̄ = ᾱ − ȳ − s̄,
//! ```
//!
//! and, for a surface without damping (c_s = 0, ζ_s = ∞), the surface a spring in series with the
//! contact: s̄ = F̄/λ_s, F̄ = k_e (ᾱ − ȳ) with k_e = λ_s/(1 + λ_s). A locked dashpot (c = ∞,
//! ζ = 0) holds ȳ at 0. The flow exp(Aτ) is evaluated in closed form (nalgebra's Padé matrix
//! exponential, to rounding); only the end of contact, the first fall of F̄ to 0, and the peaks
//! are root-found (Brent), on a grid fine against the slowest period of the series.

use super::{Outcome, Surface, horizon};
use crate::model::params::Normalized;
use crate::solver::roots::brent;
use crate::solver::{Method, Unresolved};
use nalgebra::{Matrix4, RowVector4, Vector4};

/// The most grid steps a run may take before the horizon.
const MAX_STEPS: usize = 2_000_000;
/// A ball whose remaining energy could not give it a COR above this has come to rest.
const REST_COR: f64 = 1e-9;

struct System {
    a: Matrix4<f64>,
    /// F̄ = force · u.
    force: RowVector4<f64>,
    /// The surface is a spring alone (c_s = 0): s̄ = F̄/λ_s is no state of its own.
    spring_only: bool,
    lambda: f64,
    lambda_s: f64,
    k_e: f64,
}

impl System {
    fn new(n: &Normalized, s: &Surface) -> System {
        let spring_only = s.zeta_s.is_infinite();
        let k_e = s.lambda_s / (1.0 + s.lambda_s);
        let force = if spring_only {
            RowVector4::new(k_e, 0.0, -k_e, 0.0)
        } else {
            RowVector4::new(1.0, 0.0, -1.0, -1.0)
        };
        let mut a = Matrix4::zeros();
        a[(0, 1)] = 1.0;
        a.set_row(1, &(-force));
        if n.zeta > 0.0 {
            let row = (force - RowVector4::new(0.0, 0.0, n.lambda, 0.0)) * (2.0 * n.zeta);
            a.set_row(2, &row);
        }
        if !spring_only {
            let row = (force - RowVector4::new(0.0, 0.0, 0.0, s.lambda_s)) * (2.0 * s.zeta_s);
            a.set_row(3, &row);
        }
        System {
            a,
            force,
            spring_only,
            lambda: n.lambda,
            lambda_s: s.lambda_s,
            k_e,
        }
    }

    fn at(&self, tau: f64) -> Vector4<f64> {
        (self.a * tau).exp() * Vector4::new(0.0, 1.0, 0.0, 0.0)
    }

    fn deflection(&self, u: &Vector4<f64>) -> f64 {
        if self.spring_only {
            (self.force * u)[0] / self.lambda_s
        } else {
            u[3]
        }
    }

    /// Twice the energy still held (kinetic, contact, springs): √ of it bounds the COR.
    fn energy2(&self, u: &Vector4<f64>) -> f64 {
        let f = (self.force * u)[0];
        let held = if self.spring_only {
            f * f / self.k_e
        } else {
            f * f + self.lambda_s * u[3] * u[3]
        };
        u[1] * u[1] + held + self.lambda * u[2] * u[2]
    }

    /// The peak of `row · u(τ)` near grid point τ_k (spacing h), where its rate
    /// `row · A u` falls through 0; the grid value when it does not bracket.
    fn peak(&self, row: RowVector4<f64>, tau_k: f64, h: f64, grid: f64) -> f64 {
        let rate = row * self.a;
        let g = |t: f64| (rate * self.at(t))[0];
        let (lo, hi) = ((tau_k - h).max(0.0), tau_k + h);
        let (glo, ghi) = (g(lo), g(hi));
        if !(glo > 0.0 && ghi < 0.0) {
            return grid;
        }
        let t = brent(g, lo, hi, glo, ghi, 1e-15 * hi);
        grid.max((row * self.at(t))[0])
    }
}

/// The impact of the reduced ball on a compliant surface, linear law, no flattening: the
/// caller checks z̄_m ≤ z̄_p. An error is the budget that ran out, with the steps taken.
pub(super) fn solve(n: &Normalized, s: &Surface) -> Result<Outcome, (Unresolved, usize)> {
    let sys = System::new(n, s);
    let t_max = horizon(n, s);
    // the slowest period of the series is 2π/√k with k = 1/(1 + 1/λ + 1/λ_s); sample it
    // 600 times, and the horizon at most MAX_STEPS times
    let soft = if n.lambda > 0.0 && n.zeta > 0.0 {
        1.0 / n.lambda
    } else {
        0.0
    };
    let h = (0.01 * (1.0 + soft + 1.0 / s.lambda_s).sqrt()).max(t_max / MAX_STEPS as f64);
    let w = walk(&sys, h, t_max);
    let f_max = sys.peak(sys.force, w.k_peak as f64 * h, h, w.f_grid);
    let s_max = if sys.spring_only {
        f_max / s.lambda_s
    } else {
        sys.peak(
            RowVector4::new(0.0, 0.0, 0.0, 1.0),
            w.k_s as f64 * h,
            h,
            w.s_grid,
        )
    };
    let (rebound, tau_end, u_end) = match w.end {
        Some(tau) => (true, tau, sys.at(tau)),
        None if sys.energy2(&w.u).sqrt() < REST_COR => (false, t_max, w.u),
        None => return Err((Unresolved::Horizon, w.k)),
    };
    Ok(Outcome {
        rebound,
        tau_end,
        velocity_end: u_end[1],
        f_max,
        z_max: f_max,
        z_f: 0.0,
        s_max,
        method: Method::Exact,
    })
}

/// The history at `times` (normalized): (F̄, z̄, ᾱ, s̄) on the exact flow; z̄ = F̄ on the linear
/// law without flattening.
pub(super) fn sample(n: &Normalized, s: &Surface, times: &[f64]) -> Vec<[f64; 4]> {
    let sys = System::new(n, s);
    times
        .iter()
        .map(|&tau| {
            let u = sys.at(tau);
            let f = (sys.force * u)[0];
            [f, f, u[0], sys.deflection(&u)]
        })
        .collect()
}

/// The grid walk of `solve`: where F̄ first fell to 0 (refined), or `None` at the horizon or at
/// rest; the state and step there; the grid's peaks of F̄ and s̄ and their steps.
struct Walk {
    end: Option<f64>,
    u: Vector4<f64>,
    k: usize,
    f_grid: f64,
    k_peak: usize,
    s_grid: f64,
    k_s: usize,
}

fn walk(sys: &System, h: f64, t_max: f64) -> Walk {
    let step = (sys.a * h).exp();
    let mut w = Walk {
        end: None,
        u: Vector4::new(0.0, 1.0, 0.0, 0.0),
        k: 0,
        f_grid: 0.0,
        k_peak: 0,
        s_grid: 0.0,
        k_s: 0,
    };
    let mut f_prev = 0.0;
    loop {
        w.k += 1;
        if w.k as f64 * h > t_max {
            return w;
        }
        w.u = step * w.u;
        let f = (sys.force * w.u)[0];
        if f > w.f_grid {
            (w.f_grid, w.k_peak) = (f, w.k);
        }
        let d = sys.deflection(&w.u);
        if d > w.s_grid {
            (w.s_grid, w.k_s) = (d, w.k);
        }
        if f_prev > 0.0 && f <= 0.0 {
            // a ball with no energy left to leave with has come to rest: F̄ falls through 0
            // in the rounding of the creep, not at a separation
            if sys.energy2(&w.u).sqrt() >= REST_COR {
                let (a, b) = ((w.k - 1) as f64 * h, w.k as f64 * h);
                w.end = Some(separation(sys, a, b, f_prev, f));
            }
            return w;
        }
        f_prev = f;
    }
}

/// The time in [a, b] at which F̄ falls to 0, by Brent on the exact flow (the grid's values at
/// the ends when the flow's own, by rounding, do not bracket).
fn separation(sys: &System, a: f64, b: f64, fa: f64, fb: f64) -> f64 {
    let g = |t: f64| (sys.force * sys.at(t))[0];
    let (ga, gb) = (g(a), g(b));
    let (ga, gb) = if ga > 0.0 && gb <= 0.0 {
        (ga, gb)
    } else {
        (fa, fb)
    };
    brent(g, a, b, ga, gb, 1e-15 * b)
}
