use super::*;
use crate::Ball;
use crate::analysis::fit::apply;

fn golf() -> Ball {
    Ball::from_preset("golf").unwrap()
}

fn spec(text: &str, dist: Dist, samples: usize, seed: u64) -> McSpec {
    McSpec::new(parse_vary(text).unwrap(), dist, samples, seed).unwrap()
}

fn run(ball: &Ball, s: &McSpec) -> Samples {
    Sampler::new(ball.params, ball.law, s.clone())
        .samples(0, s.samples)
        .unwrap()
}

#[test]
fn vary_is_parsed_in_percent_or_fraction_and_put_in_order() {
    let v = parse_vary("k_r=0.05, k_p=5%,c=2.5 %").unwrap();
    let names: Vec<&str> = v.iter().map(|s| s.what.name()).collect();
    assert_eq!(names, ["k_p", "c", "k_r"]);
    assert_eq!(v[0].spread, 0.05);
    assert_eq!(v[1].spread, 0.025);
    assert_eq!(v[2].spread, 0.05);
}

#[test]
fn bad_vary_names_the_field() {
    let msg = |t: &str| parse_vary(t).unwrap_err().to_string();
    assert_eq!(
        msg("k_q=5%"),
        "invalid vary: unknown parameter 'k_q' (choose from k_p, c, k_r, z_p, k_h, m, v0, pressure, temperature)"
    );
    assert_eq!(
        msg("k_p"),
        "invalid vary: 'k_p' is not NAME=SPREAD (e.g. k_p=5% or k_p=0.05)"
    );
    assert_eq!(msg("c=1%,c=2%"), "invalid vary: c given twice");
    let e = McSpec::new(parse_vary("k_p=-5%").unwrap(), Dist::Normal, 10, 1).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid vary k_p: -0.05 (the spread must be a finite number ≥ 0)"
    );
    let e = McSpec::new(parse_vary("k_r=1").unwrap(), Dist::Uniform, 10, 1).unwrap_err();
    assert!(
        e.to_string().starts_with("invalid vary k_r: 1 (a uniform"),
        "{e}"
    );
    let e = McSpec::new(parse_vary("k_r=1%").unwrap(), Dist::Normal, 0, 1).unwrap_err();
    assert_eq!(e.to_string(), "invalid samples: 0 (must be at least 1)");
    assert_eq!(
        McSpec::new(vec![], Dist::Normal, 1, 1).unwrap_err(),
        McError::Empty
    );
}

/// With no spread every sample is the nominal ball: the statistics are `run`'s impact, sd 0.
#[test]
fn zero_spread_is_the_deterministic_impact() {
    let ball = golf();
    let r = ball.impact().unwrap();
    let s = spec("k_p=0,c=0,k_r=0", Dist::Normal, 50, 7);
    let st = summarize(&run(&ball, &s));
    assert!(
        (st.cor.mean - r.cor).abs() < 1e-12,
        "{} {}",
        st.cor.mean,
        r.cor
    );
    assert_eq!(st.cor.sd, 0.0);
    assert_eq!(st.cor.min, st.cor.max);
    let rel = |a: f64, b: f64| ((a - b) / b).abs();
    assert!(rel(st.max_force.q.q50, r.max_force) < 1e-12);
    assert!(rel(st.contact_time.q.q99, r.contact_time.unwrap()) < 1e-12);
}

