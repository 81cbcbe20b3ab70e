//! Several impacts' Taylor steps at once (issue 30 item 1): the Hertz and elastic–plastic
//! impacts [`summary`](super::summary) answers, one impact a SIMD lane, as heyoka's batch
//! mode does. Each step's series (85 % of an impact's instructions one by one: callgrind,
//! BENCHMARKS.md, eleventh session) are computed in lanes, and so is a quiet step's end (no
//! event: the step rule lane by lane, Horner sums in lanes); a step with an event goes to the
//! single impact's code (`stages::PowerImpact`) with that lane's series. A lane runs the same
//! IEEE operations in the same order as the single path (`power::series_of`, `poly::eval`), so
//! every answer is its bits (tests/physics/taylor_batch.rs
//! `batched_summaries_are_the_single_ones_bit_for_bit`).
//!
//! The lanes are plain `[f64; W]` with element-wise operators, compiled inside
//! `#[target_feature]` functions so that LLVM packs them into registers: sixteen lanes
//! (`WIDE`) in two AVX-512 registers where the CPU has them, eight (`NARROW`) in two AVX2
//! ones elsewhere (tests run both widths on every CPU): the `wide` crate fixes its registers when it is compiled (two SSE2 registers on
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
use lanes::{Lanes, each};

/// Impacts in step on AVX2 (two registers of f64) and without it.
const NARROW: usize = 8;
/// Impacts in step on AVX-512: two registers of f64, whose series and sums keep twice the
/// operations in flight that eight lanes do (on AVX2, sixteen lanes would be four registers
/// an operand, and the series' pair loop would spill).
#[cfg(any(target_arch = "x86_64", test))]
const WIDE: usize = 16;

type LaneSeries<const W: usize> = [[Lanes<W>; POWER_LEN]; 4];
/// `power::series_of`'s scratch in lanes.
type Scratch<const W: usize> = [[Lanes<W>; POWER_LEN]; 2];

