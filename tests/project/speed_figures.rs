//! Every speed figure of README.md and docs/*.md is a figure of BENCHMARKS.md's current table
//! (issue 55 item 2): a page cannot quote a speed that the last run of `benches/figures.sh`
//! did not print. A page quotes a figure as a link to the table — `[23.1 µs][bench]` with
//! `[bench]: ../BENCHMARKS.md#the-current-table` under the page, or an inline link — and the
//! link's text must stand in the table's figure column with whole numbers at both ends
//! (`0.42 µs` is not the end of `10.42 µs`, `3.4 µs` not the start of `3.41 µs`).
//!
//! A speed figure written without that link fails too. Outside code, every number in µs or
//! ns is one (no physical duration in these pages is that short), and so is every number in
//! ms, s, minutes or × (a ratio, not `200 × 60`) in a sentence that speaks of computing time
//! (`SPEED_WORDS`); a contact's milliseconds and a flight's seconds sit in sentences without
//! those words. `python3 benches/figure_quotes.py` lists the quotes, checks them against a
//! table and rewrites them from a new one.

use std::path::PathBuf;

/// The table's anchor, as a page's link names it (`../` before it from docs/).
const TABLE: &str = "BENCHMARKS.md#the-current-table";

/// Units of a figure, longest first (`ms` before `s`); a memory (MB) is a figure a link may
/// quote, never a speed.
const UNITS: [&str; 10] = [
    "core-seconds",
    "minutes",
    "seconds",
    "min",
    "µs",
    "ns",
    "ms",
    "MB",
    "s",
    "×",
];

/// Units no physical duration of these pages is quoted in: a speed wherever they stand.
const ALWAYS_SPEED: [&str; 2] = ["µs", "ns"];

/// Words of a sentence about obeying a signal: the time from a signal to the exit (and a
/// test's bound on it) is a promise docs/guarantees.md holds to a test, not a speed of
/// computing; its ms and s are left to that page (µs and ns still count).
const SIGNAL_WORDS: [&str; 5] = ["signal", "sigint", "sigterm", "ctrl-c", "keyboardinterrupt"];

/// Words right before a figure that make it a time taken (`fits in about 0.4 s`; `within`
/// is a bound, not a time taken).
const TAKEN_IN: [&str; 4] = ["in ", "in about ", "in under ", "in some "];

/// Words of a sentence about how long bouncelab takes to compute (matched in lower case).
const SPEED_WORDS: [&str; 26] = [
    "a call",
    "cpu",
    "one core",
    "two cores",
    "all cores",
    "per impact",
    "an impact",
    "a sample",
    "an element",
    "a shot",
    "scipy",
    "faster",
    "slower",
    "takes",
    "took",
    "costs",
    "cost ",
    "benchmark",
    "median",
    "timed",
    "keystroke",
    "release build",
    "debug build",
    "machine",
    "in rust",
    "from python",
];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The figures of a text: (start, end, unit) byte spans of a number and its unit. A `×`
/// followed by a number or a Greek letter is a size or a product (`200 × 60`, `3 × π²`), not
/// a figure; a unit followed by a letter, digit or `_` is a word (`5 seeds`, `1.96 s_θ`).
fn figures(text: &str) -> Vec<(usize, usize, &'static str)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let boundary = i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b"._-".contains(&b[i - 1]));
        if !(b[i].is_ascii_digit() && boundary) {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < b.len()
            && (b[j].is_ascii_digit()
                || (b[j] == b'.' && b.get(j + 1).is_some_and(u8::is_ascii_digit)))
        {
            j += 1;
        }
        let gap = if text[j..].starts_with(' ') { 1 } else { 0 };
        let rest = &text[j + gap..];
        let unit = UNITS.iter().find(|u| {
            let Some(after) = rest.strip_prefix(**u) else {
                return false;
            };
            let factor = |c: char| c.is_ascii_digit() || ('\u{370}'..'\u{400}').contains(&c);
            let size = **u == "×" && after.trim_start().starts_with(factor);
            !after.starts_with(|c: char| c.is_alphanumeric() || c == '_') && !size
        });
        if let Some(u) = unit {
            out.push((i, j + gap + u.len(), *u));
        }
        i = j;
    }
    out
}

/// `needle` inside `hay` with whole numbers at both ends: no digit or point before it, no
/// digit or letter after it.
fn contains_whole(hay: &str, needle: &str) -> bool {
    hay.match_indices(needle).any(|(at, _)| {
        let before = hay[..at].chars().next_back();
        let after = hay[at + needle.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_digit() || c == '.')
            && !after.is_some_and(|c| c.is_alphanumeric())
    })
}

