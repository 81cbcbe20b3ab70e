//! Four linear-law impacts per instruction stream: [`super::summary`] in `f64x4` lanes (issue
//! 30 item 3), for the Monte Carlo, `bouncelab.impacts` and anything else that asks for many.
//!
//! The same closed form, the same steps and the same checks as the scalar path, lane by lane
//! (the module's introduction): the cubic's lone real root by Cardano polished by Newton, the
//! pair's own zeros for the first guesses (two `atan2`), Householder's fourth-order steps
//! turning each point by series, the values at the roots by Taylor's series and the rounding
//! bound that decides whether 1e-13 is kept. Each lane runs on its own (masked), so its
//! answer is a function of its own (λ, ζ) only, never of its neighbours: a Monte Carlo sample
//! is the same in any grouping (`same_answer_on_one_thread_and_many`).
//!
//! A lane the common path does not settle — the pair does not oscillate, the pair part of z̄'
//! starts negative, a step too long for the series and the `sin_cos` turn, a root past its
//! lobe (the bracket search's cases), λ or ζ zero, rτ so small that e^{rτ} − 1 needs
//! `exp_m1` — is handed to the scalar [`super::summary`], whole. The transcendental functions
//! are `wide`'s (Cephes and SLEEF polynomials, an ulp or two, the same numbers for a given
//! build on every machine), where the scalar path calls libm's: the answers agree with the
//! scalar path's to 1e-12 (tests/map_lanes.rs), not bit for bit.

use super::Summary;
use super::flow::SMALL;
use super::search::{MAX_REFINE, SETTLED, TAU_MAX};
use std::f64::consts::{FRAC_PI_2, PI};
use wide::f64x4;

/// Impacts per call of [`summary4`].
pub const LANES: usize = 4;

type V = f64x4;

#[inline(always)]
fn v(x: f64) -> V {
    V::splat(x)
}

/// The flow of four (λ, ζ): [`super::flow::Flow`]'s fields, lane by lane.
struct Flow4 {
    size: [V; 4],
    r: V,
    sigma: V,
    omega2: V,
    omega: V,
    a: V,
    d: V,
    p: V,
    q: V,
    jet: [[V; 3]; 6],
}

/// [`super::flow::Point`], lane by lane.
#[derive(Clone, Copy)]
struct Point4 {
    t: V,
    real: V,
    decay: V,
    ec: V,
    es: V,
}

impl Point4 {
    #[inline(always)]
    fn select(mask: V, yes: Point4, no: Point4) -> Point4 {
        Point4 {
            t: mask.select(yes.t, no.t),
            real: mask.select(yes.real, no.real),
            decay: mask.select(yes.decay, no.decay),
            ec: mask.select(yes.ec, no.ec),
            es: mask.select(yes.es, no.es),
        }
    }
}

/// A root lane by lane: τ, the point last evaluated and its jet (as `search::Root`).
#[derive(Clone, Copy)]
struct Root4 {
    t: V,
    point: Point4,
    jet: [V; 6],
}

/// The lone real root of s³ + a2 s² + s + a0 and the deflated quadratic (p1, p0), as
/// `propagator::lone_real_root` gives them (Cardano, then at most four Newton steps that must
/// settle), and the lanes where it answers.
#[inline(always)]
fn lone_real_root(a2: V, a0: V) -> (V, V, V, V) {
    let (one, zero) = (v(1.0), v(0.0));
    let shift = a2 / v(3.0);
    let p = one - a2 * shift;
    let q = (v(2.0) * shift * shift - one) * shift + a0;
    let disc = v(0.25) * q * q + p * p * p / v(27.0);
    let sign = q.is_sign_negative().select(v(-1.0), one);
    let u = (v(-0.5) * q - sign * disc.sqrt()).cbrt();
    let mut ok = disc.simd_gt(zero) & u.simd_ne(zero);
    let mut r = u - p / (v(3.0) * u) - shift;
    let mut done = zero.simd_ne(zero);
    for _ in 0..4 {
        let value = ((r + a2) * r + one) * r + a0;
        let slope = (v(3.0) * r + v(2.0) * a2) * r + one;
        let step = value / slope;
        let next = r - step;
        r = done.select(r, next);
        done |= step.abs().simd_le(v(4.0 * f64::EPSILON) * next.abs());
    }
    ok &= done & r.simd_ne(zero);
    // deflate: the division form where r³ dominates a0, else the multiplication form
    let first = (r.abs() * r.abs() * r.abs()).simd_ge(a0);
    let p0_div = -a0 / r;
    let p1_div = (p0_div - one) / r;
    let p1_mul = a2 + r;
    let p0_mul = one + r * p1_mul;
    (
        r,
        first.select(p1_div, p1_mul),
        first.select(p0_div, p0_mul),
        ok,
    )
}

