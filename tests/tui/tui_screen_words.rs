//! Issue 51 item 4: one number format and no internal names on screen. Every view and dialog
//! is drawn at the five sizes; no screen shows a library name (`max_force_normalized`,
//! `zeta`, `peers-force-time`, `kelvin-voigt-no-tension`, …) nor a number written with more
//! than four significant digits. The `y` box is left out: it is a command line to copy,
//! with the options' own names and every digit it needs to reproduce the screen.

use crate::tui_common;

use bouncelab::preset::Preset;
use bouncelab::tui::action::Action;
use bouncelab::tui::app::App;
use ratatui::crossterm::event::KeyCode;

use tui_common::*;

const SIZES: [(u16, u16); 5] = [(80, 24), (100, 30), (120, 40), (160, 50), (200, 60)];

/// Names of the library and the command line that a screen names by symbol or in words.
const INTERNAL: [&str; 12] = [
    "max_force_normalized",
    "permanent_indentation",
    "contact_time",
    "tangential_stiffness",
    "inertia_factor",
    "zeta",
    "lambda",
    "peers-force-time",
    "peers-",
    "kelvin-voigt",
    "no-tension",
    "elastic_plastic",
];

/// The significant digits of a number as written: leading zeros and the point dropped, and
/// an integer's trailing zeros ("54500" is three).
fn significant(number: &str) -> usize {
    let digits: String = number.chars().filter(char::is_ascii_digit).collect();
    let digits = digits.trim_start_matches('0');
    if number.contains('.') {
        digits.len()
    } else {
        digits.trim_end_matches('0').len()
    }
}

/// The numbers of `row` with more than four significant digits (a number: digits with at most
/// one point between them, not part of a word such as "p12" or "F_m2").
fn long_numbers(row: &str) -> Vec<String> {
    let c: Vec<char> = row.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if !c[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        let start = i;
        let mut point = false;
        while i < c.len()
            && (c[i].is_ascii_digit()
                || (c[i] == '.' && !point && c.get(i + 1).is_some_and(char::is_ascii_digit)))
        {
            point |= c[i] == '.';
            i += 1;
        }
        let word = start > 0 && (c[start - 1].is_alphabetic() || c[start - 1] == '_');
        let text: String = c[start..i].iter().collect();
        if !word && significant(&text) > 4 {
            out.push(text);
        }
    }
    out
}

#[test]
fn the_number_reader_counts_significant_digits() {
    assert_eq!(significant("54500"), 3);
    assert_eq!(significant("0.001000"), 4);
    assert_eq!(significant("1000.010"), 7);
    assert_eq!(long_numbers("F_m 13268 N beside 13270, p12"), ["13268"]);
    assert_eq!(long_numbers("e 0.7506 (0.75, +0.1%)"), Vec::<String>::new());
    assert_eq!(
        long_numbers("v 1.00000000000000e15 m/s"),
        ["1.00000000000000"]
    );
}

/// The screens to look at: (what, keys from the first screen, whether to check it).
fn screens() -> Vec<(&'static str, Vec<KeyCode>)> {
    use KeyCode::{Char, Tab};
    vec![
        ("impact", vec![]),
        ("sweeps", vec![Tab]),
        ("models", vec![Tab, Tab]),
        ("map", vec![Tab, Tab, Tab]),
        ("map peak force", vec![Tab, Tab, Tab, Char('n')]),
        (
            "map contact time",
            vec![Tab, Tab, Tab, Char('n'), Char('n')],
        ),
        ("oblique", vec![Char('i')]),
        ("oblique map", vec![Char('i'), Char('t')]),
        ("drop", vec![Char('d')]),
        ("flight", vec![Char('h')]),
        ("help", vec![Char('?')]),
        ("m form", vec![Char('m')]),
        ("picker", vec![Char('g')]),
        ("pin", vec![Char('p')]),
        ("crosshair", vec![Char('x')]),
        ("normalized", vec![Char('N')]),
        ("value entry", vec![Char('=')]),
        ("save entry", vec![Char('S')]),
        ("law hertz", vec![Char('c')]),
        ("law elastic-plastic", vec![Char('c'), Char('c')]),
        ("law 4", vec![Char('c'), Char('c'), Char('c')]),
        ("law 5", vec![Char('c'), Char('c'), Char('c'), Char('c')]),
        (
            "law 5 models",
            vec![Char('c'), Char('c'), Char('c'), Char('c'), Tab, Tab],
        ),
    ]
}

#[test]
fn no_screen_shows_an_internal_name_or_a_long_number() {
    let mut failures = Vec::new();
    for preset in [
        Preset::embedded().remove(0),
        Preset::embedded_all().remove(3),
    ] {
        for (what, keys) in screens() {
            for (w, h) in SIZES {
                let mut app = App::new(preset.clone(), false);
                app.update(Action::Resize(w, h));
                press(&mut app, &keys);
                let rows = screen_text(&draw(&app, w, h));
                for row in &rows {
                    let lower = row.to_lowercase();
                    for name in INTERNAL {
                        if lower.contains(name) {
                            failures.push(format!(
                                "{} {what} {w}×{h}: '{name}' in '{row}'",
                                preset.name
                            ));
                        }
                    }
                    for n in long_numbers(row) {
                        failures.push(format!("{} {what} {w}×{h}: {n} in '{row}'", preset.name));
                    }
                }
            }
        }
    }
    failures.dedup();
    assert!(
        failures.is_empty(),
        "{} found:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The flight view's bounce lines give the spin its unit, as its launch lines do (issue 51
/// item 4: "in 41.11 m/s at 11.2°  ω 200.0", a bare number).
#[test]
fn every_spin_on_the_flight_view_has_its_unit() {
    for (w, h) in SIZES {
        let mut app = App::new(Preset::embedded().remove(0), false);
        app.update(Action::Resize(w, h));
        press(&mut app, &[KeyCode::Char('h')]);
        let rows = screen_text(&draw(&app, w, h));
        let mut spins = 0;
        for row in &rows {
            for (i, _) in row.match_indices("ω ") {
                let rest = &row[i + "ω ".len()..];
                let number: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-'))
                    .collect();
                if number.is_empty() {
                    continue;
                }
                spins += 1;
                assert!(
                    rest[number.len()..].starts_with(" rad/s"),
                    "{w}×{h}: a spin without its unit in '{row}'"
                );
            }
        }
        assert!(spins >= 2, "{w}×{h}: {spins} spins\n{}", rows.join("\n"));
    }
}
