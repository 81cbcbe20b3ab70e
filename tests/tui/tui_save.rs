//! `s` in the explorer: state → name prompt → save request → file (in a temporary presets
//! folder) → the message in the header; and the saved file loaded back (explorer and
//! `bouncelab run`) with the same λ, ζ, v0 and law. The overwrite question and failures are in
//! `tui_save_overwrite.rs`.

use crate::save_flow;

use bouncelab::ContactLaw;
use bouncelab::catalog::{self, Catalog};
use bouncelab::preset::Preset;
use bouncelab::tui::action::Mode;
use bouncelab::tui::app::{App, Overlay, Purpose, Severity};
use bouncelab::tui::save;
use save_flow::{
    message, perform, press, save_as, save_modified, save_request, state, superball, type_name,
};
use std::fs;

#[test]
fn s_opens_a_prompt_with_a_suggested_name() {
    let mut app = superball();
    press(&mut app, "s");
    assert_eq!(app.mode(), Mode::Input);
    let Overlay::Input(i) = app.overlay() else {
        panic!("no prompt")
    };
    assert_eq!(i.purpose, Purpose::PresetName);
    assert_eq!(i.text, "superball-custom");
    // q, e, s are text here, not commands
    press(&mut app, "qes");
    assert!(!app.should_quit());
    let Overlay::Input(i) = app.overlay() else {
        panic!("no prompt")
    };
    assert_eq!(i.text, "superball-customqes");
    press(&mut app, "\x1b");
    assert_eq!(app.mode(), Mode::Normal);
    assert_eq!(message(&app), ("not saved".into(), Severity::Info));
    assert!(save_request().is_none());
}

#[test]
fn bad_names_are_refused_and_the_prompt_stays_open() {
    let mut app = superball();
    press(&mut app, "s");
    for (name, why) in [
        (
            "my ball",
            "' ' cannot be in a name: use letters, digits, - and _",
        ),
        ("golf", "golf is an embedded preset: choose another name"),
        (
            "../x",
            "'.' cannot be in a name: use letters, digits, - and _",
        ),
        ("", "type a name for the preset"),
    ] {
        type_name(&mut app, name);
        press(&mut app, "\n");
        assert_eq!(app.mode(), Mode::Input, "{name}");
        assert_eq!(message(&app), (why.into(), Severity::Warning));
        let Overlay::Input(i) = app.overlay() else {
            panic!()
        };
        assert_eq!(i.error.as_deref(), Some(why));
        assert!(save_request().is_none(), "nothing to write for {name:?}");
    }
}

#[test]
fn a_saved_preset_loads_back_with_the_same_lambda_zeta_v0_and_law() {
    let dir = tempfile::tempdir().unwrap();
    let presets = dir.path().join("bouncelab").join("presets");
    let (app, path) = save_modified(&presets, "mine");
    assert_eq!(path, presets.join("mine.toml"), "the folder is created");
    assert_eq!(
        message(&app),
        (
            format!("saved preset mine to {}", save::short_path(&path)),
            Severity::Info
        )
    );
    let text = fs::read_to_string(&path).unwrap();
    assert!(
        text.starts_with("# Saved from the bouncelab explorer, from the preset 'superball'."),
        "{text}"
    );
    // in the explorer: bit for bit
    let cat = Catalog::load(Some(&presets), None).expect("the catalog loads");
    let loaded = cat.get("mine").unwrap().preset.clone();
    assert_eq!(loaded.name, "mine");
    let back = App::new(loaded.clone(), true);
    assert_eq!(state(&back), state(&app));
    assert_eq!(back.setting().params, app.setting().params);
    assert_eq!(loaded.law, ContactLaw::ElasticPlastic);
    // the ball is the superball's
    let sb = &app.presets()[0];
    assert_eq!(loaded.measured.mass, sb.measured.mass);
    assert_eq!(loaded.measured.radius, sb.measured.radius);
    assert_eq!(loaded.material, sb.material);

    // and on the command line
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_bouncelab"))
        .args(["run", "--preset", "mine", "--format", "json"])
        .env("XDG_CONFIG_HOME", dir.path())
        .env("HOME", dir.path())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let (lambda, zeta, v0, _) = state(&app);
    let rel = |k: &str, want: f64| {
        let got = json[k].as_f64().unwrap();
        assert!(
            (got - want).abs() <= 1e-12 * want.abs(),
            "{k}: {got} vs {want}"
        );
    };
    rel("lambda", lambda);
    rel("zeta", zeta);
    rel("v0", v0);
    assert_eq!(json["law"], "elastic-plastic");
    assert_eq!(json["origin"], path.display().to_string());
}

