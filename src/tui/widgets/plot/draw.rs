//! A plot drawn whole (`Plot::draw_in`, the `Widget`): its frame and title, the axes' powers
//! of ten on the frame, then the axes, the series, the marks and the legend (plot.rs,
//! legend.rs).

use super::{Plot, PlotLayout};
use crate::figure::ticks::factor_label;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Widget};

impl Plot<'_> {
    /// The powers of ten of scaled axes, on the frame's right end: y's on the top border
    /// ("y ×10⁻¹⁵"), x's on the bottom one, where no title, label or curve is.
    fn draw_factors(&self, area: Rect, l: &PlotLayout, buf: &mut Buffer) {
        let style = self.theme.axis();
        for (axis, row, name) in [(&l.y, area.y, "y"), (&l.x, area.bottom() - 1, "x")] {
            let Some(e) = axis.exponent else { continue };
            let text = format!(" {name} {} ", factor_label(e));
            let w = text.chars().count() as u16;
            if w + 4 > area.width {
                continue;
            }
            buf.set_stringn(area.right() - 1 - w, row, &text, usize::from(w), style);
        }
    }

    /// The plot drawn in `area` on `layout` (its [`Plot::layout`], or another's to compare
    /// with: tests/tui/tui_legend.rs); the rows the legend asks for above the plot, 0 when it
    /// found a place that hides no data (or has them already).
    pub fn draw_in(&self, area: Rect, layout: Option<&PlotLayout>, buf: &mut Buffer) -> u16 {
        // the frame's top row less its corners, the space before the title (the one after
        // it may meet the corner) and the y axis' power of ten
        let factor = layout
            .and_then(|l| l.y.exponent)
            .map_or(0, |e| factor_label(e).chars().count() + 4);
        let room = usize::from(area.width).saturating_sub(3 + factor);
        Block::bordered()
            .border_style(self.theme.dim())
            .title(Line::styled(
                format!(
                    " {} ",
                    crate::tui::widgets::title::fit(&self.figure.screen_title, room)
                ),
                self.theme.title(),
            ))
            .render(area, buf);
        let Some(l) = layout else { return 0 };
        self.draw_factors(area, l, buf);
        self.draw_axes(l, buf);
        self.draw_series(l, buf);
        let (labels, dropped) = self.draw_marks(l, buf);
        self.draw_legend(l, (&labels, dropped), buf)
    }
}

impl Widget for &Plot<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let area = area.intersection(buf.area);
        let layout = self.layout(area);
        self.draw_in(area, layout.as_ref(), buf);
    }
}
