//! The lanes' `exp` and `atan2` against libm's, `cbrt` against `wide`'s, and the same bits in
//! every lane type.

use super::super::lane::{LANES, Lane};
use super::{
    atan2, cbrt, cos_sinc_sq, cos_sinc_sq_estrin, exp, exp_estrin, exp_m1_small, exp_small,
    exp_small_estrin, ln_guess,
};
use wide::f64x4;

/// splitmix64 as a unit stream: the same points on every run.
fn units(seed: u64, n: usize) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// The distance from `got` to `want` in units of `want`'s last place.
fn ulps(got: f64, want: f64) -> f64 {
    if got == want {
        return 0.0;
    }
    let ulp = want.abs().next_up() - want.abs();
    (got - want).abs() / ulp.max(f64::from_bits(1))
}

/// The function applied four at a time through the portable lane type.
fn in_lanes(xs: &[f64], f: impl Fn(f64x4) -> f64x4) -> Vec<f64> {
    xs.chunks(LANES)
        .flat_map(|c| {
            let a = std::array::from_fn(|i| c[i.min(c.len() - 1)]);
            f(f64x4::from_array(a)).to_array()[..c.len()].to_vec()
        })
        .collect()
}

fn exp_arguments() -> Vec<f64> {
    let mut xs: Vec<f64> = units(7, 200_000)
        .iter()
        .map(|u| -745.0 + 1454.0 * u)
        .collect();
    xs.extend(units(8, 50_000).iter().map(|u| (u - 0.5) * 4.0));
    xs.extend(units(9, 50_000).iter().map(|u| (u - 0.5) * 1e-6));
    xs.extend([
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5 * std::f64::consts::LN_2,
        709.7,
        -708.3,
    ]);
    xs
}

/// The largest distance in ulp from `got[i]` to `want[i]`.
fn worst_ulps(got: &[f64], want: &[f64]) -> f64 {
    got.iter()
        .zip(want)
        .map(|(&g, &w)| ulps(g, w))
        .fold(0.0, f64::max)
}

/// `f`, named `name`, is libm's exp to 2 ulp over `exp_arguments` (where eˣ is normal), and
/// past the range 0, ∞ and NaN as libm's: `exp`'s test and `exp_estrin`'s.
fn assert_exp_is_libms(name: &str, f: impl Fn(f64x4) -> f64x4) {
    let xs = exp_arguments();
    let got = in_lanes(&xs, &f);
    let worst = xs
        .iter()
        .zip(&got)
        .filter(|(x, _)| x.exp() >= f64::MIN_POSITIVE)
        .map(|(x, g)| (ulps(*g, x.exp()), *x))
        .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a });
    assert!(worst.0 <= 2.0, "{name}({}) off by {} ulp", worst.1, worst.0);
    // past the range: 0, ∞ and NaN as libm's
    let edges = in_lanes(&[-800.0, -1e300, 800.0, f64::NAN], f);
    assert_eq!(edges[..3], [0.0, 0.0, f64::INFINITY], "{name}");
    assert!(edges[3].is_nan(), "{name}");
}

#[test]
fn exp_is_libms_to_two_ulp() {
    assert_exp_is_libms("exp", exp);
}

fn atan2_arguments() -> Vec<(f64, f64)> {
    let (a, b) = (units(11, 200_000), units(12, 200_000));
    let mut p: Vec<(f64, f64)> = a
        .iter()
        .zip(&b)
        .map(|(u, w)| {
            let angle = (u - 0.5) * 2.0 * std::f64::consts::PI;
            let r = 10f64.powf(-6.0 + 12.0 * w);
            (r * angle.sin(), r * angle.cos())
        })
        .collect();
    // far from the diagonal too: |y/x| up to 1e12 either way
    p.extend(a.iter().zip(&b).take(50_000).map(|(u, w)| {
        let ratio = 10f64.powf(-12.0 + 24.0 * u);
        (
            if *w < 0.5 { ratio } else { -ratio },
            if *u < 0.3 { -1.0 } else { 1.0 },
        )
    }));
    p.extend([
        (0.0, 1.0),
        (1.0, 0.0),
        (0.0, -1.0),
        (-1.0, 0.0),
        (1.0, 1.0),
        (-1.0, -1.0),
    ]);
    p.extend([
        (0.0, 0.0),
        (-0.0, 0.0),
        (0.0, -0.0),
        (-0.0, -0.0),
        (0.66, 1.0),
        (1.0, 0.66),
    ]);
    p
}