impl Flow4 {
    /// The flows, and the lanes whose pair oscillates and decays (`Flow::new`'s coefficients,
    /// each of two equal forms the one of smaller terms).
    #[inline(always)]
    fn new(lambda: V, zeta: V) -> (Flow4, V) {
        let (one, zero) = (v(1.0), v(0.0));
        let two_zeta = v(2.0) * zeta;
        let (a2, a0) = (two_zeta * (one + lambda), two_zeta * lambda);
        let (r, p1, p0, mut ok) = lone_real_root(a2, a0);
        let sigma = v(0.5) * p1;
        let omega2 = p0 - sigma * sigma;
        let gap = (r + sigma) * (r + sigma) + omega2;
        ok &= gap.simd_gt(zero) & p0.simd_gt(zero) & omega2.simd_gt(zero);
        let (a_sum, sa_sum) = ((r + a0) / gap, (r.abs() + a0.abs()) / gap.abs());
        let two_sigma = v(2.0) * sigma;
        let a_diff = (two_sigma - two_zeta) / gap;
        let sa_diff = (two_sigma.abs() + two_zeta.abs()) / gap.abs();
        let pick = sa_sum.simd_le(sa_diff);
        let (a, sa) = (pick.select(a_sum, a_diff), pick.select(sa_sum, sa_diff));
        let d_mul = one - (r + sigma) * a;
        let sd_mul = one + (r + sigma).abs() * sa;
        let d_div = (sigma - a0 + a * omega2) / (sigma + r);
        let sd_div = (sigma.abs() + a0 + sa * omega2.abs()) / (sigma + r).abs();
        let pick = sd_mul.simd_le(sd_div);
        let (d, sd) = (pick.select(d_mul, d_div), pick.select(sd_mul, sd_div));
        let b = -a;
        let p = -(d + sigma * b) / p0;
        let sp = (sd + sigma.abs() * sa) / p0;
        let q = b + sigma * p;
        let size = [sa, sd, sp, sa + sigma.abs() * sp];
        let mut jet = [[zero; 3]; 6];
        let (mut ar, mut c, mut s) = (a, -a, d);
        for row in &mut jet {
            *row = [ar, c, s];
            (ar, c, s) = (ar * r, s - sigma * c, -omega2 * c - sigma * s);
        }
        let omega = omega2.sqrt();
        let flow = Flow4 {
            size,
            r,
            sigma,
            omega2,
            omega,
            a,
            d,
            p,
            q,
            jet,
        };
        (flow, ok)
    }

    /// `Flow::at_phase`: the point at τ from (cos ωτ, sin ωτ).
    #[inline(always)]
    fn at_phase(&self, t: V, cos: V, sin: V) -> Point4 {
        let decay = (-self.sigma * t).exp();
        Point4 {
            t,
            real: (self.r * t).exp(),
            decay,
            ec: decay * cos,
            es: decay * sin / self.omega,
        }
    }

    /// `Flow::at` where the pair oscillates.
    #[inline(always)]
    fn at(&self, t: V) -> Point4 {
        let (sin, cos) = (self.omega * t).sin_cos();
        self.at_phase(t, cos, sin)
    }

