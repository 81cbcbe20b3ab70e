//! Flattening cells four or eight at a time (issue 30 item 2): `map::fast::flattening`'s
//! closed form (src/map/fast/flatten.rs says what it computes) over any [`Lane`], lane by lane
//! and masked, so a lane's answer is a function of its own (λ, ζ, z̄_p) only.
//!
//! The loading is the lanes' own flow (`Flow4::new`, the kernel's cubic by Cardano and
//! Newton), its turn τ_m from the pair's phase atan2(P, −Q) by Householder's steps; the turn's
//! values (z̄_m, z̄''(τ_m), ∫₀^τ_m z̄) from the last jet by Taylor's series, as the scalar path
//! takes them. The unloading is the same cubic at (λ/k, ζ√k) from the state (u0, 0, u2)
//! (`Unload::from_state` in `lanes/unload.rs`: `solver::modes::Modes::coefficients`' A, B, D), its
//! separation from the pair's first zero of u past the phase 0 (`search::separation_guess`),
//! refined the same way.
//! The rounding bounds — the turn's, the unloading's own (the scalar `tight` bound), and the
//! turn's errors carried to s_f by the flow's responses — decide `KEEP` as masks.
//!
//! A lane is handed back (`None`; [`crate::map::fast::lanes::flattenings`] asks the scalar `flattening`) where the
//! loading's pair part of z̄' starts negative (P ≤ 0) or either pair does not oscillate (three
//! real roots), where a refinement does not settle on a falling crossing within its lobe
//! (the scalar path's bracket search: reloads, long steps), and where the bound cannot keep
//! `KEEP`. A lane's answer agrees with the scalar `flattening` to 1e-12, not bit for bit: the
//! exponential, `atan2` and `cbrt` are the lanes' (`math.rs`), and the flows' sums and steps
//! are `math::Estrin`'s (tests/physics/map_flatten_lanes.rs) — a lone cell (`flattening_one`) is one
//! dependent chain, shortened where a series, a quotient by a constant or by ω stood on it.

use super::super::lane::{LANES, Lane};
use super::super::math::{Estrin, atan2};
use super::{Flow4, Point4, Root4, answers, householder_root, taylor};
use crate::map::fast::{KEEP, Summary, flattening};
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2, PI};
use wide::f64x4;

#[path = "unload.rs"]
mod unload;
use unload::Unload;

/// `Flow::derivative_rounding` of the loading (B = −A: B's scale is A's).
#[inline(always)]
fn derivative_rounding<L: Lane>(f: &Flow4<L, Estrin>, pt: &Point4<L>, k: usize) -> L {
    let v = L::splat;
    let (one, t) = (v(1.0), pt.t);
    let (cm, sm) = (pt.decay, pt.decay * t.min(one / f.omega));
    let real = pt.real * (one + f.r.abs() * t);
    let rho = f.sigma.abs() + f.omega2.abs().sqrt();
    let grow = one + rho * t;
    let (cm, sm) = (cm * grow, sm * grow);
    let [ar, c, s] = f.jet[k];
    let [sa, sd, _, _] = f.size;
    let (mut pr, mut pp) = (one, one);
    for _ in 0..k {
        (pr, pp) = (pr * f.r.abs(), pp * (one + rho));
    }
    let terms = ar.abs() * real + c.abs() * cm + s.abs() * sm;
    let carried = sa * pr * real + (sa * cm + sd * sm) * pp;
    v(f64::EPSILON) * (terms + carried)
}

/// The loading's τ_m guess: the pair's first zero of z̄' at the phase atan2(P, −Q)
/// (`search::peak_point`), and the lanes where P > 0.
#[inline(always)]
fn peak_guess<L: Lane>(f: &Flow4<L, Estrin>) -> (Point4<L>, L) {
    // x/ω as x·(1/ω) (`Flow4::inv_omega`, formed off the chain), and one 1/√(P² + Q²)
    let inv_w = f.inv_omega;
    let p = f.d + f.sigma * f.a;
    let q = (f.a * f.omega2 - f.sigma * f.d) * inv_w;
    let theta_m = atan2(p, -q);
    let inv_norm = L::splat(1.0) / (p * p + q * q).sqrt();
    (
        f.at_phase(theta_m * inv_w, -q * inv_norm, p * inv_norm),
        p.gt(L::splat(0.0)),
    )
}

