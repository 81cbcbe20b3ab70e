//! A number a figure prints is the number its command prints: the same quantity, agreeing
//! under the figure's rounding, and a note beside it that holds for the numbers shown.

use crate::common;

use common::*;

/// The subtitle of a force–displacement figure, from its `<desc>`.
fn subtitle(dir: &std::path::Path, v0: &str) -> String {
    let args = argv_with(
        "figure force-displacement --v0 {} --out fd.svg --force",
        &[v0],
    );
    ok_at_calibrated(dir, &args);
    let svg = std::fs::read_to_string(dir.join("fd.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let desc = doc.descendants().find(|n| n.has_tag_name("desc")).unwrap();
    desc.text()
        .unwrap()
        .split(". Series")
        .next()
        .unwrap()
        .to_string()
}

/// "…; flattened: z_m = 4.003 mm > z_p = 4 mm" → (word, z_m, sign, z_p).
fn note(subtitle: &str) -> (String, f64, String, f64) {
    let tail = subtitle.rsplit("; ").next().unwrap();
    let (word, rest) = tail.split_once(": ").unwrap();
    let parts: Vec<&str> = rest.split_whitespace().collect();
    // z_m = A mm SIGN z_p = B mm
    assert_eq!(
        (parts[0], parts[3], parts[5]),
        ("z_m", "mm", "z_p"),
        "{tail}"
    );
    let n = |s: &str| s.parse::<f64>().unwrap_or_else(|_| panic!("{s} in {tail}"));
    (word.into(), n(parts[2]), parts[4].into(), n(parts[7]))
}

/// Around the speed where the superball starts to flatten (5.8 m/s, z_m = z_p = 4 mm), the
/// subtitle said "no flattening: z_m = 4 mm < z_p = 4 mm" at 5.79 m/s and "flattened: z_m =
/// 4 mm > z_p = 4 mm" at 5.8, where `bouncelab run` prints 3.996 and 4.003 mm.
#[test]
fn the_flattening_note_holds_for_its_numbers_and_agrees_with_run() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for v0 in ["3.12", "5.78", "5.79", "5.795", "5.8", "5.81", "12"] {
        let s = subtitle(d, v0);
        let (word, z_m, sign, z_p) = note(&s);
        let run = json(&["run", "--v0", v0, "--format", "json"]);
        let (m, p) = (f(&run, "max_indentation") * 1e3, f(&run, "z_p") * 1e3);
        assert_eq!(word == "flattened", m > p, "{v0}: {s}");
        let holds = match sign.as_str() {
            ">" => z_m > z_p,
            "<" => z_m < z_p,
            other => panic!("{v0}: {other} in {s}"),
        };
        assert!(holds, "{v0}: the sign holds for the numbers shown: {s}");
        // the printed z_m is run's, rounded: within half a unit of its last digit
        let digits = s
            .rsplit("z_m = ")
            .next()
            .unwrap()
            .split(' ')
            .next()
            .unwrap();
        let last = digits.split_once('.').map_or(0, |(_, f)| f.len());
        let half = 0.5 * 10f64.powi(-(last as i32));
        assert!(
            (z_m - m).abs() <= half * (1.0 + 1e-12),
            "{v0}: {z_m} vs run's {m}"
        );
        assert_eq!(z_p, p);
    }
}

/// The `<text>` contents of a figure.
fn texts(svg: &str) -> Vec<String> {
    parse_svg(svg).texts
}

/// The number in `text` between `before` and `after`, as printed.
fn between<'a>(text: &'a str, before: &str, after: &str) -> Option<&'a str> {
    let rest = text.split_once(before)?.1;
    Some(rest.split_once(after)?.0)
}

