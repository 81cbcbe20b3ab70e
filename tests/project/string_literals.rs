//! No message holds the source's indentation. A string literal continued on the next line
//! without a `\` keeps the next line's leading spaces: "… no normal distribution has
//! (22 spaces) (not positive definite) …" (src/api/mc.rs), "more than 100 times its (18 spaces)
//! value" (src/preset/fit_table.rs), "(give (14 spaces) --surface-stiffness" (src/cli/collide.rs)
//! reached users (issue 52's trial). Every `"…"` literal of src/ and python/src is read as the
//! compiler reads it (a `\` at a line's end eats the newline and the next line's indentation)
//! and must hold no run of 8 or more spaces between two words, nor a raw line break followed
//! by 8 spaces. Raw strings (`r"…"`, `r#"…"#`) are left alone: their layout is their own. The
//! widest run a message or table label means to hold is 7 spaces (the explorer's and
//! `statics`' aligned labels, 3 to 5): 8 is indentation.
//!
//! Read by a small scanner rather than a Rust parser crate: the rule needs only where literals
//! begin and end (comments, char literals and lifetimes told apart), and no parser is among
//! the dependencies.

use super::architecture::rust_files;
use std::fs;
use std::path::Path;

/// A run of this many spaces inside a literal is source indentation.
const INDENT: usize = 8;

/// The non-raw string literals of `src` (Rust source): (line, body between the quotes).
fn string_literals(src: &str) -> Vec<(usize, String)> {
    let c: Vec<char> = src.chars().collect();
    let (mut i, mut line, mut out) = (0, 1, Vec::new());
    let at = |i: usize, s: &str| s.chars().enumerate().all(|(k, x)| c.get(i + k) == Some(&x));
    let ident = |i: usize| i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_');
    while i < c.len() {
        if c[i] == '\n' {
            line += 1;
        }
        if at(i, "//") {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if at(i, "/*") {
            let mut depth = 0;
            while i < c.len() {
                if at(i, "/*") {
                    depth += 1;
                    i += 1;
                } else if at(i, "*/") {
                    depth -= 1;
                    i += 1;
                    if depth == 0 {
                        i += 1;
                        break;
                    }
                } else if c[i] == '\n' {
                    line += 1;
                }
                i += 1;
            }
        } else if (c[i] == 'r' || at(i, "br")) && !ident(i) && raw_start(&c, i).is_some() {
            let (hashes, body) = raw_start(&c, i).unwrap();
            let close: String = std::iter::once('"')
                .chain("#".repeat(hashes).chars())
                .collect();
            i = body;
            while i < c.len() && !at(i, &close) {
                line += usize::from(c[i] == '\n');
                i += 1;
            }
            i += close.chars().count();
        } else if c[i] == '\'' {
            // a char literal ('x', '\n', '\u{2028}', '"') or a lifetime ('a)
            if c.get(i + 1) == Some(&'\\') {
                // the backslash and the character it escapes (which may be a quote)
                i += 3;
                while i < c.len() && c[i] != '\'' {
                    i += 1;
                }
                i += 1;
            } else if c.get(i + 2) == Some(&'\'') {
                i += 3;
            } else {
                i += 1;
            }
        } else if c[i] == '"' {
            let start = line;
            let mut body = String::new();
            i += 1;
            while i < c.len() && c[i] != '"' {
                if c[i] == '\\' && c.get(i + 1) == Some(&'\n') {
                    // the compiler drops the newline and the next line's leading whitespace
                    i += 1;
                    while i < c.len() && c[i].is_whitespace() {
                        line += usize::from(c[i] == '\n');
                        i += 1;
                    }
                    continue;
                }
                if c[i] == '\\' {
                    body.push(c[i]);
                    i += 1;
                }
                line += usize::from(c[i] == '\n');
                body.push(c[i]);
                i += 1;
            }
            out.push((start, body));
            i += 1;
        } else {
            i += 1;
        }
    }
    out
}

/// Where a raw string starts at `i` (`r"`, `r#"`, `br##"`): its number of `#` and the index of
/// its first character.
fn raw_start(c: &[char], i: usize) -> Option<(usize, usize)> {
    let mut j = i + if c[i] == 'b' { 2 } else { 1 };
    let hashes = c[j..].iter().take_while(|&&x| x == '#').count();
    j += hashes;
    (c.get(j) == Some(&'"')).then_some((hashes, j + 1))
}

/// Whether `body` (as typed between the quotes) holds a run of [`INDENT`] spaces between a
/// word and the next, or after a line break typed as such. After an escaped `\n` or `\t` an
/// indented line is meant.
fn holds_indentation(body: &str) -> bool {
    let run = " ".repeat(INDENT);
    body.match_indices(&run).any(|(k, _)| {
        let head = &body[..k];
        let before = head.chars().next_back();
        let after = body[k..].trim_start_matches(' ').chars().next();
        let escaped = head.ends_with("\\n") || head.ends_with("\\t");
        let between = before.is_some_and(|b| b != ' ') && after.is_some() && !escaped;
        before == Some('\n') || between
    })
}

#[test]
fn the_scanner_reads_literals_as_the_compiler_does() {
    let src = "let a = \"one \\\n          two\"; // \"x          y\"\n\
               let b = 'q'; let c = '\"'; fn f<'a>() {}\n\
               let d = r#\"raw          kept\"#;\n\
               let e = \"has          (gap)\";\n\
               let g = \"line\n        indented\";\n";
    let lits = string_literals(src);
    let bodies: Vec<&str> = lits.iter().map(|(_, b)| b.as_str()).collect();
    assert_eq!(
        bodies,
        ["one two", "has          (gap)", "line\n        indented"]
    );
    assert_eq!(lits[1].0, 5, "the line a literal starts on");
    let flagged: Vec<bool> = bodies.iter().map(|b| holds_indentation(b)).collect();
    assert_eq!(flagged, [false, true, true]);
    // aligned labels keep their spaces
    assert!(!holds_indentation("  return deflection   {}"));
    assert!(!holds_indentation("     Δe"));
    assert!(!holds_indentation("title\\n        indented on purpose"));
    assert!(!holds_indentation("padded        "));
}

#[test]
fn no_string_literal_holds_source_indentation() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    rust_files(&root.join("python/src"), &mut files);
    files.sort();
    let mut found = Vec::new();
    for file in &files {
        let text = fs::read_to_string(file).unwrap();
        for (line, body) in string_literals(&text) {
            if holds_indentation(&body) {
                let shown: String = body.chars().take(80).collect();
                let at = file.strip_prefix(root).unwrap().display();
                found.push(format!("{at}:{line}: {shown:?}"));
            }
        }
    }
    assert!(
        found.is_empty(),
        "string literals holding the source's indentation (continue the line with `\\`):\n{}",
        found.join("\n")
    );
}
