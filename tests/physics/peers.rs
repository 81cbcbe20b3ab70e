//! The peers' impacts (src/peers/) against their closed forms, and against an independent
//! integration of the dimensional equations with the `differential-equations` crate
//! (docs/peers.md §2–3).

use bouncelab::peers::rules::{hunt_crossley_cor, kelvin_voigt_cor, kelvin_voigt_no_tension_cor};
use bouncelab::peers::{PeerBall, PeerModel, cor, impact};
use differential_equations::methods::ExplicitRungeKutta;
use differential_equations::ode::{ODE, solve_ode};
use differential_equations::solout::DefaultSolout;

/// Kelvin–Voigt with tension against e = exp(−πζ/√(1−ζ²)) (no rebound for ζ ≥ 1), and the
/// contact time π/ω_d.
#[test]
fn kelvin_voigt_with_tension_closed_form() {
    for i in 0..=40 {
        let zeta = 0.025 * i as f64;
        let e = cor(PeerModel::KelvinVoigt, zeta).unwrap();
        assert!(
            (e - kelvin_voigt_cor(zeta)).abs() < 1e-11,
            "ζ = {zeta}: {e}"
        );
    }
    for zeta in [1.0, 1.5, 4.0] {
        assert_eq!(
            cor(PeerModel::KelvinVoigt, zeta).unwrap(),
            0.0,
            "ζ = {zeta}"
        );
    }
    let ball = PeerBall {
        mass: 0.05,
        radius: 0.02,
        v0: 2.0,
        k: 4e5,
        k_h: 1e7,
    };
    let eta = 2.0 * 0.3 * (ball.mass * ball.k).sqrt();
    let r = impact(PeerModel::KelvinVoigt, &ball, eta, 0).unwrap();
    let wd = (ball.k / ball.mass).sqrt() * (1.0f64 - 0.09).sqrt();
    let tf = r.contact_time.unwrap();
    assert!((tf - std::f64::consts::PI / wd).abs() < 1e-12 * tf, "{tf}");
}

/// Clipped Kelvin–Voigt against e = exp(−2ζ arccos ζ/√(1−ζ²)) (arccosh beyond ζ = 1): the
/// force vanishes at ω_d t = 2 arccos ζ (rules.rs).
#[test]
fn kelvin_voigt_no_tension_closed_form() {
    for i in 0..=60 {
        let zeta = 0.05 * i as f64;
        let e = cor(PeerModel::KelvinVoigtNoTension, zeta).unwrap();
        let closed = kelvin_voigt_no_tension_cor(zeta);
        assert!((e - closed).abs() < 1e-11, "ζ = {zeta}: {e} vs {closed}");
    }
}

/// The Hunt–Crossley family against its first integral χ(1 + e) + ln(1 − χe) = ln(1 + χ).
#[test]
fn hunt_crossley_first_integral() {
    for chi in [0.0, 0.01, 0.1, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0, 40.0] {
        let e = cor(PeerModel::HuntCrossley, chi).unwrap();
        let closed = hunt_crossley_cor(chi);
        assert!((e - closed).abs() < 1e-10, "χ = {chi}: {e} vs {closed}");
        // beyond χ ≈ 10, 1 − χe is below the rounding of 1 (e = 1/χ to double precision)
        if chi > 0.0 && chi <= 10.0 {
            let residual = chi * (1.0 + e) + (-chi * e).ln_1p() - chi.ln_1p();
            assert!(residual.abs() < 1e-9 * chi, "χ = {chi}: {residual}");
        }
    }
}

/// The same impact in SI units, integrated by the `differential-equations` crate's DOP853:
/// m δ'' = −F(δ, δ̇), δ(0) = 0, δ̇(0) = v0, with F = 0 for δ ≤ 0. Once a clipped force has let
/// go it stays 0 (δ falls at constant speed), so integrating well past the contact and reading
/// the final speed needs no event location: an independent path to the same COR.
struct Si {
    model: PeerModel,
    ball: PeerBall,
    damping: f64,
}

