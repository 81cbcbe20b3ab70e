//! [`Lane`] in one 256-bit AVX register (`__m256d`): the lane type of the kernel's AVX2
//! compilation (`lanes_only_avx2`).
//!
//! Written by hand over `core::arch` because no crate gives it on stable Rust: `wide` picks its
//! `f64x4`'s representation when it is compiled (two SSE2 registers on the default target,
//! whatever a `#[target_feature]` function around it enables), `sleef`'s Rust ports need the
//! nightly `std::simd`, and the stable SIMD crates found (`simd_vector`, `pulp`) offer no f64
//! exponential or `atan2`. Each method is one instruction, `#[inline(always)]`, so that inside
//! the `#[target_feature(enable = "avx2")]` kernel the intrinsics inline and the values stay in
//! ymm registers (BENCHMARKS.md, "The lanes in one AVX register").
//!
//! Safety: every intrinsic here needs AVX (`shl52`, `shr52` and `sign_negative` AVX2, `mul_add`
//! FMA). An [`Avx`] is only made inside the kernel's AVX2 compilation (AVX2 and FMA enabled),
//! which [`super::lanes_only`] calls after `is_x86_feature_detected!` of both: the module is private to the lanes, and no value of the
//! type leaves the kernel.

use super::lane::{LANES, Lane, wide_sin_cos};
use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitAndAssign, BitOr, BitOrAssign, Div, Mul, Neg, Not, Sub};

/// Four f64 in one AVX register.
#[derive(Clone, Copy)]
pub struct Avx(__m256d);

/// `Avx(intrinsic(...))`, the intrinsic run in an unsafe block (the module's safety note).
macro_rules! op {
    ($e:expr) => {
        // SAFETY: an Avx exists only where the CPU has AVX2 (the module's safety note)
        Avx(unsafe { $e })
    };
}

macro_rules! binary {
    ($tr:ident, $f:ident, $intr:ident) => {
        impl $tr for Avx {
            type Output = Avx;
            #[inline(always)]
            fn $f(self, o: Avx) -> Avx {
                op!($intr(self.0, o.0))
            }
        }
    };
}

binary!(Add, add, _mm256_add_pd);
binary!(Sub, sub, _mm256_sub_pd);
binary!(Mul, mul, _mm256_mul_pd);
binary!(Div, div, _mm256_div_pd);
binary!(BitAnd, bitand, _mm256_and_pd);
binary!(BitOr, bitor, _mm256_or_pd);

impl Neg for Avx {
    type Output = Avx;
    /// The sign bit flipped, as `-x` on a scalar.
    #[inline(always)]
    fn neg(self) -> Avx {
        op!(_mm256_xor_pd(self.0, _mm256_set1_pd(-0.0)))
    }
}

impl Not for Avx {
    type Output = Avx;
    #[inline(always)]
    fn not(self) -> Avx {
        op!(_mm256_xor_pd(
            self.0,
            _mm256_castsi256_pd(_mm256_set1_epi64x(-1))
        ))
    }
}

impl BitAndAssign for Avx {
    #[inline(always)]
    fn bitand_assign(&mut self, o: Avx) {
        *self = *self & o;
    }
}

impl BitOrAssign for Avx {
    #[inline(always)]
    fn bitor_assign(&mut self, o: Avx) {
        *self = *self | o;
    }
}

/// A comparison as its AVX predicate: ordered (false where either is NaN) but for ≠,
/// unordered (true there), as SSE2's `cmpltpd` … `cmpneqpd` that `wide`'s portable `f64x4`
/// runs, so that both lane types give the same masks.
macro_rules! compare {
    ($f:ident, $pred:ident) => {
        #[inline(always)]
        fn $f(self, o: Avx) -> Avx {
            op!(_mm256_cmp_pd::<$pred>(self.0, o.0))
        }
    };
}

impl Lane for Avx {
    type Array = [f64; LANES];
    #[inline(always)]
    fn splat(x: f64) -> Avx {
        op!(_mm256_set1_pd(x))
    }
    #[inline(always)]
    fn from_array(a: [f64; LANES]) -> Avx {
        op!(_mm256_loadu_pd(a.as_ptr()))
    }
    #[inline(always)]
    fn to_array(self) -> [f64; LANES] {
        let mut a = [0.0; LANES];
        // SAFETY: a holds four f64; the CPU has AVX (the module's safety note)
        unsafe { _mm256_storeu_pd(a.as_mut_ptr(), self.0) };
        a
    }
    #[inline(always)]
    fn sqrt(self) -> Avx {
        op!(_mm256_sqrt_pd(self.0))
    }
    #[inline(always)]
    fn floor(self) -> Avx {
        op!(_mm256_floor_pd(self.0))
    }
    #[inline(always)]
    fn abs(self) -> Avx {
        op!(_mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0))
    }
    /// 0 > the bits as a signed integer: the sign bit set.
    #[inline(always)]
    fn sign_negative(self) -> Avx {
        op!(_mm256_castsi256_pd(_mm256_cmpgt_epi64(
            _mm256_setzero_si256(),
            _mm256_castpd_si256(self.0)
        )))
    }
    compare!(eq, _CMP_EQ_OQ);
    compare!(ne, _CMP_NEQ_UQ);
    compare!(lt, _CMP_LT_OQ);
    compare!(le, _CMP_LE_OQ);
    compare!(gt, _CMP_GT_OQ);
    compare!(ge, _CMP_GE_OQ);
    /// `vfmadd` (FMA3): the kernel's AVX2 compilation enables FMA too, and runs only where
    /// the CPU has both (`lanes.rs`).
    #[inline(always)]
    fn mul_add(self, m: Avx, a: Avx) -> Avx {
        op!(_mm256_fmadd_pd(self.0, m.0, a.0))
    }
    #[inline(always)]
    fn select(self, yes: Avx, no: Avx) -> Avx {
        op!(_mm256_blendv_pd(no.0, yes.0, self.0))
    }
    #[inline(always)]
    fn bitmask(self) -> u32 {
        // SAFETY: the CPU has AVX (the module's safety note)
        unsafe { _mm256_movemask_pd(self.0) as u32 }
    }
    #[inline(always)]
    fn shl52(self) -> Avx {
        op!(_mm256_castsi256_pd(_mm256_slli_epi64::<52>(
            _mm256_castpd_si256(self.0)
        )))
    }
    #[inline(always)]
    fn shr52(self) -> Avx {
        op!(_mm256_castsi256_pd(_mm256_srli_epi64::<52>(
            _mm256_castpd_si256(self.0)
        )))
    }
    #[inline(always)]
    fn sin_cos(self) -> (Avx, Avx) {
        wide_sin_cos(self)
    }
}
