//! The pin table in the readout: each pinned run against the current one — COR, peak force,
//! contact time, λ, ζ and v0 — as differences pin − now. Two lines a pin in the tall panel,
//! one line of COR differences in the compact strip.

use crate::solver::ImpactResponse;
use crate::text::sig_trim;
use crate::tui::format::percent_diff;
use crate::tui::param::Param;
use crate::tui::setting::Setting;
use crate::tui::theme::Theme;
use ratatui::style::Style;
use ratatui::text::{Line, Span};

/// One pin as the readout sees it.
#[derive(Debug, Clone, Copy)]
pub struct PinView<'a> {
    pub ball: &'a str,
    pub setting: &'a Setting,
    pub run: Option<&'a ImpactResponse>,
}

/// The current run the pins are compared with.
#[derive(Debug, Clone, Copy)]
pub struct Now<'a> {
    pub setting: &'a Setting,
    pub run: Option<&'a ImpactResponse>,
}

/// A signed absolute difference (`digits` significant, or `decimals` places when given), or
/// "—" when either side is missing or not finite.
fn delta(pin: Option<f64>, now: Option<f64>, digits: usize, decimals: Option<usize>) -> String {
    match (pin, now) {
        (Some(p), Some(n)) if (p - n).is_finite() => {
            let d = p - n;
            let s = match decimals {
                Some(places) if d != 0.0 => format!("{d:.places$}"),
                _ => sig_trim(d, digits),
            };
            if d > 0.0 {
                format!("+{s}")
            } else if d == 0.0 {
                "0".into()
            } else {
                s
            }
        }
        _ => "—".into(),
    }
}

/// A difference in percent of the current value, or "—".
fn relative(pin: Option<f64>, now: Option<f64>) -> String {
    match (pin, now) {
        (Some(p), Some(n)) => percent_diff(p, n),
        _ => "—".into(),
    }
}

/// The differences pin − now: [Δe, ΔF_m %, Δt_f %] and [Δλ, Δζ %, Δv0 m/s]. COR, λ and v0
/// absolutely (λ may be 0), peak force, contact time and ζ (a log-scale parameter) in percent.
pub fn differences(pin: &PinView, now: &Now) -> [[String; 3]; 2] {
    let e = |r: Option<&ImpactResponse>| r.map(|r| r.cor);
    let f = |r: Option<&ImpactResponse>| r.map(|r| r.max_force);
    let t = |r: Option<&ImpactResponse>| r.and_then(|r| r.contact_time);
    let p = |s: &Setting, q: Param| Some(s.get(q));
    let (ps, ns) = (pin.setting, now.setting);
    [
        [
            // COR lies in [0, 1]: three decimals
            delta(e(pin.run), e(now.run), 3, Some(3)),
            relative(f(pin.run), f(now.run)),
            relative(t(pin.run), t(now.run)),
        ],
        [
            delta(p(ps, Param::Lambda), p(ns, Param::Lambda), 3, None),
            relative(p(ps, Param::Zeta), p(ns, Param::Zeta)),
            delta(p(ps, Param::V0), p(ns, Param::V0), 3, None),
        ],
    ]
}

/// The table for the tall panel, `inner_w` columns wide with `rows` rows left: a heading,
/// then per pin its tag over its ball, beside the two rows of differences (λ, ζ, v0 in the
/// ball's row). With too few rows, only the results' row per pin, tagged "p2 golf"; with
/// fewer still, the one line of the compact strip.
pub fn table(
    pins: &[PinView],
    now: &Now,
    (inner_w, rows): (usize, usize),
    theme: &Theme,
) -> Vec<Line<'static>> {
    if pins.is_empty() {
        return Vec::new();
    }
    let full = rows >= 3 + 2 * pins.len();
    if !full && rows < 2 + pins.len() {
        return compact(pins, now).into_iter().collect();
    }
    const LABEL: usize = 11;
    let col = (inner_w.saturating_sub(LABEL) / 3).max(7);
    let row = |label: String, cells: [&str; 3], style: Style| {
        let label = crate::tui::format::clip(&label, LABEL - 1);
        let mut text = format!(" {label:<w$}", w = LABEL - 1);
        for c in cells {
            // a space before every cell, so full cells never run together
            text.push_str(&format!(" {c:>w$}", w = col - 1));
        }
        Line::styled(text, style)
    };
    let mut lines = vec![
        Line::from(vec![
            Span::styled(" pin − now", theme.title()),
            Span::styled("  (P clears)", theme.dim()),
        ]),
        row(String::new(), ["Δe", "ΔF_m", "Δt_f"], theme.dim()),
    ];
    if full {
        lines.push(row(String::new(), ["Δλ", "Δζ", "Δv0"], theme.dim()));
    }
    for (i, pin) in pins.iter().enumerate() {
        let [results, params] = differences(pin, now);
        let [a, b, c] = &results;
        let tag = match full {
            true => format!("p{}", i + 1),
            false => format!("p{} {}", i + 1, pin.ball),
        };
        lines.push(row(tag, [a, b, c], Style::default()));
        if full {
            let [a, b, c] = &params;
            lines.push(row(format!(" {}", pin.ball), [a, b, c], theme.ghost()));
        }
    }
    lines
}

