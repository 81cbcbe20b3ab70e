//! The batch's lane type: W f64 lanes with IEEE operations lane by lane, which the
//! `#[target_feature]` compilations of `super` pack into AVX-512 or AVX2 registers.

use super::super::poly::Coef;
use super::super::power::Coefs;
use std::ops::{Add, Mul, Sub};

/// W f64 lanes, each operation IEEE lane by lane.
#[derive(Clone, Copy)]
#[repr(align(64))]
pub(super) struct Lanes<const W: usize>(pub(super) [f64; W]);

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl<const W: usize> $tr for Lanes<W> {
            type Output = Lanes<W>;
            #[inline(always)]
            fn $f(self, o: Lanes<W>) -> Lanes<W> {
                Lanes(std::array::from_fn(|i| self.0[i] $op o.0[i]))
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);

impl<const W: usize> Coef for Lanes<W> {
    #[inline(always)]
    fn splat(x: f64) -> Lanes<W> {
        Lanes([x; W])
    }
    #[inline(always)]
    fn mul_add(self, a: Lanes<W>, b: Lanes<W>) -> Lanes<W> {
        Lanes(std::array::from_fn(|i| self.0[i].mul_add(a.0[i], b.0[i])))
    }
}

impl<const W: usize> Coefs<Lanes<W>> {
    /// The system `k` in every lane.
    pub(super) fn splat(k: Coefs<f64>) -> Coefs<Lanes<W>> {
        Coefs {
            two_zeta: Lanes::splat(k.two_zeta),
            lambda: Lanes::splat(k.lambda),
            a: Lanes::splat(k.a),
            minus_a: Lanes::splat(k.minus_a),
            half_b: Lanes::splat(k.half_b),
        }
    }

    /// Lane j given the system `k`.
    pub(super) fn set_lane(&mut self, j: usize, k: Coefs<f64>) {
        self.two_zeta.0[j] = k.two_zeta;
        self.lambda.0[j] = k.lambda;
        self.a.0[j] = k.a;
        self.minus_a.0[j] = k.minus_a;
        self.half_b.0[j] = k.half_b;
    }
}

/// The lanes whose j-th entry is `f(j)`: generic, so that `f` is inlined and the lanes
/// vectorised (a `&dyn Fn` was inlined or not as the optimiser's budget went), and a loop,
/// not `std::array::from_fn`, whose inner function the optimiser may leave out of line and
/// so out of the caller's AVX-512 or AVX2 compilation.
#[inline(always)]
pub(super) fn each<const W: usize>(f: impl Fn(usize) -> f64) -> Lanes<W> {
    let mut lanes = [0.0; W];
    for (j, lane) in lanes.iter_mut().enumerate() {
        *lane = f(j);
    }
    Lanes(lanes)
}
