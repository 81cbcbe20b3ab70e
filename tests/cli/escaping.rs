//! Control characters never reach the user's terminal or break a file: a preset refuses them
//! in its name and description at load (file:line:column); a path or argument that holds
//! them is printed with them shown as text (`\u{1b}`); a figure whose labels hold them is
//! still well-formed XML.

use crate::common;

use bouncelab::figure::{paper, svg};
use bouncelab::preset::{ParamSource, Preset};
use bouncelab::{ContactLaw, analysis::sweep};
use common::*;

const OSC_TITLE: &str = "\u{1b}]0;pwned\u{7}";
const CLEAR: &str = "\u{1b}[2J";

/// No byte of a C0 control but the line feed, DEL, or C1 control (U+0080 … U+009F).
fn assert_clean(what: &str, s: &str) {
    let bad = s.chars().find(|&c| c.is_control() && c != '\n');
    assert_eq!(bad, None, "{what} holds a control character: {s:?}");
}

#[test]
fn a_preset_with_control_characters_is_refused_at_load() {
    for (key, toml_text) in [
        ("name", "\\u001b]0;pwned\\u0007"),
        ("description", "\\u001b[2J"),
        ("description", "tab\\tis fine, a bell\\u0007 is not"),
    ] {
        let from = format!("{key} = \"");
        let at = SUPERBALL.find(&from).unwrap() + from.len();
        let end = at + SUPERBALL[at..].find('"').unwrap();
        let text = format!("{}{toml_text}{}", &SUPERBALL[..at], &SUPERBALL[end..]);
        let line = SUPERBALL[..at].matches('\n').count() + 1;
        let (_dir, path) = file_with(text.as_bytes());
        for args in [
            &["run", "--config", path.as_str()][..],
            &["presets", "--config", path.as_str()][..],
        ] {
            let o = bl(args);
            assert_bad(
                &o,
                &[&format!(
                    "{path}:{line}:1: {key}: holds a control character"
                )],
            );
            assert_clean("stderr", &o.stderr);
        }
    }
}

#[test]
fn control_characters_never_reach_the_terminal() {
    // a --config path is printed as the preset's origin by run and presets, in CSV too
    let dir = tempfile::tempdir().unwrap();
    let name = format!("ball{OSC_TITLE}{CLEAR}.toml");
    std::fs::write(dir.path().join(&name), renamed("superball2", "7.08e4")).unwrap();
    for args in [
        &["run", "--config", name.as_str()][..],
        &["run", "--config", name.as_str(), "--format", "csv"][..],
        &["presets", "--config", name.as_str()][..],
        &["presets", "--config", name.as_str(), "--format", "json"][..],
    ] {
        let out = ok_at(dir.path(), args);
        assert_clean("stdout", &out);
        // shown as text; JSON in its own escapes
        let shown = ["ball\\u{1b}]0;pwned\\u{7}", "ball\\u001b]0;pwned\\u0007"];
        assert!(shown.iter().any(|s| out.contains(s)), "{args:?}: {out}");
    }
    // an unknown preset's name, echoed in the error
    let o = bl(&["run", "--preset", &format!("x{CLEAR}")]);
    assert_bad(&o, &["unknown preset 'x\\u{1b}[2J'"]);
    assert_clean("stderr", &o.stderr);
}

#[test]
fn a_figure_with_control_characters_is_valid_xml() {
    let p = &Preset::embedded()[0];
    let ball = paper::Ball {
        name: format!("evil{OSC_TITLE}<&>\u{9b}\u{202e}"),
        source: format!("set{CLEAR}"),
        params: p.params_from(ParamSource::Adopted),
        law: ContactLaw::Linear,
        measured: Some(p.measured.clone()),
    };
    let rows = sweep::cor_vs_zeta(
        &[0.0, 1.0],
        &sweep::log_space(0.01, 100.0, 9),
        ContactLaw::Linear,
    )
    .unwrap();
    let fig = paper::cor_zeta(&rows, std::slice::from_ref(&ball), ContactLaw::Linear);
    let text = svg::render(&fig).unwrap();
    assert_clean("the SVG", &text.replace(['\t', '\r'], ""));
    let svg = parse_svg(&text);
    assert!(
        svg.texts
            .iter()
            .any(|t| t.contains("evil\\u{1b}]0;pwned\\u{7}<&>")),
        "{:?}",
        svg.texts
    );
}

