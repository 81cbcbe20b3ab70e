//! The surface picker (`G`) in [`App::update`] (issue 53 item 6; src/tui/surface.rs): the
//! listed surfaces come back from the loop, the arrows move the highlight (src/tui/app/picker.rs),
//! Enter puts the ball on the highlighted surface as one change `u` undoes.

use super::{App, Overlay, View};
use crate::api::SurfaceUsed;
use crate::catalog::surfaces::SurfaceEntry;
use crate::target::surface::Surface;
use crate::tui::surface::{SurfacePicker, numbers};

impl App {
    /// The loop's list: the picker opens on it, the current surface highlighted.
    pub(super) fn surfaces_listed(&mut self, entries: Vec<SurfaceEntry>, error: Option<String>) {
        if let Some(e) = &error {
            self.warn(e.clone());
        }
        let now = self.setting.surface.as_ref().map(|s| s.name.as_str());
        let picker =
            SurfacePicker::opened(entries, error, |e| Some(e.surface.name.as_str()) == now);
        self.overlay = Overlay::Surfaces(picker);
    }

    /// Enter in the surface picker: the ball on the highlighted surface, the picker closed.
    pub(super) fn choose_surface(&mut self) {
        let Overlay::Surfaces(p) = std::mem::replace(&mut self.overlay, Overlay::None) else {
            return;
        };
        let Some(entry) = p.chosen() else {
            return;
        };
        let name = entry.surface.name.clone();
        let said = numbers(&entry.surface.mechanics);
        match self.on_surface(entry.surface) {
            // the readouts cut the surface's warning to their rows: said whole here
            Ok(()) => match self.surface_warnings().into_iter().next() {
                Some(w) => self.warn(w),
                None => self.info(format!("surface {name}: {said}")),
            },
            Err(why) => self.error(format!("surface {name}: {why}")),
        }
    }

    /// The surface the oblique view's ball bounces on, as the library names it and warns of
    /// it ([`crate::tui::surface::used`]): the impact view's with the view's μ, K_t and c_t
    /// given as its `y` line gives them (μ always, K_t where set, c_t where not the
    /// surface's own).
    pub fn oblique_surface_used(&self) -> SurfaceUsed {
        let own_c_t = (self.setting.surface.as_ref()).and_then(|s| s.mechanics.tangential_damping);
        let c_t = self.setting.tangential_damping;
        let o = &self.oblique.values;
        let given = [
            Some(o.friction),
            o.tangential_stiffness,
            (c_t != own_c_t).then_some(c_t.unwrap_or(0.0)),
        ];
        crate::tui::surface::used(&self.setting, Some(given))
    }

    /// The library's warnings of the surface under the answer on screen, as the command line
    /// prints them ([`SurfaceUsed::warnings`]: its rigidity assumed): the impact's (`run`) in
    /// the views whose readout shows it, the oblique impact's (`oblique`) and, where the view
    /// rates the court (tennis), the rating's (`court`, [`SurfaceUsed::court_warnings`]);
    /// none in the drop and flight views (not yet checked there).
    pub fn surface_warnings(&self) -> Vec<String> {
        match self.view {
            View::Impact | View::Sweeps | View::Models | View::Map => {
                crate::tui::surface::used(&self.setting, None).warnings()
            }
            View::Oblique => {
                let [mut answer, court] = self.oblique_surface_warnings();
                answer.extend(court);
                answer
            }
            View::Drop | View::Flight => Vec::new(),
        }
    }

    /// The oblique view's surface warnings: the impact's (`oblique`), and the court rating's
    /// (`court`) where the view rates the court (tennis), each the library's.
    pub fn oblique_surface_warnings(&self) -> [Vec<String>; 2] {
        let s = self.oblique_surface_used();
        let rated = matches!(self.oblique.pace, Some(Ok(_)));
        [
            s.warnings(),
            if rated {
                s.court_warnings()
            } else {
                Vec::new()
            },
        ]
    }

    /// The explorer started on `surface` (`--surface NAME`): nothing to lose yet.
    pub fn with_surface(mut self, surface: Surface) -> Result<App, String> {
        self.on_surface(surface)?;
        self.undo.clear();
        self.keep();
        self.refresh();
        Ok(self)
    }

    /// The explorer started with the tangential dashpot c_t (`--tangential-damping`),
    /// checked as the form checks it.
    pub fn with_tangential_damping(mut self, c_t: f64) -> Result<App, String> {
        use crate::tui::physical::Field;
        self.setting = Field::TangentialDamping.check(c_t, &self.setting)?;
        self.keep();
        self.refresh();
        Ok(self)
    }

    /// Put the ball on `surface`, as `--surface NAME` does (one undoable change): its normal
    /// give is the target (at rest), its μ and K_t (where it gives them) the oblique view's
    /// (μ the flight view's too), its c_t the dashpot beside K_t. Refused, nothing changed, where the ball and the
    /// surface's target would not meet or the model would not take them.
    pub(in crate::tui) fn on_surface(&mut self, surface: Surface) -> Result<(), String> {
        let mut next = self.setting.clone();
        next.target = surface.mechanics.target();
        next.tangential_damping = surface.mechanics.tangential_damping;
        next.target
            .validate()
            .map_err(|e| crate::tui::physical::refusal(&e))?;
        crate::tui::physical::closing_check(&next)?;
        let mut oblique = self.oblique.values;
        // its μ is the flight view's bounce's too (the form's μ sets both)
        let mut flight = self.flight.values;
        if let Some(mu) = surface.mechanics.friction {
            oblique.friction = mu;
            flight.friction = mu;
        }
        if surface.mechanics.tangential_stiffness.is_some() {
            oblique.tangential_stiffness = surface.mechanics.tangential_stiffness;
        }
        next.surface = Some(surface);
        if next != self.setting || oblique != self.oblique.values || flight != self.flight.values {
            self.remember();
            self.setting = next;
            self.oblique.values = oblique;
            self.flight.values = flight;
        }
        Ok(())
    }
}
