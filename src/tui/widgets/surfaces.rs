//! The surface picker (`G`, issue 53 item 6): every surface with its numbers (K_s, c_s, M, μ,
//! K_t, c_t where it gives them, src/tui/surface.rs) and where it comes from, the highlighted
//! one marked ▶, scrolled as the preset picker is (src/tui/widgets/picker.rs).

use crate::catalog::surfaces::SurfaceEntry;
use crate::tui::surface::{numbers, origin};
use crate::tui::widgets::picker::{Listed, PickerBox};

/// The surface picker, centred on the area it is given.
pub type SurfacesBox<'a> = PickerBox<'a, SurfaceEntry>;

impl Listed for SurfaceEntry {
    const TITLE: &'static str = " Surfaces ";
    const ENTER: &'static str = "Enter puts the ball on it";
    const CUT_ERROR: bool = true;
    fn name(&self) -> &str {
        &self.surface.name
    }
    fn origin(&self) -> String {
        origin(&self.origin)
    }
    /// Its numbers (K_s, c_s, M, μ, K_t, c_t where it gives them).
    fn detail(&self) -> String {
        numbers(&self.surface.mechanics)
    }
}
