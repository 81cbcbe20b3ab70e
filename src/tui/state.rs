//! The pieces of the explorer's state: what the model runs on, the view, the overlays, the
//! message line and the pinned runs. The explorer's `App` owns them and changes them.

pub use super::action::CursorMove;
use super::compute::ZetaCurve;
use super::param::Param;
use super::save::SaveRequest;
pub use super::setting::Setting;
use crate::figure::explorer::Chart;
use crate::solver::ImpactResponse;
use crate::tui::views::sweeps::speed::SpeedCurve;

/// Below this the explorer asks for a larger terminal, and only resize and quit act (the
/// screen shows nothing else, so no other key may change what is unseen).
pub const MIN_WIDTH: u16 = 50;
pub const MIN_HEIGHT: u16 = 16;

/// The pages `Tab` switches between.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum View {
    /// Force–time, force–displacement, COR vs ζ.
    Impact,
    /// Normalized peak force vs ζ, COR vs impact speed.
    Sweeps,
    /// The field's contact models calibrated to the ball (src/tui/views/models/state.rs).
    Models,
    /// The design map: COR, peak force or contact time over (λ, ζ) (src/tui/views/map/state.rs).
    Map,
    /// The drop test (`d`, outside the Tab cycle): src/tui/views/drop/state.rs.
    Drop,
    /// Oblique impacts (`i`, outside the Tab cycle): src/tui/views/oblique/state.rs.
    Oblique,
    /// A shot's flight (`h`, outside the Tab cycle): src/tui/views/flight/state.rs.
    Flight,
}

impl View {
    /// The views `Tab` goes through, in order (`Shift+Tab` backwards).
    pub const CYCLE: [View; 4] = [View::Impact, View::Sweeps, View::Models, View::Map];

    /// Every view.
    pub const ALL: [View; 7] = [
        View::Impact,
        View::Sweeps,
        View::Models,
        View::Map,
        View::Drop,
        View::Oblique,
        View::Flight,
    ];

    /// The view's name, as a session file keeps it (`view = "oblique"`).
    pub fn name(self) -> &'static str {
        match self {
            View::Impact => "impact",
            View::Sweeps => "sweeps",
            View::Models => "models",
            View::Map => "map",
            View::Drop => "drop",
            View::Oblique => "oblique",
            View::Flight => "flight",
        }
    }

    /// The header's name of the view: its place in the cycle and name ("2/4 sweeps"); the
    /// views outside the cycle by name alone (the drop view "drop test").
    pub fn title(self) -> String {
        match self {
            View::Drop => "drop test".into(),
            View::Oblique | View::Flight => self.name().into(),
            View::Impact | View::Sweeps | View::Models | View::Map => {
                let n = View::CYCLE.len();
                let k = View::CYCLE.iter().position(|&v| v == self).unwrap_or(0) + 1;
                format!("{k}/{n} {}", self.name())
            }
        }
    }

    /// The view a view's own key (`d`, `i`, `h`) leads to from this one: into `own`, or out
    /// of it back to the impact view.
    pub fn toggled(self, own: View) -> View {
        if self == own { View::Impact } else { own }
    }

    /// The next view of the cycle (from the drop view: the impact view).
    pub fn next(self) -> View {
        match View::CYCLE.iter().position(|&v| v == self) {
            Some(k) => View::CYCLE[(k + 1) % View::CYCLE.len()],
            None => View::Impact,
        }
    }

    /// The previous view of the cycle (from the drop view: the impact view).
    pub fn prev(self) -> View {
        let n = View::CYCLE.len();
        match View::CYCLE.iter().position(|&v| v == self) {
            Some(k) => View::CYCLE[(k + n - 1) % n],
            None => View::Impact,
        }
    }

    /// The view's charts, in screen order (left to right, top to bottom).
    pub fn charts(self) -> &'static [Chart] {
        match self {
            View::Impact => &[Chart::ForceTime, Chart::Hysteresis, Chart::CorZeta],
            View::Sweeps => &[Chart::ForceZeta, Chart::CorSpeed],
            View::Models => &[
                Chart::ModelsCorSpeed,
                Chart::ModelsForceTime,
                Chart::ModelsForceDisplacement,
            ],
            View::Map | View::Drop | View::Oblique | View::Flight => &[],
        }
    }
}