#[test]
fn atan2_is_libms_to_two_ulp() {
    let p = atan2_arguments();
    let ys: Vec<f64> = p.iter().map(|q| q.0).collect();
    let xs: Vec<f64> = p.iter().map(|q| q.1).collect();
    let packed: Vec<f64> = ys.iter().chain(&xs).copied().collect();
    let n = ys.len();
    let got: Vec<f64> = (0..n)
        .step_by(LANES)
        .flat_map(|i| {
            let pick = |off: usize| std::array::from_fn(|k| packed[off + (i + k).min(n - 1)]);
            let out = atan2(f64x4::from_array(pick(0)), f64x4::from_array(pick(n)));
            out.to_array()[..LANES.min(n - i)].to_vec()
        })
        .collect();
    for ((y, x), g) in p.iter().zip(&got) {
        let want = y.atan2(*x);
        assert!(
            ulps(*g, want) <= 2.0 && g.is_sign_negative() == want.is_sign_negative(),
            "atan2({y}, {x}) = {g}, libm {want}: {} ulp",
            ulps(*g, want)
        );
    }
}

/// Arguments for ∛: every binade from subnormals to 1e300 either sign, the kernel's range
/// (Cardano's u from ±1e-12 to ±1e30), and the edges (±0, ±∞, NaN, the smallest normal).
fn cbrt_arguments() -> Vec<f64> {
    let mut xs: Vec<f64> = units(13, 200_000)
        .iter()
        .zip(units(14, 200_000))
        .map(|(u, w)| {
            let x = 10f64.powf(-320.0 + 620.0 * u);
            if w < 0.5 { -x } else { x }
        })
        .collect();
    xs.extend(units(15, 50_000).iter().map(|u| (u - 0.5) * 1e3));
    xs.extend([
        0.0,
        -0.0,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
        f64::from_bits(1),
        f64::MAX,
        1.0,
        -8.0,
        27.0,
    ]);
    xs
}

/// The lanes' ∛ is `wide`'s, bit for bit (the kernel's answers, and the Monte Carlo's, kept
/// when the lanes took it over from `wide`'s call).
#[test]
fn cbrt_is_wides_bit_for_bit() {
    let xs = cbrt_arguments();
    let got = in_lanes(&xs, cbrt);
    let want = in_lanes(&xs, f64x4::cbrt);
    for ((x, g), w) in xs.iter().zip(&got).zip(&want) {
        assert_eq!(g.to_bits(), w.to_bits(), "cbrt({x:e}) = {g:e}, wide {w:e}");
    }
    // and ∛ itself to 2 ulp of libm's where normal
    for (x, g) in xs.iter().zip(&got) {
        if x.is_finite() && x.abs() >= f64::MIN_POSITIVE {
            assert!(
                ulps(*g, x.cbrt()) <= 2.0,
                "cbrt({x:e}) = {g:e}, libm {}",
                x.cbrt()
            );
        }
    }
}

/// The AVX lane type gives the portable one's bits, function by function (the whole kernel:
/// tests/physics/map_lanes.rs `avx2_and_portable_kernels_agree_bit_for_bit`).
#[cfg(target_arch = "x86_64")]
#[test]
fn avx_and_portable_math_agree_bit_for_bit() {
    use super::super::avx::Avx;
    if !std::arch::is_x86_feature_detected!("avx2") {
        eprintln!("no AVX2 on this CPU: nothing to compare");
        return;
    }
    #[target_feature(enable = "avx2")]
    fn both(a: [f64; LANES], b: [f64; LANES]) -> [[f64; LANES]; 5] {
        let (x, y) = (Avx::from_array(a), Avx::from_array(b));
        let (s, c) = x.sin_cos();
        [
            exp(x).to_array(),
            atan2(x, y).to_array(),
            s.to_array(),
            c.to_array(),
            cbrt(x).to_array(),
        ]
    }
    let mut xs = exp_arguments();
    xs.extend(cbrt_arguments());
    let ys: Vec<f64> = atan2_arguments()
        .iter()
        .map(|q| q.1)
        .cycle()
        .take(xs.len())
        .collect();
    for (a, b) in xs.chunks_exact(LANES).zip(ys.chunks_exact(LANES)) {
        let (a, b): ([f64; LANES], [f64; LANES]) = (a.try_into().unwrap(), b.try_into().unwrap());
        // SAFETY: the CPU has AVX2, just checked
        let avx = unsafe { both(a, b) };
        let (x, y) = (f64x4::from_array(a), f64x4::from_array(b));
        let (s, c) = x.sin_cos();
        let portable = [exp(x), atan2(x, y), s, c, cbrt(x)].map(|r| r.to_array());
        let bits = |r: [[f64; LANES]; 5]| r.map(|a| a.map(f64::to_bits));
        assert_eq!(bits(avx), bits(portable), "at {a:?}, {b:?}");
    }
}

