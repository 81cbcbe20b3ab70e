//! Several impacts' Taylor steps at once (issue 30 item 1): the Hertz and elastic–plastic
//! impacts [`summary`](super::summary) answers, one impact a SIMD lane, as heyoka's batch
//! mode does. Each step's series (85 % of an impact's instructions one by one: callgrind,
//! BENCHMARKS.md, eleventh session) are computed in lanes, and so is a quiet step's end (no
//! event: the step rule lane by lane, Horner sums in lanes); a step with an event goes to the
//! single impact's code (`stages::PowerImpact`) with that lane's series. A lane runs the same
//! IEEE operations in the same order as the single path (`power::series_of`, `poly::eval`), so
//! every answer is its bits (tests/taylor_batch.rs
//! `batched_summaries_are_the_single_ones_bit_for_bit`).
//!
//! The lanes are plain `[f64; W]` with element-wise operators, compiled inside
//! `#[target_feature]` functions so that LLVM packs them into one AVX-512 register (two AVX2
//! ones): the `wide` crate fixes its registers when it is compiled (two SSE2 registers on
//! the default target, `map::fast::lanes::avx`'s note). A fused multiply–add enters only as
//! `mul_add` (the series' products, the step's Horner sums), the same one rounding in a lane
//! as in the single path and on every CPU: one instruction in the FMA compilations, libm's
//! `fma` without them (`tests::series_are_the_same_bits_without_fma_instructions`,
//! `super::fused`'s tests). Rust fuses nothing by itself, so every other product and sum is
//! rounded apart, as in the single path. Only code inlined into those compilations has FMA:
//! a closure left out of line would call libm's `fma` eight times a lane operation.

use super::poly::Coef;
use super::power::{self, Coefs};
use super::stages::{PowerImpact, Progress};
use super::{POWER_LEN, POWER_RULES, Summary};
use super::{fused, poly};
use crate::model::contact::ContactLaw;
use crate::model::params::Normalized;
use std::ops::{Add, Mul, Sub};

/// Impacts in step: one AVX-512 register of f64, two of AVX2.
const W: usize = 8;