/// The inputs' moments and quantiles against each distribution's closed form (20 000
/// samples: the tolerances are some five standard errors).
#[test]
fn the_inputs_follow_their_distribution() {
    let ball = golf();
    let k_p = ball.params.k_p;
    let n = 20_000;
    let draw = |dist| {
        let s = Sampler::new(ball.params, ball.law, spec("k_p=10%", dist, n, 3));
        let v: Vec<f64> = (0..n as u64).map(|i| s.inputs(i)[0] / k_p).collect();
        crate::analysis::mc_stats::stats(&v)
    };
    let normal = draw(Dist::Normal);
    assert!((normal.mean - 1.0).abs() < 5.0 * 0.1 / (n as f64).sqrt());
    assert!((normal.sd / 0.1 - 1.0).abs() < 5.0 / (2.0 * n as f64).sqrt());
    // the normal's 97.5 % point is 1.959964 sd above the mean
    assert!((normal.q.q97_5 - (1.0 + 0.1 * 1.959964)).abs() < 0.005);
    let uniform = draw(Dist::Uniform);
    assert!((uniform.sd - 0.1 / 3f64.sqrt()).abs() < 0.01 * 0.1 / 3f64.sqrt());
    assert!(uniform.min >= 0.9 && uniform.max < 1.1);
    // a uniform's quartiles lie halfway to its ends
    assert!((uniform.q.q25 - 0.95).abs() < 0.002 && (uniform.q.q75 - 1.05).abs() < 0.002);
    let log = draw(Dist::Lognormal);
    assert!((log.mean - 1.0).abs() < 5.0 * 0.1 / (n as f64).sqrt());
    assert!((log.sd / 0.1 - 1.0).abs() < 0.03);
    // the median of exp(μ + σN) is e^μ = (1 + s²)^(−1/2)
    assert!((log.q.q50 - 1.01f64.powf(-0.5)).abs() < 0.003);
    assert!(log.min > 0.0);
}

/// `Dist::below` (the share of a spread's draws below a value, worked from each law's CDF)
/// against the share of the sampler's own draws below it, for each law, with a correlation
/// too (the copula keeps each marginal): within five binomial standard errors.
#[test]
fn the_share_below_a_value_is_the_draws_share() {
    let ball = golf();
    let k_p = ball.params.k_p;
    let n = 20_000;
    for dist in [Dist::Normal, Dist::Uniform, Dist::Lognormal] {
        for vary in ["k_p=10%", "k_p=10%,c=10%"] {
            let mut sp = spec(vary, dist, n, 5);
            if vary.contains(',') {
                let (k, c) = (Varied::Param(Param::KP), Varied::Param(Param::C));
                sp = sp.with_correlation(vec![(k, c, 0.8)]).unwrap();
            }
            let s = Sampler::new(ball.params, ball.law, sp);
            let v: Vec<f64> = (0..n as u64).map(|i| s.inputs(i)[0] / k_p).collect();
            for ratio in [0.8, 0.95, 1.0, 1.07, 1.15] {
                let drawn = v.iter().filter(|&&x| x < ratio).count() as f64 / n as f64;
                let p = dist.below(0.1, ratio);
                let se = (p * (1.0 - p) / n as f64).sqrt().max(1.0 / n as f64);
                assert!(
                    (drawn - p).abs() <= 5.0 * se,
                    "{} {vary} below {ratio}: drawn {drawn}, worked {p}",
                    dist.name()
                );
            }
        }
    }
    assert_eq!(Dist::Normal.below(0.0, 1.0), 0.0);
    assert_eq!(Dist::Uniform.below(0.1, 0.85), 0.0);
    assert_eq!(Dist::Lognormal.below(0.1, 0.0), 0.0);
}

#[test]
fn same_answer_on_one_thread_and_many_and_in_any_chunks() {
    let ball = golf();
    let s = spec("k_p=5%,c=5%,k_r=5%", Dist::Normal, 3 * BLOCK / 2 + 17, 42);
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| run(&ball, &s))
    };
    let one = on(1);
    assert_eq!(one, on(3));
    let sampler = Sampler::new(ball.params, ball.law, s.clone());
    let mut chunks = sampler.samples(0, 1000).unwrap();
    chunks.extend(sampler.samples(1000, s.samples - 1000).unwrap());
    assert_eq!(chunks, one);
    // a sample alone is the same sample
    assert_eq!(sampler.outcome(12_345).unwrap().cor, one.cor[12_345]);
    // another seed, other samples
    let other = run(
        &ball,
        &McSpec {
            seed: 43,
            ..s.clone()
        },
    );
    assert_ne!(other.cor[0], one.cor[0]);
}

