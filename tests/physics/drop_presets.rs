//! Provenance of the new balls' fitted numbers (presets/*.toml, docs/drop.md): the stored
//! damping is the fit to the standard's nominal COR, and the stored v0 and COR are the
//! standard's impact speed and that nominal COR; every new ball runs through the library's
//! paths.

use bouncelab::drop::standards::{self, Test};
use bouncelab::drop::{Air, DropBall, fit};
use bouncelab::preset::{ParamSource, Preset};

#[test]
fn stored_damping_is_the_fit_to_the_nominal_cor() {
    // the squash ball's c sits on the large-ζ branch (a soft dashpot), which `fit_damping`
    // does not search: tests/physics/conditions_squash.rs re-fits it; the volleyball's c is
    // assumed, with no standard to fit it to (presets/volleyball.toml); the golf ball at
    // driver speeds has no standard either: its K_r and z_p are fitted to quoted CORs at two
    // speeds, which tests/physics/golf_driver.rs re-fits
    let own_fit = |p: &Preset| !["squash", "volleyball", "golf-driver"].contains(&p.name.as_str());
    for p in Preset::embedded_all().into_iter().skip(3).filter(own_fit) {
        let s = standards::for_ball(&p.name).unwrap();
        let b = DropBall {
            params: p.params(),
            law: p.law,
            radius: p.measured.radius,
        };
        let (target, speed) = fit::nominal_cor(s, &b, Some(Air::default())).unwrap_or_else(|| {
            // one-sided: presets/softball.toml states its target
            let Test::Cor { speed } = s.test else {
                panic!("{}", p.name)
            };
            (s.window[1].unwrap() - 0.015, speed)
        });
        let lambda = p.adopted.k_r / p.adopted.k_p.unwrap();
        let fitted = fit::fit_damping(&b, lambda, speed, target).unwrap();
        let stored = p.adopted.damping.unwrap();
        assert!(
            (fitted.damping - stored).abs() < 1e-6 * stored,
            "{}: fitted {} vs stored {stored}",
            p.name,
            fitted.damping
        );
        // the [measured] table holds the test's speed and the target COR, rounded
        assert!((p.measured.v0 - speed).abs() < 1e-4 * speed, "{}", p.name);
        let cor = p.measured.cor.unwrap();
        assert!((cor - target).abs() < 1e-4, "{}: {cor} vs {target}", p.name);
        // the materials set repeats K_p (the effective modulus was fitted to it)
        let m = p.params_from(ParamSource::Materials);
        assert!((m.k_p - fitted.k_p).abs() < 1e-3 * fitted.k_p, "{}", p.name);
    }
}

#[test]
fn an_unreachable_cor_is_an_error() {
    let p = Preset::embedded_all().remove(7);
    let b = DropBall {
        params: p.params(),
        law: p.law,
        radius: p.measured.radius,
    };
    // λ = 1: the minimum of e over ζ at 60 mph lies above 0.455 (presets/softball.toml)
    let e = fit::fit_damping(&b, 1.0, standards::MPH_60, 0.455).unwrap_err();
    assert!(e.to_string().contains("out of reach"), "{e}");
}
