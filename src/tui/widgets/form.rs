//! The physical-inputs form (`m`): each field with its value and unit (the readout's: m in g,
//! R and z_p in mm, four significant digits) (E with the relation
//! that ties it to K_p, "—" for a metal ball; p and T, "—" where the ball has none), the highlighted one marked ▶, the derived ω0, z̄_p, λ, ζ of the current values, and the validity warning when the
//! run leaves the model (z_m or α_max beyond R).

use crate::tui::format::value;
use crate::tui::physical::{self, Field, Form};
use crate::tui::setting::Setting;
use crate::tui::theme::Theme;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Clear, Paragraph, Widget, Wrap};

/// The form, centred on the area it is given.
#[derive(Debug, Clone)]
pub struct FormBox<'a> {
    pub form: Form,
    pub setting: &'a Setting,
    /// The surface's μ and K_t the oblique view runs on (`App::form_surface`).
    pub surface: [f64; 2],
    /// Why the current run is outside the model, if it is ([`physical::validity`]).
    pub warning: Option<String>,
    pub theme: Theme,
}

impl Widget for &FormBox<'_> {
    fn render(self, area: Rect, buf: &mut Buffer) {
        let w = 46.min(area.width);
        let inner = usize::from(w.saturating_sub(2));
        let mut lines = Vec::new();
        let d = physical::derived(&self.setting.params);
        let derived: Vec<String> = d
            .iter()
            .map(|(name, v)| format!("{name} {}", value(*v)))
            .collect();
        lines.push(Line::styled(
            format!(" {}  {}", derived[0], derived[1]),
            self.theme.dim(),
        ));
        lines.push(Line::styled(
            format!(" {}  {}", derived[2], derived[3]),
            self.theme.dim(),
        ));
        let warning = self
            .warning
            .as_deref()
            .map(|t| crate::tui::format::wrap(t, inner.saturating_sub(1)))
            .unwrap_or_default();
        for l in &warning {
            lines.push(Line::styled(format!(" {l}"), self.theme.warning()));
        }
        lines.push(Line::styled(
            " ↑↓ field · Enter/= type · Esc closes",
            self.theme.dim(),
        ));
        // the fields scroll, the rest stays: the warning and the hint were cut off below an
        // 80 × 24 screen (issue 51 item 6; tests/tui/tui_form.rs,
        // `the_form_with_a_warning_keeps_its_hint_and_selected_field_at_every_size`)
        // a row kept above and below, the title and the key bar, where the screen is short
        // (80 × 24 with the surface's μ, K_t, c_t): the fields scroll instead
        let tall = area.height.saturating_sub(2).max(area.height.min(5));
        let room = usize::from(tall.saturating_sub(2)).saturating_sub(lines.len());
        let mut fields = self.shown_fields(room.max(1));
        fields.append(&mut lines);
        let lines = fields;
        let h = (lines.len() as u16 + 2).min(tall);
        let popup = crate::tui::widgets::centred(area, w, h);
        Clear.render(popup, buf);
        let title = Line::styled(" Physical inputs ", self.theme.title());
        Paragraph::new(lines)
            .block(Block::bordered().title(title))
            .wrap(Wrap { trim: false })
            .render(popup, buf);
    }
}

impl FormBox<'_> {
    /// The field lines that fit in `room` rows: all of them, or a window holding the
    /// selected field (as near the middle as the ends allow).
    fn shown_fields(&self, room: usize) -> Vec<Line<'static>> {
        let all = self.field_lines();
        if all.len() <= room {
            return all;
        }
        let selected = Field::ALL
            .iter()
            .position(|&f| f == self.form.selected)
            .unwrap_or(0);
        let first = selected.saturating_sub(room / 2).min(all.len() - room);
        all.into_iter().skip(first).take(room).collect()
    }

    /// The value of `f` shown: the setting's, or the surface's μ and K_t.
    fn value(&self, f: Field) -> f64 {
        match f {
            Field::Friction => self.surface[0],
            Field::TangentialStiffness => self.surface[1],
            _ => f.get(self.setting),
        }
    }

    fn field_lines(&self) -> Vec<Line<'static>> {
        Field::ALL
            .iter()
            .map(|&f| {
                let here = f == self.form.selected;
                let style = if here {
                    self.theme.selected()
                } else {
                    ratatui::style::Style::default()
                };
                // the readout's one format and units: m 37.40 g, z_p 4.000 mm, M ∞ (the wall)
                let shown = f.show(self.value(f));
                let (number, unit) = shown.split_once(' ').unwrap_or((&shown, ""));
                let mut spans = vec![
                    Span::raw(if here { "▶" } else { " " }),
                    Span::styled(format!("{:<4}{number:>10} {unit}", f.symbol()), style),
                ];
                if f == Field::E {
                    // what E is in this model: the modulus K_p and z_p imply (Eq. 20)
                    spans.push(Span::styled("  K_p = 2π E z_p", self.theme.dim()));
                }
                // why a condition has no value (issue 56): the library takes none for it
                let none = self.value(f).is_nan();
                match f {
                    Field::Pressure if none => {
                        spans.push(Span::styled("  solid ball", self.theme.dim()))
                    }
                    Field::Temperature if none => {
                        spans.push(Span::styled("  not recorded", self.theme.dim()))
                    }
                    _ => {}
                }
                Line::from(spans)
            })
            .collect()
    }
}