/// A small spread on K_r alone: the COR's sd is |∂e/∂K_r| s K_r to first order (the slope by
/// central differences through `Ball`), and its median the nominal COR.
#[test]
fn small_spreads_propagate_as_the_derivative_says() {
    let ball = golf();
    let k_r = ball.params.k_r;
    let cor_at = |k| {
        let mut b = ball.clone();
        b.params.k_r = k;
        b.impact().unwrap().cor
    };
    let h = 1e-4 * k_r;
    let slope = (cor_at(k_r + h) - cor_at(k_r - h)) / (2.0 * h);
    let s = spec("k_r=0.5%", Dist::Normal, 20_000, 5);
    let st = summarize(&run(&ball, &s));
    let expected = slope.abs() * 0.005 * k_r;
    assert!(
        (st.cor.sd / expected - 1.0).abs() < 0.04,
        "{} vs {expected}",
        st.cor.sd
    );
    assert!((st.cor.q.q50 - cor_at(k_r)).abs() < 0.05 * expected);
}

#[test]
fn k_h_follows_k_p_and_mass_and_speed_vary_too() {
    let ball = golf();
    let s = Sampler::new(
        ball.params,
        ball.law,
        spec("k_p=5%,m=1%,v0=2%", Dist::Uniform, 1, 9),
    );
    let p = s.params(0).unwrap();
    let v = s.inputs(0);
    assert_eq!((p.k_p, p.mass, p.v0), (v[0], v[1], v[2]));
    assert_eq!(p.k_h, ImpactParams::k_h_matching(p.k_p, p.z_p));
    // the fit's and the overrides' own application gives the same ball, K_h and z_p included
    let base = ImpactParams {
        mass: v[1],
        v0: v[2],
        ..ball.params
    };
    assert_eq!(p, apply(&base, &[Param::KP], &[v[0]]));
    let s = Sampler::new(
        ball.params,
        ball.law,
        spec("k_p=5%,c=1%,k_r=2%,z_p=3%,k_h=4%", Dist::Normal, 1, 2),
    );
    let (p, v) = (s.params(0).unwrap(), s.inputs(0));
    let all = [Param::KP, Param::C, Param::KR, Param::ZP, Param::KH];
    assert_eq!(p, apply(&ball.params, &all, &v));
}

/// A normal spread so wide that K_r crosses 0 is refused with the sample that did; the
/// lognormal of the same spread never crosses.
#[test]
fn a_normal_draw_out_of_the_domain_is_named() {
    let ball = golf();
    let wide = spec("k_r=200%", Dist::Normal, 200, 1);
    let e = Sampler::new(ball.params, ball.law, wide)
        .samples(0, 200)
        .unwrap_err();
    assert!(
        e.to_string().starts_with("invalid vary: sample ") && e.to_string().contains("k_r"),
        "{e}"
    );
    let log = spec("k_r=200%", Dist::Lognormal, 200, 1);
    assert_eq!(run(&ball, &log).len(), 200);
}

/// An elastic–plastic sample takes `solver::table::summary` (the Hertz table below yield, the
/// Taylor steps past it): its zero-spread answer is that summary's, bit for bit, and within
/// 1e-9 of `run`'s adaptive solver (tests/physics/taylor.rs holds both paths to it over the property
/// domain). The golf ball at its own speed stays below yield, at 10 v0 it yields.
#[test]
fn elastic_plastic_samples_take_the_fast_path() {
    let mut paths = [0usize; 2];
    for speed in [1.0, 10.0] {
        let mut ball = golf().with_law(ContactLaw::ElasticPlastic);
        ball.params.v0 *= speed;
        let s = spec("c=0", Dist::Normal, 3, 1);
        let samples = run(&ball, &s);
        let n = ball.params.normalized();
        let t = crate::solver::table::summary(&n, ContactLaw::ElasticPlastic)
            .expect("the golf ball is within the fast path's domain");
        paths[usize::from(t.steps > 0)] += 1;
        let w0 = ball.params.omega0();
        let r = ball.impact().unwrap();
        for i in 0..3 {
            assert_eq!(samples.cor[i], t.cor, "{speed} v0");
            let f = t.max_force * ball.params.mass * ball.params.v0 * w0;
            assert_eq!(samples.max_force[i], f, "{speed} v0");
            assert_eq!(samples.contact_time[i], t.contact_time / w0, "{speed} v0");
        }
        assert!(!r.stiff);
        assert!(
            (samples.cor[0] - r.cor).abs() < 1e-9,
            "{speed} v0: {t:?} {r:?}"
        );
        assert!((samples.max_force[0] / r.max_force - 1.0).abs() < 1e-9);
        let t_f = r.contact_time.unwrap();
        assert!((samples.contact_time[0] / t_f - 1.0).abs() < 1e-9);
    }
    // one below yield (the table, no steps), one past it (the Taylor steps)
    assert_eq!(paths, [1, 1]);
}

