//! A chart's title fitted to its frame: the axes and their units stay, everything else goes
//! first (tests/tui/tui_render.rs: `chart_titles_keep_their_units_at_every_size`).
//!
//! Titles are parts joined by " · ": a name ("Force–time"), the axes with their units
//! (`F [N] vs t [ms]`), qualifiers ("linear law, no flattening"), the crosshair's reading
//! (`+(1.2, 60.9)`), a computation's stop (`stopped: it panicked: … (R retries)`,
//! src/tui/app/stopped.rs). When the whole title does not fit, the parts other than the axes,
//! a reading and a stop are dropped, those right of the axes first; then the words that name
//! an axis in the axes themselves ("Normalized peak force Fm/(m v0 ω0)" → `Fm/(m v0 ω0)`);
//! then the axes are written tighter (`F[N]–t[ms]`); then the vertical axis stays alone
//! (`v_c[m/s]`); last, whole words are cut from the right with "…", never inside a
//! bracketed unit — and never down to a bare "…" (tests/tui/tui_small.rs).

/// `title` as a frame `frame_width` cells wide writes it on its top row: fitted ([`fit`]) and
/// set off by a space each side, so it never touches the corner (the oblique view's
/// `┌Paths · angles…`, issue 51).
pub fn framed(title: &str, frame_width: u16) -> String {
    format!(
        " {} ",
        fit(title, usize::from(frame_width).saturating_sub(4))
    )
}

/// `title` in at most `width` characters (a terminal cell each).
pub fn fit(title: &str, width: usize) -> String {
    let fits = |s: &str| s.chars().count() <= width;
    if fits(title) {
        return title.to_string();
    }
    let mut parts: Vec<&str> = title.split(" · ").collect();
    let axes = parts
        .iter()
        .position(|p| p.contains(" vs ") || p.contains('['))
        .unwrap_or(0);
    // the parts that stay: the axes, a reading (the crosshair's "+(x, y)"), a stop and a
    // pause (the drop view's "paused", issue 51 item 6)
    let kept = |i: usize, p: &str| {
        i == axes || p.starts_with("+(") || p.starts_with("stopped:") || p == "paused"
    };
    // the others go, those after the axes from the right first, then those before them
    let order: Vec<usize> = (axes + 1..parts.len())
        .rev()
        .chain((0..axes).rev())
        .filter(|&i| !kept(i, parts[i]))
        .collect();
    let mut gone = vec![false; parts.len()];
    for i in order {
        gone[i] = true;
        let candidate = join(&parts, &gone);
        if fits(&candidate) {
            return candidate;
        }
    }
    // the axes ever shorter: unnamed, tighter, and the vertical one alone where the axes are
    // all the title keeps (a reading or a stop beside them is cut at a word instead)
    let unnamed = unname(parts[axes]);
    let tight = tighten(&unnamed);
    let vertical = tight.split('–').next().unwrap_or_default().to_string();
    let alone = gone.iter().filter(|g| !**g).count() == 1;
    let shorter = [&unnamed, &tight, &vertical];
    for axes_text in &shorter[..if alone { 3 } else { 2 }] {
        parts[axes] = axes_text;
        let candidate = join(&parts, &gone);
        if fits(&candidate) {
            return candidate;
        }
    }
    parts[axes] = &tight;
    let cut = crate::tui::format::clip(&join(&parts, &gone), width);
    if cut != "…" {
        return cut;
    }
    // not even the first word fits: the vertical axis' symbol, cut if it must be, says more
    // than a bare "…"
    let symbol = vertical.split('[').next().unwrap_or_default();
    if fits(symbol) || width < 2 {
        return symbol.chars().take(width).collect();
    }
    symbol.chars().take(width - 1).chain(['…']).collect()
}

/// The axes without the words that name them, each side keeping its symbol and units:
/// `"Normalized peak force Fm/(m v0 ω0) vs ζ (log)"` → `"Fm/(m v0 ω0) vs ζ (log)"`,
/// `"COR e vs impact speed v0 [m/s]"` → `"COR e vs v0 [m/s]"` (an acronym is a symbol).
fn unname(axes: &str) -> String {
    axes.split(" vs ")
        .map(|side| {
            let words = words(side);
            // the symbol: the last word that is not a unit or "(log)"
            let symbol = words
                .iter()
                .rposition(|w| !w.starts_with('[') && !w.starts_with('('))
                .unwrap_or(0);
            let first = (0..symbol).find(|&i| !naming(words[i])).unwrap_or(symbol);
            words[first..].join(" ")
        })
        .collect::<Vec<_>>()
        .join(" vs ")
}

