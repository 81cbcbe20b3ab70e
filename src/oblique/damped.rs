//! The tangential dashpot's closed forms (docs/oblique.md §1): while sticking the damped
//! oscillator ũ'' + 2βũ' + ω̃_t²ũ = 0 (β = gc̃/2) from a phase's start, its largest trial
//! force, and the spring LAMMPS's linear_history resets onto the cap while sliding.

use super::Scaled;

/// A damped stick's start: ũ0 and ṽ_c0 at δ = 0.
#[derive(Debug, Clone, Copy)]
pub(super) struct Start {
    pub u0: f64,
    pub vc0: f64,
}

impl Start {
    /// (ũ, ṽ_c) of a damped stick δ after its start: with C = cos ω_d δ, S = sin(ω_d δ)/ω_d
    /// (cosh and sinh(γδ)/γ when overdamped, 1 and δ when critical, `damped_basis`),
    /// ũ = e^{−βδ}(ũ0 C + (ṽ0 + βũ0) S), ṽ_c = e^{−βδ}(ṽ0 C − (βṽ0 + ω̃_t²ũ0) S).
    pub(super) fn state(&self, s: &Scaled, delta: f64) -> (f64, f64) {
        let (e, c, sn) = damped_basis(s, delta);
        let (u0, v0, b) = (self.u0, self.vc0, s.beta);
        let w2 = s.omega_t * s.omega_t;
        (
            e * (u0 * c + (v0 + b * u0) * sn),
            e * (v0 * c - (b * v0 + w2 * u0) * sn),
        )
    }

    /// The largest |f| = |k̃ũ + c̃ṽ_c| over a damped stick: f solves the stick's own equation,
    /// so f = e^{−βδ}(f0 C + (f0' + βf0) S) with f0' = k̃ṽ0 − c̃g f0, and its first extremum
    /// (f' = 0: f0' C = (βf0' + ω̃_t²f0) S) is its largest crest, the later ones decaying; else
    /// an end.
    /// Over a stick of length `len`.
    pub(super) fn max_force(&self, s: &Scaled, len: f64) -> f64 {
        let f_at = |d: f64| {
            let (u, vc) = self.state(s, d);
            (s.kt * u + s.ct * vc).abs()
        };
        let f0 = s.kt * self.u0 + s.ct * self.vc0;
        let d0 = s.kt * self.vc0 - s.ct * s.g * f0;
        let q = s.beta * d0 + s.omega_t * s.omega_t * f0;
        let w2 = s.omega_t * s.omega_t - s.beta * s.beta;
        let crest = if w2 > 0.0 {
            let wd = w2.sqrt();
            Some((d0 * wd).atan2(q).rem_euclid(std::f64::consts::PI) / wd)
        } else if w2 < 0.0 {
            // tanh(γδ) = γ f0'/q, one root at most
            let gm = (-w2).sqrt();
            let r = gm * d0 / q;
            (q != 0.0 && r > 0.0 && r < 1.0).then(|| r.atanh() / gm)
        } else {
            (q != 0.0 && d0 / q > 0.0).then(|| d0 / q)
        };
        let inside = crest.filter(|&d| d <= len).map_or(0.0, f_at);
        f_at(0.0).max(f_at(len)).max(inside)
    }
}

/// ũ on a slide: the spring LAMMPS's linear_history resets so that k̃ũ + c̃ṽ_c is the cap sμF̄.
pub(super) fn slip_spring(s: &Scaled, sg: f64, force: f64, vc: f64) -> f64 {
    if s.ct > 0.0 {
        (sg * s.mu * force - s.ct * vc) / s.kt
    } else {
        sg * s.mu * force / s.kt
    }
}

/// (e^{−βδ}, C, S) of a damped stick: C = cos ω_d δ and S = sin(ω_d δ)/ω_d with
/// ω_d² = ω̃_t² − β² > 0; cosh γδ and sinh(γδ)/γ with γ² = −ω_d² > 0; 1 and δ when critical.
pub(crate) fn damped_basis(s: &Scaled, delta: f64) -> (f64, f64, f64) {
    let e = (-s.beta * delta).exp();
    let w2 = s.omega_t * s.omega_t - s.beta * s.beta;
    if w2 > 0.0 {
        let wd = w2.sqrt();
        let (sn, cs) = (wd * delta).sin_cos();
        (e, cs, sn / wd)
    } else if w2 < 0.0 {
        let gm = (-w2).sqrt();
        (e, (gm * delta).cosh(), (gm * delta).sinh() / gm)
    } else {
        (e, 1.0, delta)
    }
}
