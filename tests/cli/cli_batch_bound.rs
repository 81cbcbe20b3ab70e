//! A batch's whole run is bounded (issue 54 item 9): a batch of more than
//! `analysis::batch::MAX_BALLS` balls is refused at the first ball past the bound, naming the
//! limit, before any fit runs and before any output is written; a batch at the bound is read.

use crate::common;

use common::{assert_bad, bl_at};
use std::time::Instant;

/// `n` tennis balls, each dropped once from the ITF's 2.54 m.
fn lot(n: usize) -> String {
    let mut s = String::from("id,drop_height_m,rebound_height_m\n");
    for i in 0..n {
        s.push_str(&format!("B{i},2.54,1.40\n"));
    }
    s
}

#[test]
fn a_batch_past_its_bound_is_refused_before_any_fit_naming_the_limit() {
    let max = bouncelab::analysis::batch::MAX_BALLS;
    let dir = tempfile::tempdir().unwrap();
    // 10⁵ balls: once fitted one by one for hours, every outcome held to the end
    std::fs::write(dir.path().join("lot.csv"), lot(100_000)).unwrap();
    let start = Instant::now();
    let args = [
        "batch",
        "lot.csv",
        "--preset",
        "tennis",
        "--csv-out",
        "out.csv",
    ];
    let o = bl_at(dir.path(), &args);
    let line = format!("lot.csv:{}:1:", max + 2);
    let limit = format!("at most {max} balls");
    assert_bad(&o, &[&line, &limit, "split the file"]);
    assert!(!dir.path().join("out.csv").exists(), "nothing written");
    // no fit ran: the refusal comes from reading the file (a single fit would show here only
    // on a machine some hundred times slower than any test runs on; the message is the proof)
    eprintln!("refused in {:?}", start.elapsed());
}

#[test]
fn the_library_s_split_takes_a_batch_at_its_bound_and_refuses_one_more() {
    let max = bouncelab::analysis::batch::MAX_BALLS;
    let balls = bouncelab::analysis::batch::split(&lot(max)).unwrap();
    assert_eq!(balls.len(), max);
    let e = bouncelab::analysis::batch::split(&lot(max + 1)).unwrap_err();
    assert!(
        e.to_string().contains(&format!("at most {max} balls")),
        "{e}"
    );
}