/// Every preset, two laws, its speed and 3× it: the permanent indentation z_f in the
/// force–displacement legend, the threshold z_p, and the measured e on cor-velocity are
/// `bouncelab run`'s numbers, rounded as the figure rounds them (`text::short`, three digits).
#[test]
fn legend_numbers_are_runs_rounded_as_the_figure_rounds() {
    use bouncelab::text::short;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut checked = 0;
    for p in bouncelab::preset::Preset::embedded_all() {
        for law in ["linear", "elastic-plastic"] {
            for k in [1.0, 3.0] {
                let v0 = (k * p.measured.v0).to_string();
                let base = ["--preset", &p.name, "--law", law, "--v0", &v0];
                let mut args = vec!["figure", "force-displacement"];
                args.extend(base);
                args.extend(["--out", "fd.svg", "--force"]);
                ok_at_calibrated(d, &args);
                let svg = std::fs::read_to_string(d.join("fd.svg")).unwrap();
                let mut run = vec!["run"];
                run.extend(base);
                run.extend(["--format", "json"]);
                let r = json(&run);
                let mm = |key: &str| short(f(&r, key) * 1e3, 3);
                for t in texts(&svg) {
                    if let Some(z_f) = between(&t, "permanent indentation z_f (", " mm)") {
                        assert_eq!(z_f, mm("permanent_indentation"), "{} {law} {v0}", p.name);
                        checked += 1;
                    }
                    if let Some(z_p) = between(&t, "flattening threshold z_p (", " mm)") {
                        assert_eq!(z_p, mm("z_p"), "{} {law} {v0}", p.name);
                        checked += 1;
                    }
                }
            }
        }
        let args = argv_with(
            "figure cor-velocity --preset {} --out cv.svg --force",
            &[&p.name],
        );
        ok_at_calibrated(d, &args);
        let svg = std::fs::read_to_string(d.join("cv.svg")).unwrap();
        let r = json(&["run", "--preset", &p.name, "--format", "json"]);
        if r["measured"]["cor"].is_null() {
            // a ball with no published COR (the volleyball, docs/presets.md) marks none
            assert!(
                !texts(&svg).iter().any(|t| t.starts_with("e = ")),
                "{}: a COR marked that was never measured",
                p.name
            );
            continue;
        }
        let e = short(f(&r["measured"], "cor"), 3);
        assert!(
            texts(&svg).contains(&format!("e = {e}")),
            "{}: e = {e}",
            p.name
        );
        checked += 1;
    }
    assert!(checked > 20, "{checked} numbers checked");
}

/// The figures named every reference COR "measured (Cross 1999)", the drop-test balls' too,
/// whose preset files say "Not measured" (the COR that puts each mid-window); a user's own
/// ball made from a paper ball's file is not Cross's.
#[test]
fn a_reference_cor_is_labelled_by_where_it_comes_from() {
    let dir = tempfile::tempdir().unwrap();
    let label = |args: &[&str]| {
        let mut all = vec!["figure", "cor-velocity", "--out", "cv.svg", "--force"];
        all.extend_from_slice(args);
        ok_at_calibrated(dir.path(), &all);
        let svg = std::fs::read_to_string(dir.path().join("cv.svg")).unwrap();
        texts(&svg).join("|")
    };
    let golf = label(&["--preset", "golf"]);
    assert!(golf.contains("measured (Cross 1999)"), "{golf}");
    for ball in drop_test_balls() {
        let t = label(&["--preset", ball]);
        assert!(!t.contains("Cross 1999"), "{ball}: {t}");
        assert!(t.contains("standard's mid-window"), "{ball}: {t}");
    }
    // a user's ball made from the golf ball's file, with its own COR
    let golf_toml = std::fs::read_to_string("presets/golf.toml").unwrap();
    let mine = golf_toml
        .replace("name = \"golf\"", "name = \"my-golf\"")
        .replace("cor = 0.84", "cor = 0.81");
    assert_eq!(
        mine.matches("my-golf").count() + mine.matches("0.81").count(),
        2
    );
    let path = dir.path().join("mine.toml");
    std::fs::write(&path, mine).unwrap();
    let t = label(&["--config", path.to_str().unwrap()]);
    assert!(!t.contains("Cross 1999") && t.contains("measured"), "{t}");
}
