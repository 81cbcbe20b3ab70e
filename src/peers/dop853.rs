//! One step of Dormand and Prince's 8(5,3) pair (DOP853; Hairer, Nørsett & Wanner, *Solving
//! ODEs I*, §II.10, and their dop853.f) for a two-number state, with Hairer's combined error
//! estimate. The coefficients are the `differential-equations` crate's.

// DOP853's coefficients as constants, so that the stage loops unroll with the zeros folded
// away; printed from `differential_equations::tableau::ButcherTableau::dop853()` in shortest
// round-trip form, and `tests::tableau_is_the_crates` holds them equal to it.
#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::approx_constant)]
mod tableau {
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
use crate::solver::roots::brent;
use tableau::{A, B, BH, C, ER};

/// Relative and absolute tolerance per step, in normalized units (x, x' of order 1). With the
/// 8th-order pair every COR comes out within 1e-10 of its closed form and the peaks within
/// 1e-11 (tests/physics/peers.rs), well inside the 1e-9 the calibration promises. 1e-13 gave one more
/// digit for 20 % more time; 1e-12 is what brings one Hunt–Crossley impact under the 10 µs of
/// BENCHMARKS.md.
pub const TOL: f64 = 1e-12;

/// One DOP853 step of y' = f(t, y) from (t, y), with f(t, y) = `k0`, of size `h`: the new
/// state and the scaled error estimate (≤ 1 accepts).
pub fn step_with(
    f: &impl Fn(f64, [f64; 2]) -> [f64; 2],
    (t, y): (f64, [f64; 2]),
    k0: [f64; 2],
    h: f64,
) -> ([f64; 2], f64) {
    let mut k = [[0.0; 2]; 12];
    k[0] = k0;
    // fixed bounds (A is zero on and above the diagonal, k zero beyond the stage) let the
    // compiler unroll both loops and drop the zero coefficients
    for i in 1..12 {
        let (mut s0, mut s1) = (0.0, 0.0);
        for j in 0..12 {
            if A[i][j] != 0.0 {
                s0 += A[i][j] * k[j][0];
                s1 += A[i][j] * k[j][1];
            }
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

/// The quintic Hermite interpolant of x over a step, from x, x', x'' at both ends: (x, x', x'')
/// anywhere in the step to O(h⁶), O(h⁵), O(h⁴). Used to locate the turning point and the peak
/// force without re-taking steps (each root then costs one real step, not a dozen).
pub struct Hermite {
    /// x(θ h) = Σ c_i θ^i.
    c: [f64; 6],
    h: f64,
}

impl Hermite {
    /// From the step's ends: y = (x, x') with f(y) = k0 at the start, y1 and x'' = a1 at the end.
    pub fn new((y0, k0): ([f64; 2], [f64; 2]), y1: [f64; 2], a1: f64, h: f64) -> Hermite {
        let (x0, v0, a0) = (y0[0], h * y0[1], h * h * k0[1]);
        let (x1, v1, a1) = (y1[0], h * y1[1], h * h * a1);
        // x(θ) with x, x', x'' matching at θ = 0 and 1
        let d = x1 - x0 - v0 - 0.5 * a0;
        let e = v1 - v0 - a0;
        let f = a1 - a0;
        let c3 = 10.0 * d - 4.0 * e + 0.5 * f;
        let c4 = -15.0 * d + 7.0 * e - f;
        let c5 = 6.0 * d - 3.0 * e + 0.5 * f;
        Hermite {
            c: [x0, v0, 0.5 * a0, c3, c4, c5],
            h,
        }
    }

    /// (x, x', x'') at τ = s into the step.
    pub fn at(&self, s: f64) -> [f64; 3] {
        let (t, c, h) = (s / self.h, &self.c, self.h);
        let x = c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * (c[4] + t * c[5]))));
        let dx = c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * (4.0 * c[4] + t * 5.0 * c[5])));
        let ddx = 2.0 * c[2] + t * (6.0 * c[3] + t * (12.0 * c[4] + t * 20.0 * c[5]));
        [x, dx / h, ddx / (h * h)]
    }

    /// Where `g` of the interpolated (x, x', x'') falls from > 0 to ≤ 0 in (0, h]; h when it
    /// does not change sign on the interpolant.
    pub fn root(&self, g: impl Fn([f64; 3]) -> f64, h: f64) -> f64 {
        let f = |s: f64| g(self.at(s));
        let (g0, g1) = (f(0.0), f(h));
        if g0 > 0.0 && g1 <= 0.0 {
            brent(f, 0.0, h, g0, g1, 1e-14 * h)
        } else {
            h
        }
    }
}

#[cfg(test)]
mod tests {
    use super::tableau::*;
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