/// One line for the compact strip: each pin's COR difference.
pub fn compact(pins: &[PinView], now: &Now) -> Option<Line<'static>> {
    if pins.is_empty() {
        return None;
    }
    let mut text = String::from(" pin Δe:");
    for (i, pin) in pins.iter().enumerate() {
        let [results, _] = differences(pin, now);
        text.push_str(&format!(" p{} {}", i + 1, results[0]));
    }
    Some(Line::raw(text))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::preset::Preset;
    use crate::solver::{SolveOptions, simulate};

    #[test]
    fn differences_are_pin_minus_now() {
        let p = &Preset::embedded()[1];
        let now_s = Setting::from_preset(1, p);
        let mut pin_s = now_s.clone();
        pin_s.params = Param::V0.set(&pin_s.params, now_s.params.v0 + 1.0);
        pin_s.params = Param::Zeta.set(&pin_s.params, 2.0 * now_s.get(Param::Zeta));
        let run = |s: &Setting| simulate(&s.params, s.law, &SolveOptions::default()).unwrap();
        let (now_r, pin_r) = (run(&now_s), run(&pin_s));
        let now = Now {
            setting: &now_s,
            run: Some(&now_r),
        };
        let pin = PinView {
            ball: "golf",
            setting: &pin_s,
            run: Some(&pin_r),
        };
        let [res, par] = differences(&pin, &now);
        assert_eq!(res[0], format!("{:+.3}", pin_r.cor - now_r.cor));
        assert!(res[0].starts_with('+') || res[0].starts_with('-'));
        assert_eq!(res[1], percent_diff(pin_r.max_force, now_r.max_force));
        assert_eq!(par, ["0".to_string(), "+100%".into(), "+1".into()]);
        // a pin of the current run differs by nothing
        let same = PinView {
            ball: "golf",
            setting: &now_s,
            run: Some(&now_r),
        };
        let [res, _] = differences(&same, &now);
        assert_eq!(res, ["0".to_string(), "+0.0%".into(), "+0.0%".into()]);
        // a missing run is shown as missing, never as a number
        let none = Now {
            setting: &now_s,
            run: None,
        };
        assert_eq!(differences(&pin, &none)[0], ["—", "—", "—"]);
    }

    #[test]
    fn the_table_shrinks_to_the_rows_left() {
        let p = &Preset::embedded()[0];
        let s = Setting::from_preset(0, p);
        let now = Now {
            setting: &s,
            run: None,
        };
        let pin = PinView {
            ball: "superball",
            setting: &s,
            run: None,
        };
        let pins = [pin; 3];
        let theme = Theme::new(false);
        let text = |rows| -> Vec<String> {
            table(&pins, &now, (34, rows), &theme)
                .iter()
                .map(|l| l.to_string())
                .collect()
        };
        assert_eq!(text(9).len(), 9, "heading, two header rows, two rows a pin");
        assert!(text(9)[4].starts_with("  superball "));
        assert_eq!(text(8).len(), 5, "heading, one header row, a row a pin");
        // cut at a word, never inside one (issue 51 item 6: "p1 superb…")
        assert!(
            text(8)[2].starts_with(" p1… "),
            "a cut name ends in … after a whole word: {:?}",
            text(8)[2]
        );
        assert_eq!(text(4), [" pin Δe: p1 — p2 — p3 —"]);
        assert!(table(&[], &now, (34, 40), &theme).is_empty());
    }

    #[test]
    fn deltas_have_a_sign() {
        assert_eq!(delta(Some(0.5), Some(0.25), 3, None), "+0.25");
        assert_eq!(delta(Some(0.25), Some(0.5), 3, None), "-0.25");
        assert_eq!(delta(Some(0.25), Some(0.5), 3, Some(3)), "-0.250");
        assert_eq!(delta(Some(0.5), Some(0.5), 3, Some(3)), "0");
        assert_eq!(delta(Some(f64::NAN), Some(0.5), 3, None), "—");
    }
}
