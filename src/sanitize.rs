//! Control characters out of every text bouncelab writes.
//!
//! A preset's name or description, a file path or a typed value can hold control characters
//! (`\u001b]0;title\u0007`, `\u001b[2J`): printed raw they retitle or clear the user's terminal,
//! in an SVG they make the XML invalid. Preset files refuse them at load (`Preset::parse`); what
//! still reaches an output (a path, an argument echoed in an error) is shown here as visible
//! text, `\u{1b}`, never sent as the character itself. What holds, and the tests that check it:
//!
//! - the command line's stdout goes through [`Writer`] and its error lines through [`line`]:
//!   no byte of C0 (except the line feed), DEL or C1 reaches the terminal
//!   (tests/cli/cli_guarantees.rs, `control_characters_never_reach_the_terminal`);
//! - every file written through `crate::atomic` is passed through [`text`], and
//!   `figure::svg::render` too: an SVG stays well-formed XML (`a_figure_with_control_characters_is_valid_xml`).
//!
//! JSON escapes them itself: `cli::output::json` writes every such character as `\uXXXX`, so
//! the sanitizer finds nothing to rewrite and the document stays valid JSON
//! (tests/cli/escaping.rs, `json_stays_json_whatever_a_name_holds`).

use std::borrow::Cow;
use std::io::{self, Write};

/// Characters never written as themselves: [`control`] characters and [`invisible`] ones.
pub fn hostile(c: char) -> bool {
    control(c) || invisible(c)
}

/// C0 and C1 controls and DEL (`char::is_control`), the bidirectional overrides and isolates,
/// which reorder what a terminal shows, and the two noncharacters XML 1.0 forbids: refused in
/// a preset's name and description at load (`preset::check`).
pub fn control(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{fffe}' | '\u{ffff}'
        )
}

/// The Unicode categories that print as nothing or as a line break: Cf, format characters
/// (U+200B zero-width space, U+FEFF, the marks U+200E/F and U+061C, U+00AD soft hyphen, …),
/// Zl (U+2028) and Zp (U+2029). `golf\u{200B}` lists as `golf`: refused in preset names at
/// load (`preset::check`), shown as `\u{200b}` in every output
/// (tests/cli/escaping.rs, `invisible_characters_cannot_hide`).
pub fn invisible(c: char) -> bool {
    use unicode_properties::{GeneralCategory as G, UnicodeGeneralCategory};
    !c.is_ascii()
        && matches!(
            c.general_category(),
            G::Format | G::LineSeparator | G::ParagraphSeparator
        )
}

fn escaped(s: &str, keep: impl Fn(char) -> bool) -> Cow<'_, str> {
    // printable ASCII (and kept line feeds) holds nothing hostile: a byte scan, which the
    // compiler vectorizes, decides most text without the character-by-character test
    let newline = keep('\n');
    let plain = |b: u8| (b' '..=b'~').contains(&b) || (newline && b == b'\n');
    if s.bytes().all(plain) || !s.chars().any(|c| hostile(c) && !keep(c)) {
        return Cow::Borrowed(s);
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        if hostile(c) && !keep(c) {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// One line of text: every control character (line breaks included) shown as `\u{…}`.
pub fn line(s: &str) -> Cow<'_, str> {
    escaped(s, |_| false)
}

/// A file's text: every control character but the line feed shown as `\u{…}`.
pub fn text(s: &str) -> Cow<'_, str> {
    escaped(s, |c| c == '\n')
}

/// The first [`control`] character of `s` not in `allowed`, and its char index.
pub fn first_control(s: &str, allowed: &[char]) -> Option<(usize, char)> {
    s.chars()
        .enumerate()
        .find(|&(_, c)| control(c) && !allowed.contains(&c))
}

/// The first [`invisible`] or default-ignorable character of `s`, and its char index.
pub fn first_invisible(s: &str) -> Option<(usize, char)> {
    s.chars()
        .enumerate()
        .find(|&(_, c)| invisible(c) || ignorable(c))
}

/// Whether `c` prints as nothing though it is no format character: Unicode's
/// Default_Ignorable_Code_Point (DerivedCoreProperties.txt, Unicode 15.1: the Hangul fillers
/// U+115F, U+1160, U+3164, U+FFA0, the variation selectors, U+034F, the tags, …) and the blank
/// Braille pattern U+2800, which fonts draw empty. `golf` + U+115F listed as a second `golf`
/// (issue 54 item 9; tests/cli/field_names.rs). Written out by hand: `unicode-properties`, the crate
/// the general category comes from, has no Default_Ignorable property.
fn ignorable(c: char) -> bool {
    matches!(
        c as u32,
        0x00AD
            | 0x034F
            | 0x061C
            | 0x115F..=0x1160
            | 0x17B4..=0x17B5
            | 0x180B..=0x180F
            | 0x200B..=0x200F
            | 0x202A..=0x202E
            | 0x2060..=0x206F
            | 0x2800
            | 0x3164
            | 0xFE00..=0xFE0F
            | 0xFEFF
            | 0xFFA0
            | 0xFFF0..=0xFFF8
            | 0x1BCA0..=0x1BCA3
            | 0x1D173..=0x1D17A
            | 0xE0000..=0xE0FFF
    )
}

