//! The header (ball, law, view), the message line under the charts (the last action's
//! message, wrapped) and the status line of key hints.

use crate::model::contact::ContactLaw;
use crate::tui::format::wrap;
use crate::tui::state::{Message, Severity, View};
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::Widget;

/// A key hint: the key, what it does, and the rank at which it is dropped when space runs
/// out (lower ranks stay longer).
type Hint = (&'static str, &'static str, u8);

/// Key hints in display order.
const HINTS: [Hint; 17] = [
    ("l/L", "λ", 0),
    ("z/Z", "ζ", 0),
    ("v/V", "v0", 0),
    ("↑↓", "change", 2),
    ("←→", "select", 3),
    ("[ ]", "fine/coarse", 4),
    ("=", "type", 2),
    ("1-3", "ball", 1),
    ("c", "law", 1),
    ("p/P", "pin", 3),
    ("u", "undo", 2),
    ("e", "export", 2),
    ("s", "save", 3),
    ("r", "reset", 3),
    ("Tab", "view", 0),
    ("?", "help", 0),
    ("q", "quit", 0),
];

/// The map view's hints in place of `↑↓ change` and `←→ select`: the arrows move the cursor.
const MAP_HINTS: [Hint; 3] = [
    ("←→↑↓", "cursor", 0),
    ("n", "quantity", 1),
    ("t", "targets", 1),
];

/// The header line: ball, law, view — and the surface where the compact readout (80×24) has
/// no row for it ("tennis on clay", issue 53 item 6: every answer names its surface).
#[derive(Debug, Clone, Copy)]
pub struct Header<'a> {
    pub ball: &'a str,
    /// What the ball meets, as [`surface_words`] names it; `None` where the readout says it.
    pub surface: Option<&'a str>,
    pub law: ContactLaw,
    pub view: View,
    pub theme: Theme,
}

/// What the ball meets, in the readout's words: the surface picked (the rigid steel plate when
/// none was), or "a pair target" when the form moved the target off it (the readout's
/// ` pair: target M …` line; src/tui/widgets/readout.rs, `target_note`).
pub fn surface_words(setting: &crate::tui::setting::Setting) -> String {
    let s = setting
        .surface
        .clone()
        .unwrap_or_else(crate::target::surface::Surface::rigid_plate);
    if setting.target == s.mechanics.target() {
        s.name
    } else {
        "a pair target".into()
    }
}

impl Header<'_> {
    /// The header's words at `width` columns: the whole line; where it does not fit and the
    /// surface is to be named, the law's and the view's words shortened ("linear", "1/4
    /// impact"), then the program's name left out, so the surface stays named at 60 columns
    /// (tui_surface::the_compact_screen_names_the_surface_in_its_header); with none of these
    /// fitting, the line without the surface. `(program name shown, the rest)`.
    fn words(&self, width: usize) -> (bool, String) {
        let (law, view) = (self.law, self.view.title());
        let whole = |on: &str| format!("· {}{on} · {law} law · view {view}", self.ball);
        let fits = |brand: bool, rest: &str| {
            usize::from(brand) * BRAND.len() + rest.chars().count() <= width
        };
        if let Some(s) = self.surface {
            let on = format!(" on {s}");
            let short = format!("· {}{on} · {law} · {view}", self.ball);
            let bare = format!(" {}{on} · {law} · {view}", self.ball);
            for (brand, rest) in [(true, whole(&on)), (true, short), (false, bare)] {
                if fits(brand, &rest) {
                    return (brand, rest);
                }
            }
        }
        (true, whole(""))
    }
}

/// The program's name at the head of the header.
const BRAND: &str = " bouncelab ";

impl Widget for &Header<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let (brand, rest) = self.words(usize::from(area.width));
        let mut spans = Vec::with_capacity(2);
        if brand {
            spans.push(Span::styled(BRAND, self.theme.title()));
        }
        spans.push(Span::raw(rest));
        Line::from(spans).render(area, buf);
    }
}

/// Most rows the message line grows to; a message longer than that ends in "…". Four: the
/// ball's calibration warning (some 250 characters, its sources named) is said whole here at
/// 80 columns, where the readout has room for one line of it (issue 52 item 2;
/// tests/tui/tui_calibration.rs).
pub const MESSAGE_ROWS: usize = 4;

/// The message's lines at `width`: wrapped at spaces, never cut mid-word within
/// [`MESSAGE_ROWS`] rows (one empty row when there is no message).
pub fn message_lines(m: Option<&Message>, width: u16) -> Vec<String> {
    let Some(m) = m else {
        return vec![String::new()];
    };
    let mut lines = wrap(&m.text, usize::from(width.saturating_sub(2)));
    if lines.len() > MESSAGE_ROWS {
        lines.truncate(MESSAGE_ROWS);
        if let Some(last) = lines.last_mut() {
            last.push('…');
        }
    }
    lines
}

