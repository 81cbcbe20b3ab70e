//! `e` in the map view: the map on screen as an SVG heat map and a CSV table, through the
//! same code as `bouncelab map --format svg` and its CSV ([`crate::figure::svg_map`],
//! [`crate::map::csv`]): the quantity shown, the targets set, the ball marked.

use crate::figure::svg_map;
use crate::map::{Map, Quantity, Targets};

/// The map part of an export.
#[derive(Debug, Clone, PartialEq)]
pub struct MapExport {
    pub map: Map,
    pub quantity: Quantity,
    pub targets: Option<Targets>,
    /// The current ball's (λ, ζ), marked.
    pub own: (f64, f64),
    /// "superball at v0 = 3.12 m/s", the SVG's subtitle.
    pub title_ball: String,
    /// The ball's radius, m (NaN: none known), for the SVG's note of the cells past it.
    pub radius: f64,
}

impl MapExport {
    /// The chart's part of the file names: `map-cor`, `map-max_force`, `map-contact_time`.
    pub fn file_name(&self) -> String {
        format!("map-{}", self.quantity.name())
    }

    /// The SVG picture and the CSV table.
    pub fn render(&self) -> Result<(String, String), String> {
        let view = svg_map::View {
            quantity: self.quantity,
            targets: self.targets.as_ref(),
            own: Some(self.own),
            title_ball: self.title_ball.clone(),
            radius_note: crate::api::map_radius_note(&self.map, self.radius),
            // the explorer's ball is its setting's (its readout names what moved)
            notes: Vec::new(),
        };
        let svg = svg_map::render(&self.map, &view).map_err(|e| e.to_string())?;
        let csv = crate::map::csv::csv(&self.map, self.targets.as_ref());
        Ok((svg, csv))
    }
}
