//! Which outputs a ball's record vouches for (docs/presets.md, "The calibration record"): each
//! `[[calibration.data]]` set names what it measured (`outputs`), and an answer that reports
//! another says so: `uncalibrated_outputs` in its JSON, a note under its text's table. The
//! tennis ball's record holds a rebound and a static deflection; its peak force and contact
//! time are the model's, and `run --preset tennis` said nothing of it.

use crate::common;

use bouncelab::preset::{Output, Preset};
use common::*;
use serde_json::{Value, json as j};

const TENNIS: &str = include_str!("../../presets/tennis.toml");

fn keys(v: &Value) -> Vec<&str> {
    let list = v["uncalibrated_outputs"].as_array();
    let list = list.unwrap_or_else(|| panic!("no list: {v}"));
    list.iter().map(|k| k.as_str().unwrap()).collect()
}

#[test]
fn the_tennis_run_names_its_peak_force_and_contact_time_as_the_models() {
    let v = json(&argv("run --preset tennis --format json"));
    assert_eq!(
        keys(&v),
        [
            "max_force",
            "contact_time",
            "max_indentation",
            "permanent_indentation"
        ]
    );
    // a fact of every tennis answer, not a warning: `ok` saw an empty stderr
    assert!(warnings(&v).is_empty(), "{v}");
    let text = ok(&argv("run --preset tennis"));
    let note = "  (peak force, contact time, peak indentation and permanent indentation: the \
                model's, not in tennis's record, which holds the COR and static deflection)\n";
    assert!(text.contains(note), "{text}");
}

#[test]
fn the_baseballs_force_plate_vouches_for_its_force_and_contact_time() {
    let v = json(&argv("run --preset baseball --format json"));
    let not = keys(&v);
    assert!(
        !not.contains(&"max_force") && !not.contains(&"contact_time"),
        "{v}"
    );
    assert!(!not.contains(&"cor"), "{v}");
    let text = ok(&argv("run --preset baseball"));
    assert!(
        text.contains("  (peak indentation and permanent indentation: the model's, not in baseball's record, which holds the COR, peak force and contact time)\n"),
        "{text}"
    );
    // volleyball's record measured nothing of an impact
    let v = json(&argv("run --preset volleyball --format json"));
    assert_eq!(keys(&v)[0], "cor", "{v}");
    assert_eq!(keys(&v).len(), 5, "{v}");
    // golf-driver's K_p and c are assumed from a 1.47 m/s fit: its force is the model's
    let v = json(&argv("run --preset golf-driver --v0 45 --format json"));
    assert_eq!(keys(&v)[..2], ["max_force", "contact_time"], "{v}");
}

#[test]
fn a_changed_ball_has_no_output_vouched_for_and_its_warning_says_so() {
    let args = argv("run --preset golf --k-p 2e6 --format json");
    let v: Value = serde_json::from_str(&bl(&args).stdout).unwrap();
    assert_eq!(keys(&v).len(), 5, "{v}");
    assert!(
        outside_calibration(&v)[0].contains("k_p changed the ball"),
        "{v}"
    );
    // the text does not repeat what the warning says
    let text = ok_calibrated(&argv("run --preset golf --k-p 2e6"));
    assert!(!text.contains("the model's, not in"), "{text}");
}

#[test]
fn drop_and_sweep_velocity_name_them_too() {
    let o = bl(&argv("drop --preset tennis --height 2.54 --format json"));
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(keys(&v), ["max_force", "contact_time"], "{v}");
    let o = bl(&argv("drop --preset tennis --height 2.54"));
    assert!(
        o.stdout
            .contains("(peak force and contact time: the model's, not in tennis's record"),
        "{}",
        o.stdout
    );
    let o = bl(&argv(
        "sweep velocity --preset superball --from 3 --to 3.1 --points 2 --format json",
    ));
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(
        keys(&v),
        ["max_indentation", "permanent_indentation"],
        "{v}"
    );
}

#[test]
fn a_record_that_does_not_say_makes_no_claim() {
    let text = TENNIS
        .lines()
        .filter(|l| !l.starts_with("outputs"))
        .collect::<Vec<_>>()
        .join("\n")
        .replace("name = \"tennis\"", "name = \"old-tennis\"");
    let home = config_home(&[("old-tennis.toml", &text)]);
    let o = bl_in(home.path(), &argv("run --preset old-tennis --format json"));
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(v["uncalibrated_outputs"], Value::Null, "{v}");
    let o = bl_in(home.path(), &argv("run --preset old-tennis"));
    assert!(!o.stdout.contains("the model's, not in"), "{}", o.stdout);
    // the normalized ball has no record: nothing either
    let v = json(&argv(
        "run --normalized --lambda 1 --zeta 0.2 --format json",
    ));
    assert_eq!(v["uncalibrated_outputs"], Value::Null, "{v}");
}