/// The unloading's separation guess: the pair part of u, e^{−σs}(B cos ωs + (D/ω) sin ωs),
/// at its first zero past the phase 0 (`search::separation_guess(flow, 0)`).
#[inline(always)]
fn separation_guess<L: Lane>(f: &Flow4<L, Estrin>) -> Point4<L> {
    let v = L::splat;
    let (one, inv_w) = (v(1.0), f.inv_omega);
    let [_, b, d] = f.jet[0];
    let flip = d.lt(v(0.0)).select(v(-1.0), one);
    let (a, dw) = (-flip * b, flip * d * inv_w);
    let theta = atan2(a, dw);
    let k = (-theta * v(FRAC_1_PI)).floor() + one;
    let odd = (k - v(2.0) * (v(0.5) * k).floor()).ne(v(0.0));
    let norm_f = odd.select(v(-1.0), one) / (a * a + dw * dw).sqrt();
    f.at_phase((theta + k * v(PI)) * inv_w, dw * norm_f, a * norm_f)
}

/// `search::refine`: the root of z̄^{(k)} (k = 1: τ_m, k = 0: separation) from its guess by
/// Householder's steps ([`householder_root`]), and the lanes where it settled within a
/// quarter of the pair's period of its guess.
#[inline(always)]
fn refine<L: Lane>(f: &Flow4<L, Estrin>, guess: Point4<L>, live: L, k: usize) -> (Root4<L>, L) {
    let v = L::splat;
    let (root, found) = householder_root(f, guess, live, k);
    let lobe = (root.t - guess.t).le(v(FRAC_PI_2) / f.omega);
    (root, found & lobe)
}

/// The loading's turn: τ_m's root, z̄_m, z̄''(τ_m), ∫₀^τ_m z̄, and the bounds on the rounding
/// of z̄_m, z̄'(τ_m), z̄''(τ_m) and the integral (`flatten::turn`), and the lanes where it holds.
struct Turn<L: Lane> {
    t: L,
    z_m: L,
    z2: L,
    integral: L,
    dz: [L; 3],
    dint: L,
}

#[inline(always)]
fn turn<L: Lane>(lambda: L, zeta: L, live: L) -> (Turn<L>, L) {
    let v = L::splat;
    let (load, ok) = Flow4::<L, Estrin>::new(lambda, zeta);
    let (guess, pos) = peak_guess(&load);
    let (peak, found) = refine(&load, guess, live & ok & pos, 1);
    let (h, j) = (peak.t - peak.point.t, &peak.jet);
    let (dz_m, dint) = load.rounding(&peak.point);
    let top = Turn {
        t: peak.t,
        z_m: taylor::<L, Estrin>(&j[0..5], h),
        z2: taylor::<L, Estrin>(&[j[2], j[3], j[4], j[5], v(0.0)], h),
        integral: taylor::<L, Estrin>(&[load.integral(&peak.point), j[0], j[1], j[2], j[3]], h),
        dz: [
            dz_m,
            derivative_rounding(&load, &peak.point, 1),
            derivative_rounding(&load, &peak.point, 2),
        ],
        dint,
    };
    (top, live & ok & pos & found)
}