    /// `Flow::shift`: the point `h` after `pt` by series, and the lanes where every rate × |h|
    /// is within [`SMALL`] (elsewhere the caller takes [`Flow4::at`]).
    #[inline(always)]
    fn shift(&self, pt: &Point4, h: V) -> (Point4, V) {
        let rate = self.r.abs().max(self.sigma.abs()).max(self.omega);
        let fits = (rate * h.abs()).simd_le(v(SMALL));
        let (cos, sinc) = cos_sinc(self.omega * h);
        let (s_h, decay) = (h * sinc, exp_small(-self.sigma * h));
        let ec = pt.ec * cos - self.omega2 * pt.es * s_h;
        let es = pt.es * cos + pt.ec * s_h;
        let point = Point4 {
            t: pt.t + h,
            real: pt.real * exp_small(self.r * h),
            decay: pt.decay * decay,
            ec: ec * decay,
            es: es * decay,
        };
        (point, fits)
    }

    /// (z̄, …, z̄^{(5)}) at a point (`Flow::jet`).
    #[inline(always)]
    fn jet(&self, pt: &Point4) -> [V; 6] {
        std::array::from_fn(|k| {
            let [ar, c, s] = self.jet[k];
            ar * pt.real + c * pt.ec + s * pt.es
        })
    }

    /// `Flow::rounding` where the pair oscillates: (for z̄, for ∫ z̄).
    #[inline(always)]
    fn rounding(&self, pt: &Point4) -> (V, V) {
        let one = v(1.0);
        let t = pt.t;
        let (cm, sm) = (pt.decay, pt.decay * t.min(one / self.omega));
        let real = pt.real * (one + self.r.abs() * t);
        let grow = one + (self.sigma.abs() + self.omega2.abs().sqrt()) * t;
        let (cm, sm) = (cm * grow, sm * grow);
        let k = v(f64::EPSILON);
        let [sa, sd, sp, sq] = self.size;
        let z = sa * (real + cm) + sd * sm;
        let int = sa * (one + real) / self.r.abs();
        let int = int + sp * (one + cm) + sq * sm;
        (k * z, k * int)
    }

    /// `Flow::integral` where |rτ| ≥ 1e-3 (the caller checks).
    #[inline(always)]
    fn integral(&self, pt: &Point4) -> V {
        let real = self.a * (pt.real - v(1.0)) / self.r;
        real + self.p * pt.ec + self.q * pt.es - self.p
    }

    /// `search::phase_guesses` where P > 0: the points at the pair's zeros of z̄' and z̄, and
    /// the lanes where P > 0.
    #[inline(always)]
    fn guesses(&self) -> ([Point4; 2], V) {
        let w = self.omega;
        let p = self.d + self.sigma * self.a;
        let q = (self.a * self.omega2 - self.sigma * self.d) / w;
        let theta_m = p.atan2(-q);
        let flip = self.d.simd_lt(v(0.0)).select(v(-1.0), v(1.0));
        let (a, dw) = (flip * self.a, flip * self.d / w);
        let theta = a.atan2(dw);
        let k = ((theta_m - theta) / v(PI)).floor() + v(1.0);
        let odd = (k - v(2.0) * (v(0.5) * k).floor()).simd_ne(v(0.0));
        let norm_m = (p * p + q * q).sqrt();
        let norm_f = odd.select(v(-1.0), v(1.0)) / (a * a + dw * dw).sqrt();
        let peak = self.at_phase(theta_m / w, -q / norm_m, p / norm_m);
        let end = self.at_phase((theta + k * v(PI)) / w, dw * norm_f, a * norm_f);
        ([peak, end], p.simd_gt(v(0.0)))
    }
}

/// `search::householder`: the step and the lanes where it is the last one on a falling
/// crossing.
#[inline(always)]
fn householder(f: &[V]) -> (V, V) {
    let one = v(1.0);
    let inv = one / f[1];
    let (u, c2, c3) = (f[0] * inv, f[2] * inv, f[3] * inv);
    let h = u * (one - v(0.5) * u * c2) / (one - u * c2 + u * u * c3 / v(6.0));
    let settled = (c2 * h).abs().simd_le(v(SETTLED))
        & (c3.abs() * h * h).simd_le(v(SETTLED * SETTLED))
        & f[1].simd_lt(v(0.0));
    (h, settled)
}

