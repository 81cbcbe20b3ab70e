//! Ready-to-paste normal-contact parameters for DEM and multibody codes, each in the code's
//! own names and SI units, with the conventions assumed written beside them (docs/peers.md
//! §5). Every number comes from the exact calibration; where a code takes a COR and applies
//! its own rule, the COR given to it (`e_in`) is the one that makes the rule return the exact
//! damping. tests/physics/peers_export.rs re-reads each snippet and recomputes its COR.
//! The snippets themselves, one writer a code, are `codes`'s.

mod codes;

use super::rules::{self, Rule};
use super::{PeerBall, PeerError, PeerModel, calibrate, impact};
use crate::text::given;
use serde::Serialize;
use std::fmt::Write;

/// The codes a snippet can be written for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Code {
    /// LAMMPS `pair_style granular` (hooke and hertz/material normal models).
    Lammps,
    /// LIGGGHTS `model hertz`.
    Liggghts,
    /// Project Chrono SMC (`Hertz` and `Flores` force models).
    Chrono,
    /// YADE `ViscElMat` (kn, cn).
    Yade,
    /// MuJoCo's `solref` in its direct form (stiffness and damping).
    Mujoco,
}

/// The exact calibration of every model for one ball and target COR, in SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExportSet {
    /// The ball's name in the snippets' comments.
    pub label: String,
    /// Mass m, kg.
    pub mass: f64,
    /// Radius R, m.
    pub radius: f64,
    /// Impact speed v0, m/s (the calibration holds at this speed).
    pub v0: f64,
    /// The COR every model is calibrated to.
    pub target_cor: f64,
    /// Linear stiffness k, N/m.
    pub k: f64,
    /// Hertz stiffness K_h, N/m^1.5.
    pub k_h: f64,
    /// ζ = η/(2√(mk)) of Kelvin–Voigt with tension.
    pub kv_zeta: f64,
    /// Its η, kg/s.
    pub kv_eta: f64,
    /// ζ of Kelvin–Voigt clipped at F ≥ 0.
    pub kv_no_tension_zeta: f64,
    /// Its η, kg/s.
    pub kv_no_tension_eta: f64,
    /// Tsuji's α = η/√(m K_h).
    pub tsuji_alpha: f64,
    /// Its η, kg/(s·m^0.25).
    pub tsuji_eta: f64,
    /// Hunt–Crossley's χ (dimensionless: F = K_h δ^{3/2} (1 + χ δ̇/v0)).
    pub hunt_crossley_chi: f64,
    /// α = χ/v0, s/m, for codes whose damping is a material constant.
    pub hunt_crossley_alpha: f64,
    /// Contact time of the clipped Kelvin–Voigt model, s (the MuJoCo contact's).
    pub kv_no_tension_contact_time: Option<f64>,
    /// MuJoCo `timestep` (Euler) keeping every contact phase within [`STEP_TOL`], s.
    pub mujoco_timestep: Option<f64>,
    /// LAMMPS `timestep` (velocity Verlet) doing the same for every `fix` line, s.
    pub lammps_timestep: Option<f64>,
    /// The tangential model of oblique impacts, when asked for (`peers --friction`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential: Option<super::tangential::TangentialExport>,
    /// The bounce the export is for, the κ of the code's sphere against the ball's, and
    /// bouncelab's answer at the code's κ (`peers --export`, [`super::case`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub case: Option<super::case::ExportCase>,
}

/// How far from the target an advised time step may leave the COR at any contact phase
/// (docs/peers.md §5): 3/4 of the 0.002 the real codes are held to, for phases between those
/// checked.
pub const STEP_TOL: f64 = 1.5e-3;

