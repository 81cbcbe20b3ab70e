//! What the lanes' kernel asks of four f64 side by side ([`Lane`]), and its portable answer:
//! `wide`'s `f64x4` (two SSE2 registers on the default x86-64 target).
//!
//! The kernel is written once over [`Lane`] and compiled for three lane types: `f64x4` here,
//! `Avx` (one 256-bit register, `avx.rs`) and `Pair` of two `Avx` (`pair.rs`). Every primitive
//! is exact or a single IEEE operation correctly rounded (+, −, ×, ÷, √, floor, comparisons,
//! bit selection and shifts), so every lane type gives the same bits for the same operations;
//! everything else (`max`, `min`, `is_finite`, the exponential, `atan2` and `cbrt` of
//! `math.rs`) is built from the primitives, in [`Lane`]'s provided methods or `math.rs`, once
//! for all. `sin_cos` (the rare long step) is `wide`'s in all: the same function, the same
//! bits.

use std::ops::{Add, BitAnd, BitAndAssign, BitOr, BitOrAssign, Div, Mul, Neg, Not, Sub};
use wide::f64x4;

/// Impacts per call of the kernel: the lanes of a `Lane`.
pub const LANES: usize = 4;

/// Four f64 side by side and what the kernel does with them. A mask is a value whose lanes
/// are all ones (true) or all zeros (false), as the comparisons give them.
pub trait Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
    + BitAndAssign
    + BitOrAssign
    + Not<Output = Self>
{
    /// The lanes' values in memory: `[f64; n]` for n lanes.
    type Array: Copy + AsRef<[f64]>;
    /// x in every lane.
    fn splat(x: f64) -> Self;
    /// The lanes from an array, lane i from `a[i]`.
    fn from_array(a: Self::Array) -> Self;
    /// The lanes as an array.
    fn to_array(self) -> Self::Array;
    /// √x, correctly rounded.
    fn sqrt(self) -> Self;
    /// ⌊x⌋, exact.
    fn floor(self) -> Self;
    /// |x| (the sign bit cleared).
    fn abs(self) -> Self;
    /// The lanes whose sign bit is set (−0 included).
    fn sign_negative(self) -> Self;
    /// self = other (false where either is NaN).
    fn eq(self, other: Self) -> Self;
    /// self ≠ other (true where either is NaN, as SSE2's `cmpneqpd`).
    fn ne(self, other: Self) -> Self;
    /// self < other (false where either is NaN).
    fn lt(self, other: Self) -> Self;
    /// self ≤ other.
    fn le(self, other: Self) -> Self;
    /// self > other.
    fn gt(self, other: Self) -> Self;
    /// self ≥ other.
    fn ge(self, other: Self) -> Self;
    /// Per lane, `yes` where the mask `self` is true, else `no`.
    fn select(self, yes: Self, no: Self) -> Self;
    /// Bit i set where lane i of the mask is true.
    fn bitmask(self) -> u32;
    /// The bits of x shifted left by 52: 2ⁿ where x = 2⁵² + 1023 + n for an integer
    /// n ∈ [−1022, 1023] (its last 11 bits are n's biased exponent: `math::exp`).
    fn shl52(self) -> Self;
    /// The bits of x shifted right by 52: a non-negative x's biased exponent in the last 11
    /// bits (`math::cbrt`).
    fn shr52(self) -> Self;

    /// Any lane of the mask true.
    #[inline(always)]
    fn any(self) -> bool {
        self.bitmask() != 0
    }
    /// The larger of the two, `self` where `other` is NaN (a compare and a select: the same
    /// bits in every lane type).
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        other.gt(self).select(other, self)
    }
    /// The smaller of the two, `self` where `other` is NaN.
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        other.lt(self).select(other, self)
    }
    /// The finite lanes: x − x is 0 exactly there, NaN at ±∞ and NaN.
    #[inline(always)]
    #[allow(clippy::eq_op)] // x − x on purpose: 0 or NaN says finite or not
    fn is_finite(self) -> Self {
        (self - self).eq(Self::splat(0.0))
    }
    /// (sin x, cos x), `wide`'s (the same function in every lane type: `wide_sin_cos`).
    fn sin_cos(self) -> (Self, Self);
    /// self·m + a rounded once (a fused multiply-add, IEEE 754's fusedMultiplyAdd): the same
    /// bits in every lane type.
    fn mul_add(self, m: Self, a: Self) -> Self;
}

/// (sin x, cos x) of four lanes by `wide`'s `f64x4::sin_cos`, whatever register they are in
/// (the AVX lanes'; the portable lanes are `f64x4` and call it directly).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub fn wide_sin_cos<L: Lane<Array = [f64; LANES]>>(x: L) -> (L, L) {
    let (s, c) = f64x4::new(x.to_array()).sin_cos();
    (L::from_array(s.to_array()), L::from_array(c.to_array()))
}

impl Lane for f64x4 {
    type Array = [f64; LANES];
    /// `f64::mul_add` lane by lane: correctly rounded everywhere (libm's `fma` where the
    /// target has no FMA instruction), where `wide`'s `f64x4::mul_add` multiplies and adds
    /// apart without FMA at compile time (two roundings: not the AVX kernel's bits).
    #[inline(always)]
    fn mul_add(self, m: Self, a: Self) -> Self {
        let (x, y, z) = (self.to_array(), m.to_array(), a.to_array());
        f64x4::new([
            x[0].mul_add(y[0], z[0]),
            x[1].mul_add(y[1], z[1]),
            x[2].mul_add(y[2], z[2]),
            x[3].mul_add(y[3], z[3]),
        ])
    }
    #[inline(always)]
    fn splat(x: f64) -> Self {
        f64x4::splat(x)
    }
    #[inline(always)]
    fn from_array(a: [f64; LANES]) -> Self {
        f64x4::new(a)
    }
    #[inline(always)]
    fn to_array(self) -> [f64; LANES] {
        f64x4::to_array(self)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        f64x4::sqrt(self)
    }
    #[inline(always)]
    fn floor(self) -> Self {
        f64x4::floor(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f64x4::abs(self)
    }
    #[inline(always)]
    fn sign_negative(self) -> Self {
        f64x4::is_sign_negative(self)
    }
    #[inline(always)]
    fn eq(self, other: Self) -> Self {
        f64x4::simd_eq(self, other)
    }
    #[inline(always)]
    fn ne(self, other: Self) -> Self {
        f64x4::simd_ne(self, other)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Self {
        f64x4::simd_lt(self, other)
    }
    #[inline(always)]
    fn le(self, other: Self) -> Self {
        f64x4::simd_le(self, other)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Self {
        f64x4::simd_gt(self, other)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> Self {
        f64x4::simd_ge(self, other)
    }
    #[inline(always)]
    fn select(self, yes: Self, no: Self) -> Self {
        f64x4::select(self, yes, no)
    }
    #[inline(always)]
    fn bitmask(self) -> u32 {
        f64x4::to_bitmask(self)
    }
    #[inline(always)]
    fn shl52(self) -> Self {
        let bits: wide::u64x4 = wide::bytemuck::cast(self);
        wide::bytemuck::cast(bits << 52_u32)
    }
    #[inline(always)]
    fn shr52(self) -> Self {
        let bits: wide::u64x4 = wide::bytemuck::cast(self);
        wide::bytemuck::cast(bits >> 52_u32)
    }
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        f64x4::sin_cos(self)
    }
}
