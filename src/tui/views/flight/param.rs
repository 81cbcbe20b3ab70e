//! The flight view's values: the launch's speed, elevation, spin and height and the surface's
//! μ, their steps (fine, and coarse with Shift, PgUp/PgDn or `]`), and their command-line
//! names. Their ranges are the library's (`Ball::shot` refuses a value by name; the view then
//! keeps the last value it took and says why).

/// A value of the flight view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FlightParam {
    /// |v| at launch, m/s.
    Speed,
    /// Degrees above the horizontal (negative: down): `a` / `A`.
    Elevation,
    /// ω, rad/s, > 0 topspin: `w` / `W`.
    Spin,
    /// Height of the ball's centre at launch, m.
    Height,
    /// The surface's μ: `k` / `K`.
    Friction,
}

impl FlightParam {
    pub const ALL: [FlightParam; 5] = [
        FlightParam::Speed,
        FlightParam::Elevation,
        FlightParam::Spin,
        FlightParam::Height,
        FlightParam::Friction,
    ];

    pub fn symbol(self) -> &'static str {
        match self {
            FlightParam::Speed => "v",
            FlightParam::Elevation => "elev",
            FlightParam::Spin => "ω",
            FlightParam::Height => "H",
            FlightParam::Friction => "μ",
        }
    }

    /// `bouncelab shot`'s option for it.
    pub fn option(self) -> &'static str {
        match self {
            FlightParam::Speed => "--speed",
            FlightParam::Elevation => "--elevation",
            FlightParam::Spin => "--spin",
            FlightParam::Height => "--height",
            FlightParam::Friction => "--friction",
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            FlightParam::Speed => " m/s",
            FlightParam::Elevation => "°",
            FlightParam::Spin => " rad/s",
            FlightParam::Height => " m",
            FlightParam::Friction => "",
        }
    }

    /// The fine and coarse steps.
    fn steps(self) -> (f64, f64) {
        match self {
            FlightParam::Speed => (1.0, 5.0),
            FlightParam::Elevation => (1.0, 5.0),
            FlightParam::Spin => (10.0, 100.0),
            FlightParam::Height => (0.1, 0.5),
            FlightParam::Friction => (0.05, 0.2),
        }
    }

    /// `value` one step up or down, rounded to the step (so that steps from a typed value
    /// land on round numbers and a step and its inverse come back).
    pub fn step(self, value: f64, up: bool, coarse: bool) -> f64 {
        let (fine, big) = self.steps();
        let s = if coarse { big } else { fine };
        let next = value + if up { s } else { -s };
        // the f64 nearest the decimal (3 × 0.1 is 0.30000000000000004; `y` writes 0.3)
        let rounded = crate::tui::exact::tidy((next / s).round() * s);
        // −0 reads as "-0" on the screen
        if rounded == 0.0 { 0.0 } else { rounded }
    }

    pub fn next(self) -> FlightParam {
        let i = FlightParam::ALL
            .iter()
            .position(|p| *p == self)
            .unwrap_or(0);
        FlightParam::ALL[(i + 1) % FlightParam::ALL.len()]
    }

    pub fn prev(self) -> FlightParam {
        let n = FlightParam::ALL.len();
        let i = FlightParam::ALL
            .iter()
            .position(|p| *p == self)
            .unwrap_or(0);
        FlightParam::ALL[(i + n - 1) % n]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_step_and_its_inverse_come_back_on_round_values() {
        for p in FlightParam::ALL {
            for coarse in [false, true] {
                // a round value: three of this step (3 m/s is no round value for 5 m/s steps),
                // as the f64 nearest the decimal (3 × 0.1 is 0.30000000000000004; steps land
                // on 0.3)
                let (fine, big) = p.steps();
                let v = crate::tui::exact::tidy(3.0 * if coarse { big } else { fine });
                let up = p.step(v, true, coarse);
                assert_eq!(p.step(up, false, coarse), v, "{p:?}");
            }
        }
        assert_eq!(FlightParam::Spin.step(200.0, false, true), 100.0);
        assert_eq!(FlightParam::Elevation.step(1.0, false, false), 0.0);
        assert!(
            FlightParam::Elevation
                .step(1.0, false, false)
                .is_sign_positive()
        );
        assert_eq!(FlightParam::Speed.next().prev(), FlightParam::Speed);
    }
}
