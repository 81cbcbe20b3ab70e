//! What `update` knows of the screen: its size (below the minimum nothing but quitting acts)
//! and how far the help is scrolled.

use super::{App, Overlay};
use crate::tui::action::{Action, Scroll};
use crate::tui::keys::help_max_scroll;
use crate::tui::state::{MIN_HEIGHT, MIN_WIDTH};

impl App {
    /// Whether the terminal is below the minimum size: the screen then only asks for a larger
    /// one. An unknown size (no `Resize` yet, as in tests) is not too small.
    pub fn too_small(&self) -> bool {
        self.size
            .is_some_and(|(w, h)| w < MIN_WIDTH || h < MIN_HEIGHT)
    }

    /// Whether `action` may act below the minimum size: quitting, the new size, the clock,
    /// and every answer of the loop and the workers (`answers::is_answer`: dropped, a
    /// result would be lost — tests/tui/tui_oblique.rs, tests/tui/tui_picker.rs).
    pub(super) fn acts_when_too_small(action: &Action) -> bool {
        matches!(action, Action::Quit | Action::Resize(..) | Action::Tick(_))
            || super::answers::is_answer(action)
    }

    pub(super) fn resize(&mut self, width: u16, height: u16) {
        self.size = Some((width, height));
        self.help_scroll = self.help_scroll.min(self.help_max());
    }

    /// Scroll the help, within its lines: at the end the last line is at the bottom.
    pub(super) fn scroll_help(&mut self, how: Scroll) {
        if self.overlay != Overlay::Help {
            return;
        }
        let page = self.size.map_or(10, |(_, h)| h.saturating_sub(3).max(1));
        let s = self.help_scroll;
        let next = match how {
            Scroll::Up => s.saturating_sub(1),
            Scroll::Down => s.saturating_add(1),
            Scroll::PageUp => s.saturating_sub(page),
            Scroll::PageDown => s.saturating_add(page),
            Scroll::Home => 0,
            Scroll::End => u16::MAX,
        };
        self.help_scroll = next.min(self.help_max());
    }

    /// The last scroll position of the help on the known screen (none known: all of it fits).
    fn help_max(&self) -> u16 {
        self.size.map_or(0, |(w, h)| help_max_scroll(w, h))
    }
}
