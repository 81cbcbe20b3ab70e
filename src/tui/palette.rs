//! How many colours the terminal shows, and 24-bit colours brought down to them. The map's
//! viridis cells are the explorer's only 24-bit colours; a terminal that does not say it takes
//! them (`COLORTERM=truecolor` or `24bit`) gets the nearest of the xterm 256-colour palette
//! (`TERM=…256color`) or of the 16 ANSI colours, as htop and btop do.

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::style::Color;

/// The colours a terminal shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Depth {
    /// 24-bit colour.
    TrueColor,
    /// The xterm 256-colour palette.
    Indexed,
    /// The 16 ANSI colours.
    Ansi,
}

/// The depth a terminal announces through `COLORTERM` and `TERM`.
pub fn detect(colorterm: Option<&str>, term: Option<&str>) -> Depth {
    if matches!(colorterm, Some("truecolor" | "24bit")) {
        Depth::TrueColor
    } else if term.is_some_and(|t| t.contains("256color")) {
        Depth::Indexed
    } else {
        Depth::Ansi
    }
}

/// The six levels of each channel of the xterm colour cube (indices 16–231).
const CUBE: [u8; 6] = [0, 95, 135, 175, 215, 255];

/// The 16 ANSI colours as xterm draws them.
const ANSI: [(Color, (u8, u8, u8)); 16] = [
    (Color::Black, (0, 0, 0)),
    (Color::Red, (205, 0, 0)),
    (Color::Green, (0, 205, 0)),
    (Color::Yellow, (205, 205, 0)),
    (Color::Blue, (0, 0, 238)),
    (Color::Magenta, (205, 0, 205)),
    (Color::Cyan, (0, 205, 205)),
    (Color::Gray, (229, 229, 229)),
    (Color::DarkGray, (127, 127, 127)),
    (Color::LightRed, (255, 0, 0)),
    (Color::LightGreen, (0, 255, 0)),
    (Color::LightYellow, (255, 255, 0)),
    (Color::LightBlue, (92, 92, 255)),
    (Color::LightMagenta, (255, 0, 255)),
    (Color::LightCyan, (0, 255, 255)),
    (Color::White, (255, 255, 255)),
];

fn distance(a: (u8, u8, u8), b: (u8, u8, u8)) -> u32 {
    let d = |x: u8, y: u8| (i32::from(x) - i32::from(y)).unsigned_abs();
    d(a.0, b.0).pow(2) + d(a.1, b.1).pow(2) + d(a.2, b.2).pow(2)
}

/// The nearest xterm 256-colour index: the cube's or the grey ramp's (232–255), whichever is
/// nearer.
fn indexed((r, g, b): (u8, u8, u8)) -> u8 {
    let level = |c: u8| {
        (0..6)
            .min_by_key(|&i| (i32::from(CUBE[i]) - i32::from(c)).unsigned_abs())
            .unwrap_or(0)
    };
    let (i, j, k) = (level(r), level(g), level(b));
    let cube = 16 + 36 * i + 6 * j + k;
    let cube_rgb = (CUBE[i], CUBE[j], CUBE[k]);
    let mean = (u32::from(r) + u32::from(g) + u32::from(b)) / 3;
    // greys 8, 18, …, 238
    let step = (mean.saturating_sub(3) / 10).min(23) as u8;
    let grey = 8 + 10 * step;
    if distance((grey, grey, grey), (r, g, b)) < distance(cube_rgb, (r, g, b)) {
        232 + step
    } else {
        cube as u8
    }
}

/// `color` as a terminal of `depth` shows it: 24-bit colours brought to the nearest it has.
pub fn shown(color: Color, depth: Depth) -> Color {
    let Color::Rgb(r, g, b) = color else {
        return color;
    };
    match depth {
        Depth::TrueColor => color,
        Depth::Indexed => Color::Indexed(indexed((r, g, b))),
        Depth::Ansi => ANSI
            .iter()
            .min_by_key(|(_, rgb)| distance(*rgb, (r, g, b)))
            .map_or(color, |(c, _)| *c),
    }
}

/// Every cell of `area` in colours a terminal of `depth` shows.
pub fn bring_down(buf: &mut Buffer, area: Rect, depth: Depth) {
    if depth == Depth::TrueColor {
        return;
    }
    for y in area.top()..area.bottom() {
        for x in area.left()..area.right() {
            let cell = &mut buf[(x, y)];
            let (fg, bg) = (shown(cell.fg, depth), shown(cell.bg, depth));
            cell.set_fg(fg).set_bg(bg);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_terminal_says_what_it_shows() {
        assert_eq!(detect(Some("truecolor"), Some("xterm")), Depth::TrueColor);
        assert_eq!(detect(Some("24bit"), None), Depth::TrueColor);
        assert_eq!(detect(None, Some("xterm-256color")), Depth::Indexed);
        assert_eq!(detect(None, Some("tmux-256color")), Depth::Indexed);
        assert_eq!(detect(None, Some("xterm")), Depth::Ansi);
        assert_eq!(detect(None, None), Depth::Ansi);
    }

    #[test]
    fn colours_go_to_the_nearest_the_terminal_has() {
        for (colour, depth, want) in [
            // the cube's corners and a grey
            (Color::Rgb(255, 0, 0), Depth::Indexed, Color::Indexed(196)),
            (Color::Rgb(0, 0, 0), Depth::Indexed, Color::Indexed(16)),
            (
                Color::Rgb(128, 128, 128),
                Depth::Indexed,
                Color::Indexed(244),
            ),
            // viridis' ends: dark purple and yellow
            (Color::Rgb(68, 1, 84), Depth::Indexed, Color::Indexed(53)),
            (Color::Rgb(253, 231, 37), Depth::Ansi, Color::LightYellow),
            (Color::Rgb(68, 1, 84), Depth::Ansi, Color::Black),
            // named colours stay
            (Color::Cyan, Depth::Ansi, Color::Cyan),
            (Color::Rgb(1, 2, 3), Depth::TrueColor, Color::Rgb(1, 2, 3)),
        ] {
            assert_eq!(shown(colour, depth), want, "{colour:?} at {depth:?}");
        }
    }
}
