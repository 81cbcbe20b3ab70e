//! The measured-data readers accept what spreadsheets write (a UTF-8 BOM, RFC 4180 quoting,
//! CRLF and CR-only line ends) and refuse in a file what the command line refuses in an
//! argument, each error at its `file:line:column` with exit 2 (issue 28, docs/guarantees.md).

use crate::common;

use common::*;

/// `fit --cor-table data.csv --format json` on `text` in a fresh folder.
fn fit_cor_json(text: &[u8]) -> String {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("data.csv"), text).unwrap();
    let o = bl_at(
        dir.path(),
        &["fit", "--cor-table", "data.csv", "--format", "json"],
    );
    assert_eq!(o.code, 0, "{}", o.stderr);
    o.stdout
}

/// One table written as Excel, LibreOffice and a classic Mac write it: the same fit, to the bit.
#[test]
fn spreadsheet_files_are_read() {
    let plain = fit_cor_json(b"v0,cor\n2,0.8\n4,0.75\n6,0.7\n");
    for (what, text) in [
        (
            "BOM, CRLF",
            &b"\xef\xbb\xbfv0,cor\r\n2,0.8\r\n4,0.75\r\n6,0.7\r\n"[..],
        ),
        ("CR only", b"v0,cor\r2,0.8\r4,0.75\r6,0.7\r"),
        (
            "quoted header and values",
            b"\"v0\",\"cor\"\n\"2\",\"0.8\"\n4,\"0.75\"\n\"6\",0.7\n",
        ),
        (
            "BOM, quotes, CR, a comment",
            b"\xef\xbb\xbf# rig 2\r\"v0\";\"cor\"\r2;\"0,8\"\r4;0,75\r6;0,7",
        ),
    ] {
        assert_eq!(fit_cor_json(text), plain, "{what}");
    }
}

fn bad(name: &str, text: &[u8], args: &[&str], needles: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(name), text).unwrap();
    assert_bad(&bl_at(dir.path(), args), needles);
}

/// Places are counted the same whatever the line ends and quotes: CR-only lines are lines, a
/// quoted cell's column is its quote's.
#[test]
fn errors_keep_their_place_with_every_line_end() {
    for nl in ["\n", "\r\n", "\r"] {
        let text = format!("# rig{nl}t,F{nl}0,0{nl}1e-5,\"x\"{nl}");
        bad(
            "t.csv",
            text.as_bytes(),
            &["fit", "--force-time", "t.csv"],
            &["t.csv:4:6: force 'x' is not a number"],
        );
    }
    // the BOM is no part of the first column's name, nor of the message's column count
    bad(
        "t.csv",
        b"\xef\xbb\xbftime_s,colour\n0,1\n",
        &["fit", "--force-time", "t.csv"],
        &["t.csv:1:8: unknown column 'colour'"],
    );
    // an invisible character in a name is shown, so the user sees why `force` is unknown
    bad(
        "t.csv",
        "time_s,force\u{200b}\n0,1\n".as_bytes(),
        &["fit", "--force-time", "t.csv"],
        &["t.csv:1:8: unknown column 'force\\u{200b}'"],
    );
}

/// `1e-400` rounds to 0: refused in a file as it is as an argument, never read as 0.
#[test]
fn numbers_in_files_are_read_as_arguments_are() {
    let arg = bl(&["fit", "--cor", "0.8", "--v0", "1e-400"]);
    assert_bad(&arg, &["1e-400 is too small: it rounds to 0"]);
    bad(
        "cor.csv",
        b"v0,cor\n1e-400,0.5\n",
        &["fit", "--cor-table", "cor.csv"],
        &["cor.csv:2:1: impact speed 1e-400 is too small: it rounds to 0"],
    );
    bad(
        "t.csv",
        b"t;F\n0;0\n1e-5;-1,5e-999\n",
        &["fit", "--force-time", "t.csv"],
        &["t.csv:3:6: force -1,5e-999 is too small: it rounds to 0"],
    );
}

/// `figure --measured` tells the kind by the names it knows: a trace with a misspelt force
/// column is a trace whose misspelt column is blamed.
#[test]
fn the_misspelt_column_is_blamed() {
    bad(
        "m.csv",
        b"time_ms,forse_N\n0,1\n",
        &argv("figure force-time --out f.svg --measured m.csv"),
        &["m.csv:1:9: unknown column 'forse_N'"],
    );
}

/// A number no measurement can have is the file's fault: exit 2 at its cell, not exit 1 from a
/// fit that found no starting point.
#[test]
fn out_of_domain_numbers_are_named_at_their_cell() {
    let fit = |flag: &'static str| move |name: &'static str| vec!["fit", flag, name];
    let cor = fit("--cor-table");
    bad(
        "cor.csv",
        b"v0,cor\n2,0.7\n1e300,0.5\n",
        &cor("cor.csv"),
        &["cor.csv:3:1: impact speed 1e300 is out of the range"],
    );
    bad(
        "cor.csv",
        b"v0,cor,cor_sd\n2,0.7,0.01\n3,0.6,1e300\n",
        &cor("cor.csv"),
        &["cor.csv:3:7: COR standard deviation 1e300 is out of the range"],
    );
    bad(
        "cor.csv",
        b"v0,cor,max_force_kN\n2,0.7,1e20\n",
        &cor("cor.csv"),
        &["cor.csv:2:7: peak force 1e23 is out of the range"],
    );
    let drops = fit("--drop-test");
    bad(
        "d.csv",
        b"drop_height_m,rebound_height_m\n1e-300,0\n",
        &drops("d.csv"),
        &["d.csv:2:1: drop height 1e-300 m is out of the range"],
    );
    // a subnormal is refused where it is read (issue 54 item 7), at its cell
    bad(
        "d.csv",
        b"drop_height_m,rebound_height_m\n1e-310,0\n",
        &drops("d.csv"),
        &["d.csv:2:1: drop height 1e-310 is too small"],
    );
    bad(
        "d.csv",
        b"drop_height_m,rebound_height_m\n1,1e-300\n",
        &drops("d.csv"),
        &["d.csv:2:3: rebound height 1e-300 m is out of the range"],
    );
}
