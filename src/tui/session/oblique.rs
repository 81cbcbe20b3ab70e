//! The oblique view in a session file (issue 31): θ, ω, μ and the K_t and κ set in the view
//! (absent: the ball's), the parameter the arrows move, the page and the map's quantity.
//! Absent from a version-1 file: the view's defaults (16°, no spin, μ 0.6).

use crate::tui::views::oblique::map::Quantity;
use crate::tui::views::oblique::param::ObliqueParam;
use crate::tui::views::oblique::state::{ObliqueValues, ObliqueView, Page};
use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObliqueState {
    /// θ, degrees to the surface.
    pub angle: f64,
    /// ω, rad/s (> 0 topspin).
    pub spin: f64,
    /// μ.
    pub friction: f64,
    /// K_t, N/m (absent: Mindlin's, from the ball's K_p and ν).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential_stiffness: Option<f64>,
    /// κ = I/(m R²) (absent: the preset's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inertia_factor: Option<f64>,
    /// angle, spin, friction, tangential-stiffness or inertia-factor.
    pub selected: String,
    /// charts or map.
    pub page: String,
    /// The map's quantity: angle_out, spin_out or e_x.
    pub quantity: String,
}

fn page_name(p: Page) -> &'static str {
    match p {
        Page::Charts => "charts",
        Page::Map => "map",
    }
}

fn quantity_name(q: Quantity) -> &'static str {
    match q {
        Quantity::AngleOut => "angle_out",
        Quantity::SpinOut => "spin_out",
        Quantity::Ex => "e_x",
    }
}

impl ObliqueState {
    pub fn of(view: &ObliqueView) -> ObliqueState {
        ObliqueState {
            angle: view.values.angle,
            spin: view.values.spin,
            friction: view.values.friction,
            tangential_stiffness: view.values.tangential_stiffness,
            inertia_factor: view.values.inertia_factor,
            selected: view.selected.name().into(),
            page: page_name(view.page).into(),
            quantity: quantity_name(view.quantity).into(),
        }
    }

    /// Set `view` from the file, each value checked by the library's range (the one
    /// `bouncelab oblique` applies); or why not (`oblique: …`).
    pub fn restore(&self, view: &mut ObliqueView) -> Result<(), String> {
        let checked =
            |p: ObliqueParam, v: f64| p.library_check(v).map_err(|e| format!("oblique: {e}"));
        let optional = |p: ObliqueParam, v: Option<f64>| v.map(|v| checked(p, v)).transpose();
        let values = ObliqueValues {
            angle: checked(ObliqueParam::Angle, self.angle)?,
            spin: checked(ObliqueParam::Spin, self.spin)?,
            friction: checked(ObliqueParam::Friction, self.friction)?,
            tangential_stiffness: optional(
                ObliqueParam::TangentialStiffness,
                self.tangential_stiffness,
            )?,
            inertia_factor: optional(ObliqueParam::InertiaFactor, self.inertia_factor)?,
        };
        view.selected = ObliqueParam::ALL
            .into_iter()
            .find(|p| p.name() == self.selected)
            .ok_or_else(|| format!("oblique: selected: unknown parameter '{}'", self.selected))?;
        view.page = [Page::Charts, Page::Map]
            .into_iter()
            .find(|&p| page_name(p) == self.page)
            .ok_or_else(|| format!("oblique: page: unknown page '{}'", self.page))?;
        view.quantity = Quantity::ALL
            .into_iter()
            .find(|&q| quantity_name(q) == self.quantity)
            .ok_or_else(|| format!("oblique: quantity: unknown quantity '{}'", self.quantity))?;
        view.values = values;
        Ok(())
    }
}