/// The series of W impacts' phases into `c`, in lanes: the AVX-512 compilation where the
/// CPU has it, else AVX2's, each with FMA; elsewhere plain, `mul_add` then libm's `fma`.
fn series<const W: usize>(
    k: Coefs<Lanes<W>>,
    x: [Lanes<W>; 4],
    c: &mut LaneSeries<W>,
    scratch: &mut Scratch<W>,
) {
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
    power::series_of::<Lanes<W>, POWER_LEN>(k, x, c, scratch)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn series_avx2<const W: usize>(
    k: Coefs<Lanes<W>>,
    x: [Lanes<W>; 4],
    c: &mut LaneSeries<W>,
    scratch: &mut Scratch<W>,
) {
    power::series_of::<Lanes<W>, POWER_LEN>(k, x, c, scratch)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,fma")]
fn series_avx512<const W: usize>(
    k: Coefs<Lanes<W>>,
    x: [Lanes<W>; 4],
    c: &mut LaneSeries<W>,
    scratch: &mut Scratch<W>,
) {
    power::series_of::<Lanes<W>, POWER_LEN>(k, x, c, scratch)
}

/// The summaries of `ns` under `law`, each as [`super::summary`] gives it (the same bits):
/// the Hertz and elastic–plastic laws in lanes, sixteen at a time where the CPU has AVX-512
/// and FMA (`WIDE`), else eight (`NARROW`); the linear law one by one.
pub fn summaries(ns: &[Normalized], law: ContactLaw) -> Vec<Option<Summary>> {
    if law == ContactLaw::Linear {
        return ns.iter().map(|n| super::summary(n, law)).collect();
    }
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx512f") && std::arch::is_x86_feature_detected!("fma")
    {
        return summaries_in::<WIDE>(ns, law);
    }
    summaries_in::<NARROW>(ns, law)
}

/// [`summaries`] W at a time.
fn summaries_in<const W: usize>(ns: &[Normalized], law: ContactLaw) -> Vec<Option<Summary>> {
    let mut out = vec![None; ns.len()];
    let mut queue = ns.iter().enumerate();
    let mut slots: [Option<(usize, PowerImpact)>; W] = [None; W];
    let mut c = [[Lanes::splat(0.0); POWER_LEN]; 4];
    let mut scratch = [[Lanes::splat(0.0); POWER_LEN]; 2];
    let mut lane = [[0.0; POWER_LEN]; 4];
    // the slots' systems, and which of them may have changed since they were put in lanes
    let mut k = Coefs::<Lanes<W>>::splat(Coefs::IDLE);
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
fn steps<const W: usize>(
    c: &LaneSeries<W>,
    x: &[Lanes<W>; 4],
    slots: &[Option<(usize, PowerImpact)>; W],
) -> Lanes<W> {
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
fn quick_steps<const W: usize>(c: &LaneSeries<W>, x: &[Lanes<W>; 4], eps: f64) -> Lanes<W> {
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
fn quick_steps_avx2<const W: usize>(c: &LaneSeries<W>, x: &[Lanes<W>; 4], eps: f64) -> Lanes<W> {
    quick_steps_in(c, x, eps)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
fn quick_steps_avx512<const W: usize>(c: &LaneSeries<W>, x: &[Lanes<W>; 4], eps: f64) -> Lanes<W> {
    quick_steps_in(c, x, eps)
}

/// `Phase::scales`, the fused rules' norms (`Rules::step`) and `poly::quick_step_of_norms`
/// lane by lane, the same operations in the same order (so the same bits); a lane whose norms or exponent
/// leave the quick rule's plain case takes `quick_step_of_norms` itself.
#[inline(always)]
fn quick_steps_in<const W: usize>(c: &LaneSeries<W>, x: &[Lanes<W>; 4], eps: f64) -> Lanes<W> {
    // written out, as `evaluations_in`'s sums: a closure left out of line (`map`, `fold`)
    // is compiled without this function's features
    let reciprocal = |v: usize| each(|j| 1.0 / x[v].0[j].abs().max(1.0));
    let r = [reciprocal(0), reciprocal(1), reciprocal(2), reciprocal(3)];
    let (a1, a2) = (norm(c, &r, ORDER - 1), norm(c, &r, ORDER));
    let y: Lanes<W> = each(|j| poly::quick_exponent(a1.0[j], a2.0[j], ORDER, eps));
    let h: Lanes<W> = each(|j| poly::exp2_core(y.0[j]));
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
fn norm<const W: usize>(c: &LaneSeries<W>, r: &[Lanes<W>; 4], n: usize) -> Lanes<W> {
    let mut acc = Lanes::splat(0.0);
    for (cv, rv) in c.iter().zip(r) {
        acc = each(|j| acc.0[j].max(cv[n].0[j].abs() * rv.0[j]));
    }
    acc
}

/// What `power::Phase::advance` evaluates on a step, in lanes: s(h), s'(h) and the state at
/// h, each by `fused::horner` as `Rules::horner` sums them (the same bits), and s'(0), the
/// series' c₁.
struct Ahead<const W: usize> {
    s_end: Lanes<W>,
    ds0: Lanes<W>,
    dsh: Lanes<W>,
    x: [Lanes<W>; 4],
}

/// [`Ahead`] of the series `c` at the steps `h`: the AVX-512 or AVX2 compilation where the
/// CPU has it, each with FMA, as [`series`].
fn evaluations<const W: usize>(c: &LaneSeries<W>, h: Lanes<W>) -> Ahead<W> {
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
fn evaluations_avx2<const W: usize>(c: &LaneSeries<W>, h: Lanes<W>) -> Ahead<W> {
    evaluations_in(c, h)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,fma")]
fn evaluations_avx512<const W: usize>(c: &LaneSeries<W>, h: Lanes<W>) -> Ahead<W> {
    evaluations_in(c, h)
}

#[inline(always)]
fn evaluations_in<const W: usize>(c: &LaneSeries<W>, h: Lanes<W>) -> Ahead<W> {
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
fn refill<'a, const W: usize>(
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
fn update_coefs<const W: usize>(
    k: &mut Coefs<Lanes<W>>,
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
fn states<const W: usize>(slots: &[Option<(usize, PowerImpact)>; W]) -> [Lanes<W>; 4] {
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

mod lanes;
#[cfg(test)]
mod tests;