/// Whether `word` names an axis rather than writes it: a word of letters in lower case after
/// its first ("peak", "Normalized"), or a label ending in ':' ("models:").
fn naming(word: &str) -> bool {
    let mut chars = word.chars();
    let lettered = chars.next().is_some_and(char::is_alphabetic)
        && chars.clone().count() >= 1
        && chars.all(char::is_lowercase);
    lettered || (word.len() > 1 && word.ends_with(':'))
}

/// `side` split at its spaces outside brackets and parentheses: `"Fm/(m v0 ω0) [N]"` is two
/// words.
fn words(side: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in side.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            ' ' if depth == 0 => {
                if i > start {
                    out.push(&side[start..i]);
                }
                start = i + 1;
            }
            _ => {}
        }
    }
    if start < side.len() {
        out.push(&side[start..]);
    }
    out
}

/// The parts not `gone`, joined as titles are.
fn join(parts: &[&str], gone: &[bool]) -> String {
    let left: Vec<&str> = parts
        .iter()
        .zip(gone)
        .filter(|(_, g)| !**g)
        .map(|(p, _)| *p)
        .collect();
    left.join(" · ")
}

/// The axes written without spaces a reader can spare: `"F [N] vs t [ms] (log)"` →
/// `"F[N]–t[ms] log"`.
fn tighten(axes: &str) -> String {
    axes.replace(" [", "[")
        .replace(" vs ", "–")
        .replace(" (log)", " log")
        .replace(", ", ",")
}

#[cfg(test)]
mod tests {
    use super::fit;

    #[test]
    fn the_units_stay_and_the_rest_goes_first() {
        let t = "Force–time · F [N] vs t [ms]";
        assert_eq!(fit(t, 40), t);
        // 60×20 cut it to "Force–time · F [N] vs t [ms"
        assert_eq!(fit(t, 26), "F [N] vs t [ms]");
        assert_eq!(fit(t, 12), "F[N]–t[ms]");
        let c = "COR e vs ζ (log) · linear law, no flattening";
        assert_eq!(fit(c, 30), "COR e vs ζ (log)");
        assert_eq!(fit(c, 14), "COR e–ζ log");
        let h = "Force–displacement · F [N] vs α, z [mm]";
        // 80×24 showed "vs α, z [m"
        assert_eq!(fit(h, 34), "F [N] vs α, z [mm]");
        // the crosshair's reading stays with the axes
        let x = "+(1.2, 60.9) · Force–time · F [N] vs t [ms]";
        assert_eq!(fit(x, 36), "+(1.2, 60.9) · F [N] vs t [ms]");
        assert_eq!(fit(x, 26), "+(1.2, 60.9) · F[N]–t[ms]");
        // a stop stays too: the ball's name goes first
        let s = "COR e vs v0 [m/s] · superball · stopped: it panicked: boom (R retries)";
        assert_eq!(
            fit(s, 60),
            "COR e vs v0 [m/s] · stopped: it panicked: boom (R retries)"
        );
        assert_eq!(fit(s, 40), "COR e–v0[m/s] · stopped: it panicked:…");
        // the axes stay whole beside a stop: its words are cut instead
        assert!(fit(s, 50).starts_with("COR e–v0[m/s] · stopped:"));
    }

    #[test]
    fn a_title_that_cannot_fit_is_cut_at_a_word_with_an_ellipsis() {
        let t = "Normalized peak force Fm/(m v0 ω0) vs ζ (log) · linear law";
        let got = fit(t, 10);
        assert!(got.ends_with('…') && got.chars().count() <= 20, "{got}");
        assert!(!got.contains('['), "{got}");
        // never a bare "…"
        assert_eq!(fit("abc", 2), "a…");
        assert_eq!(fit("Slip · v_c [m/s] vs t [ms]", 12), "v_c[m/s]");
        assert_eq!(fit("Slip · v_c [m/s] vs t [ms]", 5), "v_c");
        assert_eq!(
            fit(t, 28),
            "Fm/(m v0 ω0) vs ζ (log)",
            "the axis' name goes before its symbol"
        );
        assert_eq!(fit("abc", 0), "");
        for w in 0..60 {
            assert!(fit(t, w).chars().count() <= w, "{w}");
            assert!(w == 0 || fit(t, w) != "…", "{w}");
        }
    }
}