/// `search::refine_both`: τ_m (i = 0, the root of z̄') and τ_f (i = 1, of z̄) from their
/// guesses, side by side; the lanes where each settled within [`MAX_REFINE`] steps inside
/// (0, [`TAU_MAX`]) and within a quarter of the pair's period of its guess.
#[inline(always)]
fn refine_both(flow: &Flow4, guesses: [Point4; 2], live: V) -> ([Root4; 2], V) {
    let mut points = guesses;
    let mut active = [live, live];
    let mut found = [v(0.0), v(0.0)];
    let mut roots = guesses.map(|point| Root4 {
        t: point.t,
        point,
        jet: [v(0.0); 6],
    });
    for _ in 0..MAX_REFINE {
        for i in 0..2 {
            if !active[i].any() {
                continue;
            }
            let point = points[i];
            let jet = flow.jet(&point);
            let (h, settled) = householder(&jet[1 - i..5 - i]);
            let t = point.t - h;
            let inside = t.simd_gt(v(0.0)) & t.simd_lt(v(TAU_MAX));
            let now = active[i] & inside & settled;
            roots[i] = Root4 {
                t: now.select(t, roots[i].t),
                point: Point4::select(now, point, roots[i].point),
                jet: std::array::from_fn(|k| now.select(jet[k], roots[i].jet[k])),
            };
            found[i] |= now;
            active[i] &= inside & !settled;
            if !active[i].any() {
                // every lane of this event settled or left: no next point to turn to
                continue;
            }
            let (shifted, fits) = flow.shift(&point, -h);
            let far = active[i] & !fits;
            points[i] = if far.any() {
                Point4::select(fits, shifted, flow.at(t))
            } else {
                shifted
            };
        }
        if !(active[0] | active[1]).any() {
            break;
        }
    }
    let quarter = v(FRAC_PI_2) / flow.omega;
    let near = |i: usize| (roots[i].t - guesses[i].t).simd_le(quarter);
    let ok = found[0] & found[1] & near(0) & near(1) & roots[1].t.simd_gt(roots[0].t);
    (roots, ok)
}

/// `search::taylor`.
#[inline(always)]
fn taylor(c: &[V], h: V) -> V {
    c[0] + h * (c[1] + h / v(2.0) * (c[2] + h / v(3.0) * (c[3] + h / v(4.0) * c[4])))
}

/// The lanes' own answers: lane i is [`super::summary`]`(lambda[i], zeta[i])` to 1e-12 where
/// the common path settles it, `None` where it hands the lane to the scalar path (which may
/// still answer: [`summary4`] asks it).
///
/// The kernel runs compiled twice: for the build's target (SSE2 on the default x86-64 one)
/// and with AVX2, picked where the CPU has it (`is_x86_feature_detected!` caches the answer).
/// A `#[target_feature]` compilation of the same code rather than another lane type, because
/// `wide` picks its representation when it is compiled, so a second, AVX `wide` cannot sit
/// beside the first in one build; inside an `avx2` function the same operations take the VEX
/// encodings (9 % fewer instructions: BENCHMARKS.md, "The map through the lanes"). FMA is not
/// enabled on purpose: Rust never fuses a multiply and an add by itself, so both compilations
/// round alike and give the same bits (`avx2_and_portable_kernels_agree_bit_for_bit`): a map's
/// CSV does not depend on the CPU.
pub fn lanes_only(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, just checked
        return unsafe { lanes_only_avx2(lambda, zeta) };
    }
    kernel(lambda, zeta)
}

/// The kernel compiled with AVX2 enabled.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn lanes_only_avx2(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    kernel(lambda, zeta)
}

/// [`lanes_only`] compiled for the build's own target (SSE2 on the default x86-64 one): what
/// [`lanes_only`] runs where AVX2 is missing.
pub fn lanes_only_portable(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    kernel(lambda, zeta)
}

