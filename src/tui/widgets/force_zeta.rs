//! Normalized peak force F̄_m against ζ on a decade axis (Fig. 3): the COR-vs-ζ chart's code
//! with the other quantity.

use super::cor_zeta::{Quantity, zeta_plot};
use super::plot::Plot;
use crate::tui::app::App;

pub fn plot(app: &App) -> Plot {
    zeta_plot(app, Quantity::PeakForce)
}
