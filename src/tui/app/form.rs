//! The physical-inputs form (`m`) as part of [`App::update`]: the highlighted field moves,
//! Enter types a value through the value entry, and each accepted value is one undoable change.

use super::{App, Overlay, Purpose, Setting};
use crate::text::parse::number;
use crate::text::sig_trim;
use crate::tui::action::{Action, Scroll};
use crate::tui::physical::{self, Field, Form};
use crate::tui::views::flight::param::FlightParam;
use crate::tui::views::oblique::param::ObliqueParam;

/// The text a field's entry opens with: its value, or nothing when it has no finite one (the
/// wall's M = ∞, a metal ball's E). Never the form's "—": typing appends to the entry's text,
/// so "0.8" typed into "—" read "'—0.8' is not a number" (issue 51;
/// tests/tui/tui_form.rs: `an_entry_opens_holding_its_value_or_empty`).
/// In the field's screen unit (g, mm), as the form shows it, to six digits: an entry
/// submitted as it opened is no change (`submit_physical`).
fn entry_text(field: Field, v: f64) -> String {
    if v.is_finite() {
        sig_trim(v * field.screen().1, 6)
    } else {
        String::new()
    }
}

/// The SI value of `text` typed in `field`: a number in the field's screen unit, or for the
/// pressure a number with its unit as `--pressure` reads it (0.8bar, 8psi, 55kPa, 80000Pa).
/// A number in a screen unit is the decimal typed, its point moved (45.93 g is 0.04593 kg to
/// the bit, not 45.93/1000 an ulp beside it: `y` then writes `--mass 0.04593`).
fn typed(field: Field, text: &str) -> Result<f64, String> {
    match number(text) {
        Ok(v) => Ok(crate::tui::exact::from_screen(v, field.screen().1)),
        Err(_) if field == Field::Pressure => {
            crate::conditions::pressure::parse("pressure", text.trim())
        }
        Err(e) => Err(e),
    }
}

impl App {
    pub(super) fn form(&mut self, action: Action) {
        match action {
            Action::OpenForm => self.open_form(Field::Mass),
            Action::FormMove(how) => {
                if let Overlay::Form(f) = &mut self.overlay {
                    f.selected = match how {
                        Scroll::Up | Scroll::PageUp => f.selected.prev(),
                        Scroll::Down | Scroll::PageDown => f.selected.next(),
                        Scroll::Home => Field::ALL[0],
                        Scroll::End => Field::ALL[Field::ALL.len() - 1],
                    };
                }
            }
            Action::FormEdit => {
                if let Overlay::Form(f) = self.overlay {
                    let now = entry_text(f.selected, self.form_value(f.selected));
                    self.open_input(Purpose::Physical(f.selected), now);
                }
            }
            _ => {}
        }
    }

    pub(super) fn open_form(&mut self, selected: Field) {
        self.overlay = Overlay::Form(Form { selected });
        if let Some(w) = self.validity() {
            self.warn(w);
        }
    }

    /// Enter in a form field's entry: an accepted value is one undoable change and the form
    /// comes back; a refused one keeps the entry open with the reason and the range.
    pub(super) fn submit_physical(&mut self, field: Field, text: &str) {
        // empty, or as it opened: the value stays to its last digit (six shown would round it)
        if text.is_empty() || text == entry_text(field, self.form_value(field)) {
            self.open_form(field);
            return;
        }
        if let Some(p) = field.surface_param() {
            return self.submit_surface(field, p, text);
        }
        let checked = typed(field, text)
            .map_err(|e| {
                format!(
                    "{e}; {} kept (range {})",
                    field.symbol(),
                    field.range_text()
                )
            })
            .and_then(|v| match field {
                Field::Pressure | Field::Temperature => {
                    let preset = self.preset();
                    let base = |s: &Setting| crate::tui::command::conditioned_base(preset, s);
                    physical::conditions::set(field, v, &self.setting, preset, &base)
                        .map_err(|e| format!("{e}; {} kept", field.symbol()))
                }
                _ => field.check(v, &self.setting),
            });
        match checked {
            Ok(next) => {
                self.change(next);
                // the run the warning reads is the new one
                self.refresh_run();
                self.open_form(field);
                if self.message.is_none() {
                    // the one screen format: tui::format::value
                    self.info(format!(
                        "{} = {}",
                        field.symbol(),
                        field.show(field.get(&self.setting))
                    ));
                }
            }
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                self.warn(why);
            }
        }
    }

    /// A form field's value (SI) as the form shows it: the setting's, the oblique view's μ and
    /// K_t (the ball's Mindlin K_t where none is set, as the impact runs on it).
    pub fn form_value(&self, field: Field) -> f64 {
        match field.surface_param() {
            Some(p) => self.oblique_value(p),
            None => field.get(&self.setting),
        }
    }

    /// The surface's μ and K_t the form shows ([`App::form_value`]).
    pub fn form_surface(&self) -> [f64; 2] {
        [Field::Friction, Field::TangentialStiffness].map(|f| self.form_value(f))
    }

    /// Enter in μ's or K_t's entry (the surface's, src/tui/physical/surface.rs): checked as the
    /// oblique view checks it, one undoable change of the oblique view's value — and of the
    /// flight view's μ, the same surface's — or refused with the reason, the entry kept open.
    fn submit_surface(&mut self, field: Field, p: ObliqueParam, text: &str) {
        let read = typed(field, text)
            .map_err(|e| {
                format!(
                    "{e}; {} kept (range {})",
                    field.symbol(),
                    field.range_text()
                )
            })
            .and_then(|v| p.check(v));
        let v = match read {
            Ok(v) => v,
            Err(why) => {
                if let Overlay::Input(input) = &mut self.overlay {
                    input.error = Some(why.clone());
                }
                return self.warn(why);
            }
        };
        let (mut oblique, mut flight) = (self.oblique.values, self.flight.values);
        if field == Field::Friction {
            oblique.friction = v;
            flight = flight.with(FlightParam::Friction, v);
        } else {
            oblique.tangential_stiffness = Some(v);
        }
        if oblique != self.oblique.values || flight != self.flight.values {
            self.remember();
            self.oblique.values = oblique;
            self.flight.values = flight;
        }
        self.open_form(field);
        self.info(format!("{} = {}", field.symbol(), field.show(v)));
    }

    /// Whether the current run leaves the model's validity (z_m or α_max beyond R), and by
    /// how much: [`physical::validity`] on the run's own numbers.
    pub fn validity(&self) -> Option<String> {
        let deflection = self.target_motion.as_ref().map(|m| m.deflection.as_slice());
        physical::validity(self.run.as_ref()?, deflection, self.setting.radius)
    }
}
