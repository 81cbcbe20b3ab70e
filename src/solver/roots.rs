//! Bracketed root finding for event location (the phase switch z' = 0, the end of contact
//! F = 0). Why hand-written: both solvers call these inside their event loops with `FnMut`
//! closures over an interpolant or an exact flow; they must not allocate and must always
//! terminate with a bracketed answer, which is a dozen lines each.

/// Safeguarded Newton (Numerical Recipes' rtsafe): `f` returns (g, g'); [a, b] must bracket a
/// sign change. Falls back to bisection whenever Newton would leave the bracket or stall.
pub fn newton_bracketed(mut f: impl FnMut(f64) -> (f64, f64), a: f64, b: f64) -> f64 {
    let (ga, gb) = (f(a).0, f(b).0);
    newton_bracketed_from(f, (a, ga), (b, gb))
}

/// `newton_bracketed` when g is already known at both ends: Halley's iteration with g'' = 0.
pub fn newton_bracketed_from(
    mut f: impl FnMut(f64) -> (f64, f64),
    a: (f64, f64),
    b: (f64, f64),
) -> f64 {
    halley_bracketed_from(
        |x| {
            let (g, dg) = f(x);
            (g, dg, 0.0)
        },
        a,
        b,
    )
}

/// Safeguarded Halley (after Numerical Recipes' rtsafe): `f` returns (g, g', g''); [a, b]
/// must bracket a sign change, with g known at both ends. Cubic convergence where Newton's is
/// quadratic, which saves evaluations when each one costs exponentials; falls back to
/// bisection whenever a step would leave the bracket or stall. It starts from the secant
/// point (the step ends are close to the root's scale already) and stops as soon as a step is
/// below the resolution of x (such a step would land on a bracket end, look "outside", and
/// send the iteration off bisecting).
pub fn halley_bracketed_from(
    mut f: impl FnMut(f64) -> (f64, f64, f64),
    (mut a, ga): (f64, f64),
    (mut b, gb): (f64, f64),
) -> f64 {
    let rising = ga < 0.0;
    let secant = a - ga * (b - a) / (gb - ga);
    let mut x = if secant > a.min(b) && secant < a.max(b) {
        secant
    } else {
        0.5 * (a + b)
    };
    let mut last_step = (b - a).abs();
    for _ in 0..100 {
        let (g, dg, ddg) = f(x);
        if g == 0.0 {
            return x;
        }
        if (g < 0.0) == rising {
            a = x;
        } else {
            b = x;
        }
        let newton = if dg != 0.0 { g / dg } else { f64::INFINITY };
        if newton.abs() <= 2.0 * f64::EPSILON * x.abs() {
            return x;
        }
        let denom = 1.0 - 0.5 * newton * ddg / dg;
        let halley = if denom > 0.5 { newton / denom } else { newton };
        let next = x - halley;
        let inside = (next - a) * (next - b) < 0.0;
        let step = if inside && halley.abs() < 0.5 * last_step {
            halley
        } else {
            x - 0.5 * (a + b)
        };
        last_step = step.abs();
        x -= step;
        if step.abs() <= 2.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE)
            || (b - a).abs() <= 4.0 * f64::EPSILON * x.abs()
        {
            return x;
        }
    }
    x
}

/// The first of several watched functions to rise through 0 within a step [t0, t1]: each
/// g_i that is below 0 at t0 (`g0[i]`) and at or above it at t1 (`g1[i]`) is located by
/// [`brent`] on `g(i, t)` (an integrator's dense output), and the earliest is returned with its
/// index. The events of the compliant target's chain and of the two-ball pair
/// (`target::numeric`, `target::pair`).
pub fn first_rising<const N: usize>(
    g0: [f64; N],
    g1: [f64; N],
    t0: f64,
    t1: f64,
    mut g: impl FnMut(usize, f64) -> f64,
) -> Option<(f64, usize)> {
    let mut best: Option<(f64, usize)> = None;
    for i in 0..N {
        if g0[i] < 0.0 && g1[i] >= 0.0 {
            let tc = brent(
                |t| g(i, t),
                t0,
                t1,
                g0[i],
                g1[i],
                1e-15 * t1.abs().max(1e-300),
            );
            if best.is_none_or(|(bt, _)| tc < bt) {
                best = Some((tc, i));
            }
        }
    }
    best
}

/// Brent–Dekker on [a, b] with g(a), g(b) of opposite signs (or one zero).
pub fn brent(mut f: impl FnMut(f64) -> f64, a: f64, b: f64, fa: f64, fb: f64, tol: f64) -> f64 {
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let q0 = fa / fc;
                let r = fb / fc;
                (
                    s * (2.0 * m * q0 * (q0 - r) - (b - a) * (r - 1.0)),
                    (q0 - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = d;
            }
        } else {
            d = m;
            e = d;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = f(b);
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn newton_stops_once_converged() {
        let mut calls = 0;
        let r = newton_bracketed(
            |x| {
                calls += 1;
                (x * x - 2.0, 2.0 * x)
            },
            1.0,
            2.0,
        );
        assert!((r - 2f64.sqrt()).abs() <= 2.0 * f64::EPSILON);
        assert!(calls <= 8, "{calls} evaluations");
    }

    #[test]
    fn halley_finds_roots_in_few_steps() {
        let mut calls = 0;
        let r = halley_bracketed_from(
            |x| {
                calls += 1;
                (x.cos(), -x.sin(), -x.cos())
            },
            (1.0, 1f64.cos()),
            (2.0, 2f64.cos()),
        );
        assert!((r - std::f64::consts::FRAC_PI_2).abs() <= 4.0 * f64::EPSILON);
        assert!(calls <= 5, "{calls} evaluations");
    }

    #[test]
    fn both_find_cos_root() {
        let r = newton_bracketed(|x| (x.cos(), -x.sin()), 1.0, 2.0);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let r = brent(f64::cos, 1.0, 2.0, 1f64.cos(), 2f64.cos(), 1e-15);
        assert!((r - std::f64::consts::FRAC_PI_2).abs() < 1e-14);
    }
}
