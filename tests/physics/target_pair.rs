//! Two balls that both deform (docs/targets.md §8, `target::pair`): identical balls meeting
//! head-on at ±v bounce exactly as one of them off a rigid wall at v, for every preset and
//! every law; unequal balls on the linear law against an independent integration of the two
//! bodies in SI.

use bouncelab::Ball;
use bouncelab::model::contact::ContactLaw;
use bouncelab::preset::Preset;
use bouncelab::target::pair;

#[test]
fn identical_balls_head_on_are_the_wall_impact() {
    let mut worst: f64 = 0.0;
    let mut n = 0;
    for preset in Preset::embedded_all() {
        for law in [
            ContactLaw::Linear,
            ContactLaw::Hertz,
            ContactLaw::ElasticPlastic,
        ] {
            let ball = Ball::from_preset(&preset.name).unwrap().with_law(law);
            let v = ball.params.v0;
            let wall = ball.impact().unwrap();
            assert!(wall.rebound, "{}", preset.name);
            let p = &ball.params;
            let got = pair::solve(p, p, law, 2.0 * v)
                .unwrap_or_else(|e| panic!("{} {law:?}: {e:?}", preset.name));
            let d = (got.cor - wall.cor).abs();
            assert!(
                d < 1e-9,
                "{} {law:?}: pair {} wall {}",
                preset.name,
                got.cor,
                wall.cor
            );
            worst = worst.max(d);
            n += 1;
        }
    }
    assert_eq!(n, 3 * Preset::embedded_all().len());
    eprintln!("{n} impacts, worst |e_pair − e_wall| {worst:e}");
}

/// The two bodies in SI by classical RK4 at a fixed step (a millionth of the contact's
/// period), each ball's recoil pair its own state and its bilinear contact (docs/model.md §3)
/// in series with the other's: loading z_i = F/K_pi; from the peak F_m on (found as the step
/// where Z = x₁ − x₂ − y₁ − y₂ stops growing), z_i = z_fi + (z_mi − z_fi) F/F_m with
/// z_fi = z_mi − z_p (2 z_mi/z_p − 1)^{1/2} above the ball's z_p (Eqs. 18–19). The end where F
/// returns to 0, interpolated linearly within the last step. Returns the pair's COR.
fn two_bodies(p1: &bouncelab::ImpactParams, p2: &bouncelab::ImpactParams, closing: f64) -> f64 {
    // F from Z on the branch in force: (Z − Z_f)/compliance, Z_f and the compliance summed
    let branch = |peak: Option<f64>| -> (f64, f64) {
        match peak {
            None => (0.0, 1.0 / p1.k_p + 1.0 / p2.k_p),
            Some(f_m) => [p1, p2].iter().fold((0.0, 0.0), |(zf, c), p| {
                let z_m = f_m / p.k_p;
                let z_f = if z_m > p.z_p {
                    z_m - p.z_p * (2.0 * z_m / p.z_p - 1.0).sqrt()
                } else {
                    0.0
                };
                (zf + z_f, c + (z_m - z_f) / f_m)
            }),
        }
    };
    let gap = |s: &[f64; 6]| s[0] - s[2] - s[4] - s[5];
    let rate = |s: &[f64; 6], b: (f64, f64)| {
        let f = ((gap(s) - b.0) / b.1).max(0.0);
        [
            s[1],
            -f / p1.mass,
            s[3],
            f / p2.mass,
            (f - p1.k_r * s[4]) / p1.damping,
            (f - p2.k_r * s[5]) / p2.damping,
        ]
    };
    let m_star = p1.mass * p2.mass / (p1.mass + p2.mass);
    let k = 1.0 / branch(None).1;
    let dt = 2.0 * std::f64::consts::PI * (m_star / k).sqrt() * 1e-6;
    let mut s = [0.0, closing, 0.0, 0.0, 0.0, 0.0];
    let add = |s: &[f64; 6], d: &[f64; 6], h: f64| std::array::from_fn(|i| s[i] + h * d[i]);
    let mut peak: Option<f64> = None;
    let mut loaded = false;
    for _ in 0..100_000_000 {
        let b = branch(peak);
        let k1 = rate(&s, b);
        let k2 = rate(&add(&s, &k1, dt / 2.0), b);
        let k3 = rate(&add(&s, &k2, dt / 2.0), b);
        let k4 = rate(&add(&s, &k3, dt), b);
        let next: [f64; 6] =
            std::array::from_fn(|i| s[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        let force = |q: &[f64; 6]| (gap(q) - b.0) / b.1;
        let (fa, fb) = (force(&s), force(&next));
        loaded |= fb > 0.0;
        if peak.is_none() && loaded && fb < fa {
            peak = Some(fa);
            continue;
        }
        if loaded && fb <= 0.0 {
            let w = fa / (fa - fb);
            let v_rel = |q: &[f64; 6]| q[3] - q[1];
            return (v_rel(&s) + w * (v_rel(&next) - v_rel(&s))) / closing;
        }
        s = next;
    }
    panic!("never let go");
}

#[test]
fn unequal_balls_agree_with_an_independent_integration() {
    let presets = ["tennis", "baseball", "superball", "golf", "softball"];
    let mut worst: f64 = 0.0;
    for (i, a) in presets.iter().enumerate() {
        for b in &presets[i + 1..] {
            let p1 = Ball::from_preset(a).unwrap().params;
            let p2 = Ball::from_preset(b).unwrap().params;
            let closing = 20.0;
            let got = pair::solve(&p1, &p2, ContactLaw::Linear, closing).unwrap();
            let reference = two_bodies(&p1, &p2, closing);
            let d = (got.cor - reference).abs();
            assert!(d < 1e-9, "{a}–{b}: pair {} two bodies {reference}", got.cor);
            worst = worst.max(d);
        }
    }
    eprintln!("worst |e_pair − e_two_bodies| {worst:e}");
}

/// Two balls with no recoil spring (λ = 0) and an overdamped dashpot (ζ ≥ 1) sink into each
/// other: the pair never lets go, which is no rebound (e 0), as the wall impact of one of them
/// says (tests/physics/closed_forms.rs), not an error. `solve` once returned `Unresolved::Horizon`.
#[test]
fn balls_that_never_let_go_are_no_rebound() {
    let ball = Ball::from_preset("tennis").unwrap();
    let p = bouncelab::ImpactParams {
        k_r: 0.0,
        damping: 5.0,
        ..ball.params
    };
    let wall = bouncelab::solver::simulate(&p, ContactLaw::Linear, &Default::default()).unwrap();
    assert!(!wall.rebound);
    let got = pair::solve(&p, &p, ContactLaw::Linear, 2.0 * p.v0).unwrap();
    assert!(!got.rebound && got.cor == 0.0, "{got:?}");
    assert!(got.f_max > 0.0 && got.z_max > 0.0, "{got:?}");
}
