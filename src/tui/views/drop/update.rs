//! The drop view's part of [`App`]: its clock, its keys (`d`, space, `b`) and the motion
//! setting (src/tui/views/drop/state.rs holds the view's state).

use crate::tui::action::Action;
use crate::tui::app::{App, View};
use crate::tui::views::drop::state::DropView;

impl App {
    /// Animate the drop view (the explorer does, unless under reduced motion; tests see the
    /// whole sequence at once unless they ask).
    pub fn with_motion(mut self, motion: bool) -> App {
        self.drop = DropView::new(motion);
        self
    }

    pub fn drop_view(&self) -> &DropView {
        &self.drop
    }

    /// Whether the event loop should send [`Action::Tick`]s: the drop view is playing.
    pub fn animating(&self) -> bool {
        self.view == View::Drop && self.drop.playing
    }

    /// The drop view's keys (`d`, space, `b`) and the animation clock.
    pub(in crate::tui) fn drop_action(&mut self, action: &Action) {
        match action {
            Action::ToggleDrop => {
                self.toggle_view(View::Drop);
                // entering: the animation starts from the release
                self.drop = DropView::new(self.drop.motion);
            }
            Action::DropPause if self.view == View::Drop => self.drop.toggle_pause(),
            Action::DropReplay if self.view == View::Drop => self.drop.replay(),
            Action::Tick(dt) if self.view == View::Drop => self.drop.tick(*dt),
            _ => {}
        }
    }
}
