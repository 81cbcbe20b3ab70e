//! The oblique view's parameters (θ, ω, μ, and the tangential model's K_t and κ): their
//! steps, and their one range, the library's (`Oblique::validate`, src/oblique/mod.rs), which
//! `bouncelab oblique` applies too: a value the view takes the command line takes
//! (`the_ranges_are_the_library_s` below).

use crate::oblique::{Oblique, ObliqueError};

/// A parameter of the oblique view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ObliqueParam {
    /// θ, degrees between the incoming path and the surface: `a` / `A`.
    Angle,
    /// ω, rad/s, > 0 topspin: `w` / `W`.
    Spin,
    /// μ, Coulomb's coefficient: `k` / `K`.
    Friction,
    /// K_t, the tangential spring (N/m; the ball's Mindlin value until typed or stepped):
    /// `--tangential-stiffness`.
    TangentialStiffness,
    /// κ = I/(m R²) (the preset's until typed or stepped): `--inertia-factor`.
    InertiaFactor,
}

/// The largest |ω| the library takes (rad/s).
pub const SPIN_MAX: f64 = 1e9;
/// The largest μ the library takes.
pub const FRICTION_MAX: f64 = 1e6;

impl ObliqueParam {
    pub const ALL: [ObliqueParam; 5] = [
        ObliqueParam::Angle,
        ObliqueParam::Spin,
        ObliqueParam::Friction,
        ObliqueParam::TangentialStiffness,
        ObliqueParam::InertiaFactor,
    ];

    pub fn symbol(self) -> &'static str {
        match self {
            ObliqueParam::Angle => "θ",
            ObliqueParam::Spin => "ω",
            ObliqueParam::Friction => "μ",
            ObliqueParam::TangentialStiffness => "K_t",
            ObliqueParam::InertiaFactor => "κ",
        }
    }

    /// The command line's name of it (`--angle`, `--spin`, `--friction`,
    /// `--tangential-stiffness`, `--inertia-factor`).
    pub fn name(self) -> &'static str {
        match self {
            ObliqueParam::Angle => "angle",
            ObliqueParam::Spin => "spin",
            ObliqueParam::Friction => "friction",
            ObliqueParam::TangentialStiffness => "tangential-stiffness",
            ObliqueParam::InertiaFactor => "inertia-factor",
        }
    }

    /// The library's name of it, as its refusals name it (`invalid tangential_stiffness: …`).
    pub fn field(self) -> &'static str {
        match self {
            ObliqueParam::TangentialStiffness => "tangential_stiffness",
            ObliqueParam::InertiaFactor => "inertia_factor",
            p => p.name(),
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            ObliqueParam::Angle => "°",
            ObliqueParam::Spin => " rad/s",
            ObliqueParam::Friction | ObliqueParam::InertiaFactor => "",
            ObliqueParam::TangentialStiffness => " N/m",
        }
    }

    /// The values the library takes, as users read them: the reason `Oblique::validate`
    /// gives, word for word.
    pub fn range_text(self) -> &'static str {
        match self {
            ObliqueParam::Angle => "(0, 90] degrees",
            ObliqueParam::Spin => "|ω| ≤ 1e9 rad/s",
            ObliqueParam::Friction => "[0, 1e6]",
            ObliqueParam::TangentialStiffness => "positive",
            ObliqueParam::InertiaFactor => "(0, 1]",
        }
    }

    /// The fine step, the digits a value on screen needs to show one (`tui::format::stepped`).
    pub fn fine_step(self, value: f64) -> f64 {
        match self {
            ObliqueParam::Angle => 1.0,
            ObliqueParam::Spin => 10.0,
            ObliqueParam::Friction | ObliqueParam::InertiaFactor => 0.01,
            // 10 % of the value: four digits show it
            ObliqueParam::TangentialStiffness => 0.1 * value.abs(),
        }
    }

    /// One step from `value`: θ ±1° (coarse ±5°), ω ±10 rad/s (coarse ±100), μ and κ ±0.01
    /// (coarse ±0.1), K_t ×1.1 or ÷1.1 (coarse ×2, ÷2: a stiffness spans decades and stays
    /// positive). Not clamped.
    pub fn step(self, value: f64, up: bool, coarse: bool) -> f64 {
        if self == ObliqueParam::TangentialStiffness {
            let factor: f64 = if coarse { 2.0 } else { 1.1 };
            // without the float noise of the factor (1e5 × 1.1 is 110000.00000000001)
            return crate::tui::exact::tidy(if up { value * factor } else { value / factor });
        }
        let sign = if up { 1.0 } else { -1.0 };
        let (fine, big) = match self {
            ObliqueParam::Angle => (1.0, 5.0),
            ObliqueParam::Spin => (10.0, 100.0),
            _ => (0.01, 0.1),
        };
        // rounded to the step's decimals, so ten fine steps of 0.01 land on 0.1 exactly
        let v = value + sign * if coarse { big } else { fine };
        (v * 1e6).round() / 1e6
    }

    /// The nearest value the library takes to `value` on a step that went past a bound: the
    /// closed bound (90°, ±1e9 rad/s, μ 0 or 1e6, κ 1); `None` past θ's, κ's or K_t's open
    /// bound 0, or for a value that is no finite number.
    pub fn clamp(self, value: f64) -> Option<f64> {
        if !value.is_finite() {
            return None;
        }
        match self {
            ObliqueParam::Angle if value <= 0.0 => None,
            ObliqueParam::Angle => Some(value.min(90.0)),
            ObliqueParam::Spin => Some(value.clamp(-SPIN_MAX, SPIN_MAX)),
            ObliqueParam::Friction => Some(value.clamp(0.0, FRICTION_MAX)),
            ObliqueParam::TangentialStiffness => (value > 0.0).then_some(value),
            ObliqueParam::InertiaFactor if value <= 0.0 => None,
            ObliqueParam::InertiaFactor => Some(value.min(1.0)),
        }
    }

    /// `value` checked by the library's own rule: the command line's message when refused
    /// ("invalid angle: 0 (must lie in (0, 90] degrees); θ kept").
    pub fn check(self, value: f64) -> Result<f64, String> {
        self.library_check(value)
            .map_err(|e| format!("{e}; {} kept", self.symbol()))
    }

    /// [`ObliqueParam::check`] without "kept": the command line's message word for word (a
    /// session's value, which nothing on screen keeps).
    pub fn library_check(self, value: f64) -> Result<f64, String> {
        // the other quantities at values the library takes: only this one is judged
        let mut o = Oblique {
            angle_deg: 45.0,
            spin: 0.0,
            friction: 0.5,
            tangential_stiffness: 1.0,
            inertia_factor: 0.4,
            radius: 1.0,
            tangential_damping: 0.0,
        };
        match self {
            ObliqueParam::Angle => o.angle_deg = value,
            ObliqueParam::Spin => o.spin = value,
            ObliqueParam::Friction => o.friction = value,
            ObliqueParam::TangentialStiffness => o.tangential_stiffness = value,
            ObliqueParam::InertiaFactor => o.inertia_factor = value,
        }
        match o.validate() {
            Ok(()) => Ok(value),
            Err(ObliqueError::Invalid(e)) => Err(e.to_string()),
            Err(e) => Err(e.to_string()),
        }
    }

    pub fn next(self) -> ObliqueParam {
        let i = ObliqueParam::ALL
            .iter()
            .position(|&p| p == self)
            .unwrap_or(0);
        ObliqueParam::ALL[(i + 1) % ObliqueParam::ALL.len()]
    }

    pub fn prev(self) -> ObliqueParam {
        let i = ObliqueParam::ALL
            .iter()
            .position(|&p| p == self)
            .unwrap_or(0);
        let n = ObliqueParam::ALL.len();
        ObliqueParam::ALL[(i + n - 1) % n]
    }
}

