//! What the user can ask for ([`Action`]) and the input modes; the key → action mapping is in
//! `action/keys.rs` ([`from_key`]).

use super::param::{Dir, Param};
use crate::tui::views::sweeps::speed::{SpeedCurve, SpeedRequest};
use std::path::PathBuf;

/// Everything the user can ask for. [`super::app::App::update`] is the only place they act.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// `q`: quit, after asking when pins, measured data or a fit would be lost (a second `q`
    /// or `y` in the question quits).
    Quit,
    /// Ctrl-C: quit at once, asking nothing (an interrupt).
    QuitNow,
    /// `S`: ask for the file to save the session to (src/tui/session.rs).
    SaveSession,
    /// The loop wrote the session file.
    SessionSaved(PathBuf),
    /// The session file exists: the app asks before replacing it.
    SessionExists {
        path: PathBuf,
        text: String,
    },
    /// The session file could not be written: the file and why, with the system's reason.
    SessionFailed {
        path: PathBuf,
        why: String,
    },
    /// Esc with nothing open to close: never quits (issue 29); says how to.
    Dismiss,
    /// Step `param` (and select it); `coarse` forces the coarse step, otherwise the current
    /// step size applies.
    Step {
        param: Param,
        dir: Dir,
        coarse: bool,
    },
    /// Step the selected parameter.
    StepSelected {
        dir: Dir,
        coarse: bool,
    },
    SelectNext,
    SelectPrev,
    /// Choose the coarse (true) or fine step for `l`/`z`/`v` and the arrows.
    SetCoarse(bool),
    /// Open the value entry for the selected parameter.
    OpenInput,
    InputChar(char),
    InputBackspace,
    /// Ctrl-U in the entry: clear it.
    InputClear,
    /// Delete in the entry: the character under the cursor goes.
    InputDelete,
    /// ← → Home End in the entry.
    InputCursor(CursorMove),
    InputSubmit,
    InputCancel,
    /// Load preset number `i` (0-based: superball, golf, baseball, then the start preset when
    /// it is none of these).
    LoadPreset(usize),
    CycleLaw,
    Reset,
    Pin,
    Unpin,
    Undo,
    NextView,
    PrevView,
    ToggleHelp,
    CloseHelp,
    /// Scroll the help.
    HelpScroll(Scroll),
    /// The terminal is now `width` × `height` cells.
    Resize(u16, u16),
    /// A COR-vs-speed sweep finished (from the background worker).
    SpeedReady(SpeedRequest, Result<SpeedCurve, String>),
    /// The models view's calibrations finished (from their background worker).
    ModelsReady(
        crate::tui::views::models::state::ModelsRequest,
        Result<crate::figure::explorer::models::ModelsData, String>,
    ),
    /// Export the current view's charts (SVG + CSV each): `update` prepares an
    /// [`super::export::ExportRequest`], the event loop writes it.
    Export,
    /// The event loop wrote these files for the pending export.
    Exported {
        files: Vec<PathBuf>,
    },
    /// The pending export could not be written: why, in one line.
    ExportFailed {
        msg: String,
    },
    /// Save the current setting as a user preset: opens the name prompt. On Enter `update`
    /// prepares a [`super::save::SaveRequest`], the event loop writes it.
    SavePreset,
    /// The event loop wrote the pending save to `path` (`replaced`: over an existing file the
    /// user agreed to overwrite).
    Saved {
        path: PathBuf,
        replaced: bool,
    },
    /// The pending save was not written because `path` exists (or holds a preset of that
    /// name, `holds`): ask before overwriting it.
    SaveExists {
        path: PathBuf,
        holds: Option<String>,
    },
    /// The pending save could not be written: why, in one line.
    SaveFailed {
        msg: String,
    },
    /// `d`: open the drop view, or leave it for the impact view.
    ToggleDrop,
    /// Space in the drop view: pause or resume the animation.
    DropPause,
    /// `b` in the drop view: replay the drop from the release.
    DropReplay,
    /// The event loop's animation clock: `dt` seconds of wall time passed.
    Tick(f64),
    /// `y`: show the `bouncelab run …` line that reproduces the screen.
    ShowCommand,
    /// `g`: open the preset picker (the loop lists the presets).
    OpenPicker,
    /// The presets the loop found, and why the user presets could not be read.
    PresetsListed(Vec<super::picker::PickEntry>, Option<String>),
    /// `G`: open the surface picker (the loop lists the surfaces; issue 53 item 6).
    OpenSurfaces,
    /// The surfaces the loop found, and why the user surfaces could not be read.
    SurfacesListed(Vec<crate::catalog::surfaces::SurfaceEntry>, Option<String>),
    /// Move the picker's highlight (the preset or the surface picker).
    PickerMove(Scroll),
    /// Enter in the picker: load the highlighted preset.
    PickerChoose,
    /// `y` to "overwrite …? y/n".
    ConfirmYes,
    /// `n` or Esc to "overwrite …? y/n".
    ConfirmNo,
    /// `o`: open the entry for a measured file's path (force–time trace, COR table or drop
    /// test). On Enter `update` asks the loop to read it ([`super::effect::Effect::LoadMeasured`]).
    OpenMeasured,
    /// The loop read and parsed the measured file at `path`.
    MeasuredLoaded {
        path: PathBuf,
        data: crate::measured::Data,
    },
    /// The measured file could not be read: `FILE:LINE:COLUMN: why`, one line.
    MeasuredFailed {
        msg: String,
    },
    /// `O`: put the measured data (and its fit) away.
    ClearMeasured,
    /// `f`: fit the current ball to the measured data on the fit worker.
    Fit,
    /// News of a fit from the fit worker: the id of its request and its progress (model runs
    /// so far) or its outcome.
    FitReady(u64, crate::tui::views::fit::state::FitNews),
    /// `F`: apply the finished fit to the ball, as one undoable change.
    ApplyFit,
    /// `N`: normalize the chart in focus (the crosshair's, else the view's first), or back.
    Normalize,
    /// `+` (1), `-` (-1), `0` (0: back to the whole data): zoom the chart in focus.
    Zoom(i8),
    /// `x`: put the crosshair on the view's first chart; with it on, on the next chart.
    Crosshair,
    /// Tab with the crosshair on: the next chart (past the last: off).
    CrosshairNext,
    /// Esc with the crosshair on: take it away.
    CrosshairOff,
    /// Arrows with the crosshair on: `dx` steps right, `dy` steps up (Shift: ten at once).
    CrosshairMove {
        dx: i32,
        dy: i32,
    },
    /// `m`: open the physical-inputs form.
    OpenForm,
    /// ↑ / ↓ in the form: the previous / next field.
    FormMove(Scroll),
    /// Enter or `=` in the form: type a value for the highlighted field.
    FormEdit,
    /// Map view, arrows: move the cursor, and the ball with it, by `lambda` cells up and
    /// `zeta` cells right.
    MapCursor {
        lambda: i32,
        zeta: i32,
    },
    /// Map view, `n`: show the next quantity (COR, peak force, contact time).
    MapQuantity,
    /// Map view, `t`: open the targets entry.
    MapTargets,
    /// One more pass of map number `generation`, from the background worker.
    MapPass {
        generation: u64,
        map: Box<crate::map::Map>,
    },
    /// The oblique view's keys (`i` to open it; src/tui/views/oblique/).
    Oblique(ObliqueKey),
    /// A key of the flight view.
    Flight(FlightKey),
    /// A worker's thread is gone (a panic in its job): `why`, with the panic's message. The
    /// view whose computation it was says so; `R` or the next request starts a new thread.
    WorkerStopped {
        work: crate::tui::background::Work,
        why: String,
    },
    /// `R`: ask again for the computations whose worker stopped.
    Retry,
    /// The oblique view's (angle, μ) map number `generation`, from its worker.
    ObliqueMapReady {
        generation: u64,
        map: Box<Result<crate::tui::views::oblique::map::ObliqueMap, String>>,
    },
}

