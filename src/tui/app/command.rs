//! The explorer's line of the screen (`y`: `bouncelab --preset … --v0 …`) and the
//! `bouncelab run …` (`collide …` on a target) line of the export's CSV header: the same
//! words, after the subcommand that computes them.

use super::{App, Setting};
use crate::tui::command::{self, Source};
use std::path::PathBuf;

impl App {
    /// The explorer started on the preset read from `path` (`bouncelab --config FILE`): the
    /// command names that file for it.
    pub fn with_config(mut self, path: PathBuf) -> App {
        self.config = Some((self.setting.preset, path));
        self
    }

    /// The explorer opened in the state the command line gave (`bouncelab --preset golf --law
    /// hertz --v0 3 …`, src/cli/explore.rs): the ball's parameters, law and radius (None: the
    /// preset's), the start of the undo history.
    /// The explorer started at the conditions `--pressure` and `--temperature` asked (the
    /// parameters `with_start` takes are the ball's at them): the form shows them, `y` and `S`
    /// carry them (issue 56). Pressure or temperature back at the record's is none.
    pub fn with_conditions(mut self, spec: crate::api::ConditionsSpec) -> App {
        let rec = self.setting.record;
        let c = &mut self.setting.conditions;
        c.pressure = spec.pressure.filter(|&p| Some(p) != rec.pressure);
        c.temperature = spec.temperature.filter(|&t| Some(t) != rec.temperature);
        self
    }

    pub fn with_start(
        mut self,
        params: crate::model::params::ImpactParams,
        law: crate::model::contact::ContactLaw,
        radius: Option<f64>,
    ) -> App {
        self.setting.params = params;
        self.setting.law = law;
        self.setting.radius = radius.unwrap_or(self.setting.radius);
        // the command line's state is the start: nothing to lose yet
        self.keep();
        self.refresh();
        self
    }

    /// The explorer started on a target (`--target-mass`, `--target-speed`,
    /// `--target-stiffness`, `--target-damping`; `None`: as it is), each value checked as the
    /// form checks it; refused with the form's reason, naming the flag.
    pub fn with_target(mut self, target: [Option<f64>; 4]) -> Result<App, String> {
        use crate::tui::physical::Field;
        let fields = [
            (Field::TargetMass, "--target-mass"),
            (Field::TargetSpeed, "--target-speed"),
            (Field::TargetStiffness, "--target-stiffness"),
            (Field::TargetDamping, "--target-damping"),
        ];
        // K_s before c_s: a dashpot needs its spring (physical::target_set)
        for i in [0, 1, 2, 3] {
            let ((field, flag), Some(v)) = (fields[i], target[i]) else {
                continue;
            };
            self.setting = field
                .check(v, &self.setting)
                .map_err(|why| format!("{flag}: {why}"))?;
        }
        self.keep();
        self.refresh();
        Ok(self)
    }

    /// Copy `y`'s line with OSC 52 or not (`clipboard::osc52_here` decides for the terminal;
    /// without this call, not).
    pub fn with_osc52(mut self, on: bool) -> App {
        self.copy.osc52 = on;
        self
    }

    /// Whether `y` copies with OSC 52.
    pub fn osc52(&self) -> bool {
        self.copy.osc52
    }

    /// The last line `y` showed: the explorer prints it on the main screen as it ends, one
    /// line the terminal's scrollback keeps whole however narrow the explorer was.
    pub fn last_command(&self) -> Option<&str> {
        self.copy.last.as_deref()
    }

    /// `y`: the explorer's line in its box, and copied to the terminal's clipboard (OSC 52)
    /// where the terminal takes it; a setting the line cannot carry is named.
    pub(super) fn show_command(&mut self) -> Vec<crate::tui::effect::Effect> {
        let line = self.command_line();
        self.overlay = crate::tui::state::Overlay::Command(line.clone());
        self.copy.last = Some(line.clone());
        if let Some(w) = crate::tui::command::not_carried(self.preset(), &self.setting) {
            self.warn(w);
        }
        if self.copy.osc52 {
            vec![crate::tui::effect::Effect::Copy(line)]
        } else {
            Vec::new()
        }
    }

    /// The explorer's line that opens it again in what the screen shows (`y`); in the
    /// oblique view, the `bouncelab oblique …` line that computes the impact it shows; in the
    /// flight view, the `bouncelab shot …` line that computes the shot it shows.
    pub fn command_line(&self) -> String {
        let (source, preset) = self.source_of(&self.setting);
        if self.view == crate::tui::state::View::Oblique {
            return command::oblique_line(source, preset, &self.setting, &self.oblique.values);
        }
        if self.view == crate::tui::state::View::Flight {
            return command::shot_line(source, preset, &self.setting, &self.flight.values);
        }
        command::explorer_line(source, preset, &self.setting)
    }

    /// The `bouncelab run` (or `collide`) line that computes what the screen shows, `y`'s
    /// words after that subcommand (the export's CSV header).
    pub fn run_line(&self) -> String {
        self.command_for(&self.setting)
    }

    fn source_of(&self, s: &Setting) -> (Source<'_>, &crate::preset::Preset) {
        let preset = &self.presets[s.preset];
        let source = match &self.config {
            Some((i, path)) if *i == s.preset => Source::Config(path),
            _ => Source::Name(&preset.name),
        };
        (source, preset)
    }

    fn command_for(&self, s: &Setting) -> String {
        let (source, preset) = self.source_of(s);
        command::run_line(source, preset, s)
    }

    /// The `#` lines an export's CSV files start with.
    pub(in crate::tui) fn csv_header(&self) -> Vec<String> {
        let pins: Vec<String> = self
            .pins
            .iter()
            .map(|g| self.command_for(&g.setting))
            .collect();
        command::csv_header(&self.run_line(), self.preset(), &self.setting, &pins)
    }
}

/// `y`'s copy: OSC 52 on or off for this terminal, and the last line shown.
#[derive(Debug, Clone, Default)]
pub struct CopyState {
    pub osc52: bool,
    pub last: Option<String>,
}
