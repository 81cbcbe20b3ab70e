//! Which compilation of the lanes' kernel runs ([`super::lanes::kernel`]): the AVX2 one where
//! the CPU has AVX2 (asked once at run time: `is_x86_feature_detected!` caches it), the
//! build's portable one elsewhere (issue 30 item 3).
//!
//! Why a `#[target_feature]` compilation of the same code rather than another lane type:
//! `wide` picks its representation when it is compiled (two SSE2 registers per `f64x4` on
//! the default x86-64 target), so a second `wide` for AVX cannot sit beside the first in one
//! build. Compiled inside an `avx2` function, the same operations take the VEX encodings
//! (three operands: fewer register copies) and whatever LLVM widens. FMA is deliberately not
//! enabled: Rust never fuses a multiply and an add by itself, so the AVX2 kernel rounds every
//! operation as the portable one does and its answers are the same bits
//! (`avx2_and_portable_kernels_agree_bit_for_bit`) — a map's CSV does not depend on the CPU.
//! Measured in BENCHMARKS.md ("The map through the lanes").

use super::Summary;
use super::lanes::{LANES, lanes_only_portable};

/// [`super::lanes::lanes_only`]: the AVX2 kernel where the CPU has it, the portable one
/// elsewhere.
pub(super) fn lanes_only(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, just checked
        return unsafe { lanes_only_avx2(lambda, zeta) };
    }
    lanes_only_portable(lambda, zeta)
}

/// The kernel compiled with AVX2 enabled.
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn lanes_only_avx2(lambda: [f64; LANES], zeta: [f64; LANES]) -> [Option<Summary>; LANES] {
    super::lanes::kernel(lambda, zeta)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The dispatched kernel (AVX2 on this machine if it has it) and the portable one give
    /// the same bits over the 200 × 120 map's grid: no FMA, the same roundings, so a CPU
    /// without AVX2 prints the same map.
    #[test]
    fn avx2_and_portable_kernels_agree_bit_for_bit() {
        let log = |i: usize, n: usize| 10f64.powf(-2.0 + 4.0 * i as f64 / (n - 1) as f64);
        let mut answered = 0;
        for i in 0..120 {
            for j in (0..200).step_by(LANES) {
                let l = [log(i, 120); LANES];
                let z = std::array::from_fn(|k| log(j + k, 200));
                let (a, b) = (lanes_only(l, z), lanes_only_portable(l, z));
                let bits = |s: &Option<Summary>| {
                    s.map(|s| [s.cor, s.max_force, s.contact_time].map(f64::to_bits))
                };
                for k in 0..LANES {
                    assert_eq!(bits(&a[k]), bits(&b[k]), "λ {}, ζ {}", l[k], z[k]);
                    answered += usize::from(a[k].is_some());
                }
            }
        }
        // most lanes answer themselves: the comparison is of numbers, not of Nones
        assert!(answered >= 20_000, "{answered}");
    }
}
