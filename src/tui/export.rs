//! `e` in the explorer: each chart of the current view as an SVG picture and its series as
//! CSV, `bouncelab-<ball>-<chart>-<n>.svg` / `.csv`, in the current directory or in
//! `$BOUNCELAB_EXPORT_DIR`.
//!
//! The figures are the ones on screen ([`crate::figure::explorer`]), built from the curves the
//! state already holds — nothing is re-solved. `App::update` stays free of side effects: it
//! builds an [`ExportRequest`] with [`request`] (pure) and returns it as an effect; the event
//! loop hands it to [`write()`], the only part that touches the file system, and reports back
//! with `Action::Exported` or `Action::ExportFailed`; [`message`] is what the header then
//! says.
//!
//! Never overwriting: `<n>` is the first number for which none of the export's files exists,
//! and every file is created with "create new", so a file that appears in between is not
//! clobbered either (the export then moves on to the next `<n>`).

use crate::figure::explorer::{self, Chart, Scene};
use crate::figure::{Figure, csv, svg};
use crate::text::io_text;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// Where exports go when set (and not empty); the current directory otherwise. Created, with
/// its parents, when missing.
pub const DIR_ENV: &str = "BOUNCELAB_EXPORT_DIR";

/// Numbers tried for `<n>` before giving up.
const MAX_N: usize = 99_999;

/// What an export writes: one figure per chart of the view.
#[derive(Debug, Clone, PartialEq)]
pub struct ExportRequest {
    /// The ball's name as it appears in file names (see [`file_stem_part`]).
    pub ball: String,
    /// (chart name in file names, its figure), in screen order.
    pub charts: Vec<(&'static str, Figure)>,
    /// The map view's map, after the charts (none in the other views).
    pub map: Option<crate::tui::views::map::export::MapExport>,
    /// `#` lines each CSV file starts with (the `bouncelab run` line and the parameters).
    pub header: Vec<String>,
}

impl ExportRequest {
    /// The export of `ball`'s `charts` (and the map view's `map`), their CSV files headed by
    /// `header`; the files named after the ball ([`file_stem_part`]).
    pub fn of(
        ball: &str,
        charts: Vec<(&'static str, Figure)>,
        map: Option<crate::tui::views::map::export::MapExport>,
        header: Vec<String>,
    ) -> ExportRequest {
        ExportRequest {
            ball: file_stem_part(ball),
            charts,
            map,
            header,
        }
    }

    /// The request with `lines` (each starting with `#`) heading its CSV files.
    pub fn with_header(mut self, lines: Vec<String>) -> ExportRequest {
        self.header = lines;
        self
    }

    /// The files of export number `n` in `dir`: per chart its `.svg`, then its `.csv`.
    pub fn paths(&self, dir: &Path, n: usize) -> Vec<PathBuf> {
        let map = self.map.iter().map(|m| m.file_name());
        self.charts
            .iter()
            .map(|(chart, _)| chart.to_string())
            .chain(map)
            .flat_map(|chart| {
                let stem = format!("bouncelab-{}-{chart}-{n}", self.ball);
                ["svg", "csv"].map(|ext| dir.join(format!("{stem}.{ext}")))
            })
            .collect()
    }
}

/// Whether `c` is safe in a file name the explorer writes (and so in a saved preset's name,
/// its file's stem): an ASCII letter or digit, `_` or `-`.
pub fn file_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '-'
}

/// A ball's name made safe for a file name: the [`file_name_char`]s are kept, anything else
/// (spaces, `/`, accents) becomes `-`.
pub fn file_stem_part(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| if file_name_char(c) { c } else { '-' })
        .collect();
    if s.is_empty() { "ball".into() } else { s }
}

/// The export of `charts`, built from `scene` exactly as the screen draws them. An error when
/// one of them has nothing to draw (its computation failed, or its sweep is still out).
pub fn request(scene: &Scene, charts: &[Chart]) -> Result<ExportRequest, String> {
    let charts = charts
        .iter()
        .map(|&chart| match explorer::missing(chart, scene) {
            Some(what) => Err(format!("no {what} to export (it could not be computed)")),
            None => Ok((chart.file_name(), explorer::figure(chart, scene))),
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(ExportRequest::of(
        &scene.ball.name,
        charts,
        None,
        Vec::new(),
    ))
}

/// A view's `answer` as its export takes it, or why there is none: "export failed: no
/// `what` (why)" when it could not be computed, "export failed: no `what` yet" before it is.
pub fn computed<'a, T>(answer: &'a Option<Result<T, String>>, what: &str) -> Result<&'a T, String> {
    match answer {
        Some(Ok(a)) => Ok(a),
        Some(Err(e)) => Err(format!("export failed: no {what} ({e})")),
        None => Err(format!("export failed: no {what} yet")),
    }
}

