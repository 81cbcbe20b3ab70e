//! The answer in SI units, with its energy balance (docs/oblique.md §3–§4).

use super::tangential::{Mode, Run};
use super::{NormalMotion, Oblique, ObliqueEnergy, ObliqueHistory, ObliqueResponse, Scaled};
use crate::model::params::ImpactParams;
use crate::solver::ImpactResponse;

/// What turns a normalized run into the SI answer.
pub(super) struct Answer<'a> {
    /// The normal impact's parameters (v0 = v_y).
    pub params: &'a ImpactParams,
    pub oblique: &'a Oblique,
    pub scaled: &'a Scaled,
    /// v_x, v_y and |v| at arrival (m/s).
    pub vx: f64,
    pub vy: f64,
    pub v: f64,
}

/// The friction's work over the slides, normalized by m v_y². On a slide with sign s from τ0
/// to τ1 the surface takes −∫F̃_t (ṽ_c − ũ') dτ, with F̃_t = −sμF̄, ũ = sμF̄/k̃ and
/// ṽ_c = ṽ_c0 − sμg ΔJ (ΔJ the normal impulse since τ0): in closed form
/// sμ ṽ_c0 ΔJ − μ²g ΔJ²/2 − μ²(F̄1² − F̄0²)/(2k̃).
///
/// With a dashpot the spring on the slide is LAMMPS's reset ũ = (sμF̄ − c̃ṽ_c)/k̃ and the
/// last term is ½k̃(ũ1² − ũ0²) of those: what the cap's force does beyond the spring, the
/// dashpot's share of it included (on the cap the two are one force).
pub(super) fn friction_work(s: &Scaled, run: &Run) -> f64 {
    let mu = s.mu;
    run.phases
        .iter()
        .enumerate()
        .filter_map(|(i, ph)| match ph.mode {
            Mode::Slip(sg) => {
                let (p0, p1) = run.ends(i);
                let dj = ph.vel0 - p1.velocity;
                let spring = if s.ct > 0.0 {
                    let u1 = ph.state(s, &p1, ph.end).0;
                    s.kt * (u1 * u1 - ph.u0 * ph.u0) / 2.0
                } else {
                    mu * mu * (p1.force.powi(2) - p0.force.powi(2)) / (2.0 * s.kt)
                };
                Some(sg * mu * ph.vc0 * dj - mu * mu * s.g * dj * dj / 2.0 - spring)
            }
            Mode::Stick => None,
        })
        .sum()
}

/// The tangential dashpot's loss over the sticks, normalized by m v_y²: c̃∫ṽ_c² dτ by
/// Gauss–Legendre (8 points a panel, panels of at most a quarter of the stick's fastest
/// radian) on the closed-form ṽ_c, independent of the closed form's own energy identity
/// d/dτ(ṽ_c²/2g + k̃ũ²/2) = −c̃ṽ_c² that the balance then checks (docs/oblique.md §4).
pub(super) fn damping_work(s: &Scaled, run: &Run) -> f64 {
    if s.ct == 0.0 {
        return 0.0;
    }
    let panel = 0.25 / s.stick_rate();
    run.phases
        .iter()
        .filter(|ph| ph.mode == Mode::Stick)
        .map(|ph| {
            let len = ph.end - ph.start;
            let n = (len / panel).ceil().max(1.0);
            let h = len / n;
            let mut sum = 0.0;
            for k in 0..n as usize {
                let mid = (k as f64 + 0.5) * h;
                for (x, w) in GAUSS8 {
                    for sgn in [-1.0, 1.0] {
                        let vc = ph.damped_state(s, mid + sgn * x * h / 2.0).1;
                        sum += w * h / 2.0 * vc * vc;
                    }
                }
            }
            s.ct * sum
        })
        .sum()
}

/// The 8-point Gauss–Legendre rule on [−1, 1]: the positive nodes with their weights (each
/// node is taken with both signs).
const GAUSS8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// What the normal motion lost (J): the audited dashpot, contact and recoil-spring terms when
/// the normal run was audited (the adaptive solver's, any law but the linear one), else — the
/// linear law's exact flow — the normal kinetic energy lost, ½ m (v_y² − v_y,out²), which those
/// three terms sum to (docs/model.md §8; `the_normal_losses_are_the_audited_ones` checks them
/// against `run`'s audit to 1e-12).
pub(super) fn normal_losses(normal: &ImpactResponse, m: f64, vy: f64) -> f64 {
    match &normal.energy {
        Some(b) => b.dashpot + b.contact + b.spring,
        None => 0.5 * m * vy * vy * (1.0 - normal.cor * normal.cor),
    }
}

