//! The lanes' kernel: [`super::super::summary`]'s closed form, four impacts side by side over
//! any [`Lane`] (the module's introduction, `lanes.rs`, says what it computes and where it
//! hands a lane back). Generic so that one text compiles to the portable `f64x4` and to the
//! AVX register (`avx.rs`); every operation is a [`Lane`] primitive or `math.rs`'s, so both
//! give the same bits (`avx2_and_portable_kernels_agree_bit_for_bit`, tests/physics/map_lanes.rs).

use super::lane::Lane;
use super::math::{Horner, Sums, atan2, exp_m1_small};
use crate::map::fast::Summary;
use crate::map::fast::flow::SMALL;
use std::f64::consts::PI;
use std::marker::PhantomData;

#[path = "cubic.rs"]
mod cubic;
#[path = "hyper.rs"]
mod hyper;
#[path = "overtake.rs"]
mod overtake;
#[path = "refine.rs"]
mod refine;

use cubic::lone_real_root;
use refine::{householder_root, refine_both, select6, taylor};

/// The flow of four (λ, ζ): `flow::Flow`'s fields, lane by lane; `S` how it sums its series
/// (`math::Sums`: [`Horner`] for the linear law's kernel, `Estrin` for the flattening's).
struct Flow4<L: Lane, S: Sums = Horner> {
    size: [L; 4],
    r: L,
    sigma: L,
    omega2: L,
    omega: L,
    /// 1/ω, for the products that stand for x/ω where `S::SHORT` (unused, so not formed,
    /// in the linear law's kernel).
    inv_omega: L,
    a: L,
    d: L,
    p: L,
    q: L,
    jet: [[L; 3]; 6],
    /// The lanes whose pair is real (ω² = −ν² < 0, three real roots): `omega` holds ν there
    /// and the flow's C, S are cosh ντ, sinh(ντ)/ν (`hyper.rs`).
    hyper: L,
    sums: PhantomData<S>,
}

/// `flow::Point`, lane by lane.
#[derive(Clone, Copy)]
struct Point4<L: Lane> {
    t: L,
    real: L,
    decay: L,
    ec: L,
    es: L,
}

