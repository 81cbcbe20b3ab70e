//! How a phase's steps are taken: the step rule, the sums and the roots each phase's rules
//! pick (`poly`'s, or `fused`'s for the elastic–plastic and Hertz phases).

use super::{fused, poly};

/// How a phase's steps are taken: their truncation `eps` and their [`Sums`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Rules {
    pub eps: f64,
    pub sums: Sums,
}

/// The step rule, sums and roots a phase takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Sums {
    /// `powf` and Horner's sums ([`poly::step_of_norms`], [`poly::root`]): the Hertz table's
    /// reference, whose nodes tests/physics/hertz_table.rs holds to the committed file's bits.
    Reference,
    /// The quick rule and roots ([`poly::quick_step_of_norms`], [`poly::root_quick`]), each
    /// product and sum rounded apart: the linear phases, so that the linear law's answers
    /// keep their bits.
    Quick,
    /// The quick rule with its norms by the scales' reciprocals, fused sums and roots
    /// (`super::fused`), the roots a Newton step sooner where they can
    /// (`poly::Stop::Predicted`): the 3/2-power phases, and the elastic–plastic straight
    /// stretch's step and roots (its sums are `linear`'s own).
    Fused,
}

impl Rules {
    /// The reference's: order 20 within [`poly::EPS`], `powf` and Horner.
    pub(super) const REFERENCE: Rules = Rules {
        eps: poly::EPS,
        sums: Sums::Reference,
    };

    /// Whether the steps are the quick rule's ([`poly::quick_step_of_norms`]).
    pub(super) const fn is_quick(&self) -> bool {
        !matches!(self.sums, Sums::Reference)
    }

    /// The step from the norms of the last two terms of series of order `order`.
    #[inline(always)]
    pub(super) fn step_of_norms(&self, next_to_last: f64, last: f64, order: usize) -> f64 {
        if self.is_quick() {
            poly::quick_step_of_norms(next_to_last, last, order, self.eps)
        } else {
            poly::step_of_norms(next_to_last, last, order, self.eps)
        }
    }

    /// Σ c_k h^k where few other sums wait on it: by Estrin's scheme where quick
    /// ([`poly::eval_estrin`], fused: `fused::estrin_one`), by Horner's for the reference.
    #[inline(always)]
    pub(super) fn eval<const L: usize>(&self, c: &[f64; L], h: f64) -> f64 {
        match self.sums {
            Sums::Fused => fused::estrin_one(c, h),
            Sums::Quick => poly::eval_estrin(c, h),
            Sums::Reference => poly::eval(c, h),
        }
    }

    /// Σ c_k h^k at a step's end, as `super::batch` sums it in lanes: by Horner's rule,
    /// fused where the rules are (`fused::horner_one`).
    #[inline(always)]
    pub(super) fn horner<const L: usize>(&self, c: &[f64; L], h: f64) -> f64 {
        match self.sums {
            Sums::Fused => fused::horner_one(c, h),
            Sums::Quick | Sums::Reference => poly::eval(c, h),
        }
    }

    /// The first h in (0, `end`] where `c(h) = target` ([`poly::root`]), `c_end` being the
    /// caller's c(end): the quick roots take it rather than sum it again; the reference sums
    /// its own, so that its bits stay the committed table's.
    pub(super) fn root<const L: usize>(
        &self,
        c: &[f64; L],
        target: f64,
        end: f64,
        c_end: f64,
    ) -> f64 {
        match self.sums {
            Sums::Fused => fused::root(c, target, end, c_end),
            Sums::Quick => poly::root_quick(c, target, end, c_end),
            Sums::Reference => poly::root(c, target, end),
        }
    }

    /// The step after which every series' last two terms, each relative to its `scales`
    /// entry, stay below `eps` ([`poly::step_of_norms`]): the norms are taken first, each
    /// term divided by its scale; under the fused rules multiplied by the scale's reciprocal,
    /// one division a series rather than two (`super::batch::quick_steps` takes them so in
    /// lanes, the same bits).
    pub(super) fn step<const L: usize>(&self, c: &[[f64; L]], scales: &[f64]) -> f64 {
        let order = L - 1;
        let (mut a1, mut a2) = (0.0f64, 0.0f64);
        for (ci, &s) in c.iter().zip(scales) {
            let (t1, t2) = if self.sums == Sums::Fused {
                let r = 1.0 / s;
                (ci[order - 1].abs() * r, ci[order].abs() * r)
            } else {
                (ci[order - 1].abs() / s, ci[order].abs() / s)
            };
            (a1, a2) = (a1.max(t1), a2.max(t2));
        }
        self.step_of_norms(a1, a2, order)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_step_keeps_the_last_terms_below_eps() {
        // the exponential's series: c_k = 1/k!
        let mut c = [0.0; poly::LEN];
        let mut f = 1.0;
        for (k, ck) in c.iter_mut().enumerate() {
            if k > 0 {
                f *= k as f64;
            }
            *ck = 1.0 / f;
        }
        let h = Rules::REFERENCE.step(&[c], &[1.0]);
        assert!(c[poly::ORDER] * h.powi(poly::ORDER as i32) <= poly::EPS * 1.000_001);
        assert!(h > 1.0 && h < 3.0, "{h}");
        // and the sum at h is e^h to the rounding
        assert!((poly::eval(&c, h) - h.exp()).abs() < 4e-16 * h.exp());
    }
}