/// A writer that passes text on with [`text`] applied. Bytes that are not UTF-8 pass
/// through unchanged except C0 controls and DEL (the only single-byte controls); a character
/// split across two writes is held back until it is complete.
pub struct Writer<W: Write> {
    inner: W,
    pending: Vec<u8>,
}

impl<W: Write> Writer<W> {
    pub fn new(inner: W) -> Self {
        Writer {
            inner,
            pending: Vec::new(),
        }
    }

    fn pass(&mut self, bytes: &[u8]) -> io::Result<()> {
        let mut rest = bytes;
        while !rest.is_empty() {
            match std::str::from_utf8(rest) {
                Ok(s) => return self.inner.write_all(text(s).as_bytes()),
                Err(e) => {
                    let (good, bad) = rest.split_at(e.valid_up_to());
                    // `good` is valid UTF-8: from_utf8 said so up to this index
                    let s = std::str::from_utf8(good).unwrap_or_default();
                    self.inner.write_all(text(s).as_bytes())?;
                    match e.error_len() {
                        // an incomplete character at the end: wait for the next write
                        None => {
                            self.pending.extend_from_slice(bad);
                            return Ok(());
                        }
                        Some(n) => {
                            let (junk, after) = bad.split_at(n);
                            self.inner.write_all(&Self::bytes(junk))?;
                            rest = after;
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Invalid UTF-8: single-byte controls shown, the rest as is.
    fn bytes(junk: &[u8]) -> Vec<u8> {
        let mut v = Vec::new();
        for &b in junk {
            if b < 0x20 && b != b'\n' || b == 0x7f {
                v.extend(format!("\\u{{{b:x}}}").bytes());
            } else {
                v.push(b);
            }
        }
        v
    }
}

impl<W: Write> Write for Writer<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.pending.is_empty() {
            self.pass(buf)?;
        } else {
            let mut all = std::mem::take(&mut self.pending);
            all.extend_from_slice(buf);
            self.pass(&all)?;
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if !self.pending.is_empty() {
            let junk = std::mem::take(&mut self.pending);
            self.inner.write_all(&Self::bytes(&junk))?;
        }
        self.inner.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controls_become_visible() {
        assert_eq!(line("a\u{1b}]0;pwned\u{7}b"), "a\\u{1b}]0;pwned\\u{7}b");
        assert_eq!(line("x\ny"), "x\\u{a}y");
        assert_eq!(text("x\ny\r"), "x\ny\\u{d}");
        assert_eq!(text("\u{9b}2J \u{202e}"), "\\u{9b}2J \\u{202e}");
        assert!(matches!(text("plain λ ζ"), Cow::Borrowed(_)));
        assert_eq!(first_control("ab\u{7f}", &[]), Some((2, '\u{7f}')));
        assert_eq!(first_control("\ta\u{1b}", &['\t']), Some((2, '\u{1b}')));
    }

    #[test]
    fn invisible_characters_become_visible() {
        for c in [
            '\u{200b}', '\u{feff}', '\u{200e}', '\u{200f}', '\u{61c}', '\u{2028}', '\u{2029}',
        ] {
            assert!(invisible(c) && hostile(c) && !control(c), "{c:?}");
            let shown = line(&format!("golf{c}")).into_owned();
            assert_eq!(shown, format!("golf\\u{{{:x}}}", c as u32));
        }
        // tag characters (Cf) outside the BMP too
        assert!(invisible('\u{e0041}'));
        assert!(!invisible('λ') && !invisible(' ') && !invisible('\u{a0}'));
        assert_eq!(first_invisible("ab\u{200b}"), Some((2, '\u{200b}')));
    }

    #[test]
    fn the_writer_holds_a_split_character_and_shows_c1() {
        let mut w = Writer::new(Vec::new());
        let c1 = "\u{9b}".as_bytes(); // two bytes in UTF-8
        w.write_all(b"a").unwrap();
        w.write_all(&c1[..1]).unwrap();
        w.write_all(&c1[1..]).unwrap();
        w.write_all("λ\u{1b}[2J\n".as_bytes()).unwrap();
        w.write_all(&[0xff, 0x07, b'\n']).unwrap();
        w.flush().unwrap();
        assert_eq!(
            w.inner,
            b"a\\u{9b}\xce\xbb\\u{1b}[2J\n\xff\\u{7}\n".to_vec()
        );
    }
}
