//! Four or eight linear-law impacts per instruction stream: [`super::summary`] in `f64x4`
//! lanes (issue 30 item 3), for the map ([`summaries`], eight a call), the Monte Carlo and
//! `bouncelab.impacts` ([`summary4`], four) and anything else that asks for many.
//!
//! The same closed form, the same steps and the same checks as the scalar path, lane by lane
//! (the module's introduction): the cubic's lone real root by Cardano polished by Newton, the
//! pair's own zeros for the first guesses (two `atan2`), Householder's fourth-order steps
//! turning each point by series, the values at the roots by Taylor's series and the rounding
//! bound that decides whether 1e-13 is kept. Each lane runs on its own (masked), so its
//! answer is a function of its own (λ, ζ) only, never of its neighbours: a Monte Carlo sample
//! is the same in any grouping (`same_answer_on_one_thread_and_many`).
//!
//! Where the pair part of z̄' starts negative (P ≤ 0) τ_m is refined from the loading's start
//! and kept where z̄' provably falls once before it (`Flow4::falls_once`, kernel.rs); where
//! |rτ| < 1e-3, e^{rτ} − 1 is its series (`math::exp_m1_small`, as the scalar path's
//! `exp_m1`). Where the cubic's three roots are real (no oscillating pair: λ ≲ 0.24, ζ ≈
//! 0.64–5) the flow is the slowest root's mode and a real pair's cosh and sinh (`lanes/hyper.rs`):
//! the scalar path's answer to 1e-12, or where its rounding bound refuses and the lanes' does
//! not (a few points in a thousand of that band), the exact solver's to 1e-12
//! (tests/physics/map_lanes.rs). Beside that band, where the pair oscillates slowly, τ_m where P ≤ 0
//! is proven first also where the pair part of z̄' rises (`Flow4::pair_rises`), and τ_f where
//! the real mode overtakes the pair long before the pair's own zero comes from its own start
//! (`lanes/overtake.rs`). A lane the common path does not settle — a step too long for the
//! series and the `sin_cos` turn, a root past its lobe (the bracket search's cases), a pair
//! nearly double, λ or ζ zero — is handed to the scalar [`super::summary`], whole.
//! The exponential and `atan2` are the lanes' own (`lanes/math.rs`: within 2 ulp of libm's,
//! the same bits on every machine), `cbrt` `wide`'s written over the lanes (its bits),
//! `sin_cos` `wide`'s, where the scalar path calls libm's: the answers agree with the scalar path's to 1e-12 (tests/physics/map_lanes.rs), not
//! bit for bit.
//!
//! The files: `lane.rs` (what the kernel asks of four f64, and `wide`'s `f64x4` answering it),
//! `avx.rs` (the same in one AVX register), `pair.rs` (two AVX registers as one lane type of
//! eight: [`lanes_only8`]), `math.rs` (`exp`, `atan2`, `cbrt`, a logarithm for guesses and the
//! short steps' series over any), `kernel.rs` (the closed form over any: its flow and guesses;
//! `cubic.rs` the cubic's root, `refine.rs` the steps to τ_m and τ_f), `hyper.rs` (its real
//! pair: three real roots), `overtake.rs` (τ_f where the real mode overtakes a slow pair),
//! `flatten.rs` (the flattening's closed form over any, eight or four cells a call; its
//! unloading in `unload.rs`) and `one.rs` (a lane of one f64: a lone cell, bit for bit its
//! lane in a group).

#[cfg(target_arch = "x86_64")]
mod avx;
mod kernel;
mod lane;
mod math;
#[cfg(target_arch = "x86_64")]
mod pair;

pub use kernel::flatten::{
    FLAT_WIDE, flattening_lanes4, flattening_lanes8, flattening_lanes8_portable, flattenings,
};
pub use kernel::flatten::{flattening_lane1, flattening_lane1_portable, flattening_one};
pub use lane::LANES;

use super::Summary;
use wide::f64x4;

/// Whether the CPU has AVX2 and FMA, which the `#[target_feature(enable = "avx2,fma")]`
/// kernels need (`is_x86_feature_detected!` caches the answer): every entry point of the
/// lanes picks its kernel by it.
#[cfg(target_arch = "x86_64")]
fn avx2_fma() -> bool {
    std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
}

/// The lanes' own answers: lane i is [`super::summary`]`(lambda[i], zeta[i])` to 1e-12 where
/// the common path settles it (where that is `None`, three real roots, the exact solver's to
/// 1e-12), `None` where it hands the lane to the scalar path (which may still answer:
/// [`summary4`] asks it).
///
/// The kernel (`kernel.rs`, generic over the lane type) runs compiled twice: on `wide`'s
/// `f64x4` for the build's target (two SSE2 registers on the default x86-64 one), and on the
/// `Avx` lane type (one ymm register, `avx.rs`) inside a `#[target_feature(enable =
/// "avx2,fma")]` function, picked where the CPU has AVX2 and FMA (`is_x86_feature_detected!`
/// caches the answer). Both run the same IEEE operations in the same order — the exponential
/// and `atan2` written once over the lane primitives (`math.rs`), the series' fused
/// multiply-adds `vfmadd` in one and `f64::mul_add` in the other (both correctly rounded;
/// Rust fuses nothing by itself) — so they give the same bits
/// (`avx2_and_portable_kernels_agree_bit_for_bit`): a map's CSV does not depend on the CPU.
pub fn lanes_only(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    #[cfg(target_arch = "x86_64")]
    if avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA, just checked
        return unsafe { lanes_only_avx2(lambda, zeta) };
    }
    kernel::kernel::<f64x4, LANES>(lambda, zeta)
}