/// The export directory: `$BOUNCELAB_EXPORT_DIR` when set and not empty, else `.`.
pub fn dir_from_env() -> PathBuf {
    dir_from(std::env::var_os(DIR_ENV))
}

/// The export directory for a value of `$BOUNCELAB_EXPORT_DIR`.
pub fn dir_from(value: Option<std::ffi::OsString>) -> PathBuf {
    match value {
        Some(d) if !d.is_empty() => PathBuf::from(d),
        _ => PathBuf::from("."),
    }
}

/// Whether anything (a file, a folder, a dangling link) has this name.
fn taken(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok()
}

/// Write the export into `dir` (created when missing) under the first `<n>` none of whose
/// files exists; returns the files written. All or nothing: on an error the files this call
/// created are removed again. Every picture is rendered before the first file is created.
pub fn write(request: &ExportRequest, dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut contents = Vec::new();
    let head: String = request.header.iter().map(|l| format!("{l}\n")).collect();
    for (_, fig) in &request.charts {
        contents.push(svg::render(fig).map_err(|e| e.to_string())?);
        contents.push(head.clone() + &csv::to_string(fig));
    }
    if let Some(m) = &request.map {
        let (svg, csv) = m.render()?;
        contents.extend([svg, head.clone() + &csv]);
    }
    if !dir.as_os_str().is_empty() && !dir.is_dir() {
        fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {}", dir.display(), io_text(&e)))?;
    }
    for n in 1..=MAX_N {
        let paths = request.paths(dir, n);
        if paths.iter().any(|p| taken(p)) {
            continue;
        }
        match create_all(&paths, &contents) {
            Ok(()) => return Ok(paths),
            // another program took one of the names in between: try the next number
            Err((_, e)) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err((path, e)) => {
                return Err(format!("cannot write {}: {}", path.display(), io_text(&e)));
            }
        }
    }
    Err(format!(
        "every number up to {MAX_N} is taken in {}",
        dir.display()
    ))
}

/// Create each path new with its text, all or none (each file a temporary renamed into place,
/// see [`crate::atomic`]): an error leaves no file of this export behind.
fn create_all(paths: &[PathBuf], contents: &[String]) -> Result<(), (PathBuf, io::Error)> {
    let mut files = crate::atomic::Outputs::new(false);
    for (path, text) in paths.iter().zip(contents) {
        files.text(path, text).map_err(|e| (e.path, e.error))?;
    }
    files.commit().map(drop).map_err(|e| (e.path, e.error))
}

/// A folder for the header line: as given when short, else its last two parts after `…/`.
pub fn short_dir(dir: &Path) -> String {
    let full = dir.display().to_string();
    if full.chars().count() <= 32 {
        return full;
    }
    let parts: Vec<String> = dir
        .components()
        .rev()
        .take(2)
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    format!(
        "…/{}",
        parts.into_iter().rev().collect::<Vec<_>>().join("/")
    )
}