#[test]
fn a_bad_outputs_value_is_named_with_file_line_and_column() {
    let text = TENNIS.replacen("outputs = [\"cor\"]", "outputs = [\"cor\", \"peak\"]", 1);
    assert_ne!(text, TENNIS);
    let line = text.lines().position(|l| l.starts_with("outputs")).unwrap() + 1;
    let err = Preset::parse(&text, "t.toml").unwrap_err().to_string();
    assert!(err.starts_with(&format!("t.toml:{line}:")), "{err}");
    assert!(err.contains("unknown variant `peak`"), "{err}");
    assert!(err.contains("calibration.data[0].outputs[1]"), "{err}");
    let text = TENNIS.replacen("outputs = [\"cor\"]", "outputs = [\"cor\", \"cor\"]", 1);
    let err = Preset::parse(&text, "t.toml").unwrap_err().to_string();
    assert!(err.starts_with(&format!("t.toml:{line}:")), "{err}");
    assert!(
        err.contains("calibration.data.outputs: names `cor` twice"),
        "{err}"
    );
}

#[test]
fn every_embedded_record_says_what_its_data_measured() {
    use Output::*;
    let force_plate = vec![Cor, MaxForce, ContactTime];
    for p in Preset::embedded_all() {
        let c = p.calibration.as_ref().unwrap();
        let want = match p.name.as_str() {
            "baseball" | "golf" | "superball" => force_plate.clone(),
            "tennis" | "softball" | "softball-44" => vec![Cor, Deflection],
            "volleyball" => vec![],
            _ => vec![Cor],
        };
        assert_eq!(c.outputs(), Some(want), "{}", p.name);
    }
    let v = json(&argv("presets --format json"));
    let tennis = &named(&v, "tennis")["calibration"]["data"];
    assert_eq!(tennis[0]["outputs"], j!(["cor"]));
    assert_eq!(tennis[1]["outputs"], j!(["deflection_m"]));
}

#[test]
fn fit_save_writes_what_its_data_measured() {
    let home = tempfile::tempdir().unwrap();
    let dir = home.path();
    crate::cli_static::tennis_fit_files(dir);
    std::fs::write(
        dir.join("force.csv"),
        "v0,cor,max_force\n3,0.7718,140\n7,0.7705,320\n11,0.7316,500\n",
    )
    .unwrap();
    let saved = |args: &str, name: &str| {
        ok_at_calibrated(dir, &argv(args));
        let path = dir.join(format!("bouncelab/presets/{name}.toml"));
        std::fs::read_to_string(path).unwrap()
    };
    let toml = saved("fit --preset tennis --cor-table cor.csv --save a", "a");
    assert!(toml.contains("\noutputs = [\"cor\"]\n"), "{toml}");
    let toml = saved("fit --preset tennis --cor-table force.csv --save b", "b");
    assert!(
        toml.contains("\noutputs = [\"cor\", \"max_force\"]\n"),
        "{toml}"
    );
    let toml = saved(
        "fit --preset tennis --cor-table cor.csv --static static.csv --save c",
        "c",
    );
    assert!(toml.contains("\noutputs = [\"cor\"]\n"), "{toml}");
    assert!(toml.contains("\noutputs = [\"deflection_m\"]\n"), "{toml}");
    let toml = saved(
        "fit --preset tennis --free k_r --drop-height 2.54 --rebound-height 1.40 --save d",
        "d",
    );
    assert!(toml.contains("\noutputs = [\"cor\"]\n"), "{toml}");
    // and the saved ball's run says so: its COR is the data's, its force the model's
    let o = bl_at(dir, &argv("run --preset a --v0 7 --format json"));
    let v: Value = serde_json::from_str(&o.stdout).expect(&o.stderr);
    assert_eq!(keys(&v)[..2], ["max_force", "contact_time"], "{v}");
}

/// A force–time trace measures the force over the contact: its peak and the contact time. Its
/// impulse gives a COR only through the impact speed and mass it is told: no COR.
#[test]
fn fit_save_of_a_trace_writes_its_force_and_contact_time() {
    use bouncelab::{SolveOptions, simulate};
    let ball = bouncelab::Ball::from_preset("superball").unwrap();
    let r = simulate(
        &ball.params,
        ball.law,
        &SolveOptions::default().with_samples(4_001),
    )
    .unwrap();
    let (h, tf) = (&r.history, r.contact_time.unwrap());
    let mut rng = crate::fit_common::Rng::new(7);
    let mut text = String::from("time_s,force_N\n");
    for i in 0..600 {
        let t = -5e-4 + i as f64 * 1e-5;
        let force = crate::fit_common::force_at(h, tf, t);
        text.push_str(&format!("{t},{}\n", force + 0.5 * rng.normal()));
    }
    let home = tempfile::tempdir().unwrap();
    let dir = home.path();
    std::fs::write(dir.join("trace.csv"), text).unwrap();
    ok_at_calibrated(
        dir,
        &argv("fit --preset superball --force-time trace.csv --v0 3.12 --save tr"),
    );
    let toml = std::fs::read_to_string(dir.join("bouncelab/presets/tr.toml")).unwrap();
    assert!(
        toml.contains("\noutputs = [\"max_force\", \"contact_time\"]\n"),
        "{toml}"
    );
}
