//! One normalized impact x'' = −F̄(x, x'), x(0) = 0, x'(0) = 1, integrated to the end of
//! contact by an embedded Runge–Kutta 8(5,3) pair (Dormand–Prince DOP853; coefficients from
//! the `differential-equations` crate's tableau, step control after Hairer, Nørsett & Wanner,
//! *Solving ODEs I*, §II.10) with the end located on the step itself.
//!
//! Why hand-written rather than the crate's solver: the exact calibration runs one impact per
//! root-finding iteration and the bench target is one Hunt–Crossley impact in ≤ 10 µs and one
//! calibration in ≤ 0.5 ms (BENCHMARKS.md). The state is two numbers; the crate's generic
//! solver allocates its solution and event machinery per call, which alone costs more than the
//! whole impact here. This loop allocates nothing unless histories are asked for.

use crate::solver::roots::{brent, newton_bracketed_from};

// DOP853's coefficients as constants, so that the stage loops unroll with the zeros folded
// away; printed from `differential_equations::tableau::ButcherTableau::dop853()` in shortest
// round-trip form, and `tests::tableau_is_the_crates` holds them equal to it.
#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::approx_constant)]
mod dop853 {
    pub const A: [[f64; 12]; 12] = [[0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[5.260015195876773e-2, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[1.97250569845379e-2, 5.91751709536137e-2, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[2.958758547680685e-2, 0e0, 8.876275643042054e-2, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[2.413651341592667e-1, 0e0, -8.845494793282861e-1, 9.24834003261792e-1, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[3.7037037037037035e-2, 0e0, 0e0, 1.7082860872947386e-1, 1.2546768756682242e-1, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[3.7109375e-2, 0e0, 0e0, 1.7025221101954405e-1, 6.021653898045596e-2, -1.7578125e-2, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0],
[3.709200011850479e-2, 0e0, 0e0, 1.7038392571223998e-1, 1.0726203044637328e-1, -1.5319437748624402e-2, 8.273789163814023e-3, 0e0, 0e0, 0e0, 0e0, 0e0],
[6.241109587160757e-1, 0e0, 0e0, -3.3608926294469414e0, -8.68219346841726e-1, 2.759209969944671e1, 2.0154067550477894e1, -4.348988418106996e1, 0e0, 0e0, 0e0, 0e0],
[4.7766253643826434e-1, 0e0, 0e0, -2.4881146199716677e0, -5.90290826836843e-1, 2.1230051448181193e1, 1.5279233632882423e1, -3.328821096898486e1, -2.0331201708508627e-2, 0e0, 0e0, 0e0],
[-9.371424300859873e-1, 0e0, 0e0, 5.186372428844064e0, 1.0914373489967295e0, -8.149787010746927e0, -1.852006565999696e1, 2.2739487099350505e1, 2.4936055526796523e0, -3.0467644718982196e0, 0e0, 0e0],
[2.273310147516538e0, 0e0, 0e0, -1.053449546673725e1, -2.0008720582248625e0, -1.79589318631188e1, 2.794888452941996e1, -2.8589982771350235e0, -8.87285693353063e0, 1.2360567175794303e1, 6.433927460157636e-1, 0e0],
];
pub const C: [f64; 12] = [0e0, 5.260015195876773e-2, 7.89002279381516e-2, 1.183503419072274e-1, 2.816496580927726e-1, 3.333333333333333e-1, 2.5e-1, 3.076923076923077e-1, 6.512820512820513e-1, 6e-1, 8.571428571428571e-1, 1e0];
pub const B: [f64; 12] = [5.4293734116568765e-2, 0e0, 0e0, 0e0, 0e0, 4.450312892752409e0, 1.8915178993145003e0, -5.801203960010585e0, 3.111643669578199e-1, -1.521609496625161e-1, 2.0136540080403034e-1, 4.471061572777259e-2];
pub const BH: [f64; 12] = [2.440944881889764e-1, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 0e0, 7.338466882816118e-1, 0e0, 0e0, 2.2058823529411766e-2];
pub const ER: [f64; 12] = [1.312004499419488e-2, 0e0, 0e0, 0e0, 0e0, -1.2251564463762044e0, -4.957589496572502e-1, 1.6643771824549864e0, -3.5032884874997366e-1, 3.341791187130175e-1, 8.192320648511571e-2, -2.2355307863886294e-2];
}
use dop853::{A, B, BH, C, ER};

/// Relative and absolute tolerance per step, in normalized units (x, x' of order 1). With the
/// 8th-order pair the COR comes out good to ~1e-12 (tests/peers.rs checks it against the
/// closed forms), well inside the 1e-9 the calibration promises.
const TOL: f64 = 1e-13;
/// Steps allowed before the run is declared unresolved (no impact here takes 1 000).
const MAX_STEPS: usize = 100_000;

/// A normalized contact law: the force on the ball and the function whose down-crossing
/// (while the ball moves out, x' < 0) ends the contact, with its time derivative.
pub trait Law {
    /// F̄(x, x'), already clipped where the model clips it.
    fn force(&self, x: f64, v: f64) -> f64;
    /// The force that drives the motion: F̄ continued smoothly past where a clip would act.
    /// Until the contact ends the two are equal (the clip acts only after the end event), and
    /// stepping with the smooth one keeps the last step, whose end sits on the clip, of full
    /// order: with the clipped force its error estimate passed a step 400 times less accurate
    /// than the tolerance (clipped Kelvin–Voigt, ζ = 0.05, against the closed form).
    fn drive(&self, x: f64, v: f64) -> f64 {
        self.force(x, v)
    }
    /// g(x, x') = 0 ends the contact.
    fn end(&self, x: f64, v: f64) -> f64;
    /// dg/dτ along the motion (a = −F̄).
    fn end_rate(&self, x: f64, v: f64, a: f64) -> f64;
    /// dF̄/dτ along the motion (a = −F̄), for locating the peak force.
    fn force_rate(&self, x: f64, v: f64, a: f64) -> f64;
    /// Time after which a ball still in contact is declared to have no rebound
    /// (Kelvin–Voigt with tension, overdamped, creeps back to x = 0 forever).
    fn horizon(&self) -> f64 {
        1e4
    }
    /// Whether the ball is known never to leave once it has turned (unloading starts): the run
    /// then ends there with no rebound.
    fn stays_after_turning(&self) -> bool {
        false
    }
    /// p such that the force is smooth in w = x^{1/p} near x = 0 (see `w_phase`).
    fn smoothing_power(&self) -> Option<i32> {
        None
    }
    /// Whether the contact ends at x = 0 (rather than where a clipped force lets go).
    fn ends_at_zero(&self) -> bool {
        false
    }
}

/// Indentation below which the start runs in w = x^{1/p}; at the end, the fraction of the peak
/// indentation below which it does.
const W_START: f64 = 0.05;
const W_END: f64 = 0.3;

/// The end of one normalized impact.
#[derive(Debug, Clone, Default)]
pub struct Run {
    /// The contact ended (F̄ or x back to 0 while moving out).
    pub rebound: bool,
    /// τ at the end (or at the horizon).
    pub tau: f64,
    /// (x, x') at the end.
    pub end: [f64; 2],
    /// Peak force and peak indentation seen at the steps (refined at the turning point).
    pub f_max: f64,
    pub x_max: f64,
    /// τ of the turning point x' = 0 (unloading starts).
    pub tau_unload: f64,
    /// F̄ at the end (0 where the force let go; η δ̇ < 0 for Kelvin–Voigt with tension).
    pub f_end: f64,
    /// Accepted and rejected steps.
    pub steps: usize,
    /// The step budget ran out.
    pub unresolved: bool,
}

fn rhs<L: Law>(law: &L, y: [f64; 2]) -> [f64; 2] {
    [y[1], -law.drive(y[0], y[1])]
}

/// One DOP853 step of y' = f(t, y) from (t, y), with f(t, y) = `k0`, of size `h`: the new
/// state and the scaled error estimate (≤ 1 accepts).
fn step_with(
    f: &impl Fn(f64, [f64; 2]) -> [f64; 2],
    (t, y): (f64, [f64; 2]),
    k0: [f64; 2],
    h: f64,
) -> ([f64; 2], f64) {
    let mut k = [[0.0; 2]; 12];
    k[0] = k0;
    for i in 1..12 {
        let (mut s0, mut s1) = (0.0, 0.0);
        for j in 0..i {
            s0 += A[i][j] * k[j][0];
            s1 += A[i][j] * k[j][1];
        }
        k[i] = f(t + C[i] * h, [y[0] + h * s0, y[1] + h * s1]);
    }
    let mut y1 = y;
    let (mut err5, mut err3) = (0.0, 0.0);
    for c in 0..2 {
        let (mut inc, mut e5, mut low) = (0.0, 0.0, 0.0);
        for i in 0..12 {
            inc += B[i] * k[i][c];
            e5 += ER[i] * k[i][c];
            low += BH[i] * k[i][c];
        }
        y1[c] += h * inc;
        let sk = TOL + TOL * y[c].abs().max(y1[c].abs());
        err5 += (e5 / sk).powi(2);
        err3 += ((inc - low) / sk).powi(2);
    }
    // Hairer's dop853 combination of the 5th- and 3rd-order estimates
    let deno = if err5 + 0.01 * err3 > 0.0 {
        err5 + 0.01 * err3
    } else {
        1.0
    };
    (y1, h.abs() * err5 * (1.0 / (2.0 * deno)).sqrt())
}

/// One step of the impact in time (autonomous: x' = v, v' = −F̄).
fn step<L: Law>(law: &L, y: [f64; 2], k0: [f64; 2], h: f64) -> ([f64; 2], f64) {
    step_with(&|_, y| rhs(law, y), (0.0, y), k0, h)
}

/// The impact near x = 0 with w = x^{1/p} as the independent variable and (τ, v) as the
/// state: dτ/dw = p w^{p−1}/v, dv/dw = −F̄(w^p, v) p w^{p−1}/v. Where F̄ holds x^{3/2} and
/// x^{1/4} it is not smooth in τ at x = 0 (x ≈ τ makes the force ∝ τ^{3/2}), and the time
/// steps shrink and are rejected by the dozen there; in w (p = 2 for x^{3/2}, 4 for x^{1/4})
/// the right-hand side is a polynomial over v, and a few steps cross the region. Valid while v
/// stays away from 0, which `stop` ensures. Runs from `w0` towards `w1` until `stop(x, v)`
/// or w1; returns (w, τ, v, steps).
fn w_phase<L: Law>(
    law: &L,
    p: i32,
    (w0, w1): (f64, f64),
    (tau0, v0): (f64, f64),
    stop: impl Fn(f64, f64) -> bool,
) -> (f64, f64, f64, usize) {
    let pf = p as f64;
    let f = |w: f64, s: [f64; 2]| {
        let dxdw = pf * w.powi(p - 1);
        let x = w.powi(p);
        [dxdw / s[1], -law.drive(x, s[1]) * dxdw / s[1]]
    };
    let (mut w, mut s) = (w0, [tau0, v0]);
    let mut h = 0.25 * (w1 - w0);
    let mut steps = 0;
    while steps < 1000 {
        let hs = if (w + h - w1) * (w1 - w0).signum() > 0.0 {
            w1 - w
        } else {
            h
        };
        let (s1, err) = step_with(&f, (w, s), f(w, s), hs);
        steps += 1;
        if err.is_nan() || err > 1.0 || s1[1].abs() < 0.25 * v0.abs() {
            h = hs / 3.0;
            continue;
        }
        w += hs;
        s = s1;
        if w == w1 || stop(w.powi(p), s[1]) {
            break;
        }
        h = hs / (err.powf(0.125) / 0.9).clamp(1.0 / 6.0, 3.0);
    }
    (w, s[0], s[1], steps)
}

/// Integrate from x = 0, x' = 1 until the contact ends. `sample_every` > 0 lands steps on
/// τ = j·sample_every and records (τ, F̄, x) there (the histories' second pass).
pub fn run<L: Law>(law: &L, sample_every: f64, samples: &mut Vec<[f64; 3]>) -> Run {
    let mut y = [0.0, 1.0];
    let (mut tau, mut h) = (0.0, 1e-3);
    let mut out = Run {
        f_max: law.force(0.0, 1.0),
        ..Run::default()
    };
    let record = sample_every > 0.0;
    // the histories' pass lands on sample times and stays in τ throughout
    let smooth = law.smoothing_power().filter(|_| !record);
    if let Some(p) = smooth {
        let stop = |x: f64, v: f64| {
            x >= W_START || v < 0.6 || law.force_rate(x, v, -law.drive(x, v)) <= 0.0
        };
        let (w, t, v, n) = w_phase(
            law,
            p,
            (0.0, W_START.powf(1.0 / p as f64)),
            (0.0, 1.0),
            stop,
        );
        (tau, y, h) = (t, [w.powi(p), v], 0.05);
        out.steps += n;
        out.f_max = law.force(y[0], y[1]);
        out.x_max = y[0];
    }
    let mut k0 = rhs(law, y);
    let mut n_sampled = 0usize;
    let horizon = law.horizon();
    let mut rising = law.force_rate(0.0, 1.0, k0[1]) > 0.0;
    while out.steps < MAX_STEPS {
        let next_sample = n_sampled as f64 * sample_every;
        if record && tau >= next_sample {
            samples.push([tau, law.force(y[0], y[1]), y[0]]);
            n_sampled += 1;
            continue;
        }
        let landing = record && tau + h >= next_sample;
        let hs = if landing { next_sample - tau } else { h };
        let (y1, err) = step(law, y, k0, hs);
        out.steps += 1;
        let at = (tau, y, k0);
        if y1[1] < 0.0 && law.end(y1[0], y1[1]) <= 0.0 {
            // The trial step passed the end of contact, where the force has a kink: its error
            // estimate says nothing about the step that stops at the end. Locate the end on
            // re-taken steps and accept the one that lands there if it is accurate, else
            // shrink towards it (a kinked step would be rejected again and again).
            let (s, y_end) = crossing(law, (y, k0), hs, |y1, a| {
                (law.end(y1[0], y1[1]), law.end_rate(y1[0], y1[1], a))
            });
            let err_s = if s > 0.0 { step(law, y, k0, s).1 } else { 0.0 };
            if err_s <= 1.0 {
                return finish(law, out, at, (s, y_end), rising);
            }
            h = s / (err_s.powf(0.125) / 0.9).clamp(1.5, 3.0);
            continue;
        }
        if err.is_nan() || err > 1.0 {
            let fac = if err.is_finite() {
                (err.powf(0.125) / 0.9).min(3.0)
            } else {
                3.0
            };
            h = hs / fac.max(1.5);
            continue;
        }
        let (f1, a1) = (law.force(y1[0], y1[1]), -law.drive(y1[0], y1[1]));
        let rising1 = law.force_rate(y1[0], y1[1], a1) > 0.0;
        refine_peaks(law, &mut out, at, hs, (y1, rising, rising1));
        rising = rising1;
        if y1[1] <= 0.0 && law.stays_after_turning() {
            out.tau = out.tau_unload;
            out.end = [out.x_max, 0.0];
            out.f_end = law.force(out.x_max, 0.0);
            return out;
        }
        out.f_max = out.f_max.max(f1);
        out.x_max = out.x_max.max(y1[0]);
        if let Some(p) = smooth.filter(|_| law.ends_at_zero())
            && y1[1] < 0.0
            && y1[0] < W_END * out.x_max
        {
            let w0 = y1[0].powf(1.0 / p as f64);
            let (_, t, v, n) = w_phase(law, p, (w0, 0.0), (tau + hs, y1[1]), |_, _| false);
            out.steps += n;
            out.rebound = true;
            out.tau = t;
            out.end = [0.0, v];
            out.f_end = 0.0;
            return out;
        }
        tau = if landing { next_sample } else { tau + hs };
        y = y1;
        k0 = [y[1], a1];
        if !landing {
            h = hs / (err.powf(0.125) / 0.9).clamp(1.0 / 6.0, 3.0);
        }
        if tau > horizon {
            out.f_end = f1;
            out.tau = tau;
            out.end = y;
            return out;
        }
    }
    out.unresolved = true;
    out.tau = tau;
    out.end = y;
    out
}

/// The point inside the step from `y` (size `h`) where `g` (with its rate) crosses zero.
fn crossing<L: Law>(
    law: &L,
    (y, k0): ([f64; 2], [f64; 2]),
    h: f64,
    g: impl Fn([f64; 2], f64) -> (f64, f64),
) -> (f64, [f64; 2]) {
    let eval = |s: f64| {
        let y1 = if s == 0.0 { y } else { step(law, y, k0, s).0 };
        (y1, g(y1, -law.drive(y1[0], y1[1])))
    };
    let (g0, g1) = (eval(0.0).1.0, eval(h).1.0);
    let s = if g0 == 0.0 {
        0.0
    } else if g1 == 0.0 || (g0 > 0.0) == (g1 > 0.0) {
        h
    } else {
        newton_bracketed_from(|s| eval(s).1, (0.0, g0), (h, g1))
    };
    (s, eval(s).0)
}

/// The end of contact at `s` into the step from `y` at `tau` (`y_end` there).
fn finish<L: Law>(
    law: &L,
    mut out: Run,
    (tau, y, k0): (f64, [f64; 2], [f64; 2]),
    (s, y_end): (f64, [f64; 2]),
    rising: bool,
) -> Run {
    let f_end = law.force(y_end[0], y_end[1]);
    let rising_end = law.force_rate(y_end[0], y_end[1], -law.drive(y_end[0], y_end[1])) > 0.0;
    refine_peaks(law, &mut out, (tau, y, k0), s, (y_end, rising, rising_end));
    out.rebound = true;
    out.f_end = f_end;
    out.tau = tau + s;
    out.end = y_end;
    out.steps += 1;
    out
}

/// Inside a step of size `h` ending at `y1`: the turning point x' = 0 (peak indentation, start
/// of unloading) and a peak of the force (dF/dτ from + to −), each located on the step.
fn refine_peaks<L: Law>(
    law: &L,
    out: &mut Run,
    (tau, y, k0): (f64, [f64; 2], [f64; 2]),
    h: f64,
    (y1, rising0, rising1): ([f64; 2], bool, bool),
) {
    if y[1] > 0.0 && y1[1] <= 0.0 {
        let (s, yt) = crossing(law, (y, k0), h, |y, a| (y[1], a));
        out.tau_unload = tau + s;
        out.x_max = out.x_max.max(yt[0]);
        out.f_max = out.f_max.max(law.force(yt[0], yt[1]));
    }
    if rising0 && !rising1 {
        // the peak is where dF̄/dτ changes sign; F̄ is flat there, so locating it to 1e-5 of
        // the step (≤ 1e-6 in τ) puts F̄_m within ~1e-12 of its value (F̄'' = O(1); Brent: no
        // second derivative needed)
        let rate = |s: f64| {
            let yp = if s == 0.0 { y } else { step(law, y, k0, s).0 };
            law.force_rate(yp[0], yp[1], -law.drive(yp[0], yp[1]))
        };
        let (r0, r1) = (rate(0.0), rate(h));
        let s = if r0 > 0.0 && r1 <= 0.0 {
            brent(rate, 0.0, h, r0, r1, 1e-5 * h)
        } else {
            h
        };
        let yp = step(law, y, k0, s).0;
        out.f_max = out.f_max.max(law.force(yp[0], yp[1]));
    }
}

#[cfg(test)]
mod tests {
    use super::dop853::*;
    use differential_equations::tableau::ButcherTableau;

    #[test]
    fn tableau_is_the_crates() {
        let t = ButcherTableau::<f64, 12, 16>::dop853();
        for (i, row) in A.iter().enumerate() {
            assert_eq!(row[..], t.a[i][..12], "a[{i}]");
        }
        assert_eq!(B, t.b);
        assert_eq!(C[..], t.c[..12]);
        assert_eq!(Some(BH), t.bh);
        assert_eq!(Some(ER), t.er);
    }
}