/// `exp_m1_small` is libm's `exp_m1` to 2 ulp over |x| < 1e-3 (where the kernel takes it:
/// the short contacts' e^{rτ} − 1), sub-normal arguments and ±0 included; e^x − 1 by
/// subtraction would be off by up to ε/|x| relative there.
#[test]
fn exp_m1_small_is_libms_to_two_ulp() {
    let mut xs: Vec<f64> = units(31, 100_000)
        .iter()
        .map(|u| (u - 0.5) * 2e-3)
        .collect();
    xs.extend(
        units(32, 20_000)
            .iter()
            .map(|u| 10f64.powf(-300.0 + 297.0 * u)),
    );
    xs.extend([0.0, -0.0, 1e-310, -1e-310, 9.99e-4, -9.99e-4]);
    let got = in_lanes(&xs, exp_m1_small);
    let want: Vec<f64> = xs.iter().map(|x| x.exp_m1()).collect();
    let worst = worst_ulps(&got, &want);
    assert!(worst <= 2.0, "{worst} ulp");
}

/// `ln_guess` is ln x to 2e-8 (absolute; its series leaves 1.1e-8, and ln x is at most 710)
/// over x from 1e-300 to 1e300 and around 1 (where its fraction d is near 0.5 or 1): a start
/// for Householder's steps, held to the error its series leaves.
#[test]
fn ln_guess_is_ln_to_2e_8() {
    let mut xs: Vec<f64> = units(33, 50_000)
        .iter()
        .map(|u| 10f64.powf(-300.0 + 600.0 * u))
        .collect();
    xs.extend(units(34, 10_000).iter().map(|u| 0.5 + 1.5 * u));
    xs.extend([1.0, 2.0, 0.5, 1.0 + f64::EPSILON, 1.0 - f64::EPSILON / 2.0]);
    let got = in_lanes(&xs, ln_guess);
    for (&x, &g) in xs.iter().zip(&got) {
        assert!((g - x.ln()).abs() <= 2e-8, "ln {x}: {g} vs {}", x.ln());
    }
}

/// `cos_sinc_sq` of x² ≥ 0 is (cos x, sin(x)/x) and of −y² (cosh y, sinh(y)/y), each within
/// 2 ulp of libm's over |x|, |y| ≤ 1/16 (`flow::SMALL`, the short steps' reach).
#[test]
fn cos_sinc_sq_is_cosh_and_sinhc_too() {
    let xs: Vec<f64> = units(35, 20_000).iter().map(|u| u / 16.0).collect();
    let sq: Vec<f64> = xs.iter().map(|x| x * x).collect();
    let neg: Vec<f64> = sq.iter().map(|s| -s).collect();
    let first = |x2: f64x4| cos_sinc_sq(x2).0;
    let second = |x2: f64x4| cos_sinc_sq(x2).1;
    let sinc = |x: f64| if x == 0.0 { 1.0 } else { x.sin() / x };
    let sinhc = |x: f64| if x == 0.0 { 1.0 } else { x.sinh() / x };
    let want: [(Vec<f64>, Vec<f64>); 4] = [
        (in_lanes(&sq, first), xs.iter().map(|x| x.cos()).collect()),
        (in_lanes(&sq, second), xs.iter().map(|&x| sinc(x)).collect()),
        (in_lanes(&neg, first), xs.iter().map(|x| x.cosh()).collect()),
        (
            in_lanes(&neg, second),
            xs.iter().map(|&x| sinhc(x)).collect(),
        ),
    ];
    for (k, (got, want)) in want.iter().enumerate() {
        let worst = worst_ulps(got, want);
        assert!(worst <= 2.0, "function {k}: {worst} ulp");
    }
}

/// The flattening's sums by Estrin's scheme (`Sums` for `Estrin`): `exp_estrin` is libm's to
/// 2 ulp over `exp`'s arguments, as `exp` is; `exp_small_estrin` and `cos_sinc_sq_estrin` are
/// the Horner sums to 2 ulp over the short steps' reach (|x| ≤ 1/16, x² of either sign).
#[test]
fn estrin_sums_are_horners_to_two_ulp() {
    assert_exp_is_libms("exp_estrin", exp_estrin);
    let small: Vec<f64> = units(36, 20_000).iter().map(|u| (u - 0.5) / 8.0).collect();
    let sq: Vec<f64> = small.iter().map(|x| x * x.abs()).collect();
    let pairs: [(Vec<f64>, Vec<f64>); 3] = [
        (
            in_lanes(&small, exp_small_estrin),
            in_lanes(&small, exp_small),
        ),
        (
            in_lanes(&sq, |x2| cos_sinc_sq_estrin(x2).0),
            in_lanes(&sq, |x2| cos_sinc_sq(x2).0),
        ),
        (
            in_lanes(&sq, |x2| cos_sinc_sq_estrin(x2).1),
            in_lanes(&sq, |x2| cos_sinc_sq(x2).1),
        ),
    ];
    for (k, (got, want)) in pairs.iter().enumerate() {
        let worst = worst_ulps(got, want);
        assert!(worst <= 2.0, "sum {k}: {worst} ulp");
    }
}