/// What a key asks of the flight view (src/tui/views/flight/).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FlightKey {
    /// `h`: open the flight view, or leave it for the impact view.
    Toggle,
    /// `a`/`A`, `w`/`W`, `k`/`K`: step the elevation, the spin or μ (and select it).
    Step {
        param: crate::tui::views::flight::param::FlightParam,
        up: bool,
        coarse: bool,
    },
    /// ↑ ↓: step the selected value (Shift, PgUp/PgDn: coarse).
    StepSelected { up: bool, coarse: bool },
    /// ← →: select the next or previous of speed, elevation, spin, height, μ.
    Select { next: bool },
}

/// What a key asks of the oblique view.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ObliqueKey {
    /// `i`: open the oblique view, or leave it for the impact view.
    Toggle,
    /// `a`/`A`, `w`/`W`, `k`/`K`: step θ, ω or μ (and select it).
    Step {
        param: crate::tui::views::oblique::param::ObliqueParam,
        up: bool,
        coarse: bool,
    },
    /// ↑ ↓ on the charts: step the selected one (Shift, PgUp/PgDn: coarse).
    StepSelected { up: bool, coarse: bool },
    /// ← → on the charts: select the next or previous of θ, ω, μ.
    Select { next: bool },
    /// `=` or Enter: type the selected one's value.
    Type,
    /// `t`: the charts or the (angle, μ) map.
    Page,
    /// `n`: the map's next quantity (outgoing angle, spin, e_x).
    Quantity,
    /// Arrows on the map: θ by `angle` cells, μ by `friction` cells.
    Cursor { angle: i32, friction: i32 },
}

/// How the help scrolls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scroll {
    Up,
    Down,
    PageUp,
    PageDown,
    Home,
    End,
}

/// What the keyboard is talking to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    Normal,
    Help,
    /// Typing a value or a name: printable keys are text.
    Input,
    /// A yes/no question: only `y`, `n` and Esc answer, other keys do nothing.
    Confirm,
    /// The terminal is below the minimum size: only quitting acts.
    TooSmall,
    /// The map view: the arrows move the cursor, `n` and `t` act; other keys as in `Normal`.
    Map,
    /// The preset picker: arrows move, Enter loads, Esc closes.
    Picker,
    /// The crosshair is on a chart: arrows move it, Tab and `x` go to the next chart, Esc
    /// takes it away; other keys as in `Normal`.
    Crosshair,
    /// The physical-inputs form: arrows select a field, Enter or `=` types its value, Esc
    /// closes.
    Form,
    /// "Quit and lose …?": `q` or `y` quits, `n` or Esc stays.
    QuitConfirm,
    /// The oblique view's charts: `a w k` step θ, ω, μ, the arrows select and step them;
    /// other keys as in `Normal`.
    Oblique,
    /// The oblique view's map: the arrows move the cursor (θ, μ); other keys as in `Oblique`.
    ObliqueMap,
    /// The flight view: the arrows select and step the launch and μ, `a w k` step the
    /// elevation, spin and μ; other keys as in `Normal`.
    Flight,
}

mod keys;
pub use keys::{MAP_LEAP, from_event, from_key};

/// Where ← → Home End move the entry's cursor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CursorMove {
    Left,
    Right,
    Home,
    End,
}