impl<L: Lane> Point4<L> {
    #[inline(always)]
    fn select(mask: L, yes: Point4<L>, no: Point4<L>) -> Point4<L> {
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
struct Root4<L: Lane> {
    t: L,
    point: Point4<L>,
    jet: [L; 6],
}

impl<L: Lane> Root4<L> {
    #[inline(always)]
    fn select(mask: L, yes: Root4<L>, no: Root4<L>) -> Root4<L> {
        Root4 {
            t: mask.select(yes.t, no.t),
            point: Point4::select(mask, yes.point, no.point),
            jet: select6(mask, yes.jet, no.jet),
        }
    }
}

impl<L: Lane, S: Sums> Flow4<L, S> {
    /// The flows, and the lanes whose pair oscillates and decays or, with three real roots,
    /// is real and apart from r (`Flow::new`'s coefficients, each of two equal forms the one
    /// of smaller terms).
    #[inline(always)]
    fn new(lambda: L, zeta: L) -> (Flow4<L, S>, L) {
        let v = L::splat;
        let (one, zero) = (v(1.0), v(0.0));
        let two_zeta = v(2.0) * zeta;
        let (a2, a0) = (two_zeta * (one + lambda), two_zeta * lambda);
        let (r, p1, p0, mut ok, three) = lone_real_root::<L, S>(a2, a0);
        let sigma = v(0.5) * p1;
        let omega2 = p0 - sigma * sigma;
        let gap = (r + sigma) * (r + sigma) + omega2;
        let hyper = three & omega2.lt(zero);
        ok &= gap.gt(zero) & p0.gt(zero) & (omega2.gt(zero) | hyper);
        let (a_sum, sa_sum) = ((r + a0) / gap, (r.abs() + a0.abs()) / gap.abs());
        let two_sigma = v(2.0) * sigma;
        let a_diff = (two_sigma - two_zeta) / gap;
        let sa_diff = (two_sigma.abs() + two_zeta.abs()) / gap.abs();
        let pick = sa_sum.le(sa_diff);
        let (a, sa) = (pick.select(a_sum, a_diff), pick.select(sa_sum, sa_diff));
        let d_mul = one - (r + sigma) * a;
        let sd_mul = one + (r + sigma).abs() * sa;
        let d_div = (sigma - a0 + a * omega2) / (sigma + r);
        let sd_div = (sigma.abs() + a0 + sa * omega2.abs()) / (sigma + r).abs();
        let pick = sd_mul.le(sd_div);
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
        let omega = hyper.select((-omega2).sqrt(), omega2.sqrt());
        let flow = Flow4 {
            size,
            r,
            sigma,
            omega2,
            omega,
            inv_omega: one / omega,
            a,
            d,
            p,
            q,
            jet,
            hyper,
            sums: PhantomData,
        };
        (flow, ok)
    }

    /// `Flow::at_phase`: the point at τ from (cos ωτ, sin ωτ).
    #[inline(always)]
    fn at_phase(&self, t: L, cos: L, sin: L) -> Point4<L> {
        let decay = S::exp(-self.sigma * t);
        Point4 {
            t,
            real: S::exp(self.r * t),
            decay,
            ec: decay * cos,
            // sin ωτ/ω from the guess's phase before e^{−στ} is ready (`Sums::SHORT`)
            es: if S::SHORT {
                decay * (sin * self.inv_omega)
            } else {
                decay * sin / self.omega
            },
        }
    }

    /// `Flow::at`: by the phase where the pair oscillates, by `Flow4::at_hyper` where it is
    /// real.
    #[inline(always)]
    fn at(&self, t: L) -> Point4<L> {
        let (sin, cos) = (self.omega * t).sin_cos();
        let point = self.at_phase(t, cos, sin);
        if self.hyper.any() {
            Point4::select(self.hyper, self.at_hyper(t), point)
        } else {
            point
        }
    }

    /// `Flow::shift`: the point `h` after `pt` by series, and the lanes where every rate × |h|
    /// is within [`SMALL`] (elsewhere the caller takes [`Flow4::at`]).
    #[inline(always)]
    fn shift(&self, pt: &Point4<L>, h: L) -> (Point4<L>, L) {
        let v = L::splat;
        let rate = self.r.abs().max(self.sigma.abs()).max(self.omega);
        let fits = (rate * h.abs()).le(v(SMALL));
        // (ωh)², or −(νh)² where the pair is real: cos and sinc become cosh and sinhc
        let wh = self.omega * h;
        let (cos, sinc) = S::cos_sinc_sq(self.hyper.select(-(wh * wh), wh * wh));
        let (s_h, decay) = (h * sinc, S::exp_small(-self.sigma * h));
        let ec = pt.ec * cos - self.omega2 * pt.es * s_h;
        let es = pt.es * cos + pt.ec * s_h;
        let point = Point4 {
            t: pt.t + h,
            real: pt.real * S::exp_small(self.r * h),
            decay: pt.decay * decay,
            ec: ec * decay,
            es: es * decay,
        };
        (point, fits)
    }

    /// (z̄, …, z̄^{(5)}) at a point (`Flow::jet`).
    #[inline(always)]
    fn jet(&self, pt: &Point4<L>) -> [L; 6] {
        // loops over arrays rather than `std::array::from_fn`, whose closure the compiler
        // left out of line in the eight-lane kernel (a call per use, by callgrind)
        let mut out = [pt.real; 6];
        for (o, [ar, c, s]) in out.iter_mut().zip(self.jet) {
            *o = ar * pt.real + c * pt.ec + s * pt.es;
        }
        out
    }

    /// `Flow::rounding` where the pair oscillates: (for z̄, for ∫ z̄).
    #[inline(always)]
    fn rounding(&self, pt: &Point4<L>) -> (L, L) {
        let v = L::splat;
        let one = v(1.0);
        let t = pt.t;
        let (cm, sm) = (pt.decay, pt.decay * t.min(one / self.omega));
        // a real pair: e^{−στ} cosh ντ, and the terms of sinh's difference over ν (`hyper.rs`)
        let (cm, sm) = (
            self.hyper.select(pt.ec.abs(), cm),
            self.hyper.select(pt.ec.abs() / self.omega, sm),
        );
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

    /// `Flow::integral`: e^{rτ} − 1 by subtraction where |rτ| ≥ 1e-3, by its series below
    /// (as `flow::real_growth`'s `exp_m1`; λ, ζ ≲ 0.016: a short contact of a slow real
    /// mode). The rounding bound is the same either way (`Flow4::rounding`'s, the scalar's).
    #[inline(always)]
    fn integral(&self, pt: &Point4<L>) -> L {
        let v = L::splat;
        let rt = self.r * pt.t;
        let grown = rt
            .abs()
            .lt(v(1e-3))
            .select(exp_m1_small(rt), pt.real - v(1.0));
        let real = self.a * grown / self.r;
        real + self.p * pt.ec + self.q * pt.es - self.p
    }

    /// `search::phase_guesses`: the points at the pair's zeros of z̄' and z̄ where P > 0, and
    /// the lanes where P > 0. Where P ≤ 0 (a fast real mode carries z̄'(0) = 1: the band
    /// λ ≲ 0.24, ζ ≈ 0.64–5 on the map) τ_m's guess is the loading's start, τ = 0 — the
    /// real mode's decay takes Householder's steps to the root in two to four (the scalar
    /// path brackets it) — and τ_f's the pair's first zero of z̄ after the phase 0, as the
    /// scalar path's `separation_guess(flow, 0)`; the third value is ω√(P² + Q²), the bound
    /// on the pair part's slope that [`Flow4::falls_once`] takes. Where the pair is real τ_m's
    /// guess is τ = 0 too and τ_f's `Flow4::hyper_guess`'s; the fourth value is the lanes
    /// whose guesses stand (all but real pairs without a zero of z̄'s pair part).
    #[inline(always)]
    fn guesses(&self) -> ([Point4<L>; 2], L, L, L) {
        let v = L::splat;
        let (one, zero) = (v(1.0), v(0.0));
        let w = self.omega;
        let p = self.d + self.sigma * self.a;
        let q = (self.a * self.omega2 - self.sigma * self.d) / w;
        let pos = p.gt(zero);
        let theta_m = atan2(p, -q);
        let flip = self.d.lt(zero).select(v(-1.0), one);
        let (a, dw) = (flip * self.a, flip * self.d / w);
        let theta = atan2(a, dw);
        let after = pos.select(theta_m, zero);
        let k = ((after - theta) / v(PI)).floor() + one;
        let odd = (k - v(2.0) * (v(0.5) * k).floor()).ne(zero);
        let norm_m = (p * p + q * q).sqrt();
        let norm_f = odd.select(v(-1.0), one) / (a * a + dw * dw).sqrt();
        let peak = self.at_phase(theta_m / w, -q / norm_m, p / norm_m);
        let start = Point4 {
            t: zero,
            real: one,
            decay: one,
            ec: one,
            es: zero,
        };
        let end = self.at_phase((theta + k * v(PI)) / w, dw * norm_f, a * norm_f);
        let peak = Point4::select(pos, peak, start);
        let (peak, end, fine) = if self.hyper.any() {
            let (end_h, fine) = self.hyper_guess();
            let peak = Point4::select(self.hyper, start, peak);
            (peak, Point4::select(self.hyper, end_h, end), fine)
        } else {
            (peak, end, v(0.0).eq(zero))
        };
        ([peak, end], pos, w * norm_m, fine)
    }

    /// Where P ≤ 0, the lanes whose root τ* of z̄' (refined from 0, last evaluated at `pt`)
    /// is its first: z̄' = e^{−στ}(L(τ) − M(τ)), L = A r e^{(r+σ)τ} (A r = 1 − P ≥ 1) and
    /// M = −(P cos ωτ + Q sin ωτ), |M'| ≤ ω√(P² + Q²) = `slope`. Where r + σ < 0, L falls,
    /// and L − M falls strictly on [0, τ*] — so that τ* is its only zero there — wherever
    /// either holds:
    ///
    /// - |r + σ| L(τ*) > `slope` (|L'| is least at τ*). L(τ*) ≥ L(τ_pt) e^{−1/2} where
    ///   |(r + σ)(τ* − τ_pt)| ≤ 1/2: asked as |r + σ| A r e^{rτ_pt} ≥ 2 `slope` e^{−στ_pt},
    ///   without a division.
    /// - M rises on [0, τ*] (`Flow4::pair_rises`): near the band of three real roots, where
    ///   the real mode alone does not outrun the pair's slope.
    #[inline(always)]
    fn falls_once(&self, t: L, pt: &Point4<L>, slope: L) -> L {
        let v = L::splat;
        let rate = self.r + self.sigma;
        let real_slope = -rate * self.a * self.r * pt.real;
        let outruns =
            (rate * (t - pt.t)).abs().le(v(0.5)) & real_slope.ge(v(2.0) * slope * pt.decay);
        rate.lt(v(0.0)) & (outruns | self.pair_rises(t, pt, slope))
    }

    /// The lanes where M = −(P cos ωτ + Q sin ωτ) provably rises on [0, τ*]: M' = ω g,
    /// g = P sin ωτ − Q cos ωτ = √(P² + Q²) sin(ωτ − ψ), a sinusoid, is ≥ 0 at both ends of
    /// [0, ωτ*] and that span is shorter than π (a sinusoid's negative half lasts π, so it
    /// cannot fit between two non-negative ends closer than π). g(0) = −Q; g(τ*) from the
    /// last point, e^{−στ}g(τ_pt) = P ω e^{−στ}S − Q e^{−στ}C, less its largest change to τ*
    /// (|g'| ≤ ω√(P² + Q²) = `slope`, so |Δg| ≤ `slope` |τ* − τ_pt|).
    #[inline(always)]
    fn pair_rises(&self, t: L, pt: &Point4<L>, slope: L) -> L {
        let v = L::splat;
        let zero = v(0.0);
        let w = self.omega;
        let p = self.d + self.sigma * self.a;
        let q = (self.a * self.omega2 - self.sigma * self.d) / w;
        let g_pt = p * w * pt.es - q * pt.ec;
        let drift = slope * (t - pt.t).abs() * pt.decay;
        (-q).ge(zero) & (w * t).lt(v(PI)) & g_pt.ge(drift)
    }
}

/// The body of `lanes_only` and `lanes_only8`, inlined into each of their compilations
/// (portable, AVX2; four lanes, or eight in two registers): N impacts in one `L` of N lanes.
#[inline(always)]
pub fn kernel<L: Lane<Array = [f64; N]>, const N: usize>(
    lambda: [f64; N],
    zeta: [f64; N],
) -> [Option<Summary>; N] {
    let v = L::splat;
    let (l, z) = (L::from_array(lambda), L::from_array(zeta));
    let valid = l.gt(v(0.0)) & z.gt(v(0.0)) & l.is_finite() & z.is_finite();
    // a lane left out computes a harmless ball (λ = 1, ζ = 0.1), its answer then dropped
    let (l, z) = (valid.select(l, v(1.0)), valid.select(z, v(0.1)));
    let (flow, ok) = Flow4::<L, Horner>::new(l, z);
    let (guesses, pos, slope, fine) = flow.guesses();
    let live = valid & ok & fine;
    let ([peak, end], [ok_m, ok_f]) = refine_both(&flow, guesses, live, (pos, slope));
    // a slow pair overtaken by the real mode: τ_f again, from its own start (`overtake.rs`)
    let late = live & ok_m & !ok_f & !flow.hyper;
    let (end, ok_f) = if late.any() {
        let (late_end, found) = overtake::refine_overtaken(&flow, peak.t, guesses[1].t, late);
        (Root4::select(found, late_end, end), ok_f | found)
    } else {
        (end, ok_f)
    };
    let settled = ok_m & ok_f;
    let taylor = taylor::<L, Horner>;
    let z_m = taylor(&peak.jet[0..5], peak.t - peak.point.t);
    let h = end.t - end.point.t;
    let integral = flow.integral(&end.point);
    let j = &end.jet;
    let cor = taylor(&[integral, j[0], j[1], j[2], j[3]], h) - v(1.0);
    let (dz_m, _) = flow.rounding(&peak.point);
    let (dz_f, dint) = flow.rounding(&end.point);
    let slope = taylor(&j[1..6], h).abs();
    let keep = v(crate::map::fast::KEEP);
    let precise = dz_m.le(keep * z_m) & dint.le(keep * cor.abs()) & dz_f.le(keep * slope * end.t);
    answers((live & settled & precise).bitmask(), cor, z_m, end.t)
}

/// The lanes' answers, the linear law's kernel's and the flattening's alike: lane i's
/// (e, F̄_m = z̄_m, τ_f) where bit i of `answered` is set, `None` (handed back) elsewhere.
#[inline(always)]
fn answers<L: Lane<Array = [f64; N]>, const N: usize>(
    answered: u32,
    cor: L,
    max_force: L,
    contact_time: L,
) -> [Option<Summary>; N] {
    let (cor, max_force, contact_time) = (
        cor.to_array(),
        max_force.to_array(),
        contact_time.to_array(),
    );
    let mut out = [None; N];
    for (i, o) in out.iter_mut().enumerate() {
        *o = (answered & (1 << i) != 0).then_some(Summary {
            cor: cor[i],
            max_force: max_force[i],
            contact_time: contact_time[i],
        });
    }
    out
}

/// Flattening cells over the same lanes (issue 30 item 2): a child of this module, for its
/// flow, points, roots and steps.
#[path = "flatten.rs"]
pub(super) mod flatten;
