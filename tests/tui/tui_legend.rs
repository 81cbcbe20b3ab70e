//! Issue 51 item 6: a chart's legend never hides its data. Each chart of each view is drawn
//! twice at the five sizes: as the explorer draws it, and with no legend; every cell the
//! second shows inside the plot shows the same in the first (the legend goes to an empty
//! corner, or outside the plot, on the frame).

use crate::tui_common::buffer_text;
use bouncelab::figure::Figure;
use bouncelab::preset::Preset;
use bouncelab::tui::app::App;
use bouncelab::tui::theme::Theme;
use bouncelab::tui::ui::{self, Chart};
use bouncelab::tui::widgets::plot::Plot;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::widgets::Widget;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// The cells inside `fig`'s plot where drawing it with its legend shows something else than
/// drawing it without: one string a cell, for the failure's message.
fn hidden_cells(fig: &Figure, area: Rect) -> Vec<String> {
    let theme = Theme::new(false);
    let plot = Plot::new(fig, theme);
    let Some(layout) = plot.layout(area) else {
        return Vec::new();
    };
    let mut with = Buffer::empty(area);
    plot.render(area, &mut with);
    let mut bare = fig.clone();
    for s in &mut bare.series {
        s.look.key = None;
    }
    // the same figure without a legend, drawn on the layout the legend was given
    let mut without = Buffer::empty(area);
    Plot::new(&bare, theme).draw_in(area, Some(&layout), &mut without);
    layout
        .plot
        .positions()
        .filter(|&p| without[p].symbol() != " " && without[p].symbol() != with[p].symbol())
        .map(|p| format!("({}, {}) '{}'", p.x, p.y, without[p].symbol()))
        .collect()
}

/// Every impact-view chart of the four embedded balls, in the sizes the explorer gives them
/// at the five terminal sizes.
#[test]
fn no_legend_hides_a_charts_data() {
    let mut failures = Vec::new();
    for (i, preset) in Preset::embedded().into_iter().enumerate() {
        let app = App::new(preset, true);
        for (w, h) in SIZES {
            let Some(s) = ui::screen(&app, Rect::new(0, 0, w, h)) else {
                continue;
            };
            for (chart, area) in &s.charts {
                let fig = ui::figure(&app, *chart);
                let hidden = hidden_cells(&fig, *area);
                if !hidden.is_empty() {
                    let mut buf = Buffer::empty(*area);
                    Plot::new(&fig, Theme::new(false)).render(*area, &mut buf);
                    failures.push(format!(
                        "ball {i} {w}×{h} {chart:?}: hides {}\n{}",
                        hidden.join(" "),
                        buffer_text(&buf)
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The same for the other charts at the chart sizes the five terminals give the impact view
/// (the models view draws its charts with the same widget).
#[test]
fn no_legend_hides_data_on_the_zeta_and_speed_charts() {
    let app = App::new(Preset::embedded().remove(0), true);
    let mut failures = Vec::new();
    for chart in [Chart::CorZeta, Chart::ForceZeta, Chart::CorSpeed] {
        for (w, h) in [(40, 11), (50, 14), (60, 19), (80, 24), (100, 29)] {
            let area = Rect::new(0, 0, w, h);
            let hidden = hidden_cells(&ui::figure(&app, chart), area);
            if !hidden.is_empty() {
                failures.push(format!("{chart:?} {w}×{h}: {}", hidden.join(" ")));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
