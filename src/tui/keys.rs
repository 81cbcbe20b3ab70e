//! The keys the help lists (`?`): the table the help draws, and how many lines it has, which
//! `update` needs to stop the help's scrolling at its end.

/// (keys, what they do); a row without text is a section heading.
pub const KEYS: [(&str, &str); 78] = [
    ("l / L", "λ up / down (±0.01, coarse ±0.1)"),
    ("z / Z", "ζ up / down (×1.1, coarse ×2)"),
    ("v / V", "v0 up / down (±0.1, coarse ±1 m/s)"),
    ("↑ / ↓", "change the selected parameter"),
    ("Shift+↑↓ PgUp/Dn", "coarse step"),
    ("← / →", "select λ, ζ or v0"),
    ("[ / ]", "fine / coarse steps"),
    ("= or Enter", "type an exact value"),
    ("1 2 3", "load superball, golf, baseball"),
    ("4", "the start preset, if another"),
    ("g", "pick a preset (embedded and user)"),
    ("G", "pick a surface (embedded and user)"),
    ("m", "edit m, R, K_p, …, v0, p, T, the target"),
    ("x", "crosshair: read values off a chart"),
    ("N", "normalize a chart: F/F_m vs t/t_f"),
    ("+ / - / 0", "zoom a chart in / out / whole data"),
    ("c", "cycle the contact law"),
    ("r", "reset to the preset"),
    ("R", "retry a computation that stopped"),
    ("p / P", "pin this run (≤ 8) / clear pins"),
    ("u", "undo the last change"),
    ("e", "export this view (SVG + CSV files)"),
    ("s", "save as a user preset (asks a name)"),
    ("S", "save the session (asks a file)"),
    ("y", "show the command line that reopens this"),
    (
        "Tab / Shift+Tab",
        "switch view (impact, sweeps, models, map)",
    ),
    ("d", "drop test (space pauses, b replays)"),
    ("i", "oblique impact: angle, spin, friction"),
    ("h", "flight: a shot, its bounce and landing"),
    ("o / O", "load measured data / put it away"),
    ("f / F", "fit the ball to it / apply the fit"),
    ("?", "this help (Esc, ? or q closes)"),
    ("q", "quit (asks if work would be lost)"),
    ("Ctrl-C", "quit at once (Esc never quits)"),
    ("", ""),
    ("In the map view", ""),
    ("← → / ↑ ↓", "move the cursor (the ball): ζ / λ"),
    ("Shift+arrows", "move it 8 cells"),
    ("n", "show COR, peak force or contact time"),
    ("t", "targets, e.g. cor>=0.8,max_force<=2000"),
    ("", ""),
    ("In the oblique view (i)", ""),
    ("a/A w/W k/K", "step θ ±1°, ω ±10 rad/s, μ ±0.01"),
    ("↑ ↓ / ← →", "change / select θ, ω, μ, K_t, κ"),
    ("= or Enter", "type the selected one's value"),
    ("t", "the charts or the (θ, μ) map"),
    ("← → / ↑ ↓", "on the map: move the cursor, θ / μ"),
    ("n", "map of angle out, spin out or e_x"),
    ("i", "back to the impact view"),
    ("", ""),
    ("In the flight view (h)", ""),
    ("← → / ↑ ↓", "select / step v, elevation, ω, H, μ"),
    ("a/A w/W k/K", "step elevation ±1°, ω ±10 rad/s, μ ±0.05"),
    ("y / e", "the bouncelab shot line / export the path"),
    ("h", "back to the impact view"),
    ("", ""),
    ("In this help", ""),
    ("↑↓ j k PgUp/Dn", "scroll (Home / End: top / end)"),
    ("", ""),
    ("In the preset or surface picker (g, G)", ""),
    ("↑↓ Enter / Esc", "choose, load / close"),
    ("", ""),
    ("With the crosshair (x)", ""),
    ("←→↑↓ Shift: ×10", "move it; it reads x, y and the curve"),
    ("Tab or x / Esc", "next chart / take it away"),
    ("", ""),
    ("In the physical inputs (m)", ""),
    ("↑↓ Enter or =", "choose a field, type its value"),
    ("Esc or m", "close (u undoes each value)"),
    ("", ""),
    ("In the value or name entry", ""),
    ("Enter / Esc", "accept / cancel"),
    ("← → Home End", "move the cursor"),
    ("Backspace / Del", "delete before / at the cursor"),
    ("Ctrl-U", "clear the entry"),
    ("", ""),
    ("At \"overwrite …? y/n\"", ""),
    ("y / n or Esc", "replace the file / keep it"),
];

/// One row of the help as a screen `width` columns wide shows it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HelpRow {
    /// The key, padded to the key column; blank on a text's continuation rows.
    pub key: String,
    /// The text (or a part of it, wrapped at spaces), or a section's heading.
    pub text: String,
    /// Whether the row is a section's heading.
    pub heading: bool,
}

/// The help's box width on a screen `width` columns wide: its widest row, or the screen.
pub fn help_width(width: u16) -> u16 {
    let (key_w, text_w) = help_columns();
    ((key_w + text_w + 5) as u16).min(width)
}

/// The widths of the key column and of the widest text.
fn help_columns() -> (usize, usize) {
    // section headings (rows without text) span the line: they do not widen the key column
    let key_w = KEYS
        .iter()
        .filter(|k| !k.1.is_empty())
        .map(|k| k.0.chars().count())
        .max()
        .unwrap_or(0);
    let text_w = KEYS.iter().map(|k| k.1.chars().count()).max().unwrap_or(0);
    (key_w, text_w)
}

/// The help's rows in a box [`help_width`] wide: a text wider than its column wraps at
/// spaces onto rows under it (at 60 columns "switch view (impact, sweeps, models, ma" was cut).
pub fn help_rows(width: u16) -> Vec<HelpRow> {
    let (key_w, _) = help_columns();
    // the box's inside less " key  " before the text
    let text_col = usize::from(help_width(width))
        .saturating_sub(key_w + 5)
        .max(8);
    let mut rows = Vec::new();
    for (k, t) in KEYS {
        if t.is_empty() {
            rows.push(HelpRow {
                key: String::new(),
                text: (*k).to_string(),
                heading: true,
            });
            continue;
        }
        for (i, part) in crate::tui::format::wrap(t, text_col)
            .into_iter()
            .enumerate()
        {
            let key: &str = if i == 0 { k } else { "" };
            rows.push(HelpRow {
                key: format!("{key:<key_w$}"),
                text: part,
                heading: false,
            });
        }
    }
    rows
}

/// The first help row that can be shown at the top on a `width` × `height` screen: the
/// help's box takes the whole height at most, two rows of it the border.
pub fn help_max_scroll(width: u16, height: u16) -> u16 {
    let shown = height.saturating_sub(2) as usize;
    help_rows(width).len().saturating_sub(shown) as u16
}
