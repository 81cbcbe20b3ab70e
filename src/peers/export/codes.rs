//! The snippet of each code from an [`ExportSet`], in the code's own names
//! and SI units (docs/peers.md §5).
//!
//! Conventions verified against the codes' sources: LAMMPS `src/GRANULAR/gran_sub_mod_*`
//! (F_hertz = k_n a δ with a = √(R δ); damping force −prefactor·v_n, coeff_restitution:
//! prefactor = damp √(m_eff F_n/δ), damp = 2|β| for hooke and √(3/2)·2√(5/6)|β| for hertz,
//! β = ln e/√(ln² e + π²)); LIGGGHTS `model hertz` and Chrono SMC `Hertz` (k_n = (4/3) Y* √(R*δ),
//! γ_n = 2√(5/6)|β|√(S_n m*), S_n = 2 Y* √(R*δ)); Chrono SMC `Flores` (γ_n = 8(1 − c_r) k_n δ /
//! (5 c_r v_char), c_r clamped to ≥ 0.01); YADE `ViscElMat` (normal force clipped at 0, kn and
//! cn of a contact the series combination of both materials'); MuJoCo's direct `solref`
//! (a + d (b v + k r) = (1 − d) a0 with b = damping/d_max, k = stiffness·d/d_max²).

use super::{ExportSet, STEP_TOL};
use crate::text::number as num;
use std::fmt::Write;

/// A line saying the code's rule cannot reach the exact damping.
fn unreachable_line(c: &str, what: &str, alpha: f64) -> String {
    format!(
        "{c} not representable: the exact {what} needs α = {} ≥ √5, beyond the log-decrement \
         rule this code applies\n",
        num(alpha)
    )
}

pub(super) fn lammps(s: &ExportSet) -> String {
    let mut o = String::new();
    s.header(&mut o, "#", "");
    let k_n = s.k_h / s.radius.sqrt();
    match s.lammps_timestep {
        Some(h) => {
            let _ = writeln!(
                o,
                "# velocity Verlet (fix nve/sphere): at this step every fix below gives the target COR\n\
                 # within {} wherever in a step the ball meets the wall (the error shrinks about\n\
                 # in proportion to the step)\n\
                 timestep {}",
                num(STEP_TOL),
                num(h)
            );
        }
        None => {
            let _ = writeln!(
                o,
                "# no timestep down to contact time/100000 keeps every contact phase within {}",
                num(STEP_TOL)
            );
        }
    }
    let _ = write!(
        o,
        "# units si; fix wall/gran uses m_eff = m, R_eff = R (the wall has infinite mass and radius)\n\
         # Kelvin-Voigt, tension allowed until δ = 0 (hooke, damping velocity: F = k_n δ + damp δ̇):\n\
         fix kv all wall/gran granular hooke {} {} tangential linear_nohistory 0.0 0.0 \
         damping velocity zplane 0.0 NULL\n\
         # Kelvin-Voigt clipped at F >= 0 (limit_damping), damping calibrated to that model:\n\
         fix kvclip all wall/gran granular hooke {} {} tangential linear_nohistory 0.0 0.0 \
         damping velocity limit_damping zplane 0.0 NULL\n\
         # Tsuji (hertz: F = k_n a δ, a = √(R δ), so k_n = K_h/√R; damping coeff_restitution sets\n\
         # η = √5 β(e) √(m_eff K_h) δ^(1/4), β = |ln e|/√(ln² e + π²); the e given is e_in, the input\n\
         # that makes it the exact η, not the target COR). Not damping tsuji: its polynomial in e\n\
         # gained a factor √2 in 2025 versions, so the same input differs between versions.\n",
        num(s.k),
        num(s.kv_eta),
        num(s.k),
        num(s.kv_no_tension_eta),
    );
    match s.tsuji_e_in() {
        Some(e) => {
            let _ = writeln!(
                o,
                "fix tsuji all wall/gran granular hertz {} {} tangential linear_nohistory 0.0 0.0 \
                 damping coeff_restitution limit_damping zplane 0.0 NULL",
                num(k_n),
                num(e)
            );
        }
        None => o.push_str(&unreachable_line("#", "Tsuji damping", s.tsuji_alpha)),
    }
    o
}

