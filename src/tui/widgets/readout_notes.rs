//! The readout's notes under the results: what the run did, the model's and the calibration's
//! warnings, what the ball meets, the conditions and where the measurements were taken; and
//! the energy budget.

use super::{CALIBRATION_ROWS, MEASURED_ROWS, Readout, SURFACE_ROWS, measured_here};
use crate::preset::Preset;
use crate::solver::EnergyBudget;
use crate::tui::format::value;
use crate::tui::setting::Setting;
use crate::tui::widgets::warning::{cut_lines, warning_lines};
use ratatui::text::{Line, Span};

/// Why the preset's measured values are not compared, if they are not: against a wall while
/// the run is a pair's (a pair's COR is no wall's measurement: issue 51 item 5), at the
/// conditions the form set (the library's reason, `run`'s `comparison_withheld`:
/// [`crate::Ball::measurement_withheld`]), or taken at another speed (the line's v0).
fn not_compared(preset: &Preset, setting: &Setting) -> Option<String> {
    if setting.target != crate::target::Target::wall() {
        return Some(": a wall's, not compared with the pair".into());
    }
    if !setting.conditions.is_empty() {
        // the ball at the conditions, without the λ, ζ, K_p … typed: the explorer compares a
        // ball the user tuned (its difference column is how one tunes it), so only the
        // conditions withhold the measurement here, in the library's words for them
        let ball = crate::Ball {
            overrides: Vec::new(),
            ..crate::tui::physical::conditions::library_ball(preset, setting)
        };
        if let Some(why) = ball.measurement_withheld() {
            return Some(format!(": not compared: {why}"));
        }
    }
    (!measured_here(preset, setting)).then(|| ": not compared".into())
}