/// The message line(s): the last action's message, in its severity's style.
#[derive(Debug, Clone, Copy)]
pub struct MessageLine<'a> {
    pub message: Option<&'a Message>,
    pub theme: Theme,
}

impl Widget for &MessageLine<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let Some(m) = self.message else { return };
        let style = match m.severity {
            Severity::Info => self.theme.info(),
            Severity::Warning => self.theme.warning(),
            Severity::Error => self.theme.error(),
        };
        for (i, line) in message_lines(self.message, area.width).iter().enumerate() {
            let y = area.y + i as u16;
            if y < area.bottom() {
                buf.set_stringn(area.x + 1, y, line, usize::from(area.width), style);
            }
        }
    }
}

/// The status line of key hints, as many as fit.
#[derive(Debug, Clone, Copy)]
pub struct KeyHints {
    pub theme: Theme,
    /// In the map view: its own hints for the arrows.
    pub map: bool,
    /// In the drop view: its own keys in place of `e`, which exports nothing there.
    pub drop: bool,
    /// The drop view's animation paused: its key bar says so and that space plays.
    pub drop_paused: bool,
    /// In the oblique view (its page): its own keys in place of `e` and of the arrows' hints
    /// on the map.
    pub oblique: Option<crate::tui::views::oblique::state::Page>,
    /// In the flight view: its own keys in place of the arrows' hints.
    pub flight: bool,
}

/// The flight view's own keys (src/tui/views/flight/).
const FLIGHT_HINTS: [Hint; 6] = [
    ("←→", "select", 0),
    ("↑↓", "step", 0),
    ("a/A", "elev", 1),
    ("w/W", "ω", 1),
    ("k/K", "μ", 1),
    ("h", "back", 0),
];

/// The oblique view's own keys (src/tui/views/oblique/).
const OBLIQUE_HINTS: [Hint; 5] = [
    ("a/A", "θ", 0),
    ("w/W", "ω", 0),
    ("k/K", "μ", 0),
    ("t", "map", 1),
    // the way out of the view stays at every width (issue 51 item 6: 80 × 24 dropped it)
    ("i", "back", 0),
];

/// The drop view's own keys (src/tui/views/drop/state.rs).
const DROP_HINTS: [Hint; 2] = [("space", "pause", 0), ("b", "replay", 1)];

impl Widget for &KeyHints {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let hints_shown: Vec<Hint> = if self.map {
            own_first(&MAP_HINTS, &["↑↓", "←→"])
        } else if let Some(page) = self.oblique {
            let arrows = page == crate::tui::views::oblique::state::Page::Map;
            let mut own = OBLIQUE_HINTS.to_vec();
            if arrows {
                own[3] = ("t", "charts", 1);
                own.insert(3, ("←→↑↓", "θ μ", 0));
            }
            let replaced: &[&str] = if arrows {
                &["e", "[ ]", "1-3", "↑↓", "←→"]
            } else {
                &["e", "[ ]", "1-3"]
            };
            // the view's own keys before λ, ζ, v0 where the row is short
            own_first(&own, replaced)
                .into_iter()
                .map(|(k, d, r)| {
                    let knob = matches!(k, "l/L" | "z/Z" | "v/V");
                    (k, d, if knob { r.max(1) } else { r })
                })
                .collect()
        } else if self.flight {
            own_first(&FLIGHT_HINTS, &["↑↓", "←→", "="])
        } else if self.drop {
            let mut v = own_first(&DROP_HINTS, &["e"]);
            if self.drop_paused {
                // "paused" on the key bar at every width, where the readout's own line
                // may not show (issue 51 item 6: 80 × 24 showed no sign of the pause)
                v[0] = ("space", "play · paused", 0);
            }
            v
        } else {
            HINTS.to_vec()
        };
        hints(&self.theme, &hints_shown, area, buf);
    }
}

/// A view's key bar: its `own` keys first, then the common [`HINTS`] but those it takes over
/// (`replaced`, by key).
fn own_first(own: &[Hint], replaced: &[&str]) -> Vec<Hint> {
    let mut v = own.to_vec();
    v.extend(HINTS.iter().filter(|h| !replaced.contains(&h.0)));
    v
}

fn hints(theme: &Theme, all: &[Hint], area: Rect, buf: &mut Buffer) {
    let width = |h: &Hint| h.0.chars().count() + h.1.chars().count() + 3;
    let mut budget = usize::from(area.width);
    let mut keep = vec![false; all.len()];
    for rank in 0..=4 {
        for (i, h) in all.iter().enumerate() {
            if h.2 == rank && width(h) <= budget {
                keep[i] = true;
                budget -= width(h);
            }
        }
    }
    let mut spans = vec![Span::raw(" ")];
    for (h, _) in all.iter().zip(keep).filter(|(_, k)| *k) {
        spans.push(Span::styled(h.0, theme.key()));
        spans.push(Span::raw(format!(" {}  ", h.1)));
    }
    Line::from(spans).style(theme.dim()).render(area, buf);
}