pub(super) fn liggghts(s: &ExportSet) -> String {
    let mut o = String::new();
    s.header(&mut o, "#", "");
    // two equal materials give Y* = Y/(2(1 − ν²)); the normal force needs Y* = E* only
    let nu = 0.3;
    let y = 2.0 * (1.0 - nu * nu) * s.e_star();
    let _ = write!(
        o,
        "# model hertz (F = (4/3) Y* √(R* δ) δ + γ_n δ̇, γ_n = 2√(5/6) β √(2 Y* √(R* δ) m*)): Tsuji's law\n\
         # with η = √5 β(e) √(m K_h); limitForce on clips F >= 0. Ball (type 1) and wall (type 2)\n\
         # share one material, so Y* = Y/(2(1 - ν²)) = E* = 3 K_h/(4 √R) = {}; ν only enters the\n\
         # tangential model. coefficientRestitution is e_in, the input that gives the exact η.\n",
        num(s.e_star())
    );
    let _ = writeln!(
        o,
        "fix m1 all property/global youngsModulus peratomtype {} {}",
        num(y),
        num(y)
    );
    let _ = writeln!(
        o,
        "fix m2 all property/global poissonsRatio peratomtype {} {}",
        num(nu),
        num(nu)
    );
    match s.tsuji_e_in() {
        Some(e) => {
            let _ = writeln!(
                o,
                "fix m3 all property/global coefficientRestitution peratomtypepair 2 {} {} {} {}",
                num(e),
                num(e),
                num(e),
                num(e)
            );
        }
        None => o.push_str(&unreachable_line("#", "Tsuji damping", s.tsuji_alpha)),
    }
    o.push_str(
        "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n\
         pair_style gran model hertz tangential history limitForce on\n\
         pair_coeff * *\n\
         fix wall all wall/gran model hertz tangential history limitForce on primitive type 2 \
         zplane 0.0\n",
    );
    o
}

pub(super) fn chrono(s: &ExportSet) -> String {
    let mut o = String::new();
    s.header(&mut o, "//", "");
    let nu = 0.3;
    let y = 2.0 * (1.0 - nu * nu) * s.e_star();
    // Flores: χ = 8(1 − c_r)/(5 c_r), so c_r = 8/(8 + 5χ); Chrono clamps c_r to >= 0.01
    let cr_flores = 8.0 / (8.0 + 5.0 * s.hunt_crossley_chi);
    let _ = write!(
        o,
        "// ChSystemSMC with material properties; ball and fixed wall share the material, so\n\
         // E_eff = E/(2(1 - ν²)) = E* = 3 K_h/(4 √R) = {}, R_eff = R, m_eff = m.\n\
         sys.UseMaterialProperties(true);\n\
         auto mat = chrono_types::make_shared<ChContactMaterialSMC>();\n\
         mat->SetYoungModulus({});\n\
         mat->SetPoissonRatio({});\n\
         mat->SetFriction(0);\n\
         // Hunt-Crossley family: the Flores model, F = K_h δ^1.5 (1 + 8(1 - c_r)/(5 c_r) δ̇/v),\n\
         // v = the impact speed with TangentialDisplacementModel::MultiStep (relvel_init);\n\
         // c_r below is the input that gives the exact χ = {}, not the target COR.\n\
         sys.SetContactForceModel(ChSystemSMC::ContactForceModel::Flores);\n\
         sys.SetTangentialDisplacementModel(ChSystemSMC::TangentialDisplacementModel::MultiStep);\n\
         mat->SetRestitution({});\n",
        num(s.e_star()),
        num(y),
        num(nu),
        num(s.hunt_crossley_chi),
        num(cr_flores)
    );
    o.push_str(
        "// or Tsuji's law: the Hertz model, γ_n = 2√(5/6) β √(S_n m_eff) (η = √5 β √(m K_h)):\n",
    );
    match s.tsuji_e_in() {
        Some(e) => {
            let _ = writeln!(
                o,
                "// sys.SetContactForceModel(ChSystemSMC::ContactForceModel::Hertz);\n\
                 // mat->SetRestitution({});",
                num(e)
            );
        }
        None => o.push_str(&unreachable_line("//", "Tsuji damping", s.tsuji_alpha)),
    }
    o
}