/// The body of [`lanes_only`], inlined into each of its compilations (portable, AVX2).
#[inline(always)]
fn kernel(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    let (l, z) = (V::new(lambda), V::new(zeta));
    let valid = l.simd_gt(v(0.0)) & z.simd_gt(v(0.0)) & l.is_finite() & z.is_finite();
    // a lane left out computes a harmless ball (λ = 1, ζ = 0.1), its answer then dropped
    let (l, z) = (valid.select(l, v(1.0)), valid.select(z, v(0.1)));
    let (flow, ok) = Flow4::new(l, z);
    let (guesses, pair) = flow.guesses();
    let live = valid & ok & pair;
    let (roots, settled) = refine_both(&flow, guesses, live);
    let [peak, end] = roots;
    let z_m = taylor(&peak.jet[0..5], peak.t - peak.point.t);
    let h = end.t - end.point.t;
    let integral = flow.integral(&end.point);
    let j = &end.jet;
    let cor = taylor(&[integral, j[0], j[1], j[2], j[3]], h) - v(1.0);
    let (dz_m, _) = flow.rounding(&peak.point);
    let (dz_f, dint) = flow.rounding(&end.point);
    let slope = taylor(&j[1..6], h).abs();
    let keep = v(super::KEEP);
    let precise = dz_m.simd_le(keep * z_m)
        & dint.simd_le(keep * cor.abs())
        & dz_f.simd_le(keep * slope * end.t)
        & (flow.r * end.point.t).abs().simd_ge(v(1e-3));
    let answered = (live & settled & precise).to_bitmask();
    let (cor, z_m, t_f) = (cor.to_array(), z_m.to_array(), end.t.to_array());
    std::array::from_fn(|i| {
        (answered & (1 << i) != 0).then_some(Summary {
            cor: cor[i],
            max_force: z_m[i],
            contact_time: t_f[i],
        })
    })
}

/// COR, F̄_m and τ_f of four normalized linear-law impacts without flattening: lane i is
/// [`super::summary`]`(lambda[i], zeta[i])` to 1e-12 (the same `None`s: a lane the lanes do
/// not settle is the scalar path's answer).
pub fn summary4(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    let lanes = lanes_only(lambda, zeta);
    std::array::from_fn(|i| lanes[i].or_else(|| super::summary(lambda[i], zeta[i])))
}

/// [`summary4`] over slices of equal length, four at a time (the last group padded with its
/// own last point, whose answers are dropped): `out[i]` is `summary(lambda[i], zeta[i])` to
/// 1e-12, whatever the slices' length.
pub fn summaries(lambda: &[f64], zeta: &[f64], out: &mut [Option<Summary>]) {
    assert!(lambda.len() == zeta.len() && zeta.len() == out.len());
    for ((l, z), o) in lambda
        .chunks(LANES)
        .zip(zeta.chunks(LANES))
        .zip(out.chunks_mut(LANES))
    {
        let pad = |s: &[f64]| std::array::from_fn(|i| s[i.min(s.len() - 1)]);
        let answers = summary4(pad(l), pad(z));
        o.copy_from_slice(&answers[..o.len()]);
    }
}

/// 1/k!, k ≤ 13 (as flow.rs's).
const INV_FACTORIAL: [f64; 14] = {
    let mut c = [1.0; 14];
    let mut k = 1;
    while k < 14 {
        c[k] = c[k - 1] / k as f64;
        k += 1;
    }
    c
};

/// `flow::exp_small`: Σ xᵏ/k!, k ≤ 10, good where |x| ≤ [`SMALL`].
#[inline(always)]
fn exp_small(x: V) -> V {
    (0..=10)
        .rev()
        .fold(v(0.0), |sum, k| sum * x + v(INV_FACTORIAL[k]))
}

/// `flow::cos_sinc`: (cos x, sin(x)/x) to x¹⁰, good where |x| ≤ [`SMALL`].
#[inline(always)]
fn cos_sinc(x: V) -> (V, V) {
    let x2 = x * x;
    let sign = |k: usize| if k.is_multiple_of(2) { 1.0 } else { -1.0 };
    let cos = (0..=5).rev().fold(v(0.0), |sum, k| {
        sum * x2 + v(sign(k) * INV_FACTORIAL[2 * k])
    });
    let sinc = (0..=5).rev().fold(v(0.0), |sum, k| {
        sum * x2 + v(sign(k) * INV_FACTORIAL[2 * k + 1])
    });
    (cos, sinc)
}