/// What the header says after an export: the file names, shortened to a pattern when there
/// are several charts, e.g. `exported bouncelab-superball-*-1.svg/.csv (3 charts)`, and the
/// folder when it is not the current one.
pub fn message(files: &[PathBuf]) -> String {
    let name = |p: &PathBuf| {
        p.file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let mut stems: Vec<String> = Vec::new();
    let mut exts: Vec<String> = Vec::new();
    for f in files {
        let n = name(f);
        let (stem, ext) = n.rsplit_once('.').unwrap_or((&n, ""));
        if !stems.iter().any(|s| s == stem) {
            stems.push(stem.to_string());
        }
        if !exts.iter().any(|e| e == ext) {
            exts.push(ext.to_string());
        }
    }
    let exts = exts
        .iter()
        .map(|e| format!(".{e}"))
        .collect::<Vec<_>>()
        .join("/");
    let names = match stems.as_slice() {
        [] => return "nothing exported".into(),
        [one] => format!("{one}{exts}"),
        many => {
            let pattern = pattern(many);
            format!("{pattern}{exts} ({} charts)", many.len())
        }
    };
    let dir = files[0].parent().filter(|d| {
        let s = d.as_os_str();
        !s.is_empty() && s != "."
    });
    match dir {
        Some(d) => format!("exported {names} in {}", short_dir(d)),
        None => format!("exported {names}"),
    }
}

/// `a-x-1`, `a-y-1` → `a-*-1`: the common start and end, cut at a `-`.
fn pattern(stems: &[String]) -> String {
    let first = &stems[0];
    let mut head = first.len();
    let mut tail = first.len();
    for s in &stems[1..] {
        head = head.min(common_prefix(first, s));
        tail = tail.min(common_prefix(&rev(first), &rev(s)));
    }
    let head = first[..head].rfind('-').map_or(0, |i| i + 1);
    let tail_start = first.len() - tail;
    let tail_start = first[tail_start..]
        .find('-')
        .map_or(first.len(), |i| tail_start + i);
    if head >= tail_start {
        return first.clone();
    }
    format!("{}*{}", &first[..head], &first[tail_start..])
}

fn rev(s: &str) -> String {
    s.chars().rev().collect()
}

/// Length in bytes of the common start of `a` and `b`, on a character boundary.
fn common_prefix(a: &str, b: &str) -> usize {
    a.chars()
        .zip(b.chars())
        .take_while(|(x, y)| x == y)
        .map(|(x, _)| x.len_utf8())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_are_safe() {
        assert_eq!(file_stem_part("superball"), "superball");
        assert_eq!(file_stem_part("my golf/ball"), "my-golf-ball");
        assert_eq!(file_stem_part("bälle"), "b-lle");
        assert_eq!(file_stem_part(""), "ball");
    }

    #[test]
    fn message_shortens_to_a_pattern() {
        let f = |names: &[&str]| names.iter().map(PathBuf::from).collect::<Vec<_>>();
        let files = f(&[
            "./bouncelab-superball-force-time-1.svg",
            "./bouncelab-superball-force-time-1.csv",
            "./bouncelab-superball-force-displacement-1.svg",
            "./bouncelab-superball-force-displacement-1.csv",
            "./bouncelab-superball-cor-zeta-1.svg",
            "./bouncelab-superball-cor-zeta-1.csv",
        ]);
        assert_eq!(
            message(&files),
            "exported bouncelab-superball-*-1.svg/.csv (3 charts)"
        );
        let files = f(&["out/bouncelab-golf-cor-zeta-12.svg"]);
        assert_eq!(
            message(&files),
            "exported bouncelab-golf-cor-zeta-12.svg in out"
        );
        let files = f(&[
            "/a/very/long/path/to/some/exports/folder/bouncelab-golf-force-zeta-2.svg",
            "/a/very/long/path/to/some/exports/folder/bouncelab-golf-cor-velocity-2.svg",
        ]);
        assert_eq!(
            message(&files),
            "exported bouncelab-golf-*-2.svg (2 charts) in …/exports/folder"
        );
    }

    #[test]
    fn a_name_taken_in_between_is_not_clobbered_and_the_attempt_is_undone() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.svg"), dir.path().join("b.csv"));
        fs::write(&b, "someone else's").unwrap();
        let err = create_all(&[a.clone(), b.clone()], &["1".into(), "2".into()]).unwrap_err();
        assert_eq!(err.0, b);
        assert_eq!(err.1.kind(), io::ErrorKind::AlreadyExists);
        assert!(!a.exists(), "what this attempt created is removed");
        assert_eq!(fs::read_to_string(&b).unwrap(), "someone else's");
    }

    #[test]
    fn pattern_cuts_at_dashes() {
        let s = |v: &[&str]| v.iter().map(|x| x.to_string()).collect::<Vec<_>>();
        assert_eq!(
            pattern(&s(&["b-g-force-zeta-2", "b-g-cor-zeta-2"])),
            "b-g-*-zeta-2"
        );
        assert_eq!(pattern(&s(&["b-x-1", "b-y-1"])), "b-*-1");
    }
}
