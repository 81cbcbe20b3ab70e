//! The three parameters the explorer changes live (λ, ζ, v0): their ranges, steps and checks.
//! Everything else about the ball comes from the preset. The ranges and the checks are the
//! command line's (`bouncelab run --lambda/--zeta/--v0`): the library's constants and its
//! `api::set_lambda_zeta` / `ImpactParams::validate`, so a value one takes the other takes.

use crate::model::params::{
    ImpactParams, LAMBDA_RANGE, MEANINGFUL_MAX, MEANINGFUL_MIN, POSITIVE_RANGE, Range, ZETA_RANGE,
};

/// A live parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Param {
    /// λ = K_r / K_p (Eq. 24): moves K_r.
    Lambda,
    /// ζ = √(m K_p) / (2c) (Eq. 24): moves c.
    Zeta,
    /// Impact speed v0 (m/s).
    V0,
}

/// Which way a step goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    Up,
    Down,
}

/// Smallest impact speed the explorer accepts (m/s), as `run --v0`: the meaningful minimum.
pub const V0_MIN: f64 = MEANINGFUL_MIN;

impl Param {
    pub const ALL: [Param; 3] = [Param::Lambda, Param::Zeta, Param::V0];

    pub fn symbol(self) -> &'static str {
        match self {
            Param::Lambda => "λ",
            Param::Zeta => "ζ",
            Param::V0 => "v0",
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            Param::V0 => " m/s",
            _ => "",
        }
    }

    /// The values `run` accepts (λ, ζ: 0 or 1e-15 … 1e6; v0: 1e-15 … 1e15 m/s): the
    /// library's own ranges, one source for the prompt, the checks and the messages. Inside
    /// it [`Param::check`] may still refuse a value: a v0 that makes z̄_p = z_p ω0/v0 too
    /// small, or a λ that takes K_r out of its range, as `run` does.
    pub fn range(self) -> Range {
        match self {
            Param::Lambda => LAMBDA_RANGE,
            Param::Zeta => ZETA_RANGE,
            Param::V0 => POSITIVE_RANGE,
        }
    }

    /// The range as users read it, e.g. "0 or 1e-15 … 1e6", "1e-15 … 1e15 m/s".
    pub fn range_text(self) -> String {
        format!("{}{}", self.range().text, self.unit())
    }

    /// One step from `value`: λ ±0.01 / ±0.1, ζ ×÷1.1 / ×÷2 (log scale), v0 ±0.1 / ±1 m/s.
    /// Not clamped.
    pub fn step(self, value: f64, dir: Dir, coarse: bool) -> f64 {
        let sign = if dir == Dir::Up { 1.0 } else { -1.0 };
        // without the steps' float noise: three steps of 0.1 from 3 are 3.3, which `y` writes
        // as typed (not 3.3000000000000003; src/tui/exact.rs)
        crate::tui::exact::tidy(match self {
            Param::Lambda => value + sign * if coarse { 0.1 } else { 0.01 },
            Param::V0 => value + sign * if coarse { 1.0 } else { 0.1 },
            Param::Zeta => {
                let factor: f64 = if coarse { 2.0 } else { 1.1 };
                value * factor.powf(sign)
            }
        })
    }

    /// `value` brought into [`Param::range`]'s closed span 0 (or its smallest value) … its
    /// largest; `None` for a value that is not a finite number. The flag tells whether it had
    /// to move.
    pub fn clamp(self, value: f64) -> Option<(f64, bool)> {
        if !value.is_finite() {
            return None;
        }
        let r = self.range();
        let lo = if r.zero { 0.0 } else { r.lo };
        let v = value.clamp(lo, r.hi);
        Some((v, v != value))
    }

    /// `params` with this parameter set to `value`, if `run` takes it: checked by the command
    /// line's own path (`api::set_lambda_zeta` for λ and ζ, `ImpactParams::validate` for v0,
    /// as `run --v0`). Refused, never clamped, with the command line's message, the parameter
    /// named by its symbol ("invalid λ: 1e-16 (outside the range 0 or 1e-15 … 1e6); λ kept"),
    /// the range added when the reason does not name it.
    pub fn check(self, value: f64, params: &ImpactParams) -> Result<ImpactParams, String> {
        let mut next = *params;
        let valid = match self {
            Param::Lambda => crate::api::set_lambda_zeta(&mut next, Some(value), None),
            Param::Zeta => crate::api::set_lambda_zeta(&mut next, None, Some(value)),
            Param::V0 => {
                next.v0 = value;
                next.validate().map_err(Into::into)
            }
        };
        valid.map(|()| next).map_err(|e| self.refusal(&e, params))
    }

    /// Why `check` refused, in the screen's words: the parameter's symbol (λ, never the
    /// command line's `lambda`), and a range the refused value lies outside — for a λ or ζ
    /// whose K_r or c leaves the meaningful range, this ball's (issue 51 item 8: "invalid
    /// zeta: 1e-14 (gives c = 2.257376796195088e15 kg/s …); ζ kept (range 0 or 1e-15 … 1e6)"
    /// showed a range holding the value it refused).
    fn refusal(self, e: &crate::api::BallError, params: &ImpactParams) -> String {
        let kept = format!("{} kept", self.symbol());
        if let crate::api::BallError::Derived {
            value: v,
            gives,
            derived,
            unit,
            reason,
            ..
        } = e
        {
            let (lo, hi) = self.ball_range(params);
            let zero = if self.range().zero { "0 or " } else { "" };
            return format!(
                "invalid {}: {} (gives {gives} = {} {unit}: {reason}); {kept} (range for this \
                 ball {zero}{} … {})",
                self.symbol(),
                crate::text::short(*v, 4),
                crate::text::short(*derived, 4),
                crate::text::short(lo, 4),
                crate::text::short(hi, 4)
            );
        }
        let cli = format!("invalid {}:", self.cli_name());
        let said = e
            .to_string()
            .replacen(&cli, &format!("invalid {}:", self.symbol()), 1);
        // the range once: named here unless the reason already names it
        if said.contains(self.range().text) {
            format!("{said}; {kept}")
        } else {
            format!("{said}; {kept} (range {})", self.range_text())
        }
    }

    /// The command line's name of the parameter, as its messages give it.
    fn cli_name(self) -> &'static str {
        match self {
            Param::Lambda => "lambda",
            Param::Zeta => "zeta",
            Param::V0 => "v0",
        }
    }

    /// The λ (ζ) this ball takes: those whose K_r = λ K_p (c = √(m K_p)/(2ζ), Eq. 24) lies in
    /// the meaningful range, within the parameter's own range.
    fn ball_range(self, p: &ImpactParams) -> (f64, f64) {
        let r = self.range();
        let (lo, hi) = match self {
            Param::Lambda => (MEANINGFUL_MIN / p.k_p, MEANINGFUL_MAX / p.k_p),
            Param::Zeta => {
                let c0 = (p.mass * p.k_p).sqrt() / 2.0;
                (c0 / MEANINGFUL_MAX, c0 / MEANINGFUL_MIN)
            }
            Param::V0 => (r.lo, r.hi),
        };
        (lo.max(r.lo), hi.min(r.hi))
    }

    /// The parameter's value in `params`.
    pub fn get(self, params: &ImpactParams) -> f64 {
        match self {
            Param::Lambda => params.normalized().lambda,
            Param::Zeta => params.normalized().zeta,
            Param::V0 => params.v0,
        }
    }

    /// `params` with this parameter set to `value` (λ moves K_r, ζ moves c: Eq. 24).
    pub fn set(self, params: &ImpactParams, value: f64) -> ImpactParams {
        let n = params.normalized();
        match self {
            Param::Lambda => params.with_lambda_zeta(value, n.zeta),
            Param::Zeta => params.with_lambda_zeta(n.lambda, value),
            Param::V0 => ImpactParams {
                v0: value,
                ..*params
            },
        }
    }

    pub fn next(self) -> Param {
        let i = Param::ALL.iter().position(|&p| p == self).unwrap_or(0);
        Param::ALL[(i + 1) % 3]
    }

    pub fn prev(self) -> Param {
        let i = Param::ALL.iter().position(|&p| p == self).unwrap_or(0);
        Param::ALL[(i + 2) % 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zeta_steps_are_multiplicative() {
        let up = Param::Zeta.step(0.5, Dir::Up, false);
        assert!((up - 0.55).abs() < 1e-12);
        assert!((Param::Zeta.step(0.5, Dir::Down, true) - 0.25).abs() < 1e-12);
        assert!((Param::Lambda.step(1.0, Dir::Down, true) - 0.9).abs() < 1e-12);
    }

    #[test]
    fn clamp_reports_movement_and_refuses_non_numbers() {
        assert_eq!(Param::Lambda.clamp(-0.01), Some((0.0, true)));
        assert_eq!(Param::Zeta.clamp(5e6), Some((1e6, true)));
        assert_eq!(Param::V0.clamp(0.0), Some((V0_MIN, true)));
        assert_eq!(Param::V0.clamp(3.0), Some((3.0, false)));
        assert_eq!(Param::Zeta.clamp(f64::NAN), None);
        assert_eq!(Param::Zeta.clamp(f64::INFINITY), None);
    }

    #[test]
    fn every_refusal_is_the_command_line_s_message_with_the_range() {
        // one range and the command line's own message for every refusal
        let p = ImpactParams::from_normalized(1.0, 0.2, 3.0);
        let said = |param: Param, v: f64| param.check(v, &p).unwrap_err();
        assert_eq!(
            said(Param::Lambda, 1e-16),
            "invalid λ: 1e-16 (outside the range 0 or 1e-15 … 1e6); λ kept"
        );
        assert!(said(Param::Lambda, 1000000.0000000001).contains("the range is 0 or 1e-15 … 1e6"));
        assert_eq!(
            said(Param::Zeta, f64::INFINITY),
            "invalid ζ: inf (must be finite); ζ kept (range 0 or 1e-15 … 1e6)"
        );
        assert_eq!(
            said(Param::V0, f64::NAN),
            "invalid v0: NaN (not a number); v0 kept (range 1e-15 … 1e15 m/s)"
        );
        assert_eq!(Param::Lambda.range_text(), "0 or 1e-15 … 1e6");
        assert_eq!(Param::V0.range_text(), "1e-15 … 1e15 m/s");
        assert!(Param::Lambda.check(0.0, &p).is_ok() && Param::Zeta.check(0.0, &p).is_ok());
    }

    /// A ζ whose c leaves the meaningful range is refused with this ball's range, which the
    /// refused value lies outside, in four digits (it showed "range 0 or 1e-15 … 1e6" around
    /// the refused 1e-14, and c to sixteen digits).
    #[test]
    fn a_derived_refusal_shows_a_range_without_the_refused_value() {
        // a heavy, stiff ball: m 1000 kg, K_p 1e12 N/m, so c = √(m K_p)/(2ζ) passes 1e15
        // kg/s below ζ 1.6e-8 and K_r = λ K_p passes 1e15 N/m above λ 1000
        let mut p = ImpactParams::from_normalized(1.0, 0.2, 3.0);
        (p.mass, p.k_p) = (1e3, 1e12);
        for (param, v) in [(Param::Zeta, 1e-9), (Param::Lambda, 1e4)] {
            let said = param.check(v, &p).unwrap_err();
            let (lo, hi) = param.ball_range(&p);
            assert!(!(lo..=hi).contains(&v), "{said}");
            assert!(said.contains("range for this ball"), "{said}");
            assert!(!said.contains("1e-15 … 1e6"), "{said}");
            assert!(!said.contains("zeta") && !said.contains("lambda"), "{said}");
            assert!(!said.contains("58113883"), "four digits: {said}");
        }
    }

    #[test]
    fn set_moves_the_right_constant() {
        let p = ImpactParams::from_normalized(1.0, 0.2, 3.0);
        let q = Param::Lambda.set(&p, 0.4);
        assert_eq!((q.mass, q.k_p, q.damping), (p.mass, p.k_p, p.damping));
        assert!((Param::Lambda.get(&q) - 0.4).abs() < 1e-12);
        let q = Param::Zeta.set(&p, 0.8);
        assert_eq!(q.k_r, p.k_r);
        assert!((Param::Zeta.get(&q) - 0.8).abs() < 1e-12);
        assert_eq!(Param::V0.set(&p, 2.5).v0, 2.5);
    }
}
