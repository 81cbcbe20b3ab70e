//! A shot's answer as numbers by name: the columns `mc --shot` (its samples' rows) and
//! Python's `shots` (its arrays) read off each shot, one definition of each (NaN for a
//! bounce that did not happen).

use super::ShotReport;

/// Every number [`ShotReport::quantity`] answers, in the order of Python's `shots` arrays:
/// the first bounce's (its time and place, the speed and angle in and out, the spin out),
/// the end's state, then the net's clearance (NaN where the ball does not reach it) and
/// verdict (1 cleared, else 0).
pub const SHOT_QUANTITIES: [&str; 14] = [
    "landing_t",
    "landing_x",
    "v_in",
    "angle_in",
    "v_out",
    "angle_out",
    "spin_out",
    "end_t",
    "end_x",
    "end_y",
    "end_vx",
    "end_vy",
    "net_clearance",
    "net_cleared",
];

impl ShotReport {
    /// The number named `name` (one of [`SHOT_QUANTITIES`]; `None` for any other name).
    pub fn quantity(&self, name: &str) -> Option<f64> {
        let nan = f64::NAN;
        let b = self.bounces.first();
        let s = &self.end.state;
        let net = self.net.as_ref();
        Some(match name {
            "landing_t" => b.map_or(nan, |b| b.t),
            "landing_x" => b.map_or(nan, |b| b.x),
            "v_in" => b.map_or(nan, |b| b.v_in),
            "angle_in" => b.map_or(nan, |b| b.angle_in),
            "v_out" => b.map_or(nan, |b| b.v_out),
            "angle_out" => b.map_or(nan, |b| b.angle_out),
            "spin_out" => b.map_or(nan, |b| b.spin_out),
            "end_t" => s.t,
            "end_x" => s.x,
            "end_y" => s.y,
            "end_vx" => s.vx,
            "end_vy" => s.vy,
            "net_clearance" => net.and_then(|n| n.clearance).unwrap_or(nan),
            "net_cleared" => net.map_or(0.0, |n| f64::from(u8::from(n.cleared))),
            _ => return None,
        })
    }

    /// The numbers named `names`, in their order.
    ///
    /// # Panics
    /// On a name not in [`SHOT_QUANTITIES`]: the callers' names are constants, each listed
    /// there (`every_row_name_is_a_quantity`).
    pub fn quantities<const N: usize>(&self, names: &[&str; N]) -> [f64; N] {
        names.map(|n| {
            self.quantity(n)
                .unwrap_or_else(|| panic!("{n} is not a shot quantity"))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::shot_mc::ROW;
    use super::super::{Ball, ShotSpec};
    use super::SHOT_QUANTITIES;

    /// Every name of `mc --shot`'s row and of [`SHOT_QUANTITIES`] is answered by
    /// `ShotReport::quantity`: a tennis serve's first bounce's numbers where it bounces, NaN
    /// where it ends on its landing (no bounce); no net, so no clearance (NaN) and a verdict
    /// of 0.
    #[test]
    fn every_row_name_is_a_quantity() {
        let ball = Ball::from_preset("tennis").unwrap();
        for bounces in [0, 1] {
            let mut spec = ShotSpec::new(2.8, 50.0, -6.0, 200.0, 0.6);
            spec.ends.bounces = bounces;
            let r = ball.shot(&spec).unwrap();
            for name in ROW.iter().chain(&SHOT_QUANTITIES) {
                assert!(r.quantity(name).is_some(), "{name}");
            }
            let landing_x = r.quantity("landing_x").unwrap();
            match r.bounces.first() {
                Some(b) => assert_eq!(landing_x, b.x, "bounces {bounces}"),
                None => assert!(landing_x.is_nan(), "bounces {bounces}"),
            }
            assert_eq!(r.bounces.len(), bounces, "bounces {bounces}");
            assert!(r.quantity("net_clearance").unwrap().is_nan());
            assert_eq!(r.quantity("net_cleared"), Some(0.0));
            assert_eq!(r.quantity("end_vy"), Some(r.end.state.vy));
            assert_eq!(r.quantity("no_such"), None);
        }
    }
}
