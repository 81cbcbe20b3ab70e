//! [`Pair`]: two lane values side by side as one [`Lane`] of twice the width, each operation
//! run on both halves — the kernel's eight-lane compilation (`lanes_only8`, two AVX registers).
//!
//! Why: the kernel is a long chain of dependent operations (Cardano and Newton's divisions,
//! the flow's coefficients, `atan2` and the exponentials' Horner sums, Householder's steps), so
//! one register of four lanes leaves the core waiting on latency (an instruction a cycle or
//! so). Two independent registers in one instruction stream give the out-of-order core a
//! second chain to run in those waits (BENCHMARKS.md, "Two registers in one stream"). Each
//! half runs exactly the operations it would run alone, so a lane's bits are its four-lane
//! kernel's (`eight_lanes_are_two_fours_bit_for_bit`, tests/physics/map_lanes.rs): the loops that stop
//! when no lane is active only run longer, on lanes whose answers are masked off.

use super::lane::Lane;
use std::ops::{Add, BitAnd, BitAndAssign, BitOr, BitOrAssign, Div, Mul, Neg, Not, Sub};

/// Two lane values; lane i of the pair is lane i of the first for i < the first's width, else
/// lane i − width of the second.
#[derive(Clone, Copy)]
pub struct Pair<L>(L, L);

macro_rules! binary {
    ($tr:ident, $f:ident) => {
        impl<L: Lane> $tr for Pair<L> {
            type Output = Pair<L>;
            #[inline(always)]
            fn $f(self, o: Pair<L>) -> Pair<L> {
                Pair(self.0.$f(o.0), self.1.$f(o.1))
            }
        }
    };
}

binary!(Add, add);
binary!(Sub, sub);
binary!(Mul, mul);
binary!(Div, div);
binary!(BitAnd, bitand);
binary!(BitOr, bitor);

impl<L: Lane> Neg for Pair<L> {
    type Output = Pair<L>;
    #[inline(always)]
    fn neg(self) -> Pair<L> {
        Pair(-self.0, -self.1)
    }
}

impl<L: Lane> Not for Pair<L> {
    type Output = Pair<L>;
    #[inline(always)]
    fn not(self) -> Pair<L> {
        Pair(!self.0, !self.1)
    }
}

impl<L: Lane> BitAndAssign for Pair<L> {
    #[inline(always)]
    fn bitand_assign(&mut self, o: Pair<L>) {
        *self = *self & o;
    }
}

impl<L: Lane> BitOrAssign for Pair<L> {
    #[inline(always)]
    fn bitor_assign(&mut self, o: Pair<L>) {
        *self = *self | o;
    }
}

/// A method of one argument on both halves.
macro_rules! unary {
    ($($f:ident),*) => {
        $(
            #[inline(always)]
            fn $f(self) -> Pair<L> {
                Pair(self.0.$f(), self.1.$f())
            }
        )*
    };
}

/// A comparison on both halves.
macro_rules! compare {
    ($($f:ident),*) => {
        $(
            #[inline(always)]
            fn $f(self, o: Pair<L>) -> Pair<L> {
                Pair(self.0.$f(o.0), self.1.$f(o.1))
            }
        )*
    };
}

/// The lanes of a pair of four-lane values: eight (the kernel's `Array`s are fixed-size).
const WIDTH: usize = 8;

impl<L: Lane<Array = [f64; WIDTH / 2]>> Lane for Pair<L> {
    type Array = [f64; WIDTH];
    #[inline(always)]
    fn splat(x: f64) -> Pair<L> {
        Pair(L::splat(x), L::splat(x))
    }
    #[inline(always)]
    fn from_array(a: [f64; WIDTH]) -> Pair<L> {
        let [a0, a1, a2, a3, a4, a5, a6, a7] = a;
        Pair(
            L::from_array([a0, a1, a2, a3]),
            L::from_array([a4, a5, a6, a7]),
        )
    }
    #[inline(always)]
    fn to_array(self) -> [f64; WIDTH] {
        let ([a0, a1, a2, a3], [a4, a5, a6, a7]) = (self.0.to_array(), self.1.to_array());
        [a0, a1, a2, a3, a4, a5, a6, a7]
    }
    unary!(sqrt, floor, abs, sign_negative, shl52, shr52);
    compare!(eq, ne, lt, le, gt, ge);
    #[inline(always)]
    fn select(self, yes: Pair<L>, no: Pair<L>) -> Pair<L> {
        Pair(self.0.select(yes.0, no.0), self.1.select(yes.1, no.1))
    }
    #[inline(always)]
    fn bitmask(self) -> u32 {
        self.0.bitmask() | self.1.bitmask() << (WIDTH / 2)
    }
    #[inline(always)]
    fn mul_add(self, m: Pair<L>, a: Pair<L>) -> Pair<L> {
        Pair(self.0.mul_add(m.0, a.0), self.1.mul_add(m.1, a.1))
    }
    #[inline(always)]
    fn sin_cos(self) -> (Pair<L>, Pair<L>) {
        let ((s0, c0), (s1, c1)) = (self.0.sin_cos(), self.1.sin_cos());
        (Pair(s0, s1), Pair(c0, c1))
    }
}
