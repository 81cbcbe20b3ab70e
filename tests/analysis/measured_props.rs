//! The measured-data parsers on any text: an answer or an error pointing inside the text,
//! never a panic.

use bouncelab::measured::{CorTable, DropTest, Trace, parse_any};
use proptest::prelude::*;

fn within(text: &str, e: &bouncelab::measured::MeasuredError) {
    // lines as the readers count them: LF, CRLF and a lone CR each end one
    let lines = text
        .replace("\r\n", "\n")
        .replace('\r', "\n")
        .lines()
        .count()
        .max(1)
        + 1;
    assert!(
        e.line >= 1 && e.line <= lines,
        "line {} of {lines}: {e}",
        e.line
    );
    assert!(e.column >= 1, "{e}");
    assert!(!e.message.contains('\n'), "{e}");
}

/// Text built from the pieces data files are made of, so that most cases get past the header.
fn csvish() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        Just("t".to_string()),
        Just("F".to_string()),
        Just("v0".to_string()),
        Just("cor".to_string()),
        Just("drop_height_m".to_string()),
        Just("rebound_height_m".to_string()),
        Just(",".to_string()),
        Just(";".to_string()),
        Just("\t".to_string()),
        Just("\n".to_string()),
        Just("\r".to_string()),
        Just("\r\n".to_string()),
        Just("\"".to_string()),
        Just("\u{feff}".to_string()),
        Just("# c\n".to_string()),
        Just("NaN".to_string()),
        Just("-".to_string()),
        (-1e3f64..1e3).prop_map(|x| format!("{x}")),
        "[a-z0-9.,;éß\u{1b}]{0,4}",
    ];
    prop::collection::vec(piece, 0..60).prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn never_panics(text in csvish()) {
        for r in [
            parse_any(&text).err(),
            Trace::parse(&text).err(),
            CorTable::parse(&text).err(),
            DropTest::parse(&text).err(),
        ].into_iter().flatten() {
            within(&text, &r);
        }
        if let Ok(t) = Trace::parse(&text) {
            prop_assert!(t.time.windows(2).all(|w| w[0] < w[1]));
            prop_assert!(t.force.iter().all(|f| f.is_finite()));
            if let Err(e) = t.summary() {
                within(&text, &e);
            }
        }
        if let Ok(c) = CorTable::parse(&text) {
            prop_assert!(c.points.iter().all(|p| p.v0 > 0.0 && (0.0..=1.0).contains(&p.cor)));
        }
    }
}

/// A COR table as any spreadsheet may write it (line ends LF, CRLF or CR, a UTF-8 BOM or not,
/// cells quoted or not): read to the same numbers on the same lines as the plain text.
fn written(rows: &[(f64, f64)], nl: &str, bom: bool, quoted: bool) -> String {
    let q = |s: String| if quoted { format!("\"{s}\"") } else { s };
    let mut text = String::from(if bom { "\u{feff}" } else { "" });
    text.push_str(&format!(
        "# rig{nl}{},{}{nl}",
        q("v0".into()),
        q("cor".into())
    ));
    for (v, e) in rows {
        text.push_str(&format!("{},{}{nl}", q(v.to_string()), q(e.to_string())));
    }
    text
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn line_ends_boms_and_quotes_change_nothing(
        rows in prop::collection::vec((1e-3f64..1e3, 0.0f64..=1.0), 1..20),
        nl in prop_oneof![Just("\n"), Just("\r\n"), Just("\r")],
        bom: bool,
        quoted: bool,
    ) {
        let plain = CorTable::parse(&written(&rows, "\n", false, false)).unwrap();
        let other = CorTable::parse(&written(&rows, nl, bom, quoted)).unwrap();
        prop_assert_eq!(&other, &plain);
        prop_assert_eq!(plain.points.iter().map(|p| (p.v0, p.cor)).collect::<Vec<_>>(), rows);
    }
}
