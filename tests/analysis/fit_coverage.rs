//! Repeated over noise seeds, the reported 95 % intervals cover the truth about 95 % of the
//! time: intervals that are too narrow (overconfident) or too wide (useless) both fail.

use crate::fit_common;

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
    let seeds = 60;
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
    // 60 intervals each: 95 % coverage gives 57 ± 1.7; all 60 would mean intervals too
    // wide (measured over 100 seeds: 91 and 95)
    for h in hits {
        assert!((51..=59).contains(&h), "{hits:?}");
    }
}

/// K_p, c, K_r and t0 from 400-sample traces (20 µs apart, noise 1 N on a 100 N pulse), the
/// contact starting somewhere in a 0.2 ms window the fit is not told. A seed's four intervals
/// move together (the estimates are correlated), so counting covers is a weak test over 30
/// seeds; the mean of z² = ((ln p̂ − ln p)/s_θ)² is a sharper one: 1 for honest intervals,
/// well below for intervals too wide, above for too narrow. `SEEDS=120 cargo test --test
/// fit_coverage` runs more (measured: 468 of 480 covered, mean z² 0.89 … 0.93).
#[test]
fn force_time_intervals_cover_the_truth() {
    let t = truth();
    let free = [Param::KP, Param::C, Param::KR];
    let seeds: u64 = std::env::var("SEEDS").map_or(30, |s| s.parse().unwrap());
    let mut hits = [0; 4];
    let mut z2 = [0.0; 4];
    for seed in 0..seeds {
        let mut rng = Rng::new(2000 + seed);
        let offset = 0.7e-3 + 0.2e-3 * rng.uniform();
        let tr = trace(
            &t,
            ContactLaw::Linear,
            offset,
            1.0,
            0.0,
            (400, 2e-5),
            &mut rng,
        );
        let f = fit(&guess(&t), ContactLaw::Linear, FitData::Trace(&tr), &free).unwrap();
        let truths = [t.k_p, t.damping, t.k_r];
        for (j, (e, tv)) in f.fitted.iter().zip(truths).enumerate() {
            z2[j] += ((e.value.ln() - tv.ln()) / (e.std_error / e.value)).powi(2);
        }
        let t0 = f.time_offset.clone().unwrap();
        z2[3] += ((t0.value - offset) / t0.std_error).powi(2);
        let mut all = f.fitted.clone();
        all.push(t0);
        tally(&mut hits, &all, &[t.k_p, t.damping, t.k_r, offset]);
    }
    let z2 = z2.map(|z| z / seeds as f64);
    eprintln!("force-time over {seeds} seeds: covered {hits:?}, mean z² {z2:.2?}");
    // 30 seeds: a mean z² has a spread of about √(2/30) ≈ 0.26 around 1
    for z in z2 {
        assert!((0.45..=1.7).contains(&z), "{z2:?}");
    }
    assert!(hits.iter().sum::<usize>() >= 104, "{hits:?}");
}

/// The superball (presets/superball.toml) at speed `v0`.
fn superball(v0: f64) -> bouncelab::ImpactParams {
    bouncelab::ImpactParams {
        mass: 0.0374,
        k_p: 5.45e4,
        damping: 140.0,
        k_r: 7.08e4,
        z_p: 4e-3,
        k_h: bouncelab::ImpactParams::k_h_matching(5.45e4, 4e-3),
        v0,
    }
}

/// `bouncelab run --preset superball --v0 6.24 --history --format csv` (400 rows over the
/// contact alone: no quiet stretch before or after it) with Gaussian noise of 3 N on the force.
fn superball_trace(rng: &mut Rng) -> bouncelab::measured::Trace {
    use bouncelab::{SolveOptions, simulate};
    let opts = SolveOptions::default().with_samples(400);
    let r = simulate(&superball(6.24), ContactLaw::Linear, &opts).unwrap();
    let mut text = String::from("t,force\n");
    for (t, f) in r.history.t.iter().zip(&r.history.force) {
        text.push_str(&format!("{t},{}\n", f + 3.0 * rng.normal()));
    }
    bouncelab::measured::Trace::parse(&text).unwrap()
}

