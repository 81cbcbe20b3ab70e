//! `shot --surface NAME` and `mc --shot --surface NAME` (issue 57 item 1, issue 53 item 1):
//! every bounce of the shot is `oblique` on that surface for the arriving state, and the
//! answer names the surface; plain `mc` names the rigid plate it samples on.

use crate::common;
use common::{argv, assert_bad, bl_in, f};
use serde_json::Value;
use std::path::Path;

const LAUNCH: &str = "--preset tennis --height 2.8 --speed 50 --elevation -6 --spin 200";

/// A user surface `court` that gives (K_s, c_s) with its own μ, in `dir`'s config folder.
fn court_in(dir: &Path) {
    let folder = dir.join("bouncelab/surfaces");
    std::fs::create_dir_all(&folder).unwrap();
    std::fs::write(
        folder.join("court.toml"),
        "name = \"court\"\ndescription = \"a test court\"\n[normal]\nstiffness = 3e5\n\
         damping = 12.0\n[tangential]\nfriction = 0.55\n[[sources]]\nquantity = \"stiffness\"\n\
         source = \"a test\"\n[[sources]]\nquantity = \"damping\"\nsource = \"a test\"\n\
         [[sources]]\nquantity = \"friction\"\nsource = \"a test\"\n",
    )
    .unwrap();
}

fn json_in(dir: &Path, args: &[&str]) -> Value {
    let o = bl_in(dir, args);
    assert_eq!(o.code, 0, "{args:?}: {}", o.stderr);
    serde_json::from_str(&o.stdout).unwrap_or_else(|e| panic!("{args:?}: {e}: {}", o.stdout))
}

fn close(what: &str, a: f64, b: f64) {
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0),
        "{what}: {a} against {b}"
    );
}

/// The defect: `shot` took no `--surface` (every bounce on the rigid plate, issue 57 item 1).
/// Now its bounce on a named surface is `oblique --surface` on it for the arriving state, to
/// 1e-12, μ the surface's; the explicit flags give the same bounce; the JSON `surface` is
/// `oblique`'s. Fails on the old code (no such flag: exit 2).
#[test]
fn a_shot_on_a_surface_bounces_as_oblique_on_it() {
    let dir = tempfile::tempdir().unwrap();
    court_in(dir.path());
    let shot = json_in(
        dir.path(),
        &argv(&format!("shot {LAUNCH} --surface court --format json")),
    );
    let b = &shot["bounces"][0];
    let (v, angle, spin) = (f(b, "v_in"), f(b, "angle_in"), f(b, "spin_in"));
    let oblique = json_in(
        dir.path(),
        &argv(&format!(
            "oblique --preset tennis --surface court --v0 {v} --angle {angle} --spin {spin} \
             --format json"
        )),
    );
    for (ours, its) in [
        ("v_out", "v_out"),
        ("angle_out", "angle_out_deg"),
        ("spin_out", "spin_out"),
        ("cor_normal", "cor_normal"),
        ("contact_time", "contact_time"),
    ] {
        close(ours, f(b, ours), f(&oblique, its));
    }
    assert_eq!(shot["surface"], oblique["surface"]);
    assert_eq!(shot["surface"]["name"], "court");
    assert_eq!(shot["surface"]["stiffness"], 3e5);
    assert_eq!(shot["friction"], 0.55);
    // the surface gives: not the rigid plate's bounce at the same μ
    let rigid = json_in(
        dir.path(),
        &argv(&format!("shot {LAUNCH} --friction 0.55 --format json")),
    );
    assert!((f(&rigid["bounces"][0], "cor_normal") - f(b, "cor_normal")).abs() > 1e-3);
    // the explicit flags over the rigid plate: the same bounce, bit for bit
    let explicit = json_in(
        dir.path(),
        &argv(&format!(
            "shot {LAUNCH} --surface-stiffness 3e5 --surface-damping 12 --friction 0.55 \
             --format json"
        )),
    );
    assert_eq!(explicit["bounces"], shot["bounces"]);
    assert_eq!(explicit["end"], shot["end"]);
    // the text names it
    let o = bl_in(dir.path(), &argv(&format!("shot {LAUNCH} --surface court")));
    assert_eq!(o.code, 0, "{}", o.stderr);
    let second = o.stdout.lines().nth(1).unwrap();
    assert!(second.starts_with("surface court "), "{}", o.stdout);
}

