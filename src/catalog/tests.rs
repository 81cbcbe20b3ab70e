//! `catalog`'s unit tests: the folder's files, the extra file, bad files skipped, names.

use super::*;

fn write(dir: &Path, file: &str, name: &str) -> PathBuf {
    let text = crate::preset::EMBEDDED[0]
        .1
        .replace("name = \"superball\"", &format!("name = \"{name}\""));
    let path = dir.join(file);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn folder_files_in_name_order_hidden_and_other_files_skipped() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "b.toml", "second");
    write(dir.path(), "a.toml", "first");
    write(dir.path(), ".hidden.toml", "hidden");
    write(dir.path(), "notes.txt", "text");
    std::fs::create_dir(dir.path().join("sub.toml")).unwrap();
    let cat = Catalog::load(Some(dir.path()), None).unwrap();
    let names: Vec<&str> = cat
        .entries()
        .iter()
        .map(|e| e.preset.name.as_str())
        .collect();
    // the embedded balls in their order (pinned by `preset::tests::embedded_presets_parse`),
    // then the folder's in file-name order
    let embedded: Vec<&str> = crate::preset::EMBEDDED.iter().map(|e| e.0).collect();
    let users = ["first", "second"];
    assert_eq!(names, [&embedded[..], &users].concat());
    assert_eq!(
        cat.get("first").unwrap().origin,
        Origin::File(dir.path().join("a.toml"))
    );
    // a missing folder: no user presets
    let none = Catalog::load(Some(&dir.path().join("absent")), None).unwrap();
    assert_eq!(none, Catalog::embedded());
}

#[test]
fn a_bad_folder_file_is_skipped_and_the_error_of_asking_for_it() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "good.toml", "good");
    let bad = write(dir.path(), "golfx.toml", "golf\\u115F");
    let broken = dir.path().join("broken.toml");
    std::fs::write(&broken, "name = \"x\"\n[measured\n").unwrap();
    let cat = Catalog::load(Some(dir.path()), None).unwrap();
    assert!(cat.get("good").is_ok() && cat.get("golf").is_ok());
    let skipped: Vec<&Path> = cat.skipped().iter().map(|s| s.path.as_path()).collect();
    assert_eq!(skipped, [broken.as_path(), bad.as_path()]);
    assert!(cat.skipped()[0].message().contains("broken.toml:2:10:"));
    // asked for by its name field or its file name: its error; any other name: unknown
    let invisible = |e: CatalogError| e.to_string().contains("invisible character");
    assert!(invisible(cat.get("golf\u{115F}").unwrap_err()));
    assert!(invisible(cat.get("golfx").unwrap_err()));
    assert!(matches!(cat.get("x"), Err(CatalogError::Unknown { .. })));
    assert!(matches!(cat.get("broken"), Err(CatalogError::Preset(_))));
    // given as --config: the load's error
    let err = Catalog::load(Some(dir.path()), Some(&bad)).unwrap_err();
    assert!(invisible(err));
}

#[test]
fn extra_file_is_read_once_and_found_by_path() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "mine.toml", "mine");
    let cat = Catalog::load(Some(dir.path()), Some(&p)).unwrap();
    assert_eq!(cat.entries().len(), crate::preset::EMBEDDED.len() + 1);
    assert_eq!(cat.from_file(&p).unwrap().preset.name, "mine");
    let other = tempfile::tempdir().unwrap();
    let q = write(other.path(), "x.toml", "mine");
    let err = Catalog::load(Some(dir.path()), Some(&q)).unwrap_err();
    assert!(matches!(err, CatalogError::Duplicate { .. }), "{err}");
    let msg = err.to_string();
    assert!(msg.contains("mine.toml") && msg.contains("x.toml"), "{msg}");
}

#[test]
fn unknown_names_list_the_catalog() {
    let err = Catalog::embedded().get("cricket").unwrap_err();
    assert_eq!(
        err.to_string(),
        "unknown preset 'cricket' (available: superball, golf, baseball, tennis, football, \
         basketball, table-tennis, softball, baseball-mlb, softball-44, squash, volleyball, \
         golf-driver)"
    );
}
