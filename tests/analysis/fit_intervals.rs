//! Prediction intervals (issue 27 item 5; docs/fitting.md, "Prediction intervals"): a fit of
//! noisy synthetic data saved with `--save` carries its covariance in `[fit]`, and `run` on
//! that preset reports 95 % intervals by the delta method. Checked against an independent
//! Monte Carlo propagation of the same covariance: parameters drawn from N(values, Σ) through
//! a Cholesky factor, each run by the solver directly (K_h tied to K_p and z_p by Eq. 16 here,
//! not by the library's `apply`), the spread of the outputs against the delta method's.

use crate::common;
use crate::common::embedded;
use crate::fit_common;

use bouncelab::analysis::fit::stats::t975;
use bouncelab::preset::Preset;
use bouncelab::{Ball, ContactLaw, ImpactParams, SolveOptions, simulate};
use common::{argv, argv_with, bl_in, f};
use fit_common::Rng;
use nalgebra::{DMatrix, DVector};
use serde_json::Value;
use std::path::Path;

/// The baseball's CORs at ten speeds with Gaussian noise of 0.003, as a `--cor-table` file.
fn noisy_table(dir: &Path) -> String {
    let p = Ball::from_preset("baseball").unwrap().params;
    let mut rng = Rng::new(27);
    let mut text = String::from("v0,cor\n");
    for v0 in [0.5, 1.0, 2.0, 3.0, 5.0, 8.0, 12.0, 18.0, 25.0, 35.0] {
        let e = simulate(
            &ImpactParams { v0, ..p },
            ContactLaw::Linear,
            &SolveOptions::default(),
        )
        .unwrap()
        .cor;
        text.push_str(&format!("{v0},{}\n", e + 0.003 * rng.normal()));
    }
    let path = dir.join("table.csv");
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

fn run_json(home: &Path, args: &[&str]) -> Value {
    let o = bl_in(home, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap()
}

/// The saved preset, its `[fit]` table read back by the preset loader.
fn fitted(home: &Path) -> Preset {
    let table = noisy_table(home);
    let o = bl_in(
        home,
        &argv_with(
            "fit --preset baseball --cor-table {} --save bb-fit",
            &[&table],
        ),
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    let path = home.join("bouncelab/presets/bb-fit.toml");
    Preset::parse(&std::fs::read_to_string(path).unwrap(), "bb-fit.toml").unwrap()
}

/// (e, F_m, t_f) of N(values, Σ) draws of the free parameters (k_r, z_p).
fn monte_carlo(preset: &Preset, v0: f64, n: usize) -> Vec<[f64; 3]> {
    let fit = preset.fit.as_ref().unwrap();
    assert_eq!(fit.free, ["k_r", "z_p"]);
    let k = fit.free.len();
    let sigma = DMatrix::from_fn(k, k, |i, j| fit.covariance[i][j]);
    let chol = sigma
        .cholesky()
        .expect("a positive definite covariance")
        .l();
    let mut rng = Rng::new(4);
    let base = ImpactParams {
        v0,
        ..preset.params()
    };
    (0..n)
        .map(|_| {
            let z = DVector::from_fn(k, |_, _| rng.normal());
            let d = &chol * z;
            let (k_r, z_p) = (fit.values[0] + d[0], fit.values[1] + d[1]);
            let k_h = base.k_p / (1.5 * z_p.sqrt()); // Eq. 16
            let p = ImpactParams {
                k_r,
                z_p,
                k_h,
                ..base
            };
            let r = simulate(&p, ContactLaw::Linear, &SolveOptions::default()).unwrap();
            [r.cor, r.max_force, r.contact_time.unwrap()]
        })
        .collect()
}

fn sd(xs: impl Iterator<Item = f64> + Clone) -> f64 {
    let n = xs.clone().count() as f64;
    let mean = xs.clone().sum::<f64>() / n;
    (xs.map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
}

#[test]
fn delta_method_agrees_with_monte_carlo() {
    let home = tempfile::tempdir().unwrap();
    let preset = fitted(home.path());
    let fit = preset.fit.clone().expect("--save writes [fit]");
    assert_eq!(fit.dof, 8, "10 points, 2 parameters");
    for v0 in ["3", "45"] {
        let v = run_json(
            home.path(),
            &["run", "--preset", "bb-fit", "--v0", v0, "--format", "json"],
        );
        let draws = monte_carlo(&preset, v0.parse().unwrap(), 3000);
        let t = t975(fit.dof as usize);
        for (k, key, value) in [(0, "cor_ci95", "cor"), (1, "max_force_ci95", "max_force")]
            .into_iter()
            .chain([(2, "contact_time_ci95", "contact_time")])
        {
            let ci: Vec<f64> = v[key]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            let y = f(&v, value);
            // symmetric about the answer, half-width t·sd
            assert!(
                ((ci[0] + ci[1]) / 2.0 - y).abs() < 1e-12 * y.abs(),
                "{key} {ci:?} {y}"
            );
            let delta = (ci[1] - ci[0]) / (2.0 * t);
            let mc = sd(draws.iter().map(|d| d[k]));
            // 3000 draws estimate an sd to ~1.3 %; the curvature of e(k_r, z_p) adds a little
            assert!(
                (delta / mc - 1.0).abs() < 0.06,
                "v0 {v0} {key}: delta-method sd {delta}, Monte Carlo {mc}"
            );
        }
    }
}

#[test]
fn text_and_plain_presets() {
    let home = tempfile::tempdir().unwrap();
    fitted(home.path());
    let o = bl_in(home.path(), &["run", "--preset", "bb-fit", "--v0", "45"]);
    let cor = o
        .stdout
        .lines()
        .find(|l| l.trim_start().starts_with("COR 0."))
        .unwrap();
    assert!(
        cor.contains(" (95 %: ") && cor.contains(" … "),
        "{}",
        o.stdout
    );
    // a plain preset has no interval keys (its golden output unchanged)
    let plain = run_json(
        home.path(),
        &["run", "--preset", "baseball", "--format", "json"],
    );
    assert!(plain.get("cor_ci95").is_none());
    // an override that moves a fitted parameter leaves the fit's ball: no interval claimed
    let moved = run_json(
        home.path(),
        &argv("run --preset bb-fit --k-r 5e5 --format json"),
    );
    assert!(moved.get("cor_ci95").is_none());
}

/// A malformed `[fit]` table stops the preset with `file:line:column` and the key at fault.
#[test]
fn malformed_fit_tables_are_located() {
    let base = embedded("baseball");
    let text = base.to_toml(&[]);
    let k_r = base.adopted.k_r;
    let z_p = base.adopted.z_p.unwrap();
    let good = format!(
        "\n[fit]\nfree = [\"k_r\", \"z_p\"]\nvalues = [{k_r:?}, {z_p:?}]\n\
         covariance = [[4e6, -0.3], [-0.3, 1e-7]]\ndof = 6\nresidual_sd = 0.01\n"
    );
    let ok = Preset::parse(&format!("{text}{good}"), "x.toml").unwrap();
    assert_eq!(ok.fit.as_ref().unwrap().dof, 6);
    // the table reads back from to_toml exactly
    assert_eq!(Preset::parse(&ok.to_toml(&[]), "x.toml").unwrap(), ok);
    let fit_line = text.lines().count() + 2;
    for (from, to, key, line, says) in [
        ("\"z_p\"]", "\"q\"]", "free", 1, "unknown parameter \"q\""),
        ("\"z_p\"]", "\"k_r\"]", "free", 1, "names k_r twice"),
        (
            "values = [",
            "values = [1.0, ",
            "values",
            2,
            "holds 3 values",
        ),
        (
            &format!("{k_r:?}, "),
            "5.0, ",
            "values",
            2,
            "is not the preset's k_r",
        ),
        (
            "[-0.3, 1e-7]]",
            "[-0.2, 1e-7]]",
            "covariance",
            3,
            "must equal its mirror",
        ),
        (
            "[-0.3, 1e-7]]",
            "[-0.3]]",
            "covariance",
            3,
            "must be 2 rows of 2",
        ),
        ("4e6", "-4e6", "covariance", 3, "a variance"),
        ("dof = 6", "dof = 0", "dof", 4, "at least 1"),
        (
            "residual_sd = 0.01",
            "residual_sd = -1.0",
            "residual_sd",
            5,
            "not negative",
        ),
    ] {
        let bad = format!("{text}{}", good.replacen(from, to, 1));
        let e = Preset::parse(&bad, "x.toml").unwrap_err().to_string();
        let at = format!("x.toml:{}:1: fit.{key}: ", fit_line + line);
        assert!(
            e.starts_with(&at) && e.contains(says),
            "{e}\nwanted {at} … {says}"
        );
    }
}