/// A path holding DEL, a C1 control or U+202E was written into JSON as `\u{7f}` (the terminal
/// sanitizer's escape, not JSON's): `run --config $'cfg\x7fdel.toml' --format json | jq .`
/// failed (issue 28). Now JSON escapes them itself, and the name reads back exactly.
#[test]
fn json_stays_json_whatever_a_name_holds() {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "cfg\u{7f}del.toml",
        "c1\u{85}x.toml",
        "rlo\u{202e}lmth.toml",
    ] {
        std::fs::write(dir.path().join(name), renamed("superball2", "7.08e4")).unwrap();
        for args in [
            &["run", "--config", name, "--format", "json"][..],
            &["presets", "--config", name, "--format", "json"][..],
            &argv_with(
                "sweep velocity --config {} --points 2 --format json",
                &[name],
            )[..],
        ] {
            let out = ok_at(dir.path(), args);
            assert_clean("stdout", &out);
            let v: serde_json::Value = serde_json::from_str(&out)
                .unwrap_or_else(|e| panic!("{args:?}: not JSON ({e}): {out}"));
            assert!(v.to_string().contains(name), "{args:?}: {out}");
        }
    }
}

/// The characters that print as nothing or as a line break (Unicode Cf, Zl, Zp).
const INVISIBLE: [char; 8] = [
    '\u{200b}',
    '\u{feff}',
    '\u{200e}',
    '\u{200f}',
    '\u{61c}',
    '\u{2028}',
    '\u{2029}',
    '\u{e0041}',
];

/// `name = "golf\u200B"` loaded as a second preset that listed as "golf" (issue 28): a name
/// holding a Cf, Zl or Zp character is refused at load (file:line:column), so no two names can
/// differ by them alone; in a description or a path they are shown escaped, in text and JSON.
#[test]
fn invisible_characters_cannot_hide() {
    for c in INVISIBLE {
        assert_name_refused_as_invisible(c);
    }
    let described = renamed("described", "7.08e4").replace(
        "description = \"",
        "description = \"zero\u{200b}width\u{2028}and\u{feff} ",
    );
    let home = config_home(&[("described.toml", &described)]);
    let out = ok_at(home.path(), &["presets"]);
    assert!(
        out.contains("zero\\u{200b}width\\u{2028}and\\u{feff}"),
        "{out}"
    );
    assert!(!out.chars().any(|c| INVISIBLE.contains(&c)), "{out}");
    let out = ok_at(home.path(), &["presets", "--format", "json"]);
    assert!(!out.chars().any(|c| INVISIBLE.contains(&c)), "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(
        v.to_string()
            .contains("zero\u{200b}width\u{2028}and\u{feff}")
    );
    // a path with a tag character (beyond the BMP): a surrogate pair in JSON
    let dir = tempfile::tempdir().unwrap();
    let name = "tag\u{e0041}.toml";
    std::fs::write(dir.path().join(name), renamed("tagged", "7.08e4")).unwrap();
    let out = ok_at(dir.path(), &["run", "--config", name, "--format", "json"]);
    assert!(out.contains("\\udb40\\udc41"), "{out}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v.to_string().contains(name), "{out}");
}

/// A data file whose name holds CR, LF, DEL, ESC or U+202E broke `fit --save` with a raw TOML
/// error: the name goes into the preset's comments and description escaped, and the saved
/// preset loads.
#[test]
fn fit_save_holds_any_data_file_name() {
    let dir = tempfile::tempdir().unwrap();
    for (i, bad) in [
        "\r",
        "\n",
        "\u{7f}",
        "\u{1b}[2J",
        "\u{202e}",
        "\"\\#",
        "\u{200b}",
    ]
    .iter()
    .enumerate()
    {
        let file = format!("cor{bad}.csv");
        std::fs::write(dir.path().join(&file), "v0,cor\n2,0.8\n4,0.75\n6,0.7\n").unwrap();
        let name = format!("fitted{i}");
        let o = bl_at(dir.path(), &["fit", "--cor-table", &file, "--save", &name]);
        assert_eq!(o.code, 0, "{file:?}: {}", o.stderr);
        let out = ok_at(dir.path(), &["presets", "--format", "json"]);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert!(names(&v).contains(&name.as_str()), "{file:?}: {out}");
    }
}