impl Si {
    fn force(&self, d: f64, v: f64) -> f64 {
        let b = &self.ball;
        let dp = d.max(0.0);
        if d <= 0.0 {
            return 0.0;
        }
        match self.model {
            PeerModel::KelvinVoigt => b.k * d + self.damping * v,
            PeerModel::KelvinVoigtNoTension => (b.k * d + self.damping * v).max(0.0),
            PeerModel::Tsuji => (b.k_h * dp.powf(1.5) + self.damping * dp.powf(0.25) * v).max(0.0),
            PeerModel::HuntCrossley => {
                (b.k_h * dp.powf(1.5) * (1.0 + self.damping * v / b.v0)).max(0.0)
            }
        }
    }
}

impl ODE<f64, [f64; 2]> for Si {
    fn diff(&self, _t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        dydt[0] = y[1];
        dydt[1] = -self.force(y[0], y[1]) / self.ball.mass;
    }
}

fn cor_si(model: PeerModel, ball: PeerBall, damping: f64) -> f64 {
    let ode = Si {
        model,
        ball,
        damping,
    };
    let (t, l, _) = ball.scales(model);
    let mut m = ExplicitRungeKutta::dop853()
        .rtol(1e-12)
        .atol(1e-12 * l)
        .max_steps(1_000_000);
    let sol = solve_ode(
        &mut m,
        &ode,
        0.0,
        30.0 * t,
        &[0.0, ball.v0],
        &mut DefaultSolout::new(),
    )
    .expect("the reference integrates");
    -sol.y.last().expect("a last point")[1] / ball.v0
}

/// At fixed normalized damping the COR depends on nothing else: changing v0, m and the
/// stiffness by decades changes no COR of the dimensional equations (integrated
/// independently) beyond the integrators' tolerance, and all agree with `cor`.
#[test]
fn cor_is_invariant_in_v0_mass_and_stiffness() {
    let balls = [
        (0.0374, 3.12, 5.45e4, 5.7e5),
        (0.0456, 0.2, 5.6e5, 6.8e6),
        (5.0, 20.0, 1e8, 3e9),
    ]
    .map(|(mass, v0, k, k_h)| PeerBall {
        mass,
        radius: 0.02,
        v0,
        k,
        k_h,
    });
    for (model, d) in [
        (PeerModel::KelvinVoigt, 0.2),
        (PeerModel::KelvinVoigtNoTension, 0.2),
        (PeerModel::Tsuji, 0.4),
        (PeerModel::HuntCrossley, 0.5),
    ] {
        let e = cor(model, d).unwrap();
        for b in balls {
            let damping = b.damping_si(model, d);
            let e_si = cor_si(model, b, damping);
            let e_lib = impact(model, &b, damping, 0).unwrap().cor;
            assert!((e_si - e).abs() < 1e-7, "{model} {b:?}: {e_si} vs {e}");
            assert!((e_lib - e).abs() < 1e-12, "{model} {b:?}: {e_lib} vs {e}");
        }
    }
}

/// Hunt–Crossley's original damping is a material constant α = χ/v0 (s/m): at a fixed α the
/// COR falls with speed, so a calibration of α holds at one speed only.
#[test]
fn hunt_crossley_with_a_fixed_alpha_depends_on_speed() {
    let alpha = 0.2;
    let e: Vec<f64> = [0.5, 1.0, 2.0, 4.0]
        .iter()
        .map(|v| cor(PeerModel::HuntCrossley, alpha * v).unwrap())
        .collect();
    assert!(e.windows(2).all(|w| w[1] < w[0] - 0.01), "{e:?}");
}

/// Histories: evenly spaced from 0 to the end of contact, force and indentation in SI,
/// peak force and indentation at least every sample's, and F(0) = 0 for the Hertz-type laws.
#[test]
fn histories_span_the_contact() {
    let ball = PeerBall {
        mass: 0.0374,
        radius: 0.02155,
        v0: 3.12,
        k: 5.45e4,
        k_h: 5.74e5,
    };
    for model in PeerModel::ALL {
        let d = ball.damping_si(model, 0.3);
        let r = impact(model, &ball, d, 101).unwrap();
        let h = &r.history;
        assert_eq!(h.t.len(), 101, "{model}");
        assert_eq!(h.t[0], 0.0);
        assert_eq!(*h.t.last().unwrap(), r.contact_time.unwrap());
        let dt = h.t[1] - h.t[0];
        assert!(
            h.t.windows(2)
                .all(|w| ((w[1] - w[0]) - dt).abs() < 1e-9 * dt),
            "{model}"
        );
        assert!(
            h.force.iter().all(|&f| f <= r.max_force * (1.0 + 1e-12)),
            "{model}"
        );
        assert!(
            h.indentation
                .iter()
                .all(|&z| z <= r.max_indentation * (1.0 + 1e-12))
        );
        if model.is_hertzian() {
            assert_eq!(h.force[0], 0.0, "{model}");
        }
        let summary = impact(model, &ball, d, 0).unwrap();
        assert_eq!(summary.cor, r.cor, "{model}");
    }
}