/// How many of `seeds` seeds' 95 % intervals of k_p, c, k_r, v0, t0 and the baseline (truths
/// 0 and 0) hold the truth, in the superball trial of issue 52: a trace at twice the preset's
/// speed fitted without its speed, as `fit --force-time` without `--v0` does (`--free v0`
/// added, from the preset's 3.12 m/s). `SHOW=1` prints each seed's fit.
fn speed_free_coverage(seeds: u64) -> [usize; 6] {
    let free = [Param::KP, Param::C, Param::KR, Param::V0];
    let t = superball(6.24);
    let truths = [t.k_p, t.damping, t.k_r, t.v0, 0.0, 0.0];
    let mut hits = [0; 6];
    let start = std::time::Instant::now();
    for seed in 0..seeds {
        let mut rng = Rng::new(5200 + seed);
        let tr = superball_trace(&mut rng);
        let f = fit(
            &superball(3.12),
            ContactLaw::Linear,
            FitData::Trace(&tr),
            &free,
        )
        .unwrap();
        let mut all = f.fitted.clone();
        all.extend(f.time_offset.clone());
        all.extend(f.baseline.clone());
        if std::env::var("SHOW").is_ok() {
            let show: Vec<String> = all
                .iter()
                .map(|e| {
                    format!(
                        "{} {:.4e} [{:.4e}, {:.4e}]",
                        e.name, e.value, e.ci95[0], e.ci95[1]
                    )
                })
                .collect();
            eprintln!("seed {seed}: {}", show.join("; "));
        }
        tally(&mut hits, &all, &truths);
    }
    eprintln!(
        "superball at 6.24 m/s, v0 free, {seeds} seeds: covered {hits:?} (k_p, c, k_r, v0, t0, \
         baseline), {:.0} ms a fit",
        start.elapsed().as_secs_f64() * 1e3 / seeds as f64
    );
    hits
}

/// Issue 52 item 7: 60 seeds, each interval must hold at least 53 times (88 %; honest 95 %
/// intervals fall below that with probability about 0.015 each). Measured on the Jacobian's
/// intervals alone: [55, 55, 50, 50, 52, 52] (failed); with the intervals spanning both
/// sides of the first row where the profile-t test kept the other side: [58, 58, 58, 57, 55,
/// 55]; with the hull of both sides (`analysis::fit::edge`): [59, 59, 59, 58, 59, 59].
#[test]
fn speed_free_trace_intervals_cover_the_truth() {
    let hits = speed_free_coverage(60);
    assert!(hits.iter().all(|&h| h >= 53), "{hits:?} of 60");
}

/// The same over 500 seeds (`SEEDS=N` for another count; 90 ms a fit in release on an idle
/// machine, 0.55 s on a loaded one). Measured on the Jacobian's intervals alone, 500 seeds:
/// [440, 473, 428, 419, 431, 424] of a nominal 475 (k_p 88 %, c 95 %, k_r 86 %, v0 84 %, t0
/// 86 %, baseline 85 %). With the intervals spanning both sides of the first row where the
/// profile-t test of t0 = t₁ kept the other side: [475, 487, 447, 460, 459, 460] (95.0,
/// 97.4, 89.4, 92.0, 91.8, 92.0 %), failing; the same with the estimate at the lower of the
/// two minima: [475, 487, 451, 460, 459, 460]. That test rejected the truth (t0 = t₁, the
/// kink) in 20 of the first 100 seeds where 5 were due, and the t0 and baseline misses were
/// mostly those. With the hull of both sides whatever the test says (`analysis::fit::edge`:
/// the union of a set for each side): [496, 489, 460, 494, 497,
/// 498] (99.2, 97.8, 92.0, 98.8, 99.4, 99.6 %; the same with the runs-test guard of a
/// side that cannot follow the data). k_r stays the weakest: its misses
/// are fits whose K_p, K_r and v0 moved together (K_r 2 to 5 standard errors high, v0 as
/// many low) on both sides of the first row alike. With v0 held at the truth (`--v0 6.24`)
/// the others under-covered too under the old rule: 200 seeds, [179, 177, 177, –, 174,
/// 177]. Profile-t intervals (`analysis::fit::profile`) did not mend it: 200 seeds, [174,
/// 183, 193, 173, 169, 190], 1.4 s a fit.
#[test]
#[ignore = "500 fits: minutes in a debug build; SEEDS=500 cargo test --release --test analysis speed_free -- --ignored"]
fn speed_free_trace_intervals_cover_the_truth_over_many_seeds() {
    let seeds: u64 = std::env::var("SEEDS").map_or(500, |s| s.parse().unwrap());
    let hits = speed_free_coverage(seeds);
    let least = (0.92 * seeds as f64) as usize;
    assert!(hits.iter().all(|&h| h >= least), "{hits:?} of {seeds}");
}
