//! Repeated over noise seeds, the reported 95 % intervals cover the truth about 95 % of the
//! time: intervals that are too narrow (overconfident) or too wide (useless) both fail.

mod fit_common;

use bouncelab::ContactLaw;
use bouncelab::analysis::fit::{FitData, Param, fit};
use fit_common::*;

fn tally(hits: &mut [usize], fitted: &[bouncelab::analysis::fit::Estimate], truth: &[f64]) {
    for (h, (e, t)) in hits.iter_mut().zip(fitted.iter().zip(truth)) {
        *h += (e.ci95[0] <= *t && *t <= e.ci95[1]) as usize;
    }
}

#[test]
fn cor_table_intervals_cover_the_truth() {
    let t = truth();
    let speeds = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0];
    let seeds = 100;
    let mut hits = [0; 2];
    for seed in 0..seeds {
        let mut rng = Rng::new(1000 + seed);
        let pts = cor_table(&t, ContactLaw::Linear, &speeds, 0.005, &mut rng);
        let f = fit(
            &t,
            ContactLaw::Linear,
            FitData::Cor(&pts),
            &[Param::KR, Param::ZP],
        )
        .unwrap();
        tally(&mut hits, &f.fitted, &[t.k_r, t.z_p]);
    }
    eprintln!(
        "COR table coverage over {seeds} seeds: k_r {}, z_p {}",
        hits[0], hits[1]
    );
    for h in hits {
        assert!((88..=99).contains(&h), "{hits:?}");
    }
}
