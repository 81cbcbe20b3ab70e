//! Replays the committed fuzz corpus (`fuzz/regressions/<target>/`) through the checks the fuzz
//! targets run (`fuzz/src/checks.rs`, shared by `#[path]`), on the stable toolchain: every
//! crash the fuzzers found, and a few inputs that reach far into the code, stay fixed.

#[path = "../../fuzz/src/checks.rs"]
mod checks;

use std::path::{Path, PathBuf};

fn inputs(target: &str) -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz/regressions")
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no inputs in {}", dir.display());
    files
}

/// Run `check` on every input of `target`, each under `catch_unwind`, and fail naming every
/// input that failed (not only the first).
fn replay(target: &str, check: fn(&[u8])) {
    let mut failed = Vec::new();
    let files = inputs(target);
    for path in &files {
        let data = std::fs::read(path).unwrap();
        if std::panic::catch_unwind(|| check(&data)).is_err() {
            failed.push(path.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    assert!(
        failed.is_empty(),
        "{} of {} {target} inputs fail their checks: {failed:?}",
        failed.len(),
        files.len()
    );
}

#[test]
fn preset_toml_regressions() {
    replay("preset_toml", checks::check_preset_bytes);
}

#[test]
fn solver_inputs_regressions() {
    replay("solver_inputs", checks::check_solver_bytes);
}
