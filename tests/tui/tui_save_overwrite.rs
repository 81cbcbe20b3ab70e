//! `s` in the explorer when the name is taken: nothing is overwritten before `y` to
//! "overwrite <file>? y/n" (whether the file has the name, holds a preset of that name, or
//! appears after the prompt), and failures are one-line messages that write nothing.

use crate::save_flow;

use bouncelab::catalog::{self, Catalog};
use bouncelab::tui::action::{Action, Mode};
use bouncelab::tui::app::{App, Severity};
use bouncelab::tui::save;
use save_flow::{
    message, perform, press, save_as, save_modified, save_request, superball, take_save, update,
};
use std::fs;
use std::path::Path;

/// The save performed in `dir` finds `path` taken by a preset named `holds`: the explorer
/// asks before replacing it.
fn assert_asks_before_replacing(app: &mut App, dir: &Path, path: &Path, holds: &str) {
    let answer = perform(app, dir);
    assert_eq!(
        answer,
        Action::SaveExists {
            path: path.to_path_buf(),
            holds: Some(holds.into())
        }
    );
    assert_eq!(app.mode(), Mode::Confirm);
}

#[test]
fn an_existing_file_is_replaced_only_after_yes() {
    let dir = tempfile::tempdir().unwrap();
    let (_, path) = save_modified(dir.path(), "mine");
    let first = fs::read(&path).unwrap();

    // the same name again, from other parameters
    let mut app = superball();
    save_as(&mut app, "LLs", "mine");
    assert_asks_before_replacing(&mut app, dir.path(), &path, "mine");
    assert_eq!(
        message(&app),
        ("overwrite mine.toml? y/n".into(), Severity::Warning)
    );
    assert_eq!(fs::read(&path).unwrap(), first, "nothing written yet");
    // other keys do not answer
    press(&mut app, "lq\n");
    assert_eq!(app.mode(), Mode::Confirm);
    assert!(!app.should_quit());

    press(&mut app, "n");
    assert_eq!(app.mode(), Mode::Normal);
    assert!(save_request().is_none());
    assert_eq!(
        message(&app).0,
        format!("not saved: {} left as it was", save::short_path(&path))
    );
    assert_eq!(fs::read(&path).unwrap(), first);

    save_as(&mut app, "s", "mine");
    assert!(matches!(
        perform(&mut app, dir.path()),
        Action::SaveExists { .. }
    ));
    press(&mut app, "y");
    assert_eq!(app.mode(), Mode::Normal);
    assert_eq!(
        save_request().unwrap().replace.as_deref(),
        Some(path.as_path())
    );
    assert_eq!(
        perform(&mut app, dir.path()),
        Action::Saved {
            path: path.clone(),
            replaced: true
        }
    );
    assert!(message(&app).0.ends_with("mine.toml (replaced)"));
    let now = catalog::read_preset_file(&path).unwrap();
    assert_eq!(App::new(now, true).setting().params, app.setting().params);
    let names: Vec<String> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["mine.toml"], "no temporary file left");
}

#[test]
fn a_preset_of_that_name_in_another_file_is_the_one_asked_about() {
    let dir = tempfile::tempdir().unwrap();
    let (_, first) = save_modified(dir.path(), "mine");
    let other = dir.path().join("my-balls.toml");
    fs::rename(&first, &other).unwrap();
    let mut app = superball();
    save_as(&mut app, "s", "mine");
    // not a second file "mine.toml", which would give the catalog two presets "mine"
    assert_eq!(
        perform(&mut app, dir.path()),
        Action::SaveExists {
            path: other.clone(),
            holds: Some("mine".into())
        }
    );
    press(&mut app, "y");
    perform(&mut app, dir.path());
    let cat = Catalog::load(Some(dir.path()), None).expect("still one preset 'mine'");
    assert_eq!(
        cat.get("mine").unwrap().origin,
        catalog::Origin::File(other)
    );
    assert!(!dir.path().join("mine.toml").exists());
}

#[test]
fn a_file_that_appears_after_the_prompt_is_not_clobbered() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    save_as(&mut app, "s", "mine");
    assert!(save_request().is_some());
    // another program writes the name (a preset called otherwise) before the loop gets to it
    let path = dir.path().join("mine.toml");
    let theirs = bouncelab::preset::EMBEDDED[1]
        .1
        .replace("name = \"golf\"", "name = \"theirs\"");
    fs::write(&path, &theirs).unwrap();
    assert_asks_before_replacing(&mut app, dir.path(), &path, "theirs");
    assert_eq!(fs::read_to_string(&path).unwrap(), theirs);
}

#[test]
fn failures_are_one_line_messages_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut app = superball();
    // no folder for user presets at all
    press(&mut app, "s\n");
    let request = take_save().unwrap();
    update(&mut app, save::write(&request, None));
    assert_eq!(
        message(&app),
        (
            "save failed: no folder for user presets: set XDG_CONFIG_HOME or HOME".into(),
            Severity::Error
        )
    );
    // a broken preset in the folder: names cannot be checked, so nothing is written
    fs::write(dir.path().join("broken.toml"), "name = \n").unwrap();
    press(&mut app, "s\n");
    perform(&mut app, dir.path());
    let (text, severity) = message(&app);
    assert_eq!(severity, Severity::Error);
    assert!(
        text.starts_with("save failed: cannot read the user presets (")
            && text.contains("broken.toml:1:")
            && text.ends_with("; nothing saved"),
        "{text}"
    );
    assert!(!text.contains('\n'));
    assert!(!dir.path().join("superball-custom.toml").exists());
    // the "folder" is a file
    let file = dir.path().join("broken.toml");
    press(&mut app, "s\n");
    perform(&mut app, &file);
    let (text, _) = message(&app);
    assert!(text.starts_with("save failed: "), "{text}");
    assert!(!text.contains('\n'));
}

/// The overwrite question keeps its answer line on a narrow screen with a long file name: the
/// box is as tall as its lines wrapped, as the other y/n questions are (it was as tall as its
/// lines unwrapped, so "y replaces it" fell off the box).
#[test]
fn the_overwrite_question_shows_its_answers_when_its_lines_wrap() {
    let long = format!("{}-custom.toml", "a-very-long-ball-name".repeat(3));
    for (w, h) in [(60, 20), (80, 24), (120, 40)] {
        let mut app = superball();
        press(&mut app, "s\n");
        update(
            &mut app,
            Action::SaveExists {
                path: Path::new("/home/user/.config/bouncelab/presets").join(&long),
                holds: Some("old-ball".into()),
            },
        );
        assert_eq!(app.mode(), Mode::Confirm);
        let screen =
            crate::tui_common::buffer_text(crate::tui_common::draw(&app, w, h).backend().buffer());
        assert!(
            screen.contains("y replaces it · n or Esc keeps it"),
            "{w}×{h}: the answers are cut off:\n{screen}"
        );
    }
}
