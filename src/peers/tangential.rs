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

/// The tangential model: Coulomb's μ and the spring K_t (N/m), no tangential dashpot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TangentialExport {
    /// μ ≥ 0.
    pub friction: f64,
    /// K_t > 0, N/m.
    pub tangential_stiffness: f64,
}

/// LAMMPS: the same Kelvin–Voigt fix with `tangential linear_history k_t x_gamma_t mu_s`:
/// the history spring k_t on the accumulated tangential displacement, rescaled onto the
/// Coulomb cap μ_s |F_n| while sliding, no dashpot (x_gamma_t = 0) — bouncelab's model, with
/// LAMMPS's own normal force in F_n.
pub fn lammps(s: &NormalContact, t: &TangentialExport) -> String {
    let mut o = String::new();
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
    o
}
