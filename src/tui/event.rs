//! The event loop: wait for an event, drain whatever else is queued (zero-timeout poll), apply
//! it all, recompute once, draw once — a held key never builds a backlog.

use super::action;
use super::app::App;
use ratatui::DefaultTerminal;
use ratatui::crossterm::event;
use std::time::Duration;

pub fn run(terminal: &mut DefaultTerminal, app: &mut App) -> anyhow::Result<()> {
    while !app.should_quit() {
        terminal.draw(|frame| frame.render_widget(&*app, frame.area()))?;
        let mut next = Some(event::read()?);
        while let Some(ev) = next {
            if let Some(a) = action::from_event(&ev, app.mode()) {
                app.apply(a);
            }
            if app.should_quit() {
                return Ok(());
            }
            next = if event::poll(Duration::ZERO)? {
                Some(event::read()?)
            } else {
                None
            };
        }
        app.refresh();
    }
    Ok(())
}