impl Answer<'_> {
    /// The response: outgoing motion from ṽ_c at separation (Δṽ_x = κ/(1+κ) Δṽ_c and
    /// Δ(Rω)/v_y = −Δṽ_c/(1+κ), since both move with the one force F_t), the energy and the
    /// sampled histories.
    pub(super) fn response(
        &self,
        path: &impl NormalMotion,
        run: Run,
        normal: ImpactResponse,
        samples: usize,
    ) -> ObliqueResponse {
        let (s, o, p) = (self.scaled, self.oblique, self.params);
        let (m, r, vy) = (p.mass, o.radius, self.vy);
        let tf = path.end();
        let last = run.phases.last().expect("a run has a phase");
        let (u_end, vc_end) = last.state(s, &run.end, tf);
        // the spring at first contact: 0, or the dashpot's reset −c̃ṽ_c/k̃ (`tangential::run`)
        let u_in = run.phases[0].u0;
        let dvc = vc_end - run.vc_in;
        let vx_out = self.vx + vy * s.kappa / (1.0 + s.kappa) * dvc;
        let spin_out = o.spin - vy * dvc / ((1.0 + s.kappa) * r);
        let vy_out = normal.cor * vy;
        let w0 = p.omega0();
        // a fold from +0: `sum` of no f64 is −0, which the JSON would print as -0.0
        let grip = run
            .phases
            .iter()
            .filter(|ph| ph.mode == Mode::Stick)
            .map(|ph| ph.end - ph.start)
            .fold(0.0, |total, t| total + t);
        let inertia = s.kappa * m * r * r;
        let unit = m * vy * vy;
        let normal_dissipation = normal_losses(&normal, m, vy);
        let mut energy = ObliqueEnergy {
            translational_in: 0.5 * m * self.v * self.v,
            rotational_in: 0.5 * inertia * o.spin * o.spin,
            translational_out: 0.5 * m * (vx_out * vx_out + vy_out * vy_out),
            rotational_out: 0.5 * inertia * spin_out * spin_out,
            normal_dissipation,
            friction_dissipation: friction_work(s, &run) * unit,
            tangential_spring: 0.5 * s.kt * (u_end * u_end - u_in * u_in) * unit,
            tangential_damping: (s.ct > 0.0).then(|| damping_work(s, &run) * unit),
            residual: 0.0,
        };
        let e = &energy;
        let input = e.translational_in + e.rotational_in;
        let losses = e.normal_dissipation
            + e.friction_dissipation
            + e.tangential_spring
            + e.tangential_damping.unwrap_or(0.0);
        energy.residual = (input - e.translational_out - e.rotational_out - losses).abs() / input;
        let vc_in_si = run.vc_in * vy;
        let kinks = path.kinks();
        let max_friction = run
            .phases
            .iter()
            .enumerate()
            .map(|(i, ph)| ph.max_friction(s, path, &kinks, run.ends(i)))
            .fold(0.0, f64::max);
        let history = (samples > 0).then(|| self.history(path, &run, samples));
        ObliqueResponse {
            v_in: self.v,
            angle_in_deg: o.angle_deg,
            spin_in: o.spin,
            vx_in: self.vx,
            vy_in: vy,
            v_out: vx_out.hypot(vy_out),
            angle_out_deg: vy_out.atan2(vx_out).to_degrees(),
            spin_out,
            vx_out,
            vy_out,
            cor_normal: normal.cor,
            cor_tangential: (vc_in_si != 0.0).then(|| -vc_end / run.vc_in),
            apparent_friction: (self.vx - vx_out).abs() / (vy + vy_out),
            slid_throughout: run.phases.len() == 1 && matches!(last.mode, Mode::Slip(_)),
            grip_time: grip / w0,
            contact_time: normal.contact_time.unwrap_or(tf / w0),
            max_normal_force: normal.max_force,
            max_friction_force: max_friction * m * vy * w0,
            energy,
            phases: run.phases,
            normal,
            history,
        }
    }

    /// `n` samples evenly spaced over [0, t_f].
    fn history(&self, path: &impl NormalMotion, run: &Run, n: usize) -> ObliqueHistory {
        let (s, p) = (self.scaled, self.params);
        let (vy, w0) = (self.vy, p.omega0());
        let force = p.mass * vy * w0;
        let tf = path.end();
        let mut h = ObliqueHistory::default();
        for j in 0..n {
            let tau = if n > 1 {
                tf * j as f64 / (n - 1) as f64
            } else {
                0.0
            };
            let i = run
                .phases
                .partition_point(|ph| ph.end < tau)
                .min(run.phases.len() - 1);
            let pt = path.at(tau);
            let (u, vc) = run.phases[i].state(s, &pt, tau);
            let spin =
                self.oblique.spin - vy * (vc - run.vc_in) / ((1.0 + s.kappa) * self.oblique.radius);
            h.t.push(tau / w0);
            h.normal_force.push(pt.force * force);
            h.friction_force.push(-(s.kt * u + s.ct * vc) * force);
            h.slip_velocity.push(vc * vy);
            h.spin.push(spin);
        }
        h
    }
}