/// The figure column of BENCHMARKS.md's current table, a cell a row.
fn table_figures() -> Vec<String> {
    let text = std::fs::read_to_string(root().join("BENCHMARKS.md")).unwrap();
    let section = text
        .split("\n## The current table\n")
        .nth(1)
        .expect("BENCHMARKS.md: no current table");
    let section = section.split("\n## ").next().unwrap();
    let cells: Vec<String> = section
        .lines()
        .filter(|l| l.starts_with('|') && !l.starts_with("|---") && !l.starts_with("| what |"))
        .map(|l| l.split('|').nth(2).unwrap_or("").trim().to_string())
        .collect();
    assert!(
        cells.len() > 10,
        "BENCHMARKS.md's current table has {} rows",
        cells.len()
    );
    cells
}

/// A page's links to the table: (byte span of the whole link, its text). Inline links and
/// reference links whose label is defined as the table (`[bench]: ../BENCHMARKS.md#…`).
fn table_links(text: &str, target: &str) -> Vec<(usize, usize, String)> {
    let labels: Vec<String> = text
        .lines()
        .filter_map(|l| l.strip_prefix('[')?.split_once("]: "))
        .filter(|(_, t)| t.trim() == target)
        .map(|(label, _)| label.to_string())
        .collect();
    let mut out = Vec::new();
    let mut from = 0;
    while let Some(open) = text[from..].find('[').map(|k| k + from) {
        let Some(close) = text[open..].find(']').map(|k| k + open) else {
            break;
        };
        let rest = &text[close + 1..];
        let end = [('(', ')'), ('[', ']')].iter().find_map(|&(o, c)| {
            let inner = rest.strip_prefix(o)?;
            let k = inner.find(c)?;
            let named = &inner[..k];
            let hit = if o == '(' {
                named == target
            } else {
                labels.iter().any(|l| l == named)
            };
            hit.then_some(close + 1 + k + 2)
        });
        if let Some(end) = end {
            out.push((open, end, text[open + 1..close].to_string()));
        }
        from = close + 1;
    }
    out
}

/// The text a reader sees as prose: fenced blocks, code spans and the given spans blanked
/// (each char to as many spaces as its bytes, so offsets and lines stay).
fn prose(text: &str, spans: &[(usize, usize, String)]) -> String {
    let mut out = String::with_capacity(text.len());
    let (mut fenced, mut code, mut at) = (false, false, 0);
    for line in text.split_inclusive('\n') {
        let fence = line.trim_start().starts_with("```");
        fenced ^= fence;
        code &= !(fence || line.trim().is_empty());
        for (k, c) in line.char_indices() {
            code ^= c == '`';
            let linked = spans.iter().any(|s| (s.0..s.1).contains(&(at + k)));
            if (fenced || fence || code || c == '`' || linked) && c != '\n' {
                out.extend(std::iter::repeat_n(' ', c.len_utf8()));
            } else {
                out.push(c);
            }
        }
        at += line.len();
    }
    out
}

/// The sentences of a prose text: (byte offset, sentence). A table row, a heading and a list
/// item begin their own; a blank line, `. `, `? ` and `! ` end one.
fn sentences(text: &str) -> Vec<(usize, &str)> {
    let mut cuts = vec![0];
    let b = text.as_bytes();
    for (i, _) in text.char_indices() {
        let next_is_space = b.get(i + 1).is_some_and(|c| c.is_ascii_whitespace());
        if b".?!".contains(&b[i]) && next_is_space {
            cuts.push(i + 1);
        }
        if b[i] == b'\n' {
            let line = &text[i + 1..];
            let t = line.trim_start();
            if line.starts_with('\n')
                || t.starts_with(['|', '#', '-', '*'])
                || b.get(i.wrapping_sub(1)) == Some(&b'|')
            {
                cuts.push(i + 1);
            }
        }
    }
    cuts.push(text.len());
    cuts.windows(2).map(|w| (w[0], &text[w[0]..w[1]])).collect()
}

/// Where a page fails the rule: `page:line: why`.
fn page_problems(name: &str, text: &str, target: &str, cells: &[String]) -> Vec<String> {
    let line_of = |at: usize| text[..at].matches('\n').count() + 1;
    let links = table_links(text, target);
    let mut out = Vec::new();
    for (at, _, quoted) in &links {
        if !figures(quoted).is_empty() && !cells.iter().any(|c| contains_whole(c, quoted)) {
            out.push(format!(
                "{name}:{}: `{quoted}` links to the table but no row has it",
                line_of(*at)
            ));
        }
    }
    let seen = prose(text, &links);
    for (at, sentence) in sentences(&seen) {
        let lower = sentence.to_lowercase();
        let about_speed = SPEED_WORDS.iter().any(|w| lower.contains(w));
        let about_signal = SIGNAL_WORDS.iter().any(|w| lower.contains(w));
        for (s, e, unit) in figures(sentence) {
            let taken = TAKEN_IN.iter().any(|w| {
                let before = sentence[..s].strip_suffix(w);
                before.is_some_and(|b| b.is_empty() || b.ends_with([' ', '\n', '(']))
            }) && unit != "×";
            let timed = !about_signal && (about_speed || taken);
            if unit != "MB" && (ALWAYS_SPEED.contains(&unit) || timed) {
                let words = sentence.split_whitespace().collect::<Vec<_>>().join(" ");
                out.push(format!(
                    "{name}:{}: `{}` is a speed figure not linked to the table ({target}): {words}",
                    line_of(at + s),
                    &sentence[s..e]
                ));
            }
        }
    }
    out
}

