//! The surface's μ and K_t as fields of the form (issue 53 item 1): the values the oblique
//! view runs on (θ, ω and κ stay the view's own), which the surface picker sets, the court
//! pace is rated at, `y` writes (`--friction`, `--tangential-stiffness`), a session keeps
//! (its `[oblique]` table) and `u` undoes. The form reads and sets them through the app
//! (`App::form_value`, `App::submit_physical`), checked by the oblique view's own check, the
//! library's range.

use super::Field;
use crate::tui::views::oblique::param::ObliqueParam;

impl Field {
    /// The oblique view's value this field is: μ and K_t; `None` for the others.
    pub fn surface_param(self) -> Option<ObliqueParam> {
        match self {
            Field::Friction => Some(ObliqueParam::Friction),
            Field::TangentialStiffness => Some(ObliqueParam::TangentialStiffness),
            _ => None,
        }
    }
}
