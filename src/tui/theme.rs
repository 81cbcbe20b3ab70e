//! Styles, with or without colour (NO_COLOR). Without colour, only modifiers (bold, dim,
//! reversed) tell things apart.

use crate::figure::Tone;
use ratatui::style::{Color, Modifier, Style};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Theme {
    pub color: bool,
}

impl Theme {
    pub fn new(color: bool) -> Theme {
        Theme { color }
    }

    /// A colour, or the terminal's default without colour.
    pub fn c(&self, color: Color) -> Color {
        if self.color { color } else { Color::Reset }
    }

    pub fn fg(&self, color: Color) -> Style {
        Style::default().fg(self.c(color))
    }

    /// The live model curve.
    pub fn current(&self) -> Color {
        self.c(Color::Yellow)
    }
    /// Fixed reference curves (λ = 0, 0.4, 1).
    pub fn reference(&self, i: usize) -> Color {
        self.c([Color::Red, Color::Green, Color::Blue, Color::Magenta][i % 4])
    }
    /// A secondary live curve (force vs contact indentation).
    pub fn secondary(&self) -> Color {
        self.c(Color::Cyan)
    }
    /// Measured data.
    pub fn measured(&self) -> Style {
        self.fg(Color::LightMagenta).add_modifier(Modifier::BOLD)
    }
    /// Pinned curves.
    pub fn ghost(&self) -> Style {
        self.fg(Color::DarkGray).add_modifier(Modifier::DIM)
    }
    /// Axis lines and labels.
    pub fn axis(&self) -> Style {
        self.fg(Color::Gray)
    }
    pub fn title(&self) -> Style {
        Style::default().add_modifier(Modifier::BOLD)
    }
    pub fn dim(&self) -> Style {
        Style::default().add_modifier(Modifier::DIM)
    }
    /// The selected parameter.
    pub fn selected(&self) -> Style {
        Style::default().add_modifier(Modifier::REVERSED | Modifier::BOLD)
    }
    pub fn key(&self) -> Style {
        self.fg(Color::Cyan).add_modifier(Modifier::BOLD)
    }
    pub fn info(&self) -> Style {
        self.fg(Color::Green)
    }
    pub fn warning(&self) -> Style {
        self.fg(Color::Yellow).add_modifier(Modifier::BOLD)
    }
    pub fn error(&self) -> Style {
        self.fg(Color::Red).add_modifier(Modifier::BOLD)
    }

    /// The style of a series of colour role `tone` and figure colour `color` (a
    /// [`crate::figure::PALETTE`] index): a pin and a measured file in the colour the picture
    /// gives it, so each shows its own (issue 51 item 6); the first measured file in the
    /// measured colour, every other role by its tone alone.
    pub fn series(&self, tone: Tone, color: usize) -> Style {
        // the picture's palette (Okabe & Ito) in the terminal's named colours: blue,
        // vermillion, bluish green, reddish purple, orange, sky blue, black (white on a
        // terminal), grey
        const NAMED: [Color; 8] = [
            Color::Blue,
            Color::LightRed,
            Color::Green,
            Color::Magenta,
            Color::LightYellow,
            Color::LightBlue,
            Color::White,
            Color::DarkGray,
        ];
        let named = NAMED[color % NAMED.len()];
        match tone {
            Tone::Ghost => self.fg(named).add_modifier(Modifier::DIM),
            Tone::Measured if color != crate::figure::BLACK => {
                self.fg(named).add_modifier(Modifier::BOLD)
            }
            _ => self.tone(tone),
        }
    }

    /// The style of a figure's colour role.
    pub fn tone(&self, tone: Tone) -> Style {
        match tone {
            Tone::Current => Style::default().fg(self.current()),
            Tone::Secondary => Style::default().fg(self.secondary()),
            Tone::Reference(i) => Style::default().fg(self.reference(i)),
            Tone::Measured => self.measured(),
            Tone::Ghost => self.ghost(),
            Tone::Highlight => self.warning(),
            Tone::Rule => self.axis(),
        }
    }
}