#[cfg(test)]
mod tests {
    use super::ObliqueParam::{self, *};

    #[test]
    fn the_ranges_are_the_library_s() {
        // each refusal is the library's message, which names the range this view shows
        for (p, bad) in [
            (Angle, 0.0),
            (Angle, 90.5),
            (Spin, 2e9),
            (Friction, -0.1),
            (TangentialStiffness, 0.0),
            (TangentialStiffness, f64::INFINITY),
            (InertiaFactor, 0.0),
            (InertiaFactor, 1.01),
        ] {
            let e = p.check(bad).unwrap_err();
            assert!(e.starts_with(&format!("invalid {}: ", p.field())), "{e}");
            assert!(e.contains(p.range_text()), "{e}");
        }
        assert_eq!(Angle.check(90.0), Ok(90.0));
        assert_eq!(Friction.check(0.0), Ok(0.0));
        assert_eq!(Spin.check(-1e9), Ok(-1e9));
        assert_eq!(InertiaFactor.check(1.0), Ok(1.0));
        assert_eq!(TangentialStiffness.check(1e-3), Ok(1e-3));
    }

    #[test]
    fn steps_and_bounds() {
        assert_eq!(Friction.step(0.09, true, false), 0.1);
        assert_eq!(Angle.step(16.0, false, true), 11.0);
        assert_eq!(Spin.step(0.0, true, true), 100.0);
        assert_eq!(Angle.clamp(91.0), Some(90.0));
        assert_eq!(Angle.clamp(0.0), None);
        assert_eq!(Friction.clamp(-0.01), Some(0.0));
        assert_eq!(Spin.clamp(f64::NAN), None);
        assert_eq!(InertiaFactor.clamp(1.05), Some(1.0));
        assert_eq!(InertiaFactor.clamp(0.0), None);
        assert_eq!(TangentialStiffness.clamp(-1.0), None);
        assert_eq!(TangentialStiffness.step(1e5, true, true), 2e5);
        assert_eq!(TangentialStiffness.step(1e5, false, true), 5e4);
        assert_eq!(ObliqueParam::Angle.next(), Spin);
        assert_eq!(ObliqueParam::Angle.prev(), InertiaFactor);
        assert_eq!(InertiaFactor.next(), Angle);
    }
}