/// A Hertz sample takes the Hertz table (`solver::table::summary`): its zero-spread answer is
/// the table's, within 1e-9 of `run`'s adaptive solver (the golf ball's run is not stiff:
/// docs/numerics.md). It held `run` to 1e-12 when it was `run`'s own solver.
#[test]
fn hertz_samples_take_the_table() {
    let ball = golf().with_law(ContactLaw::Hertz);
    let s = spec("c=0", Dist::Normal, 3, 1);
    let samples = run(&ball, &s);
    let n = ball.params.normalized();
    let t = crate::solver::table::hertz(&n).expect("the golf ball is in a kept patch");
    let w0 = ball.params.omega0();
    for i in 0..3 {
        assert_eq!(samples.cor[i], t.cor);
        let f = t.max_force * ball.params.mass * ball.params.v0 * w0;
        assert_eq!(samples.max_force[i], f);
        assert_eq!(samples.contact_time[i], t.contact_time / w0);
    }
    let r = ball.impact().unwrap();
    assert!(!r.stiff);
    assert!(
        (samples.cor[0] - r.cor).abs() < 1e-9,
        "{} {}",
        samples.cor[0],
        r.cor
    );
    assert!((samples.max_force[0] / r.max_force - 1.0).abs() < 1e-9);
}

/// The key kept is the one `seed_from_u64` derives: sample i is ChaCha8Rng::seed_from_u64(seed)
/// on stream i.
#[test]
fn each_sample_is_chacha8_of_the_seed_on_its_own_stream() {
    use chacha20::ChaCha8Rng;
    use chacha20::rand_core::Rng;
    let mut a = ChaCha8Rng::seed_from_u64(42);
    a.set_stream(7);
    let mut b = ChaCha8Rng::from_seed(key(42));
    b.set_stream(7);
    assert_eq!(a.next_u64(), b.next_u64());
}

/// The draws of a group of four (`fill`, from `mc_rng::first_blocks`) are those of the crate's
/// own `ChaCha8Rng::seed_from_u64(seed)` on each sample's stream, for every distribution and
/// with a correlation (seven normals a sample: some read past the first block), and the
/// samples `samples` gives are those of the balls so drawn, one at a time.
#[test]
fn group_draws_are_the_crates_generator_sample_by_sample() {
    use chacha20::ChaCha8Rng;
    let ball = golf();
    let all = "k_p=5%,c=5%,k_r=5%,z_p=3%,k_h=2%,m=1%,v0=2%";
    let specs = [
        spec("k_p=5%,c=5%,k_r=5%", Dist::Normal, 1001, 1),
        spec("k_p=5%,c=5%,k_r=5%", Dist::Uniform, 1001, 2),
        spec("k_p=5%,m=1%,v0=2%", Dist::Lognormal, 1001, 3),
        spec(all, Dist::Normal, 1001, u64::MAX)
            .with_correlation(parse_correlate("k_p:c=0.5,k_r:m=-0.3").unwrap())
            .unwrap(),
    ];
    for s in specs {
        let sampler = Sampler::new(ball.params, ball.law, s.clone());
        let got = sampler.samples(0, s.samples).unwrap();
        for i in 0..s.samples as u64 {
            let mut rng = ChaCha8Rng::seed_from_u64(s.seed);
            rng.set_stream(i);
            let (values, n) = sampler.draw_from(&mut rng);
            assert_eq!(sampler.inputs(i), values[..n], "sample {i}");
            let o = impact(&sampler.ball(&values[..n]), ball.law).unwrap();
            let k = i as usize;
            let row = (got.cor[k], got.max_force[k], got.contact_time[k]);
            assert_eq!(row, (o.cor, o.max_force, o.contact_time), "sample {i}");
        }
    }
}
