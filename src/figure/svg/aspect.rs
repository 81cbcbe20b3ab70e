//! One scale across and up for figures whose directions are meant (the oblique view's
//! paths): the plot's size in the picture and the ranges that give both axes as many units
//! per pixel.

use super::legend::{LEGEND_ROW_PX, LEGEND_TOP_PX, legend_layout};
use super::{HEIGHT, SIDE_PX, SUBTITLE_PX, WIDTH, subtitle_lines, y_label_area};
use crate::figure::Figure;
use crate::figure::ticks::{Room, ticks};

/// The plot's size (CSS pixels, width and height) inside the picture `render` draws of
/// `fig`: the picture less the titles, the legend, the margins and the axes' label areas
/// (the very sizes `render_aligned` lays out).
pub fn plot_size(fig: &Figure) -> (f64, f64) {
    let head = 46 + subtitle_lines(&fig.subtitle).len() as i32 * (SUBTITLE_PX + 5);
    let legend_h = legend_layout(fig).1.len() as i32 * LEGEND_ROW_PX + LEGEND_TOP_PX + 6;
    let left = y_label_area(&ticks(fig, false, Room::Picture));
    let w = WIDTH as i32 - SIDE_PX - 30 - left;
    let h = HEIGHT as i32 - head - legend_h - 6 - 52;
    (f64::from(w.max(1)), f64::from(h.max(1)))
}

/// `fig`'s axes given ranges with one scale across and up — as many units per pixel on both
/// — around its data with a tenth of the larger span to spare, so that a direction drawn is
/// the direction meant: a path at 16° to the surface is drawn at 16° (the oblique view's
/// paths, issue 51 item 7; tests/tui/tui_oblique_export.rs). Linear axes with one unit shown
/// (the ranges are in it, as the extents are).
pub fn equal_scales(fig: &mut Figure) {
    let (Some((x0, x1)), Some((y0, y1))) = (fig.data_extent(true), fig.data_extent(false)) else {
        return;
    };
    let pad = 0.1 * (x1 - x0).max(y1 - y0).max(f64::MIN_POSITIVE);
    let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
    let (half_x, half_y) = ((x1 - x0) / 2.0 + pad, (y1 - y0) / 2.0 + pad);
    // the y labels' width depends on the y range: settle it in a few rounds
    for _ in 0..3 {
        let (w, h) = plot_size(fig);
        let per_px = (2.0 * half_x / w).max(2.0 * half_y / h);
        fig.x.range = Some((cx - per_px * w / 2.0, cx + per_px * w / 2.0));
        fig.y.range = Some((cy - per_px * h / 2.0, cy + per_px * h / 2.0));
    }
}
