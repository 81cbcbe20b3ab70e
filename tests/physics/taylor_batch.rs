//! The Taylor steps several impacts at a time (`solver::taylor::batch`, issue 30 item 1): each
//! answer is the single path's (`solver::taylor::summary`) bit for bit — the lanes run the
//! same IEEE operations in the same order — wherever it answers and wherever it does not, in
//! any grouping; and `solver::table::summaries` is `solver::table::summary` element by
//! element. The balls are drawn over the property tests' domain (tests/physics/taylor.rs `ball`).

use crate::seeded;

use bouncelab::solver::table;
use bouncelab::solver::taylor::{Summary, batch, summary};
use bouncelab::{ContactLaw, ImpactParams, Normalized};
use seeded::Seeded;

/// `count` balls as tests/physics/taylor.rs's `ball` draws them (λ to 1e4, ζ 1e-4 … 1e4, v0 to
/// 200 m/s, mass, stiffness, flattening and K_h at random), from the tests' seeded generator.
fn balls(count: usize, seed: u64) -> Vec<Normalized> {
    let mut rng = Seeded::new(seed);
    (0..count)
        .map(|_| {
            let lambda = match rng.uniform() {
                u if u < 0.05 => 0.0,
                u if u < 0.8 => rng.log_uniform(1e-6, 1e4),
                _ => rng.log_uniform(1e-15, 1e-6),
            };
            let zeta = rng.log_uniform(1e-4, 1e4);
            let v0 = rng.log_uniform(1e-3, 200.0);
            let mass = rng.log_uniform(1e-3, 10.0);
            let k_p = rng.log_uniform(1e2, 1e8);
            let z_p = if rng.uniform() < 0.15 {
                f64::INFINITY
            } else {
                rng.log_uniform(1e-8, 1e-1)
            };
            let k_h_at = if z_p.is_finite() { z_p } else { 1e-3 };
            let k_h = ImpactParams::k_h_matching(k_p, k_h_at) * rng.log_uniform(0.1, 10.0);
            let p = ImpactParams {
                mass,
                k_p,
                damping: 1.0,
                k_r: 0.0,
                z_p,
                k_h,
                v0,
            };
            p.with_lambda_zeta(lambda, zeta).normalized()
        })
        .collect()
}

/// Every field's bits (the steps' count included), so that 0.0 and −0.0 or two NaNs differ.
fn bits(s: &Option<Summary>) -> Option<[u64; 7]> {
    s.map(|s| {
        [
            s.cor.to_bits(),
            s.max_force.to_bits(),
            s.contact_time.to_bits(),
            s.max_indentation.to_bits(),
            s.permanent_indentation.to_bits(),
            s.element_displacement.to_bits(),
            s.steps as u64,
        ]
    })
}

/// The batch against the single path over `ns`; the number answered.
fn same_as_single(ns: &[Normalized], law: ContactLaw) -> usize {
    let batched = batch::summaries(ns, law);
    assert_eq!(batched.len(), ns.len());
    for (i, (n, b)) in ns.iter().zip(&batched).enumerate() {
        let single = summary(n, law);
        assert_eq!(bits(b), bits(&single), "{law:?}, ball {i}: {n:?}");
    }
    batched.iter().filter(|s| s.is_some()).count()
}

#[test]
fn batched_summaries_are_the_single_ones_bit_for_bit() {
    for (law, seed) in [(ContactLaw::Hertz, 11), (ContactLaw::ElasticPlastic, 12)] {
        // an odd count: the last lanes run part-empty
        let ns = balls(1_501, seed);
        let answered = same_as_single(&ns, law);
        // most of the domain is the steps' (the rest stiff, or no rebound): the comparison
        // is not of `None`s
        assert!(answered > ns.len() / 3, "{law:?}: {answered} answered");
    }
    // past yield, where the elastic–plastic impact takes all three stages
    let ns = balls(1_501, 12);
    let past_yield = batch::summaries(&ns, ContactLaw::ElasticPlastic)
        .iter()
        .flatten()
        .filter(|s| s.permanent_indentation > 0.0)
        .count();
    assert!(past_yield > 100, "{past_yield} past yield");
}

#[test]
fn any_grouping_gives_the_same_bits() {
    let ns = balls(40, 13);
    let law = ContactLaw::ElasticPlastic;
    let whole = batch::summaries(&ns, law);
    for size in [1, 3, 7, 9] {
        let parts: Vec<_> = ns
            .chunks(size)
            .flat_map(|c| batch::summaries(c, law))
            .collect();
        let same = whole.iter().zip(&parts).all(|(a, b)| bits(a) == bits(b));
        assert!(same, "groups of {size}");
    }
    assert!(batch::summaries(&[], law).is_empty());
}

#[test]
fn the_linear_law_passes_through_one_by_one() {
    let ns = balls(300, 14);
    same_as_single(&ns, ContactLaw::Linear);
}

#[test]
fn table_summaries_are_table_summary_each() {
    for (law, seed) in [(ContactLaw::Hertz, 15), (ContactLaw::ElasticPlastic, 16)] {
        let ns = balls(800, seed);
        let batched = table::summaries(&ns, law);
        for (n, b) in ns.iter().zip(&batched) {
            assert_eq!(bits(b), bits(&table::summary(n, law)), "{law:?}: {n:?}");
        }
    }
}
