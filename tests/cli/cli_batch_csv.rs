//! `bouncelab batch` reads its file with the reader every measured file goes through
//! (src/measured/rows.rs, the `csv` crate), as `fit` does (issue 52 item 9, issue 55 item 1):
//! a spreadsheet's "CSV UTF-8" (a BOM, every field quoted, CRLF) and a classic-Mac file (CR
//! line ends) read exactly as the plain file; errors name the batch's line and column. The
//! batch once split its lines by hand: the BOM and the quoted header left it without an `id`
//! column (`lot.csv:1:1: no id column`, exit 2).

use crate::common;

use common::{bl_at, ok_at};
use std::path::Path;

const PLAIN: &str = "# lot 7\nid,drop_height_m,rebound_height_m\nT01,2.54,1.41\nT02,2.54,1.43\n\
                     T02,2.54,1.44\nT03,2.54,1.36\n";

fn write(dir: &Path, name: &str, bytes: &[u8]) {
    std::fs::write(dir.join(name), bytes).unwrap();
}

fn json(dir: &Path, file: &str) -> String {
    ok_at(
        dir,
        &["batch", file, "--preset", "tennis", "--format", "json"],
    )
}

/// `batch NAME` over `text` written in `dir`, refused (exit 2): what it said on stderr.
fn refused(dir: &Path, name: &str, text: &str) -> String {
    write(dir, name, text.as_bytes());
    let o = bl_at(dir, &["batch", name, "--preset", "tennis"]);
    assert_eq!(o.code, 2, "{name}: {}", o.stderr);
    o.stderr
}

/// The plain file written as a spreadsheet writes it: a UTF-8 BOM, every cell quoted, CRLF.
fn spreadsheet(plain: &str, nl: &str) -> Vec<u8> {
    let mut out = "\u{feff}".to_string();
    for line in plain.lines() {
        if line.starts_with('#') {
            out.push_str(line);
        } else {
            let cells: Vec<String> = line.split(',').map(|c| format!("\"{c}\"")).collect();
            out.push_str(&cells.join(","));
        }
        out.push_str(nl);
    }
    out.into_bytes()
}

#[test]
fn a_spreadsheets_csv_reads_as_the_plain_file() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "plain.csv", PLAIN.as_bytes());
    let want = json(dir.path(), "plain.csv");
    for (name, nl) in [("crlf.csv", "\r\n"), ("cr.csv", "\r"), ("lf.csv", "\n")] {
        write(dir.path(), name, &spreadsheet(PLAIN, nl));
        assert_eq!(json(dir.path(), name), want, "{name}");
    }
    // quoted fields holding the separator do not split a cell: an id with a comma
    write(
        dir.path(),
        "comma.csv",
        b"id,drop_height_m,rebound_height_m\n\"lot 7, T01\",2.54,1.41\n",
    );
    let r: serde_json::Value = serde_json::from_str(&json(dir.path(), "comma.csv")).unwrap();
    assert_eq!(r["balls"][0]["id"], "lot 7, T01");
}

/// A bad cell in a quoted, CRLF file is named at its own line and column in the batch (the
/// id column first, so the data cells' columns count it).
#[test]
fn errors_name_the_batchs_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let text = "\u{feff}\"id\",\"drop_height_m\",\"rebound_height_m\"\r\n\"T01\",2.54,1.41\r\n\
                \"T02\",2.54,\"x\"\r\n";
    let said = refused(dir.path(), "bad.csv", text);
    assert!(
        said.starts_with("bouncelab: error: bad.csv:3:12: rebound height 'x'"),
        "{said}"
    );
    // an id coming back, named at its cell
    let text = "id;v0;cor\nA;1;0,5\nB;1;0,6\n\"A\";2;0,4\n";
    let said = refused(dir.path(), "back.csv", text);
    assert!(
        said.contains("back.csv:4:1: id 'A' again: its rows began at line 2"),
        "{said}"
    );
}