/// W f64 lanes, each operation IEEE lane by lane.
#[derive(Clone, Copy)]
#[repr(align(64))]
pub(super) struct Lanes([f64; W]);

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for Lanes {
            type Output = Lanes;
            #[inline(always)]
            fn $f(self, o: Lanes) -> Lanes {
                Lanes(std::array::from_fn(|i| self.0[i] $op o.0[i]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);

impl Coef for Lanes {
    #[inline(always)]
    fn splat(x: f64) -> Lanes {
        Lanes([x; W])
    }
    #[inline(always)]
    fn mul_add(self, a: Lanes, b: Lanes) -> Lanes {
        Lanes(std::array::from_fn(|i| self.0[i].mul_add(a.0[i], b.0[i])))
    }
}

impl Coefs<Lanes> {
    /// The system `k` in every lane.
    fn splat(k: Coefs<f64>) -> Coefs<Lanes> {
        Coefs {
            two_zeta: Lanes::splat(k.two_zeta),
            lambda: Lanes::splat(k.lambda),
            a: Lanes::splat(k.a),
            minus_a: Lanes::splat(k.minus_a),
            half_b: Lanes::splat(k.half_b),
        }
    }

    /// Lane j given the system `k`.
    fn set_lane(&mut self, j: usize, k: Coefs<f64>) {
        self.two_zeta.0[j] = k.two_zeta;
        self.lambda.0[j] = k.lambda;
        self.a.0[j] = k.a;
        self.minus_a.0[j] = k.minus_a;
        self.half_b.0[j] = k.half_b;
    }
}

type LaneSeries = [[Lanes; POWER_LEN]; 4];
/// `power::series_of`'s scratch in lanes.
type Scratch = [[Lanes; POWER_LEN]; 2];

/// The series of W impacts' phases into `c`, in lanes: the AVX-512 compilation where the
/// CPU has it, else AVX2's, each with FMA; elsewhere plain, `mul_add` then libm's `fma`.
fn series(k: Coefs<Lanes>, x: [Lanes; 4], c: &mut LaneSeries, scratch: &mut Scratch) {
    #[cfg(target_arch = "x86_64")]
    {
        let fma = std::arch::is_x86_feature_detected!("fma");
        if fma && std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the CPU has AVX-512F and FMA, the features the function enables
            return unsafe { series_avx512(k, x, c, scratch) };
        }
        if fma && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2 and FMA, the features the function enables
            return unsafe { series_avx2(k, x, c, scratch) };
        }
    }
    power::series_of::<Lanes, POWER_LEN>(k, x, c, scratch)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn series_avx2(k: Coefs<Lanes>, x: [Lanes; 4], c: &mut LaneSeries, scratch: &mut Scratch) {
    power::series_of::<Lanes, POWER_LEN>(k, x, c, scratch)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,fma")]
fn series_avx512(k: Coefs<Lanes>, x: [Lanes; 4], c: &mut LaneSeries, scratch: &mut Scratch) {
    power::series_of::<Lanes, POWER_LEN>(k, x, c, scratch)
}

/// The summaries of `ns` under `law`, each as [`super::summary`] gives it (the same bits):
/// the Hertz and elastic–plastic laws W at a time in lanes, the linear law one by one.
pub fn summaries(ns: &[Normalized], law: ContactLaw) -> Vec<Option<Summary>> {
    if law == ContactLaw::Linear {
        return ns.iter().map(|n| super::summary(n, law)).collect();
    }
    let mut out = vec![None; ns.len()];
    let mut queue = ns.iter().enumerate();
    let mut slots: [Option<(usize, PowerImpact)>; W] = [None; W];
    let mut c = [[Lanes::splat(0.0); POWER_LEN]; 4];
    let mut scratch = [[Lanes::splat(0.0); POWER_LEN]; 2];
    let mut lane = [[0.0; POWER_LEN]; 4];
    // the slots' systems, and which of them may have changed since they were put in lanes
    let mut k = Coefs::<Lanes>::splat(Coefs::IDLE);
    let mut changed = [true; W];
    loop {
        refill(&mut slots, &mut queue, law, &mut changed);
        if slots.iter().all(Option::is_none) {
            return out;
        }
        update_coefs(&mut k, &slots, &mut changed);
        let x = states(&slots);
        series(k, x, &mut c, &mut scratch);
        let h = steps(&c, &x, &slots);
        let ahead = evaluations(&c, h);
        for (j, slot) in slots.iter_mut().enumerate() {
            let Some((i, impact)) = slot else { continue };
            let (s_end, ds0, dsh) = (ahead.s_end.0[j], ahead.ds0.0[j], ahead.dsh.0[j]);
            let progress = if impact.phase.is_quiet(h.0[j], s_end, ds0, dsh) {
                impact.take(ahead.x.map(|x| x.0[j]))
            } else {
                for (lane_v, c_v) in lane.iter_mut().zip(&c) {
                    for (lane_vn, c_vn) in lane_v.iter_mut().zip(c_v) {
                        *lane_vn = c_vn.0[j];
                    }
                }
                // an event may start another phase, on another branch
                changed[j] = true;
                impact.feed_by::<POWER_LEN>(&lane, h.0[j], s_end, (ds0, dsh))
            };
            if let Progress::Done(summary) = progress {
                out[*i] = summary;
                *slot = None;
                changed[j] = true;
            }
        }
    }
}

/// Each lane's step by `super::POWER_RULES`, the rules `stages::PowerImpact` gives every
/// phase it builds (so `power::Phase::advance`'s step, lane by lane: the same bits); 0 in an
/// empty lane.
fn steps(c: &LaneSeries, x: &[Lanes; 4], slots: &[Option<(usize, PowerImpact)>; W]) -> Lanes {
    debug_assert!(
        slots
            .iter()
            .flatten()
            .all(|(_, impact)| impact.phase.rules == POWER_RULES)
    );
    let mut h = quick_steps(c, x, POWER_RULES.eps);
    for (hj, slot) in h.0.iter_mut().zip(slots) {
        if slot.is_none() {
            *hj = 0.0;
        }
    }
    h
}

/// [`quick_steps`] is the fused rules' step (the quick rule, norms by the scales'
/// reciprocals): the rules it stands for must be those.
const _: () = assert!(matches!(POWER_RULES.sums, super::rules::Sums::Fused));

/// The series' order.
const ORDER: usize = POWER_LEN - 1;

/// [`steps`] by the quick rule within `eps` for every lane, states `x`: the AVX-512 or AVX2
/// compilation where the CPU has it, as [`series`].
fn quick_steps(c: &LaneSeries, x: &[Lanes; 4], eps: f64) -> Lanes {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the CPU has AVX-512F, the only feature the function enables
            return unsafe { quick_steps_avx512(c, x, eps) };
        }
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, the only feature the function enables
            return unsafe { quick_steps_avx2(c, x, eps) };
        }
    }
    quick_steps_in(c, x, eps)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn quick_steps_avx2(c: &LaneSeries, x: &[Lanes; 4], eps: f64) -> Lanes {
    quick_steps_in(c, x, eps)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn quick_steps_avx512(c: &LaneSeries, x: &[Lanes; 4], eps: f64) -> Lanes {
    quick_steps_in(c, x, eps)
}

/// `Phase::scales`, the fused rules' norms (`Rules::step`) and `poly::quick_step_of_norms`
/// lane by lane, the same operations in the same order (so the same bits); a lane whose norms or exponent
/// leave the quick rule's plain case takes `quick_step_of_norms` itself.
#[inline(always)]
fn quick_steps_in(c: &LaneSeries, x: &[Lanes; 4], eps: f64) -> Lanes {
    // written out, as `evaluations_in`'s sums: a closure left out of line (`map`, `fold`)
    // is compiled without this function's features
    let reciprocal = |v: usize| each(|j| 1.0 / x[v].0[j].abs().max(1.0));
    let r = [reciprocal(0), reciprocal(1), reciprocal(2), reciprocal(3)];
    let (a1, a2) = (norm(c, &r, ORDER - 1), norm(c, &r, ORDER));
    let y = each(|j| poly::quick_exponent(a1.0[j], a2.0[j], ORDER, eps));
    let h = each(|j| poly::exp2_core(y.0[j]));
    each(|j| {
        let plain = poly::is_plain(a1.0[j]) && poly::is_plain(a2.0[j]);
        if plain && poly::is_in_reach(y.0[j]) {
            h.0[j]
        } else {
            poly::quick_step_of_norms(a1.0[j], a2.0[j], ORDER, eps)
        }
    })
}

/// `Rules::step`'s norm of the terms of order `n` under the fused rules: the largest
/// |c_n| · (1/scale) over the four series, taken in their order (the same bits), lane by
/// lane, given the scales' reciprocals `r`.
#[inline(always)]
fn norm(c: &LaneSeries, r: &[Lanes; 4], n: usize) -> Lanes {
    let mut acc = Lanes::splat(0.0);
    for (cv, rv) in c.iter().zip(r) {
        acc = each(|j| acc.0[j].max(cv[n].0[j].abs() * rv.0[j]));
    }
    acc
}

/// The lanes whose j-th entry is `f(j)`: generic, so that `f` is inlined and the lanes
/// vectorised (a `&dyn Fn` was inlined or not as the optimiser's budget went), and a loop,
/// not `std::array::from_fn`, whose inner function the optimiser may leave out of line and
/// so out of the caller's AVX-512 or AVX2 compilation.
#[inline(always)]
fn each(f: impl Fn(usize) -> f64) -> Lanes {
    let mut lanes = [0.0; W];
    for (j, lane) in lanes.iter_mut().enumerate() {
        *lane = f(j);
    }
    Lanes(lanes)
}

/// What `power::Phase::advance` evaluates on a step, in lanes: s(h), s'(h) and the state at
/// h, each by `fused::horner` as `Rules::horner` sums them (the same bits), and s'(0), the
/// series' c₁.
struct Ahead {
    s_end: Lanes,
    ds0: Lanes,
    dsh: Lanes,
    x: [Lanes; 4],
}

/// [`Ahead`] of the series `c` at the steps `h`: the AVX-512 or AVX2 compilation where the
/// CPU has it, each with FMA, as [`series`].
fn evaluations(c: &LaneSeries, h: Lanes) -> Ahead {
    #[cfg(target_arch = "x86_64")]
    {
        let fma = std::arch::is_x86_feature_detected!("fma");
        if fma && std::arch::is_x86_feature_detected!("avx512f") {
            // SAFETY: the CPU has AVX-512F and FMA, the features the function enables
            return unsafe { evaluations_avx512(c, h) };
        }
        if fma && std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2 and FMA, the features the function enables
            return unsafe { evaluations_avx2(c, h) };
        }
    }
    evaluations_in(c, h)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn evaluations_avx2(c: &LaneSeries, h: Lanes) -> Ahead {
    evaluations_in(c, h)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,fma")]
fn evaluations_avx512(c: &LaneSeries, h: Lanes) -> Ahead {
    evaluations_in(c, h)
}

#[inline(always)]
fn evaluations_in(c: &LaneSeries, h: Lanes) -> Ahead {
    // s'(h): `fused::horner` over poly::derivative's series, lane by lane, whose top term 0
    // leaves the sum's +0 start as it is
    let mut dsh = Lanes::splat(0.0);
    for k in (1..POWER_LEN).rev() {
        dsh = dsh.mul_add(h, Lanes::splat(k as f64) * c[0][k]);
    }
    // written out: a closure (`each_ref().map`) need not be inlined, and outside this
    // function's FMA compilation each lane's mul_add is a call to libm's fma
    let x = [
        fused::horner(&c[0], h),
        fused::horner(&c[1], h),
        fused::horner(&c[2], h),
        fused::horner(&c[3], h),
    ];
    Ahead {
        s_end: x[0],
        ds0: c[0][1],
        dsh,
        x,
    }
}

/// Every slot's impact charged the step it is about to take, and every empty slot given the
/// next impact the steps take on (an impact refused, or out of steps, leaves its `None` in
/// the answer).
fn refill<'a>(
    slots: &mut [Option<(usize, PowerImpact)>; W],
    queue: &mut impl Iterator<Item = (usize, &'a Normalized)>,
    law: ContactLaw,
    changed: &mut [bool; W],
) {
    for (slot, changed) in slots.iter_mut().zip(changed) {
        if let Some((_, impact)) = slot
            && !impact.take_step()
        {
            *slot = None;
            *changed = true;
        }
        while slot.is_none() {
            let Some((i, n)) = queue.next() else { break };
            if let Some(mut impact) = PowerImpact::new(n, law)
                && impact.take_step()
            {
                *slot = Some((i, impact));
                *changed = true;
            }
        }
    }
}

/// The systems in lanes `k` of the slots marked `changed` (an empty lane:
/// [`Coefs::IDLE`]); the marks cleared.
fn update_coefs(
    k: &mut Coefs<Lanes>,
    slots: &[Option<(usize, PowerImpact)>; W],
    changed: &mut [bool; W],
) {
    for (j, (slot, changed)) in slots.iter().zip(changed).enumerate() {
        if std::mem::take(changed) {
            let kj = match slot {
                Some((_, impact)) => Coefs::of(&impact.sys, &impact.phase.br),
                None => Coefs::IDLE,
            };
            k.set_lane(j, kj);
        }
    }
}

/// The slots' states (s, ᾱ', ȳ, τ) in lanes (an empty lane: zeros).
fn states(slots: &[Option<(usize, PowerImpact)>; W]) -> [Lanes; 4] {
    // loops, not `array::from_fn`, whose out-of-line calls cost more than the copies
    let mut x = [Lanes::splat(0.0); 4];
    for (j, slot) in slots.iter().enumerate() {
        if let Some((_, impact)) = slot {
            for (xv, &xj) in x.iter_mut().zip(&impact.phase.x) {
                xv.0[j] = xj;
            }
        }
    }
    x
}

#[cfg(test)]
mod tests;
