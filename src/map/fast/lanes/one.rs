//! [`One`]: one f64 as a [`Lane`] of width one — the flattening kernel's compilation for a
//! cell alone (`flatten::flattening_one`: the explorer's cursor, `run`, a row), so that a lone
//! cell runs the map's operations on its own (λ, ζ, z̄_p) without seven padded copies beside it.
//!
//! Written by hand: the lane primitives are single IEEE operations on f64 (+, −, ×, ÷, √,
//! floor, comparisons) and bit operations on its representation, which no crate offers as one
//! type with masks. Each method is the scalar form of what `wide`'s `f64x4` and the AVX lane
//! type do to each of their lanes, so lane 0 of `One` is any lane of theirs bit for bit
//! (`one_lane_is_the_maps_lane_bit_for_bit`, tests/physics/map_flatten_lanes.rs): the same correctly
//! rounded operations, `mul_add` a fused multiply-add (`f64::mul_add`: one `vfmadd` where the
//! caller enables FMA, libm's `fma` elsewhere — the same bits), `sin_cos` `wide`'s
//! `f64x4::sin_cos` of the value splatted (the function the other lane types call).
//! A mask is all ones or all zeros in the f64's bits, as theirs.

use super::super::super::lane::Lane;
use std::ops::{Add, BitAnd, BitAndAssign, BitOr, BitOrAssign, Div, Mul, Neg, Not, Sub};
use wide::f64x4;

/// One f64, a lane of width one.
#[derive(Clone, Copy)]
pub struct One(f64);

/// The mask of a comparison's answer: all ones where true, zeros where false.
#[inline(always)]
fn mask(b: bool) -> One {
    One(f64::from_bits(u64::from(b).wrapping_neg()))
}

/// A binary operator on the values or on their bits.
macro_rules! binary {
    ($tr:ident, $f:ident, |$a:ident, $b:ident| $e:expr) => {
        impl $tr for One {
            type Output = One;
            #[inline(always)]
            fn $f(self, o: One) -> One {
                let ($a, $b) = (self.0, o.0);
                One($e)
            }
        }
    };
}

binary!(Add, add, |a, b| a + b);
binary!(Sub, sub, |a, b| a - b);
binary!(Mul, mul, |a, b| a * b);
binary!(Div, div, |a, b| a / b);
binary!(BitAnd, bitand, |a, b| f64::from_bits(
    a.to_bits() & b.to_bits()
));
binary!(BitOr, bitor, |a, b| f64::from_bits(
    a.to_bits() | b.to_bits()
));

impl Neg for One {
    type Output = One;
    /// The sign bit flipped.
    #[inline(always)]
    fn neg(self) -> One {
        One(-self.0)
    }
}

impl Not for One {
    type Output = One;
    #[inline(always)]
    fn not(self) -> One {
        One(f64::from_bits(!self.0.to_bits()))
    }
}

impl BitAndAssign for One {
    #[inline(always)]
    fn bitand_assign(&mut self, o: One) {
        *self = *self & o;
    }
}

impl BitOrAssign for One {
    #[inline(always)]
    fn bitor_assign(&mut self, o: One) {
        *self = *self | o;
    }
}

impl Lane for One {
    type Array = [f64; 1];
    #[inline(always)]
    fn splat(x: f64) -> One {
        One(x)
    }
    #[inline(always)]
    fn from_array(a: [f64; 1]) -> One {
        One(a[0])
    }
    #[inline(always)]
    fn to_array(self) -> [f64; 1] {
        [self.0]
    }
    #[inline(always)]
    fn sqrt(self) -> One {
        One(self.0.sqrt())
    }
    #[inline(always)]
    fn floor(self) -> One {
        One(self.0.floor())
    }
    #[inline(always)]
    fn abs(self) -> One {
        One(self.0.abs())
    }
    #[inline(always)]
    fn sign_negative(self) -> One {
        mask(self.0.is_sign_negative())
    }
    #[inline(always)]
    fn eq(self, o: One) -> One {
        mask(self.0 == o.0)
    }
    /// True where either is NaN, as the other lane types' unordered ≠.
    #[inline(always)]
    fn ne(self, o: One) -> One {
        mask(self.0 != o.0)
    }
    #[inline(always)]
    fn lt(self, o: One) -> One {
        mask(self.0 < o.0)
    }
    #[inline(always)]
    fn le(self, o: One) -> One {
        mask(self.0 <= o.0)
    }
    #[inline(always)]
    fn gt(self, o: One) -> One {
        mask(self.0 > o.0)
    }
    #[inline(always)]
    fn ge(self, o: One) -> One {
        mask(self.0 >= o.0)
    }
    /// `yes` where the mask is true: its bits all ones or all zeros, so its sign bit decides
    /// (as AVX's `blendv`).
    #[inline(always)]
    fn select(self, yes: One, no: One) -> One {
        if self.0.is_sign_negative() { yes } else { no }
    }
    #[inline(always)]
    fn bitmask(self) -> u32 {
        (self.0.to_bits() >> 63) as u32
    }
    #[inline(always)]
    fn shl52(self) -> One {
        One(f64::from_bits(self.0.to_bits() << 52))
    }
    #[inline(always)]
    fn shr52(self) -> One {
        One(f64::from_bits(self.0.to_bits() >> 52))
    }
    #[inline(always)]
    fn sin_cos(self) -> (One, One) {
        let (s, c) = f64x4::splat(self.0).sin_cos();
        (One(s.to_array()[0]), One(c.to_array()[0]))
    }
    #[inline(always)]
    fn mul_add(self, m: One, a: One) -> One {
        One(self.0.mul_add(m.0, a.0))
    }
}