impl Readout<'_> {
    /// What the run did, at which speed the measurements were taken, what is pinned.
    pub(super) fn notes(&self, inner_w: usize) -> Vec<Line<'static>> {
        let theme = &self.theme;
        let mut lines = Vec::new();
        lines.extend(self.validity_line());
        // four rows at most: the message line says it whole
        if let Some(w) = &self.calibration {
            lines.extend(warning_lines(w, inner_w, CALIBRATION_ROWS, theme));
        }
        if let Some(r) = self.run {
            // the Hertz law is elastic: it never flattens, whatever z_m and z_p (docs/model.md
            // §3; tests/cli/answer_warnings.rs)
            let hertz = self.setting.law == crate::model::contact::ContactLaw::Hertz;
            let note = match (r.rebound, r.permanent_indentation > 0.0) {
                (false, _) => " no rebound: the ball sinks into the dashpot",
                (true, true) => " flattened: z_f > 0",
                (true, false) if hertz => " Hertz: elastic, never flattens",
                (true, false) => " no flattening (z_m < z_p)",
            };
            lines.push(Line::styled(note, theme.dim()));
        }
        lines.extend(self.target_note());
        // the surface's, as `run --surface NAME` prints them (its rigidity assumed)
        for w in &self.surface_warnings {
            lines.extend(warning_lines(w, inner_w, SURFACE_ROWS, theme));
        }
        // the pressure and temperature the form set (issue 56)
        if let Some(c) = crate::tui::physical::conditions::stated(self.preset, self.setting) {
            lines.push(Line::styled(c, theme.dim()));
        }
        // a preset saved at another speed keeps no measurements, and its `[measured] v0` is
        // only the speed it runs at: claim no measurement then
        let m = &self.preset.measured;
        if m.cor.is_some() || m.max_force.is_some() || m.contact_time.is_some() {
            let elsewhere = not_compared(self.preset, self.setting).unwrap_or_default();
            // v0 as the parameters above write it (3.120, not 3.12: one number format)
            let text = format!("measured at v0 = {} m/s{elsewhere}", value(m.v0));
            if elsewhere.starts_with(": not compared: ") {
                // the library's reason, cut at a word where it does not fit
                lines.extend(cut_lines(&text, inner_w, MEASURED_ROWS, theme.dim()));
            } else {
                lines.push(Line::styled(format!(" {text}"), theme.dim()));
            }
        }
        lines
    }

    /// What the ball meets: the surface by name (the rigid steel plate when none was picked,
    /// issue 53 item 6: every answer names its surface), and the pair's line when the target
    /// is not that surface — the run is then the pair's (docs/targets.md; docs/explorer.md).
    fn target_note(&self) -> Vec<Line<'static>> {
        let t = self.setting.target;
        // the surface picked (`G`): its name and numbers; the pair's line below when the
        // form moved the target off it
        let plate = crate::target::surface::Surface::rigid_plate;
        let (s, picked) = match &self.setting.surface {
            Some(s) => (s.clone(), true),
            None => (plate(), false),
        };
        let mut lines = Vec::new();
        let on_it = t == s.mechanics.target();
        if picked || on_it {
            // named by the library's rule: `clay-modified` once the form moved K_s, c_s or M
            // off clay's own, with the numbers it runs on, as `y`'s line names it
            let used = crate::tui::surface::used(self.setting, None);
            let own = crate::tui::surface::numbers(&used.mechanics);
            lines.push(Line::styled(
                format!(" surface {}: {own}", used.name),
                self.theme.dim(),
            ));
        }
        if on_it {
            return lines;
        }
        let v = |x: f64| {
            if x.is_finite() {
                value(x)
            } else {
                "∞".into()
            }
        };
        // M in g, as the form (`m`) and `u` write it (issue 51 item 4)
        let mut text = format!(
            " pair: target M {} g, v_t {} m/s",
            v(t.mass * 1e3),
            v(t.speed)
        );
        if !t.is_rigid() {
            text.push_str(&format!(
                ", K_s {} N/m, c_s {} kg/s",
                v(t.stiffness),
                v(t.damping)
            ));
        }
        lines.push(Line::styled(text, self.theme.dim()));
        lines
    }

    /// Where the run's energy went (mJ): the budget `bouncelab run` prints, from the same
    /// solver pass ([`crate::solver::EnergyBudget`]), round-off shown as 0 as there.
    /// Without a rebound nothing goes out (e 0): what kinetic energy the ball still has when
    /// the run ends is its sinking into the dashpot, said so (issue 51 item 5: `e 0` beside
    /// `out 17.42`).
    pub(super) fn energy_lines(&self) -> Vec<Line<'static>> {
        let Some((e, rebound)) = self.run.and_then(|r| Some((r.energy?, r.rebound))) else {
            return Vec::new();
        };
        let mj = |x: f64| value(e.shown(x) * 1e3);
        let out = if rebound {
            mj(e.final_kinetic)
        } else {
            "0".into()
        };
        let mut lines = vec![
            Line::from(vec![
                Span::styled(" energy mJ", self.theme.title()),
                Span::raw(format!(" in {}  out {out}", mj(e.initial_kinetic))),
            ]),
            Line::raw(format!(
                "  dashpot {}  contact {}",
                mj(e.dashpot),
                mj(e.contact)
            )),
            Line::raw(format!(
                "  spring {}  residual {}",
                mj(e.spring),
                residual_text(&e)
            )),
        ];
        if !rebound {
            lines.push(Line::raw(format!(
                "  still sinking {}",
                mj(e.final_kinetic)
            )));
        }
        lines
    }
}

/// The budget's residual as a fraction of the energy in, to one digit; round-off — a residual
/// below 1e-12 of the energy in, the threshold [`EnergyBudget::shown`] applies to every term of
/// the budget — reads 0 (issue 51: `residual 2e-16` beside terms shown to 4 digits;
/// docs/explorer.md, tests/tui/tui_walk.rs).
fn residual_text(e: &EnergyBudget) -> String {
    let r = e.relative_residual();
    if e.shown(r * e.initial_kinetic) == 0.0 {
        "0".into()
    } else {
        format!("{r:.0e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A budget of 1 J in whose terms leave `residual` J unaccounted.
    fn budget(residual: f64) -> EnergyBudget {
        EnergyBudget {
            initial_kinetic: 1.0,
            final_kinetic: 0.5,
            dashpot: 0.3,
            contact: 0.0,
            spring: 0.2 - residual,
        }
    }

    #[test]
    fn a_round_off_residual_reads_0_and_a_real_one_its_size() {
        // the superball's default run left 2e-16 of the energy in: round-off
        assert_eq!(residual_text(&budget(2.2e-16)), "0");
        assert_eq!(residual_text(&budget(0.9e-12)), "0");
        assert_eq!(residual_text(&budget(3e-12)), "3e-12");
        assert_eq!(residual_text(&budget(2e-3)), "2e-3");
        assert_eq!(residual_text(&budget(0.0)), "0");
    }
}
