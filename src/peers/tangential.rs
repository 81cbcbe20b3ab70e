//! The tangential model of an oblique impact (docs/oblique.md §10) in the codes' own terms,
//! appended to `peers --export lammps|mujoco` when `--friction` is given: what each code can
//! take of bouncelab's linear_history spring K_t capped by μ F_n, and what it cannot.

use crate::text::number as num;
use serde::Serialize;
use std::fmt::Write;

/// The normal contact the tangential lines go with: the clipped Kelvin–Voigt k (N/m) and η
/// (kg/s) of the export, the ball's m (kg) and R (m).
#[derive(Debug, Clone, Copy)]
pub struct NormalContact {
    /// k, N/m.
    pub k: f64,
    /// η, kg/s.
    pub eta: f64,
    /// m, kg.
    pub mass: f64,
    /// R, m.
    pub radius: f64,
}

/// The tangential model: Coulomb's μ, the spring K_t (N/m) and the dashpot c_t (kg/s, 0:
/// none).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TangentialExport {
    /// μ ≥ 0.
    pub friction: f64,
    /// K_t > 0, N/m.
    pub tangential_stiffness: f64,
    /// c_t ≥ 0, kg/s; the JSON key only when a dashpot was given.
    #[serde(skip_serializing_if = "is_zero")]
    pub tangential_damping: f64,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// LAMMPS's x_gamma_t for a dashpot c_t on a contact whose normal damping is `damping
/// velocity` with η: the tangential coefficient is x_gamma_t times the normal damping's
/// prefactor, η itself (docs/oblique.md §10). `None` when η = 0 and c_t > 0 (no ratio gives it).
pub fn x_gamma_t(c_t: f64, eta: f64) -> Option<f64> {
    if c_t == 0.0 {
        Some(0.0)
    } else {
        (eta > 0.0).then(|| c_t / eta)
    }
}

/// LAMMPS: the same Kelvin–Voigt fix with `tangential linear_history k_t x_gamma_t mu_s`:
/// the history spring k_t on the accumulated tangential displacement, rescaled onto the
/// Coulomb cap μ_s |F_n| while sliding, and the dashpot x_gamma_t η = c_t (0 without one) —
/// bouncelab's model, with LAMMPS's own normal force in F_n.
pub fn lammps(s: &NormalContact, t: &TangentialExport) -> String {
    let mut o = String::new();
    if t.tangential_damping > 0.0 {
        return lammps_damped(s, t);
    }
    let _ = write!(
        o,
        "# Oblique impacts (docs/oblique.md §10): the tangential linear_history spring k_t = K_t\n\
         # on the contact's accumulated tangential displacement, capped by mu_s |F_n|, no\n\
         # tangential dashpot (x_gamma_t = 0), as bouncelab oblique; F_n is this fix's normal\n\
         # force (clipped Kelvin-Voigt), not the Christoforou-Yigit one, so grip and slip follow\n\
         # a normal force history that differs from bouncelab's (same COR, other shape).\n\
         # Spin needs atom_style sphere and fix nve/sphere.\n\
         fix kvclipt all wall/gran granular hooke {} {} tangential linear_history {} 0.0 {} \
         damping velocity limit_damping zplane 0.0 NULL\n",
        num(s.k),
        num(s.eta),
        num(t.tangential_stiffness),
        num(t.friction),
    );
    o
}

/// [`lammps`] with a tangential dashpot: x_gamma_t = c_t/η ([`x_gamma_t`]).
fn lammps_damped(s: &NormalContact, t: &TangentialExport) -> String {
    let mut o = String::new();
    let Some(x) = x_gamma_t(t.tangential_damping, s.eta) else {
        let _ = write!(
            o,
            "# Oblique impacts (docs/oblique.md §10): the tangential dashpot c_t = {} kg/s cannot\n\
             # be exported: LAMMPS scales it by the normal damping, and this contact has none.\n",
            num(t.tangential_damping)
        );
        return o;
    };
    let _ = write!(
        o,
        "# Oblique impacts (docs/oblique.md §10): the tangential linear_history spring k_t = K_t\n\
         # on the contact's accumulated tangential displacement in parallel with the dashpot\n\
         # x_gamma_t eta = c_t = {} kg/s, their force capped by mu_s |F_n| (the spring reset\n\
         # onto the cap net of the dashpot while sliding), as bouncelab oblique\n\
         # --tangential-damping; F_n is this fix's normal force (clipped Kelvin-Voigt), not the\n\
         # Christoforou-Yigit one. Spin needs atom_style sphere and fix nve/sphere.\n\
         fix kvclipt all wall/gran granular hooke {} {} tangential linear_history {} {} {} \
         damping velocity limit_damping zplane 0.0 NULL\n",
        num(t.tangential_damping),
        num(s.k),
        num(s.eta),
        num(t.tangential_stiffness),
        num(x),
        num(t.friction),
    );
    o
}

/// MuJoCo: condim 3 with the sliding friction μ. MuJoCo's friction is a soft constraint
/// on the contact's tangential velocity inside a friction cone (pyramidal by default), set
/// by the same solref/solimp as the normal one: Coulomb sliding at μ it reproduces; the
/// tangential spring K_t, its stored displacement and the grip-slip reversal it drives do
/// not exist there.
pub fn mujoco(s: &NormalContact, t: &TangentialExport) -> String {
    let (kk, bb) = (s.k / s.mass, s.eta / s.mass);
    let mut o = String::new();
    let _ = write!(
        o,
        "<!-- Oblique impacts (docs/oblique.md §10): condim 3 adds sliding friction mu = {} (the\n\
         torsional and rolling entries of friction are unused at condim 3). MuJoCo's friction is\n\
         a soft constraint on the tangential velocity within the friction cone, regularized by\n\
         the same solref as the normal direction: it slides at mu F_n as bouncelab does, but has\n\
         no tangential spring (K_t = {} N/m is not representable) and so no stored\n\
         displacement and no friction reversal while gripping. Its rebound is not the\n\
         calibrated COR (condim 1's): the tangential rows move the normal response too. -->\n\
         <geom type=\"sphere\" size=\"{}\" mass=\"{}\" priority=\"1\" condim=\"3\" \
         friction=\"{} 0 0\" solref=\"-{} -{}\" solimp=\"0.9999 0.9999 0.001 0.5 2\"/>\n",
        num(t.friction),
        num(t.tangential_stiffness),
        num(s.radius),
        num(s.mass),
        num(t.friction),
        num(kk),
        num(bb),
    );
    if t.tangential_damping > 0.0 {
        let _ = writeln!(
            o,
            "<!-- nor the tangential dashpot c_t = {} kg/s: MuJoCo has no tangential damping of its own. -->",
            num(t.tangential_damping)
        );
    }
    o
}