/// What a text entry is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    /// An exact value for a parameter (`=` or Enter).
    Value(Param),
    /// The name to save the current setting under as a user preset (`s`).
    PresetName,
    /// The path of a measured file to draw and fit to (`o`).
    MeasuredPath,
    /// The map view's targets, `cor>=0.8,max_force<=2000` (`t`).
    Targets,
    /// A field of the physical-inputs form (`m`): Enter returns to the form.
    Physical(super::physical::Field),
    /// The file to save the session to (`S`).
    SessionPath,
    /// θ, ω or μ of the oblique view (`=`); the readout beside shows its value.
    Oblique(crate::tui::views::oblique::param::ObliqueParam),
}

/// The text-entry dialog.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    pub purpose: Purpose,
    pub text: String,
    /// Why the last entry was refused.
    pub error: Option<String>,
    /// Characters of `text` before the cursor (0 … its length).
    pub cursor: usize,
}

impl Input {
    /// A dialog holding `text`, the cursor at its end.
    pub fn new(purpose: Purpose, text: String) -> Input {
        let cursor = text.chars().count();
        Input {
            purpose,
            text,
            error: None,
            cursor,
        }
    }

    /// Byte offset of the `i`-th character (the end for `i` past it).
    fn at(&self, i: usize) -> usize {
        self.text
            .char_indices()
            .nth(i)
            .map_or(self.text.len(), |(b, _)| b)
    }

    /// Type `c` at the cursor.
    pub fn insert(&mut self, c: char) {
        let b = self.at(self.cursor);
        self.text.insert(b, c);
        self.cursor += 1;
    }

    /// Backspace: the character before the cursor goes.
    pub fn backspace(&mut self) {
        if self.cursor > 0 {
            self.cursor -= 1;
            let b = self.at(self.cursor);
            self.text.remove(b);
        }
    }

    /// Delete: the character under the cursor goes.
    pub fn delete(&mut self) {
        if self.cursor < self.text.chars().count() {
            let b = self.at(self.cursor);
            self.text.remove(b);
        }
    }

    pub fn clear(&mut self) {
        self.text.clear();
        self.cursor = 0;
    }

    pub fn move_cursor(&mut self, m: CursorMove) {
        let n = self.text.chars().count();
        self.cursor = match m {
            CursorMove::Left => self.cursor.saturating_sub(1),
            CursorMove::Right => (self.cursor + 1).min(n),
            CursorMove::Home => 0,
            CursorMove::End => n,
        };
    }
}

/// The question before a preset file is replaced: the save waits for `y` or `n`.
#[derive(Debug, Clone, PartialEq)]
pub struct Confirm {
    /// The save to carry out on `y` (its `replace` names the file).
    pub request: SaveRequest,
    /// The preset name found in that file, when it could be read.
    pub holds: Option<String>,
}

/// What sits on top of the charts.
#[derive(Debug, Clone, PartialEq)]
pub enum Overlay {
    None,
    Help,
    Input(Input),
    Confirm(Confirm),
    /// "Copy as command" (`y`): the `bouncelab run …` line of the screen, to select and copy.
    Command(String),
    /// The preset picker (`g`).
    Picker(super::picker::Picker),
    /// The surface picker (`G`).
    Surfaces(super::surface::SurfacePicker),
    /// The physical-inputs form (`m`).
    Form(super::physical::Form),
    /// "Quit?" with what would be lost (`q` with pins, measured data or a fit).
    Quit(String),
    /// A y/n question before something is lost or replaced (issue 51).
    Ask(Ask),
}

/// A y/n question (`y` goes on, `n` or Esc keeps things as they are).
#[derive(Debug, Clone, PartialEq)]
pub enum Ask {
    /// `O`: put away the measured data, and the fit with it; names what goes.
    PutAway(String),
    /// `S` onto a file that exists: replace it with this session's text?
    Session {
        path: std::path::PathBuf,
        text: String,
    },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    Info,
    Warning,
    Error,
}

/// A one-line note for the user about the last action.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    pub text: String,
    pub severity: Severity,
}

/// How many runs can be pinned at once: past this the charts and the pin table stop being
/// readable, so `p` refuses with a message.
pub const MAX_PINS: usize = 8;

/// A pinned run: its curves are drawn dimmed behind the live ones, tagged `p1`, `p2`, ….
#[derive(Debug, Clone, PartialEq)]
pub struct Ghost {
    pub setting: Setting,
    pub run: Option<ImpactResponse>,
    pub zeta: Option<ZetaCurve>,
    /// Computed when the sweeps view first needs it.
    pub speed: Option<SpeedCurve>,
}
