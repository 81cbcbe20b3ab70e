//! The bounce `peers --export` is for (issue 52 item 8, docs/peers.md §5 "The case asked"):
//! `--angle θ [--spin ω]` with the speed v (`--v0`): the ball the export calibrates runs at
//! the normal speed v·sinθ, and every snippet states the code's κ against the ball's and
//! bouncelab's own answer for that bounce at the code's κ ([`crate::peers::case`]).

use super::{ExportArg, Pair, PeersArgs};
use crate::api::{Ball, ObliqueSpec};
use crate::model::materials::SOLID_INERTIA_FACTOR;
use crate::peers::case::{CaseAnswer, ExportCase};
use crate::peers::tangential::TangentialExport;

/// The bounce asked: (v, θ in degrees, ω); θ = 90 and ω = 0 without `--angle`; checked, one
/// line naming the field.
pub(super) fn asked(a: &PeersArgs, v: f64) -> anyhow::Result<(f64, f64, f64)> {
    if a.export.is_none() && (a.angle.is_some() || a.spin.is_some()) {
        anyhow::bail!("--angle and --spin state the bounce an export is for: give --export CODE");
    }
    if a.spin.is_some() && a.angle.is_none() {
        anyhow::bail!("--spin needs --angle: the bounce's angle to the surface");
    }
    let theta = a.angle.unwrap_or(90.0);
    if !(theta.is_finite() && theta > 0.0 && theta <= 90.0) {
        anyhow::bail!(
            "invalid angle: {} (degrees between the path and the surface, 0 < θ ≤ 90)",
            crate::text::number(theta)
        );
    }
    let spin = a.spin.unwrap_or(0.0);
    if !spin.is_finite() {
        anyhow::bail!(
            "invalid spin: {} (not a finite number)",
            crate::text::number(spin)
        );
    }
    Ok((v, theta, spin))
}

/// v·sinθ, exactly v head-on.
pub(super) fn normal_speed(v: f64, theta: f64) -> f64 {
    if theta == 90.0 {
        v
    } else {
        v * theta.to_radians().sin()
    }
}

/// The case for the export: `whole` is the ball at the bounce's speed (not a pair's reduced
/// ball), `e_normal` the model's COR at the normal speed (a pair's: `collide
/// --target-preset`'s), which is the answer's whatever the export's target: with or without
/// `--friction`, the e_y `oblique` gives for the bounce (tests/cli/cli_peers_case.rs,
/// `the_stated_answer_is_obliques_with_and_without_friction`).
pub(super) fn case(
    whole: &Ball,
    (v, theta, spin): (f64, f64, f64),
    pair: Option<&Pair>,
    tangential: Option<&TangentialExport>,
    e_normal: f64,
) -> anyhow::Result<ExportCase> {
    let vn = normal_speed(v, theta);
    let vx = if theta == 90.0 {
        0.0
    } else {
        v * theta.to_radians().cos()
    };
    let kappa_ball = whole.inertia_factor();
    let answer = match (tangential, pair) {
        (Some(_), Some(_)) if theta < 90.0 || spin != 0.0 => anyhow::bail!(
            "--angle with --pair and --friction: bouncelab's oblique bounce is a ball's against \
             a surface, not a pair's; export the pair head-on or without --friction"
        ),
        (Some(t), None) if theta < 90.0 || spin != 0.0 => {
            let run = |kappa: Option<f64>| {
                let spec = ObliqueSpec {
                    v: Some(v),
                    angle_deg: theta,
                    spin,
                    friction: t.friction,
                    tangential_stiffness: Some(t.tangential_stiffness),
                    inertia_factor: kappa,
                };
                whole.oblique_damped(&spec, Some(t.tangential_damping), 0)
            };
            let code = run(Some(SOLID_INERTIA_FACTOR))?;
            let own = if (kappa_ball - SOLID_INERTIA_FACTOR).abs() > 1e-12 {
                Some(run(None)?)
            } else {
                None
            };
            CaseAnswer {
                inertia_factor: SOLID_INERTIA_FACTOR,
                vx_out: code.vx_out,
                vy_out: code.vy_out,
                spin_out: code.spin_out,
                cor_normal: code.cor_normal,
                spin_out_ball_kappa: own.as_ref().map(|r| r.spin_out),
                vx_out_ball_kappa: own.as_ref().map(|r| r.vx_out),
            }
        }
        // no tangential force (no friction, or head-on without spin's lever): v_x and ω pass
        // unchanged; the normal bounce is the model's COR at the normal speed
        _ => CaseAnswer {
            inertia_factor: SOLID_INERTIA_FACTOR,
            vx_out: vx,
            vy_out: e_normal * vn,
            spin_out: spin,
            cor_normal: e_normal,
            spin_out_ball_kappa: None,
            vx_out_ball_kappa: None,
        },
    };
    Ok(ExportCase {
        speed: v,
        angle_deg: theta,
        spin,
        normal_speed: vn,
        pair: pair.map(|p| p.preset.clone()),
        inertia_factor_code: SOLID_INERTIA_FACTOR,
        inertia_factor_ball: kappa_ball,
        answer,
    })
}

/// The tangential model `--friction` asks the export to add, checked as `oblique` checks it
/// (one line naming the field, exit 2).
pub(super) fn tangential(
    a: &PeersArgs,
    b: &crate::Ball,
    code: ExportArg,
) -> anyhow::Result<Option<crate::peers::tangential::TangentialExport>> {
    let Some(mu) = a.friction else {
        return Ok(None);
    };
    if !matches!(
        code,
        ExportArg::Lammps | ExportArg::Mujoco | ExportArg::Json
    ) {
        anyhow::bail!("--friction exports the tangential model to lammps, mujoco or json only");
    }
    let k_t = a
        .tangential_stiffness
        .or(b.tangential_stiffness())
        .ok_or_else(|| {
            anyhow::anyhow!(
                "invalid tangential_stiffness: the ball is no preset and carries none: give it"
            )
        })?;
    // the same checks as an oblique impact's (angle and κ are not the export's)
    let c_t = a.tangential_damping.unwrap_or(0.0);
    crate::oblique::Oblique::new(45.0, 0.0, mu, k_t, 0.5, 1.0)?.with_tangential_damping(c_t)?;
    Ok(Some(crate::peers::tangential::TangentialExport {
        friction: mu,
        tangential_stiffness: k_t,
        tangential_damping: c_t,
    }))
}