#[test]
fn every_speed_figure_of_the_docs_is_a_row_of_the_benchmarks_table() {
    let cells = table_figures();
    let mut problems = Vec::new();
    for (name, target, text) in pages() {
        problems.extend(page_problems(&name, &text, &target, &cells));
    }
    assert!(
        problems.is_empty(),
        "{} speed figure(s) not in BENCHMARKS.md's current table (quote a row's figure as a \
         link to it, or point to the row in words):\n{}",
        problems.len(),
        problems.join("\n")
    );
}

/// The pages checked, here and by docs_examples.rs: every docs page in name order, then the
/// README.
pub(super) fn doc_pages() -> Vec<PathBuf> {
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    pages.sort();
    pages.push(root().join("README.md"));
    pages
}

/// The pages: (name as the messages give it, the table's link target from it, text).
fn pages() -> Vec<(String, String, String)> {
    let root = root();
    let page = |path: PathBuf| {
        let name = path.strip_prefix(&root).unwrap().display().to_string();
        let target = if path.parent() == Some(root.as_path()) {
            TABLE.to_string()
        } else {
            format!("../{TABLE}")
        };
        (name, target, std::fs::read_to_string(&path).unwrap())
    };
    doc_pages().into_iter().map(page).collect()
}

/// A row named in words (`BENCHMARKS.md, “one key in the explorer”`) is the start of a row
/// `benches/figures.py` measures, so a renamed or dropped row leaves no page naming it.
#[test]
fn every_row_a_page_names_is_a_row_of_figures_py() {
    let squash = |t: &str| t.split_whitespace().collect::<Vec<_>>().join(" ");
    let rows = squash(&std::fs::read_to_string(root().join("benches/figures.py")).unwrap());
    let bench = std::fs::read_to_string(root().join("BENCHMARKS.md")).unwrap();
    let mut texts = pages();
    texts.push(("BENCHMARKS.md".into(), String::new(), bench));
    let (mut missing, mut named) = (Vec::new(), 0);
    for (name, _, text) in &texts {
        for part in squash(text).split("BENCHMARKS.md, “").skip(1) {
            let row = part.split('”').next().unwrap();
            named += 1;
            if !rows.contains(&format!("(\"{row}")) {
                missing.push(format!("{name}: “{row}”"));
            }
        }
    }
    assert!(
        named >= 10,
        "only {named} rows named: the pattern went stale"
    );
    assert!(
        missing.is_empty(),
        "rows named but not in benches/figures.py's ROWS:\n{}",
        missing.join("\n")
    );
}

#[test]
fn a_figure_is_a_number_and_its_unit_whole() {
    let spans = |t: &str| {
        figures(t)
            .iter()
            .map(|&(s, e, _)| t[s..e].to_string())
            .collect::<Vec<_>>()
    };
    assert_eq!(
        spans("0.42 µs, 6421 × SciPy, 2.45 s CPU, 62 MB, 100× the tolerance"),
        ["0.42 µs", "6421 ×", "2.45 s", "62 MB", "100×"]
    );
    assert!(
        spans("at 200 × 60, a 4 × 400-point sweep, 3 × π², 10 seeds, 1e-9 s, 1.96 s_θ").is_empty()
    );
    assert!(contains_whole("0.42 µs", "0.42 µs") && !contains_whole("10.42 µs", "0.42 µs"));
    assert!(!contains_whole("3.41 µs", "3.4 µs") && contains_whole("1.02 ms–12.13 ms", "12.13 ms"));
    let page = "a [0.42 µs][bench] call and 3 µs. It fits in 0.4 s. A contact of 2.7 ms. \
                SIGINT 2 s in ends it 0.2 s later on one core.\n\n\
                [bench]: ../BENCHMARKS.md#the-current-table\n";
    let links = table_links(page, "../BENCHMARKS.md#the-current-table");
    assert_eq!(
        links.iter().map(|l| l.2.as_str()).collect::<Vec<_>>(),
        ["0.42 µs"]
    );
    let problems = page_problems(
        "p",
        page,
        "../BENCHMARKS.md#the-current-table",
        &["0.42 µs".into()],
    );
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(
        problems[0].contains("`3 µs`") && problems[1].contains("`0.4 s`"),
        "{problems:?}"
    );
    let stale = page_problems(
        "p",
        "[0.4 µs](BENCHMARKS.md#the-current-table)",
        TABLE,
        &["0.42 µs".into()],
    );
    assert!(
        stale.len() == 1 && stale[0].contains("no row has it"),
        "{stale:?}"
    );
    let bound = page_problems("p", "It ends within 60 s. It fits in 3 s.", TABLE, &[]);
    assert!(bound.len() == 1 && bound[0].contains("`3 s`"), "{bound:?}");
}
