//! Files are never overwritten silently, bad figure commands are one-line errors, and
//! `bouncelab reproduce` writes every figure and the report.

use crate::common;

use common::*;
use std::fs;

#[test]
fn existing_files_are_refused_unless_forced() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("old.svg"), "keep").unwrap();
    let o = bl_at(d, &["figure", "cor-zeta", "--out", "old.svg"]);
    assert_bad(&o, &["old.svg exists", "--force"]);
    assert_eq!(fs::read_to_string(d.join("old.svg")).unwrap(), "keep");
    // an existing --csv-out file stops the command before the SVG is written
    fs::write(d.join("old.csv"), "keep").unwrap();
    let o = bl_at(
        d,
        &argv("figure force-time --out new.svg --csv-out old.csv"),
    );
    assert_bad(&o, &["old.csv exists"]);
    assert!(!d.join("new.svg").exists());
    ok_at(
        d,
        &argv("figure force-time --out old.svg --csv-out old.csv --force"),
    );
    assert!(
        fs::read_to_string(d.join("old.svg"))
            .unwrap()
            .starts_with("<svg")
    );
    assert!(
        fs::read_to_string(d.join("old.csv"))
            .unwrap()
            .starts_with("series,kind,t,force")
    );
}

#[test]
fn bad_figure_commands_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases: [(&[&str], &[&str]); 8] = [
        (
            &["figure", "fig9", "--out", "a.svg"],
            &[
                "fig9",
                "cor-zeta, force-zeta, cor-velocity, force-time, force-displacement",
            ],
        ),
        (&["figure", "cor-zeta"], &["--out"]),
        (
            &argv("figure cor-velocity --out a.svg --lambda 1,2"),
            &["--lambda does not apply to cor-velocity"],
        ),
        (
            &["figure", "cor-zeta", "--out", "a.svg", "--v0", "3"],
            &["--v0 does not apply to cor-zeta"],
        ),
        (
            &["figure", "force-time", "--out", "a.svg", "--v0", "0"],
            &["invalid v0"],
        ),
        (
            &["figure", "cor-zeta", "--out", "a.svg", "--lambda", "-1"],
            &["invalid lambda"],
        ),
        (
            &["figure", "force-time", "--out", "nowhere/a.svg"],
            &["no such directory nowhere"],
        ),
        (
            &argv("figure force-time --out a.svg --csv-out ./a.svg"),
            &["given twice"],
        ),
    ];
    for (args, needles) in cases {
        assert_bad(&bl_at(d, args), needles);
    }
    assert!(
        fs::read_dir(d)
            .unwrap()
            .all(|e| e.unwrap().file_name() != "a.svg")
    );
}

#[test]
fn reproduce_writes_every_figure_and_the_report_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let listed = ok_at(d, &["reproduce", "--out", "new/paper"]);
    let files: Vec<&str> = listed.lines().collect();
    assert_eq!(files.len(), 2 * (2 + 3 * 4) + 1, "{listed}");
    for f in &files {
        let text = fs::read_to_string(d.join(f)).unwrap();
        if f.ends_with(".svg") {
            parse_svg(&text);
        } else if f.ends_with(".csv") {
            assert!(text.starts_with("series,kind,"), "{f}");
        }
    }
    let report = fs::read_to_string(d.join("new/paper/report.md")).unwrap();
    for ball in ["superball", "golf", "baseball"] {
        assert!(report.contains(&format!("## {ball}\n")), "{ball}");
        assert!(
            report.contains(&format!("](cor-velocity-{ball}.svg)")),
            "{ball}"
        );
    }
    // the baseball's contact time is the model's clearest miss, and is marked
    assert!(report.contains("**-28.3 %**"), "{report}");
    cor_sentence_holds_the_table(&report);
    // a second run refuses, and touches nothing; --force replaces and leaves other files alone
    fs::write(d.join("new/paper/notes.txt"), "mine").unwrap();
    fs::write(d.join("new/paper/report.md"), "edited").unwrap();
    assert_bad(
        &bl_at(d, &["reproduce", "--out", "new/paper"]),
        &["exists", "--force"],
    );
    assert_eq!(
        fs::read_to_string(d.join("new/paper/report.md")).unwrap(),
        "edited"
    );
    ok_at(d, &["reproduce", "--out", "new/paper", "--force"]);
    assert_eq!(
        fs::read_to_string(d.join("new/paper/report.md")).unwrap(),
        report
    );
    assert_eq!(
        fs::read_to_string(d.join("new/paper/notes.txt")).unwrap(),
        "mine"
    );
    fs::write(d.join("file"), "").unwrap();
    assert_bad(
        &bl_at(d, &["reproduce", "--out", "file"]),
        &["not a directory"],
    );
    assert_bad(
        &bl_at(d, &["--preset", "golf", "reproduce"]),
        &["do not apply"],
    );
}

/// The summary's sentence on the COR bounds the misses its own table shows (it once said the
/// COR "agrees by construction" above a baseball row at −0.9 %).
fn cor_sentence_holds_the_table(report: &str) {
    let said = report
        .split("leave e within ")
        .nth(1)
        .expect("the COR sentence's bound");
    let bound: f64 = said.split(" %").next().unwrap().parse().unwrap();
    let rows = report.lines().filter(|l| {
        ["| superball |", "| golf |", "| baseball |"]
            .iter()
            .any(|b| l.starts_with(b))
    });
    let mut largest: f64 = 0.0;
    for row in rows.take(3) {
        // | ball | v0 | λ | ζ | e measured | e model | Δ | …
        let delta = row.split('|').nth(7).unwrap().trim().trim_end_matches(" %");
        largest = largest.max(delta.parse::<f64>().unwrap().abs());
    }
    assert!(
        largest > 0.0 && largest <= bound,
        "{largest} % against {bound} %"
    );
    assert!(
        bound - largest < 0.05 + 1e-9,
        "the bound {bound} % is the largest miss"
    );
}
