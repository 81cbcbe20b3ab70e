mod fit_common;
use bouncelab::ContactLaw;
use bouncelab::analysis::fit::{FitData, Param, fit};
use fit_common::*;
#[test]
fn dbg() {
    let t = truth();
    let free = [Param::KP, Param::C, Param::KR];
    for seed in 0..50 {
        let mut rng = Rng::new(2000 + seed);
        let offset = 0.7e-3 + 0.2e-3 * rng.uniform();
        let tr = trace(
            &t,
            ContactLaw::Linear,
            offset,
            1.0,
            0.0,
            400,
            2e-5,
            &mut rng,
        );
        let f = fit(&guess(&t), ContactLaw::Linear, FitData::Trace(&tr), &free).unwrap();
        let z: Vec<String> = f
            .fitted
            .iter()
            .zip([t.k_p, t.damping, t.k_r])
            .map(|(e, tv)| format!("{:.2}", (e.value - tv) / e.std_error))
            .collect();
        let to = f.time_offset.unwrap();
        eprintln!(
            "z {:?} t0 {:.2} rms {:.3} it {} conv {} cond {:.1e} se {:?}",
            z,
            (to.value - offset) / to.std_error,
            f.rms_residual,
            f.iterations,
            f.converged,
            f.condition,
            f.fitted
                .iter()
                .map(|e| e.std_error / e.value)
                .collect::<Vec<_>>()
        );
    }
}
#[test]
fn timing() {
    let t = truth();
    let s = std::time::Instant::now();
    for _ in 0..20 {
        bouncelab::simulate(
            &t,
            ContactLaw::Linear,
            &bouncelab::SolveOptions::default().with_samples(400),
        )
        .unwrap();
    }
    eprintln!("sim400 {:?}", s.elapsed() / 20);
    let s = std::time::Instant::now();
    for _ in 0..20 {
        bouncelab::simulate(&t, ContactLaw::Linear, &bouncelab::SolveOptions::default()).unwrap();
    }
    eprintln!("sim0 {:?}", s.elapsed() / 20);
    let mut rng = Rng::new(1);
    let s = std::time::Instant::now();
    let tr = trace(
        &t,
        ContactLaw::Linear,
        0.8e-3,
        1.0,
        0.0,
        400,
        2e-5,
        &mut rng,
    );
    eprintln!("trace {:?}", s.elapsed());
    let s = std::time::Instant::now();
    let f = fit(
        &guess(&t),
        ContactLaw::Linear,
        FitData::Trace(&tr),
        &[Param::KP, Param::C, Param::KR],
    )
    .unwrap();
    eprintln!("fit {:?} {}", s.elapsed(), f.iterations);
}