/// The body of the lane functions: N flattening cells in one `L` of N lanes, lane i
/// `flattening(lambda[i], zeta[i], zp[i])` to 1e-12 where it answers, `None` where it hands
/// the lane back (the module's introduction).
#[inline(always)]
pub fn flatten_kernel<L: Lane<Array = [f64; N]>, const N: usize>(
    lambda: [f64; N],
    zeta: [f64; N],
    zp: [f64; N],
) -> [Option<Summary>; N] {
    let v = L::splat;
    let (l, z, zp) = (
        L::from_array(lambda),
        L::from_array(zeta),
        L::from_array(zp),
    );
    let valid = l.gt(v(0.0)) & z.gt(v(0.0)) & zp.gt(v(0.0));
    let valid = valid & l.is_finite() & z.is_finite() & zp.is_finite();
    // a lane left out computes a harmless ball (λ = 1, ζ = 0.1, flattening at 0.5)
    let (l, z, zp) = (
        valid.select(l, v(1.0)),
        valid.select(z, v(0.1)),
        valid.select(zp, v(0.5)),
    );
    let (top, live) = turn(l, z, valid);
    let live = live & top.z_m.gt(zp) & top.z2.lt(v(0.0));
    // Eqs. 18–19: z̄_f = z̄_m − z̄_r, z̄_r = z̄_p √(2z̄_m/z̄_p − 1); the unloading F̄ = k u
    let z_m = live.select(top.z_m, v(1.0));
    let zp = live.select(zp, v(0.5));
    let z_r = zp * (v(2.0) * z_m / zp - v(1.0)).sqrt();
    let u0 = z_m - (z_m - z_r).max(v(0.0));
    let k = z_m / u0;
    let (root_k, u2) = (k.sqrt(), live.select(top.z2, v(-1.0)) / k);
    let (unload, ok) = Unload::from_state(l / k, z * root_k, u0, u2);
    let live = live & ok;
    let (end, found) = refine(&unload.flow, separation_guess(&unload.flow), live, 0);
    let (he, je) = (end.t - end.point.t, &end.jet);
    let int_u = taylor::<L, Estrin>(
        &[unload.integral(&end.point), je[0], je[1], je[2], je[3]],
        he,
    );
    let cor = top.integral + root_k * int_u - v(1.0);
    let tau_f = top.t + end.t / root_k;
    // the rounding bounds as `flatten::flattening` forms them: the unloading's own, and the
    // turn's errors in u0 (twice z̄_m's) and u2 carried to s_f
    let [dz_m, dz1, dz2] = top.dz;
    let (du_f, dint_u) = unload.rounding(&end.point);
    let [c0, c2] = unload.responses(v(2.0) * dz_m, dz2 / k, &end.point);
    let du_f = du_f + c0.0.abs() + c2.0.abs();
    let dint_u = dint_u + c0.1.abs() + c2.1.abs();
    let slope = taylor::<L, Estrin>(&je[1..6], he).abs();
    let dtau = du_f / slope / root_k + dz1 / top.z2.abs();
    let keep = v(KEEP);
    let precise = dz_m.le(keep * top.z_m)
        & (top.dint + root_k * dint_u).le(keep * cor.abs())
        & dtau.le(keep * tau_f);
    let answered = (live & found & precise & cor.is_finite() & tau_f.is_finite()).bitmask();
    answers(answered, cor, top.z_m, tau_f)
}

/// Four flattening cells at once, the lanes' own answers (`None` where a lane is handed
/// back): with AVX2 and FMA one AVX register, elsewhere `wide`'s `f64x4`; each lane the bits of
/// [`flattening_lanes8`]'s (a `Pair`'s half runs the operations it would alone). The Monte
/// Carlo's groups of four take it (`analysis::mc_impact`).
pub fn flattening_lanes4(
    lambda: [f64; LANES],
    zeta: [f64; LANES],
    zp: [f64; LANES],
) -> [Option<Summary>; LANES] {
    #[cfg(target_arch = "x86_64")]
    if super::super::avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA, just checked
        return unsafe { flattening_lanes4_avx2(lambda, zeta, zp) };
    }
    flatten_kernel::<f64x4, LANES>(lambda, zeta, zp)
}

/// The kernel on one AVX register, compiled with AVX2 and FMA enabled (the lanes' `mul_add`
/// one `vfmadd`, inlined: without FMA enabled the intrinsic is a call).
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn flattening_lanes4_avx2(
    lambda: [f64; LANES],
    zeta: [f64; LANES],
    zp: [f64; LANES],
) -> [Option<Summary>; LANES] {
    flatten_kernel::<super::super::avx::Avx, LANES>(lambda, zeta, zp)
}

/// Cells per call of [`flattening_lanes8`]: two registers of [`LANES`].
pub const FLAT_WIDE: usize = 2 * LANES;

/// Eight flattening cells at once, the lanes' own answers (`None` where a lane is handed
/// back): with AVX2 and FMA two AVX registers in one instruction stream (`pair.rs`), elsewhere two
/// calls of the portable kernel; the same bits either way (tests/physics/map_flatten_lanes.rs).
pub fn flattening_lanes8(
    lambda: [f64; FLAT_WIDE],
    zeta: [f64; FLAT_WIDE],
    zp: [f64; FLAT_WIDE],
) -> [Option<Summary>; FLAT_WIDE] {
    #[cfg(target_arch = "x86_64")]
    if super::super::avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA, just checked
        return unsafe { flattening_lanes8_avx2(lambda, zeta, zp) };
    }
    flattening_lanes8_portable(lambda, zeta, zp)
}

/// [`flattening_lanes8`] on the build's own target (`wide`'s `f64x4`), four at a time.
pub fn flattening_lanes8_portable(
    lambda: [f64; FLAT_WIDE],
    zeta: [f64; FLAT_WIDE],
    zp: [f64; FLAT_WIDE],
) -> [Option<Summary>; FLAT_WIDE] {
    let half = |a: &[f64; FLAT_WIDE], k: usize| std::array::from_fn(|i| a[k * LANES + i]);
    let four = |k| flatten_kernel::<f64x4, LANES>(half(&lambda, k), half(&zeta, k), half(&zp, k));
    let (lo, hi) = (four(0), four(1));
    std::array::from_fn(|i| if i < LANES { lo[i] } else { hi[i - LANES] })
}