#[test]
fn measurements_stay_only_at_the_speed_they_were_taken_at() {
    let dir = tempfile::tempdir().unwrap();
    // λ moved, v0 not: the superball's measurements at 3.12 m/s still apply
    let mut app = superball();
    save_as(&mut app, "ls", "same-speed");
    perform(&mut app, dir.path());
    let same = catalog::read_preset_file(&dir.path().join("same-speed.toml")).unwrap();
    assert_eq!(same.measured, app.presets()[0].measured);

    // v0 moved: cor, peak force and contact time were not measured there
    let (app, path) = save_modified(dir.path(), "faster");
    let p = catalog::read_preset_file(&path).unwrap();
    let sb = &app.presets()[0].measured;
    assert_eq!((p.measured.mass, p.measured.radius), (sb.mass, sb.radius));
    assert_eq!(p.measured.v0, app.setting().params.v0);
    assert_ne!(p.measured.v0, sb.v0);
    assert_eq!(
        (
            p.measured.cor,
            p.measured.max_force,
            p.measured.contact_time
        ),
        (None, None, None)
    );
    let text = fs::read_to_string(&path).unwrap();
    assert!(
        text.contains("were taken at\n# 3.12 m/s, not at 3.62 m/s: left out."),
        "{text}"
    );
}

#[test]
fn a_preset_on_its_materials_set_is_saved_with_that_set_as_adopted() {
    let dir = tempfile::tempdir().unwrap();
    let text = bouncelab::preset::EMBEDDED[2]
        .1
        .replace("name = \"baseball\"", "name = \"mat\"")
        .replace("parameters = \"adopted\"", "parameters = \"materials\"");
    let source = Preset::parse(&text, "mat.toml").unwrap();
    let mut app = App::new(source, true);
    save_as(&mut app, "lzs", "mat2");
    perform(&mut app, dir.path());
    let saved = catalog::read_preset_file(&dir.path().join("mat2.toml")).unwrap();
    assert_eq!(saved.parameters, bouncelab::preset::ParamSource::Adopted);
    let written = fs::read_to_string(dir.path().join("mat2.toml")).unwrap();
    assert!(
        written.contains("# 'mat' ran on the set derived from its material data"),
        "{written}"
    );
    let back = App::new(saved.clone(), true);
    assert_eq!(state(&back), state(&app));
    let (now, then) = (back.setting().params, app.setting().params);
    assert_eq!(
        (now.mass, now.k_p, now.damping, now.k_r, now.z_p, now.v0),
        (
            then.mass,
            then.k_p,
            then.damping,
            then.k_r,
            then.z_p,
            then.v0
        )
    );
    // K_h follows Eq. 16 now instead of the Hertz formula: the same up to rounding
    assert!((now.k_h - then.k_h).abs() <= 1e-12 * then.k_h);

    // saved again from the saved one: the description does not pile up
    let mut again = App::new(saved, true);
    save_as(&mut again, "s", "mat3");
    perform(&mut again, dir.path());
    let third = catalog::read_preset_file(&dir.path().join("mat3.toml")).unwrap();
    assert_eq!(
        third.description.matches("saved from the explorer").count(),
        1
    );
    assert!(
        third
            .description
            .starts_with("Baseball, cork core and leather cover (Cross 1999); "),
        "{}",
        third.description
    );
}

#[test]
fn a_saved_preset_keeps_the_balls_flight_model() {
    // the model its file names (golf-driver's), and the one a user's file gets by its name
    // (`golf` without the field): both written, so that the new name keeps it (docs/flight.md §2)
    let driver = bouncelab::preset::EMBEDDED[12];
    assert_eq!(driver.0, "golf-driver");
    let golf = bouncelab::preset::EMBEDDED[1].1;
    let field = golf
        .lines()
        .find(|l| l.starts_with("aerodynamics"))
        .unwrap();
    let bare = golf.replace(&format!("{field}\n"), "");
    let dir = tempfile::tempdir().unwrap();
    for text in [driver.1, &bare] {
        let source = Preset::parse(text, "x.toml").unwrap();
        let mut app = App::new(source, true);
        save_as(&mut app, "s", "mine");
        perform(&mut app, dir.path());
        let path = dir.path().join("mine.toml");
        let written = fs::read_to_string(&path).unwrap();
        assert!(written.contains("\naerodynamics = \"golf\""), "{written}");
        let saved = catalog::read_preset_file(&path).unwrap();
        assert_eq!(
            saved.flight_model(),
            Some(bouncelab::flight::Published::Golf)
        );
        fs::remove_file(path).unwrap();
    }
}