/// `mc --shot --surface`: the nominal shot's surface, named as `shot` names it; its
/// bounces on it (the median landing's v out is not the rigid plate's).
#[test]
fn mc_shot_runs_on_the_surface_and_names_it() {
    let dir = tempfile::tempdir().unwrap();
    court_in(dir.path());
    let run = |extra: &str| {
        json_in(
            dir.path(),
            &argv(&format!(
                "mc --shot {LAUNCH} {extra} --vary speed=2% --samples 50 --format json"
            )),
        )
    };
    let mc = run("--surface court");
    let shot = json_in(
        dir.path(),
        &argv(&format!("shot {LAUNCH} --surface court --format json")),
    );
    assert_eq!(mc["surface"], shot["surface"]);
    let rigid = run("--friction 0.55");
    let v_out = |j: &Value| f(&j["stats"]["v_out"], "q50");
    assert!((v_out(&mc) - v_out(&rigid)).abs() > 1e-3);
}

/// A surface no one has is refused by its flag, exit 2, for `shot` and `mc --shot`; plain
/// `mc` (rigid plate) refuses the surface's flags rather than ignore them.
#[test]
fn a_bad_surface_is_refused_by_its_flag() {
    let dir = tempfile::tempdir().unwrap();
    for line in [
        format!("shot {LAUNCH} --surface nope"),
        format!("mc --shot {LAUNCH} --surface nope --vary speed=2% --samples 10"),
    ] {
        let o = bl_in(dir.path(), &argv(&line));
        assert_bad(&o, &["invalid --surface: unknown surface 'nope'"]);
    }
    let o = bl_in(
        dir.path(),
        &argv("mc --preset tennis --vary k_p=5% --samples 10 --surface-stiffness 1e5"),
    );
    assert_bad(&o, &["invalid --surface-stiffness", "--shot"]);
}

/// The defect: plain `mc --format json` named no surface, where `run` names its own (issue
/// 53 item 1: every answer names its surface). It samples on the rigid plate, `run`'s
/// default, and says so. Fails on the old code (no `surface`).
#[test]
fn plain_mc_names_the_rigid_plate() {
    let dir = tempfile::tempdir().unwrap();
    let mc = json_in(
        dir.path(),
        &argv("mc --preset tennis --vary k_p=5% --samples 20 --format json"),
    );
    let run = json_in(dir.path(), &argv("run --preset tennis --format json"));
    assert_eq!(mc["surface"], run["surface"]);
    assert_eq!(mc["surface"]["name"], "steel-plate");
}

/// The defect: a shot of three bounces on clay said clay's assumed-rigid warning three times
/// in its text, and three times on stderr for a trajectory CSV, one per bounce. Each distinct
/// warning is said once there now; the JSON keeps it in every bounce's own `warnings`, each
/// bounce being `oblique` on clay. Fails on the old code (three lines).
#[test]
fn the_surface_is_warned_of_once_a_shot() {
    let launch = "shot --preset tennis --height 1 --speed 10 --elevation 0 --surface clay \
                  --friction 0.6 --bounces 3";
    let clay = |s: &str| {
        s.matches("surface clay: its normal give is ASSUMED rigid")
            .count()
    };
    let text = common::bl(&argv(launch));
    assert_eq!(text.code, 0, "{}", text.stderr);
    assert_eq!(clay(&text.stdout), 1, "{}", text.stdout);
    let csv = common::bl(&argv(&format!("{launch} --samples 50 --format csv")));
    assert_eq!(csv.code, 0, "{}", csv.stderr);
    assert_eq!(clay(&csv.stderr), 1, "{}", csv.stderr);
    let json: Value =
        serde_json::from_str(&common::bl(&argv(&format!("{launch} --format json"))).stdout)
            .unwrap();
    let bounces = json["bounces"].as_array().unwrap();
    assert_eq!(bounces.len(), 3);
    for b in bounces {
        assert_eq!(clay(&b["warnings"].to_string()), 1, "{b}");
    }
}