/// The kernel on a pair of AVX registers, compiled with AVX2 and FMA enabled.
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn flattening_lanes8_avx2(
    lambda: [f64; FLAT_WIDE],
    zeta: [f64; FLAT_WIDE],
    zp: [f64; FLAT_WIDE],
) -> [Option<Summary>; FLAT_WIDE] {
    use super::super::{avx::Avx, pair::Pair};
    flatten_kernel::<Pair<Avx>, FLAT_WIDE>(lambda, zeta, zp)
}

/// Cells a last group at most holds for [`flattenings`] to run them one by one
/// ([`flattening_one`], ≈ 2 030 instructions each) rather than padded to eight (≈ 5 920: three
/// alone would cost more, BENCHMARKS.md "Ninth session (flat9)").
const ALONE: usize = 2;

/// `out[i]` = `flattening(lambda[i], zeta[i], zp[i])` to 1e-12, eight at a time through
/// [`flattening_lanes8`] (a last group of more than `ALONE` padded with its own last cell,
/// a smaller one cell by cell through [`flattening_one`]: the same bits), each lane the lanes
/// hand back the scalar `flattening`'s answer. Slices of equal length.
pub fn flattenings(lambda: &[f64], zeta: &[f64], zp: &[f64], out: &mut [Option<Summary>]) {
    assert!(lambda.len() == zeta.len() && zeta.len() == zp.len() && zp.len() == out.len());
    let pad = |s: &[f64]| -> [f64; FLAT_WIDE] {
        let last = |_| std::array::from_fn(|i| s[i.min(s.len() - 1)]);
        s.try_into().unwrap_or_else(last)
    };
    let groups = lambda
        .chunks(FLAT_WIDE)
        .zip(zeta.chunks(FLAT_WIDE))
        .zip(zp.chunks(FLAT_WIDE));
    for (((l, z), p), o) in groups.zip(out.chunks_mut(FLAT_WIDE)) {
        if o.len() <= ALONE {
            for (i, o) in o.iter_mut().enumerate() {
                *o = flattening_one(l[i], z[i], p[i]);
            }
            continue;
        }
        let (l, z, p) = (pad(l), pad(z), pad(p));
        let lanes = flattening_lanes8(l, z, p);
        for (i, o) in o.iter_mut().enumerate() {
            *o = lanes[i].or_else(|| flattening(l[i], z[i], p[i]));
        }
    }
}

#[path = "one.rs"]
mod one;

/// One flattening cell, the lanes' own answer on a lane of width one (`one.rs`; `None` where
/// the lanes hand it back): any lane of [`flattening_lanes8`] or [`flattening_lanes4`] at the
/// same (λ, ζ, z̄_p), bit for bit, at a cell's cost. With AVX2 and FMA compiled with FMA
/// enabled (`f64::mul_add` one instruction, not libm's `fma`), elsewhere
/// [`flattening_lane1_portable`]: the same bits.
pub fn flattening_lane1(lambda: f64, zeta: f64, zp: f64) -> Option<Summary> {
    #[cfg(target_arch = "x86_64")]
    if super::super::avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA, just checked
        return unsafe { flattening_lane1_fma(lambda, zeta, zp) };
    }
    flattening_lane1_portable(lambda, zeta, zp)
}

/// [`flattening_lane1`] compiled for the build's own target.
pub fn flattening_lane1_portable(lambda: f64, zeta: f64, zp: f64) -> Option<Summary> {
    let [s] = flatten_kernel::<one::One, 1>([lambda], [zeta], [zp]);
    s
}

/// The kernel on one lane, compiled with AVX2 and FMA enabled.
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn flattening_lane1_fma(lambda: f64, zeta: f64, zp: f64) -> Option<Summary> {
    let [s] = flatten_kernel::<one::One, 1>([lambda], [zeta], [zp]);
    s
}

/// A flattening cell alone as [`flattenings`] answers it in any group, bit for bit: the
/// lanes' answer on one lane ([`flattening_lane1`]), else the scalar `flattening`'s. What a
/// lone cell (`map::eval::cell_at`), `run` and a row of `bouncelab.impacts` take.
pub fn flattening_one(lambda: f64, zeta: f64, zp: f64) -> Option<Summary> {
    flattening_lane1(lambda, zeta, zp).or_else(|| flattening(lambda, zeta, zp))
}