impl ExportSet {
    /// Every model calibrated exactly to `target` for `ball` ([`calibrate::exact`]);
    /// `label` names the ball in the snippets.
    pub fn new(ball: &PeerBall, target: f64, label: &str) -> Result<ExportSet, PeerError> {
        ball.validate()?;
        let d = |m| calibrate::exact(m, target);
        let (kv, kvn, ts, hc) = (
            d(PeerModel::KelvinVoigt)?,
            d(PeerModel::KelvinVoigtNoTension)?,
            d(PeerModel::Tsuji)?,
            d(PeerModel::HuntCrossley)?,
        );
        let mut set = ExportSet {
            label: label.to_string(),
            mass: ball.mass,
            radius: ball.radius,
            v0: ball.v0,
            target_cor: target,
            k: ball.k,
            k_h: ball.k_h,
            kv_zeta: kv,
            kv_eta: ball.damping_si(PeerModel::KelvinVoigt, kv),
            kv_no_tension_zeta: kvn,
            kv_no_tension_eta: ball.damping_si(PeerModel::KelvinVoigtNoTension, kvn),
            tsuji_alpha: ts,
            tsuji_eta: ball.damping_si(PeerModel::Tsuji, ts),
            hunt_crossley_chi: hc,
            hunt_crossley_alpha: hc / ball.v0,
            kv_no_tension_contact_time: None,
            mujoco_timestep: None,
            lammps_timestep: None,
            tangential: None,
            case: None,
        };
        set.kv_no_tension_contact_time = impact(
            PeerModel::KelvinVoigtNoTension,
            ball,
            set.kv_no_tension_eta,
            0,
        )?
        .contact_time;
        set.mujoco_timestep = set.mujoco_step(ball)?.map(|s| s.h);
        set.lammps_timestep = set
            .lammps_steps(ball)?
            .iter()
            .map(|(_, s)| s.map(|s| s.h))
            .try_fold(f64::INFINITY, |h, s| s.map(|s| h.min(s)))
            .filter(|h| h.is_finite());
        Ok(set)
    }

    /// The effective Young modulus E* = 3 K_h / (4 √R) of the Hertz stiffness.
    pub fn e_star(&self) -> f64 {
        0.75 * self.k_h / self.radius.sqrt()
    }

    /// The COR to give a code that applies the log-decrement rule to a Hertz contact
    /// (α = √5 |β|), or `None` when α ≥ √5 is beyond that rule.
    pub fn tsuji_e_in(&self) -> Option<f64> {
        rules::rule_input_for(PeerModel::Tsuji, Rule::LogDecrement, self.tsuji_alpha)
    }

    /// Two comment lines naming the ball; `c` opens a comment, `end` closes it. A comment is
    /// read, not pasted: six digits as the text answers give them (v0 = 15, not
    /// 14.999999999999998); the values the code reads keep every digit.
    /// At an angle the export's v0 is the bounce's normal speed v·sinθ, and says so (the
    /// case's line names v and θ).
    fn header(&self, out: &mut String, c: &str, end: &str) {
        let normal = match &self.case {
            Some(case) if case.angle_deg < 90.0 => " (the normal speed v·sinθ)",
            _ => "",
        };
        let _ = writeln!(
            out,
            "{c} bouncelab peers: {}, m = {} kg, R = {} m, v0 = {} m/s{normal}, target COR {}{end}",
            self.label,
            given(self.mass, 6),
            given(self.radius, 6),
            given(self.v0, 6),
            given(self.target_cor, 6)
        );
        let _ = writeln!(
            out,
            "{c} one ball against a rigid flat: effective mass m, effective radius R; SI units{end}"
        );
        if let Some(case) = &self.case {
            case.lines(out, c, end, self.target_cor);
        }
    }
}

/// The snippet for `code`.
pub fn snippet(code: Code, s: &ExportSet) -> String {
    use super::tangential::{self, NormalContact};
    let normal = NormalContact {
        k: s.k,
        eta: s.kv_no_tension_eta,
        mass: s.mass,
        radius: s.radius,
    };
    match (code, &s.tangential) {
        (Code::Lammps, Some(t)) => return codes::lammps(s) + &tangential::lammps(&normal, t),
        (Code::Mujoco, Some(t)) => return codes::mujoco(s) + &tangential::mujoco(&normal, t),
        _ => {}
    }
    match code {
        Code::Lammps => codes::lammps(s),
        Code::Liggghts => codes::liggghts(s),
        Code::Chrono => codes::chrono(s),
        Code::Yade => codes::yade(s),
        Code::Mujoco => codes::mujoco(s),
    }
}