pub(super) fn yade(s: &ExportSet) -> String {
    let mut o = String::new();
    s.header(&mut o, "#", "");
    let _ = write!(
        o,
        "# Law2_ScGeom_ViscElPhys_Basic clips the normal force at F >= 0: Kelvin-Voigt without\n\
         # tension. A contact's kn, cn are the series combination of both materials' values, so\n\
         # ball and wall each get 2k and 2η; massMultiply=False takes them as given (N/m, N·s/m).\n\
         mat = O.materials.append(ViscElMat(kn={}, cn={}, ks=0, cs=0, frictionAngle=0, \
         massMultiply=False))\n\
         # engines: InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],\n\
         #   [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()])\n",
        num(2.0 * s.k),
        num(2.0 * s.kv_no_tension_eta)
    );
    o
}

pub(super) fn mujoco(s: &ExportSet) -> String {
    let mut o = String::new();
    s.header(&mut o, "<!--", " -->");
    let (kk, bb) = (s.k / s.mass, s.kv_no_tension_eta / s.mass);
    let omega = kk.sqrt();
    let _ = write!(
        o,
        "<!-- A contact is a soft unilateral constraint: a + d (b v + k r) = (1 - d) a0 with\n\
         b = damping/dmax, k = stiffness d/dmax² for solref = \"-stiffness -damping\"; at\n\
         d = dmin = dmax it is the clipped Kelvin-Voigt law per unit mass, a = -(η/m) v - (k/m) r.\n\
         condim 1 keeps the constraint's inverse inertia 1/m. priority 1 makes this geom's condim,\n\
         solref and solimp the contact's: without it MuJoCo takes the larger condim and the mean\n\
         solimp of the two geoms, and the default plane's solimp moves the COR by up to 2e-3 (or\n\
         give the plane condim=\"1\" and this solimp). Equivalent (timeconst, dampratio) = ({}, {}).\n",
        num(1.0 / (s.kv_no_tension_zeta * omega)),
        num(s.kv_no_tension_zeta),
    );
    let t_c = s.kv_no_tension_contact_time.map_or("none".into(), num);
    match s.mujoco_timestep {
        Some(h) => {
            let _ = writeln!(
                o,
                "The contact lasts {} s; at the time step below (integrator Euler, the default)\n\
                 every contact phase (where in a step the ball meets the plane) gives the target COR\n\
                 within {}, an error that shrinks about in proportion to the step. The option goes\n\
                 under <mujoco>, the geom into a body with a free joint. -->\n\
                 <option timestep=\"{}\" integrator=\"Euler\"/>",
                t_c,
                num(STEP_TOL),
                num(h)
            );
        }
        None => {
            let _ = writeln!(
                o,
                "No time step down to contact time/100000 keeps every contact phase within {} of\n\
                 the target (contact time {} s). -->",
                num(STEP_TOL),
                t_c
            );
        }
    }
    let _ = writeln!(
        o,
        "<geom type=\"sphere\" size=\"{}\" mass=\"{}\" priority=\"1\" condim=\"1\" \
         solref=\"-{} -{}\" solimp=\"0.9999 0.9999 0.001 0.5 2\"/>",
        num(s.radius),
        num(s.mass),
        num(kk),
        num(bb)
    );
    o
}
