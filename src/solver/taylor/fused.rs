//! The 3/2-power phases' sums by fused multiply–adds (`rules::Sums::Fused`): Horner's for a
//! step's end, Estrin's for an event's state and for the roots (their series: `power::fast`,
//! compiled with FMA by `super::series_one` and `super::batch`), and the elastic–plastic
//! straight stretch's roots (`linear::stretch`). Each term is one
//! `mul_add`, rounded once: one instruction where the CPU has FMA (these functions pick a
//! compilation with it), libm's `fma` elsewhere, the same bits either way
//! (`batch::tests::series_are_the_same_bits_without_fma_instructions` holds the series so).
//! The lanes of `super::batch` run [`horner`] on their own FMA compilation, so a lane's
//! sums are the single path's bits (tests/physics/taylor_batch.rs).

use super::poly::{self, Coef};

/// Σ c_k h^k by Horner's rule, each step one fused multiply–add: half the latency of a
/// product and a sum.
#[inline(always)]
pub(super) fn horner<T: Coef, const L: usize>(c: &[T; L], h: T) -> T {
    c.iter()
        .rev()
        .fold(T::splat(0.0), |acc, &ck| acc.mul_add(h, ck))
}

/// Σ c_k h^k by Estrin's scheme (`poly::eval_estrin`'s pairs), each pair c_{2i} + c_{2i+1} x
/// one fused multiply–add.
#[inline(always)]
fn estrin<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    poly::estrin_by(c, h, |low, high, x| high.mul_add(x, low))
}

/// Whether the CPU has FMA, for the compilations below (elsewhere than x86-64 the build's
/// own target decides: aarch64 always has it).
#[cfg(target_arch = "x86_64")]
fn has_fma() -> bool {
    std::arch::is_x86_feature_detected!("fma")
}

/// [`horner`] on f64, compiled with FMA where the CPU has it.
pub(super) fn horner_one<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the CPU has FMA, the only feature the function enables
        return unsafe { horner_fma(c, h) };
    }
    horner(c, h)
}

/// [`estrin`], compiled with FMA where the CPU has it.
pub(super) fn estrin_one<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the CPU has FMA, the only feature the function enables
        return unsafe { estrin_fma(c, h) };
    }
    estrin(c, h)
}

/// `poly::root_quick`'s search with [`estrin`]'s sums, ended a Newton step sooner where it
/// can (`poly::Stop::Predicted`), compiled with FMA where the CPU has it: the first h in
/// (0, `end`] where c(h) = `target`, c(end) being `c_end`.
pub(super) fn root<const L: usize>(c: &[f64; L], target: f64, end: f64, c_end: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the CPU has FMA, the only feature the function enables
        return unsafe { root_fma(c, target, end, c_end) };
    }
    root_in(c, target, end, c_end)
}

#[inline(always)]
fn root_in<const L: usize>(c: &[f64; L], target: f64, end: f64, c_end: f64) -> f64 {
    poly::root_quick_by(c, target, end, c_end, estrin, poly::Stop::Predicted)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn horner_fma<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    horner(c, h)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn estrin_fma<const L: usize>(c: &[f64; L], h: f64) -> f64 {
    estrin(c, h)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "fma")]
fn root_fma<const L: usize>(c: &[f64; L], target: f64, end: f64, c_end: f64) -> f64 {
    root_in(c, target, end, c_end)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FMA compilations give the bits of this test's own compilation, where `mul_add`
    /// is libm's `fma` (as on a CPU without FMA): sums and roots of series of order 28 whose
    /// terms fall as a phase's do, at steps across (0, 1].
    #[test]
    fn sums_and_roots_are_the_same_bits_without_fma_instructions() {
        for round in 0..64 {
            let mut c = [0.0; 29];
            for (k, ck) in c.iter_mut().enumerate() {
                let sign = if (k * 7 + round) % 3 == 0 { -1.0 } else { 1.0 };
                *ck = sign * (1.0 + ((k * 13 + round * 5) % 17) as f64 / 17.0)
                    / 1.7f64.powi(k as i32);
            }
            c[0] = 0.4 + round as f64 / 100.0;
            c[1] = -1.0;
            let h = (1 + round) as f64 / 64.0;
            assert_eq!(
                horner_one(&c, h).to_bits(),
                horner(&c, h).to_bits(),
                "{round}"
            );
            assert_eq!(
                estrin_one(&c, h).to_bits(),
                estrin(&c, h).to_bits(),
                "{round}"
            );
            let c_end = estrin(&c, 1.0);
            let target = 0.5 * (c[0] + c_end);
            let fused = root(&c, target, 1.0, c_end);
            assert_eq!(
                fused.to_bits(),
                root_in(&c, target, 1.0, c_end).to_bits(),
                "{round}"
            );
            assert!(
                (estrin(&c, fused) - target).abs() < 1e-14,
                "{round}: {fused}"
            );
        }
    }
}