/// Tsuji's damping with α = √5 ζ gives the COR of Kelvin–Voigt clipped at F ≥ 0 with damping
/// ratio ζ, to the integrators' precision (observed; docs/peers.md §3): the LIGGGHTS/Chrono
/// rule for Hertz is off from the target exactly as the log decrement is for clipped
/// Kelvin–Voigt.
#[test]
fn tsuji_at_root5_zeta_matches_clipped_kelvin_voigt() {
    for zeta in [0.02, 0.1, 0.3, 0.6, 0.9] {
        let a = cor(PeerModel::Tsuji, 5f64.sqrt() * zeta).unwrap();
        let b = cor(PeerModel::KelvinVoigtNoTension, zeta).unwrap();
        assert!((a - b).abs() < 1e-10, "ζ = {zeta}: {a} vs {b}");
    }
}

#[test]
fn bad_input_names_the_field() {
    let ball = PeerBall {
        mass: 1.0,
        radius: 1.0,
        v0: f64::NAN,
        k: 1.0,
        k_h: 1.0,
    };
    let e = impact(PeerModel::Tsuji, &ball, 1.0, 0).unwrap_err();
    assert!(e.to_string().contains("v0"), "{e}");
    let ok = PeerBall { v0: 1.0, ..ball };
    let e = impact(PeerModel::Tsuji, &ok, -1.0, 0).unwrap_err();
    assert!(e.to_string().contains("damping"), "{e}");
}

/// Peaks against closed forms: Hertz alone (χ = 0; docs/model.md §5: z_m = (5/4)^{2/5} in the
/// peers' scaling, F_m = z_m^{3/2}, t_f = 2.94328 z_m/v0), and Kelvin–Voigt's turning point
/// (x' = 0 at ω_d t = atan(√(1−ζ²)/ζ), x_m = e^{−ζ t} sin(√(1−ζ²) t)/√(1−ζ²)) with its
/// peak force at t = 0 (F = 2ζ v0 √(mk)) or inside the contact. Held to 1e-11: ten times the
/// integrator's per-step tolerance (src/peers/dop853.rs, `TOL` = 1e-12).
#[test]
fn peaks_against_closed_forms() {
    let unit = PeerBall {
        mass: 1.0,
        radius: 1.0,
        v0: 1.0,
        k: 1.0,
        k_h: 1.0,
    };
    let r = impact(PeerModel::HuntCrossley, &unit, 0.0, 0).unwrap();
    let zm = 1.25f64.powf(0.4);
    assert!(
        (r.max_indentation - zm).abs() < 1e-11,
        "{}",
        r.max_indentation
    );
    assert!(
        (r.max_force - zm.powf(1.5)).abs() < 1e-11,
        "{}",
        r.max_force
    );
    let tf = r.contact_time.unwrap();
    assert!((tf - 2.943_275_184_324_705 * zm).abs() < 1e-10, "{tf}");
    for zeta in [0.05, 0.3, 0.7] {
        let r = impact(PeerModel::KelvinVoigt, &unit, 2.0 * zeta, 0).unwrap();
        let w = (1.0f64 - zeta * zeta).sqrt();
        let tm = (w / zeta).atan() / w;
        let xm = (-zeta * tm).exp() * (w * tm).sin() / w;
        assert!((r.max_indentation - xm).abs() < 1e-11, "ζ = {zeta}");
        // F = x + 2ζx': its maximum over the contact, from a dense grid of the closed form
        let f = |t: f64| {
            let (e, s, c) = ((-zeta * t).exp(), (w * t).sin(), (w * t).cos());
            e * s / w + 2.0 * zeta * e * (c - zeta * s / w)
        };
        let fm = (0..=200_000)
            .map(|i| f(std::f64::consts::PI / w * i as f64 / 200_000.0))
            .fold(f64::MIN, f64::max);
        assert!(
            (r.max_force - fm).abs() < 1e-9,
            "ζ = {zeta}: {} vs {fm}",
            r.max_force
        );
    }
}
