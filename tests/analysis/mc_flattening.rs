//! The Monte Carlo's flattening balls (`analysis::mc::impacts`, src/analysis/mc_impact.rs)
//! against a lone ball's flattening answer (`map::fast::lanes::flattening_one`: what `run`, a
//! row of `bouncelab.impacts` and the explorer's cursor take): the same bits in any group of
//! four, the balls the lanes hand back included. Those the Monte Carlo gives to the scalar
//! `map::fast::flattening`, and `flattening_one` hands them to it too (its lane of width one
//! is the four lanes bit for bit, `None` included: tests/physics/map_flatten_lanes.rs), so asking the
//! lane again there would change no answer and cost a kernel's run.

use crate::seeded;

use bouncelab::analysis::mc::{Outcome, impacts};
use bouncelab::map::fast::lanes::{LANES, flattening_lane1, flattening_one};
use bouncelab::map::fast::summary;
use bouncelab::{ContactLaw, ImpactParams};
use seeded::Seeded;

/// The bits of an outcome.
fn bits(o: &Outcome) -> [u64; 3] {
    [o.cor, o.max_force, o.contact_time].map(f64::to_bits)
}

/// A seeded ball past its flattening point (z̄_p below the peak without flattening), scaled
/// off the unit ball so that ω0 and the force scale are not 1.
fn flattening_ball(s: &mut Seeded) -> ImpactParams {
    let (l, z) = (s.log_uniform(1e-6, 1e4), s.log_uniform(1e-3, 1e3));
    let peak = summary(l, z).map_or(1.0, |s| s.max_force);
    let zp = peak * 10f64.powf(-4.0 * s.uniform());
    let (m, v0) = (s.log_uniform(1e-3, 1e1), s.log_uniform(1e-1, 1e2));
    let unit = ImpactParams::from_normalized(l, z, zp);
    // m, K_p = m ω0² and c, K_r in proportion keep λ and ζ; z_p = z̄_p v0/ω0 keeps z̄_p
    let w0 = s.log_uniform(1e1, 1e4);
    let k_p = m * w0 * w0;
    ImpactParams {
        mass: m,
        k_p,
        damping: unit.damping * m * w0,
        k_r: unit.k_r * k_p,
        z_p: zp * v0 / w0,
        k_h: ImpactParams::k_h_matching(k_p, zp * v0 / w0),
        v0,
    }
}

/// Groups of four seeded flattening balls: every ball that flattens has `flattening_one`'s
/// answer, bit for bit, and some of them are balls the lanes hand back to the scalar path.
#[test]
fn flattening_samples_are_the_lone_balls_answer_handed_back_or_not() {
    let mut s = Seeded::new(0x7a1d_0009);
    let (mut compared, mut handed) = (0, 0);
    for _ in 0..1500 {
        let balls: [ImpactParams; LANES] = std::array::from_fn(|_| flattening_ball(&mut s));
        let got = impacts(&balls.map(Some), ContactLaw::Linear);
        for (p, got) in balls.iter().zip(got) {
            let n = p.normalized();
            let flattens = summary(n.lambda, n.zeta).is_none_or(|s| s.max_force > n.zp_bar);
            let Some(one) = flattening_one(n.lambda, n.zeta, n.zp_bar).filter(|_| flattens) else {
                continue;
            };
            let case = format!("λ {:e}, ζ {:e}, z̄_p {:e}", n.lambda, n.zeta, n.zp_bar);
            let got = got.expect("a ball has its answer").expect(&case);
            assert_eq!(bits(&got), bits(&Outcome::in_si(p, &one)), "{case}");
            compared += 1;
            handed += usize::from(flattening_lane1(n.lambda, n.zeta, n.zp_bar).is_none());
        }
    }
    eprintln!("{compared} flattening samples, {handed} of them handed back by the lanes");
    assert!(compared >= 3000 && handed > 0, "{compared}, {handed}");
}