/// The kernel on the AVX lane type, compiled with AVX2 and FMA enabled.
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn lanes_only_avx2(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    kernel::kernel::<avx::Avx, LANES>(lambda, zeta)
}

/// [`lanes_only`] compiled for the build's own target (SSE2 on the default x86-64 one): what
/// [`lanes_only`] runs where AVX2 or FMA is missing.
pub fn lanes_only_portable(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    kernel::kernel::<f64x4, LANES>(lambda, zeta)
}

/// COR, F̄_m and τ_f of four normalized linear-law impacts without flattening: lane i is
/// [`super::summary`]`(lambda[i], zeta[i])` to 1e-12 (a lane the lanes do not settle is the
/// scalar path's answer; the same `None`s but where three real roots let the lanes answer
/// what the scalar path's bound refuses: the exact solver's answer to 1e-12 then).
pub fn summary4(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    let lanes = lanes_only(lambda, zeta);
    std::array::from_fn(|i| lanes[i].or_else(|| super::summary(lambda[i], zeta[i])))
}

/// Impacts per call of [`lanes_only8`]: two registers of [`LANES`] in one instruction stream.
pub const WIDE: usize = 2 * LANES;

/// [`lanes_only`] of eight impacts at once: lane i is `lanes_only` of its group of four's,
/// bit for bit (`eight_lanes_are_two_fours_bit_for_bit`). With AVX2 the kernel runs on two
/// AVX registers interleaved in one instruction stream (`pair.rs` says why: the kernel is
/// latency-bound, and a second independent chain fills the waits), elsewhere as two calls of
/// the portable kernel (SSE2 has too few registers for eight lanes at once).
pub fn lanes_only8(lambda: [f64; WIDE], zeta: [f64; WIDE]) -> [Option<Summary>; WIDE] {
    #[cfg(target_arch = "x86_64")]
    if avx2_fma() {
        // SAFETY: the CPU has AVX2 and FMA, just checked
        return unsafe { lanes_only8_avx2(lambda, zeta) };
    }
    let half = |a: &[f64; WIDE], k: usize| std::array::from_fn(|i| a[k * LANES + i]);
    let lo = lanes_only_portable(half(&lambda, 0), half(&zeta, 0));
    let hi = lanes_only_portable(half(&lambda, 1), half(&zeta, 1));
    std::array::from_fn(|i| if i < LANES { lo[i] } else { hi[i - LANES] })
}

/// The kernel on a pair of AVX registers, compiled with AVX2 and FMA enabled.
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn lanes_only8_avx2(lambda: [f64; WIDE], zeta: [f64; WIDE]) -> [Option<Summary>; WIDE] {
    kernel::kernel::<pair::Pair<avx::Avx>, WIDE>(lambda, zeta)
}

/// [`summary4`] over slices of equal length, eight at a time through [`lanes_only8`] (the
/// last group padded with its own last point, whose answers are dropped), each lane the lanes
/// leave to the scalar path its answer: `out[i]` is `summary(lambda[i], zeta[i])` to 1e-12,
/// and [`summary4`]'s bits, whatever the slices' length. The whole groups go straight from
/// the slices to the lanes and back (no padding, one copy of the eight answers), the scalar
/// path asked only where a lane came back `None`.
pub fn summaries(lambda: &[f64], zeta: &[f64], out: &mut [Option<Summary>]) {
    assert!(lambda.len() == zeta.len() && zeta.len() == out.len());
    let whole = lambda.len() - lambda.len() % WIDE;
    for ((l, z), o) in lambda[..whole]
        .chunks_exact(WIDE)
        .zip(zeta[..whole].chunks_exact(WIDE))
        .zip(out[..whole].chunks_exact_mut(WIDE))
    {
        let (l, z): ([f64; WIDE], [f64; WIDE]) = (l.try_into().unwrap(), z.try_into().unwrap());
        o.copy_from_slice(&lanes_only8(l, z));
        hand_back(&l, &z, o);
    }
    if whole < lambda.len() {
        let pad = |s: &[f64]| -> [f64; WIDE] { std::array::from_fn(|i| s[i.min(s.len() - 1)]) };
        let (l, z) = (pad(&lambda[whole..]), pad(&zeta[whole..]));
        let lanes = lanes_only8(l, z);
        let o = &mut out[whole..];
        o.copy_from_slice(&lanes[..o.len()]);
        hand_back(&l, &z, o);
    }
}

/// The scalar path's answer in every lane of `o` the lanes left `None`.
#[inline(always)]
fn hand_back(l: &[f64; WIDE], z: &[f64; WIDE], o: &mut [Option<Summary>]) {
    for (i, o) in o.iter_mut().enumerate() {
        if o.is_none() {
            *o = super::summary(l[i], z[i]);
        }
    }
}
