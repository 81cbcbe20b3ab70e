//! The house rules of ARCHITECTURE.md, checked on the source:
//!
//! - no module imports another that imports it back, directly or around a circle (the
//!   explorer's 15-file cycle and the four small ones of `cli::fit`, `cli::figure`,
//!   `figure::explorer` and `figure::svg_map` are gone and stay gone);
//! - imports point down the layers: the command line over the explorer over the figures over
//!   the library, never up (`tui` reading numbers or files through `cli`, say);
//! - a widget draws from a view struct, never from the explorer's whole `App`;
//! - ARCHITECTURE.md names every folder of `src` (and of `src/tui/views`), and every folder
//!   or file it names exists.
//!
//! The import graph: every file of `src` is a module; the modules a file names through `use
//! super::…`, `use crate::…` or a path in the code (`super::save::write(..)`) are its edges. A
//! module's own children named bare (`mod plot; … plot::svg(..)`) are below it by
//! construction, so they are no edge: a folder's `mod.rs` may own the shared types its files
//! import and call those files. Comments (doc links) and test code (`#[cfg(test)]` to the end
//! of a file, `tests.rs` files) are left out: they are no dependency of the program.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
pub(crate) fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module a file is: `src/tui/app/dialogs.rs` → `tui::app::dialogs`,
/// `src/tui/widgets/mod.rs` → `tui::widgets`; `src/lib.rs` → the root, "".
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") || parts == ["lib"] {
        parts.pop();
    }
    parts.join("::")
}

/// `use a::{b, c::{d, e}};` → `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        return vec![tree];
    };
    let (prefix, rest) = tree.split_at(open);
    let inner = &rest[1..rest.len() - 1];
    let (mut parts, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.is_empty())
        .flat_map(|p| expand(&format!("{prefix}{p}")))
        .collect()
}

/// Paths named in `code`: the trees of its `use` items, and `super::…` / `crate::tui::…` paths
/// written inline.
fn named_paths(code: &str) -> Vec<String> {
    let mut paths = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("use ") {
        let before = rest[..i].chars().last();
        let after = &rest[i + 4..];
        rest = after;
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_') {
            continue;
        }
        if let Some(end) = after.find(';') {
            let tree = after[..end].split(" as ").next().unwrap_or("");
            paths.extend(expand(tree));
        }
    }
    for root in ["super::", "crate::"] {
        let mut rest = code;
        while let Some(i) = rest.find(root) {
            let tail = &rest[i..];
            let end = tail
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(tail.len());
            paths.push(tail[..end].trim_end_matches(':').to_string());
            rest = &tail[root.len()..];
        }
    }
    paths
}

/// The module of `modules` a path names from inside `module`: `super` resolved, then the
/// longest known prefix. `None` for a path that names no module but the crate's root (whose
/// re-exports are the library's front door, not a layer).
fn target(module: &str, path: &str, modules: &BTreeSet<String>) -> Option<String> {
    let mut parts: Vec<&str> = path.split("::").collect();
    let mut base: Vec<&str> = module.split("::").collect();
    if parts.first() == Some(&"crate") {
        parts.remove(0);
        base.clear();
    } else if parts.first() == Some(&"super") {
        // `super` in `x.rs` and in `x/mod.rs` alike names x's parent
        while parts.first() == Some(&"super") {
            parts.remove(0);
            base.pop();
        }
    } else {
        return None;
    }
    base.extend(parts);
    (1..=base.len())
        .rev()
        .map(|n| base[..n].join("::"))
        .find(|m| modules.contains(m))
}

/// module → the modules it names.
fn import_graph() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    // the binary (`main.rs`) is outside the library; a `tests.rs` is a test module
    files.retain(|f| {
        let name = f.file_name().unwrap().to_string_lossy();
        f != &src.join("main.rs") && name != "tests.rs" && !name.ends_with("_tests.rs")
    });
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(&src, f)).collect();
    let mut graph = BTreeMap::new();
    for file in &files {
        let module = module_of(&src, file);
        let text = fs::read_to_string(file).unwrap();
        let code: String = text
            .split("#[cfg(test)]")
            .next()
            .unwrap_or("")
            .lines()
            .map(|l| l.split("//").next().unwrap_or(""))
            .collect::<Vec<_>>()
            .join("\n");
        let named: BTreeSet<String> = named_paths(&code)
            .iter()
            .filter_map(|p| target(&module, p, &modules))
            .filter(|t| *t != module)
            .collect();
        graph.insert(module, named);
    }
    graph
}

/// A cycle through the graph, as the modules on it, if there is one.
fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        m: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = stack.iter().position(|s| s == m) {
            let mut cycle = stack[i..].to_vec();
            cycle.push(m.to_string());
            return Some(cycle);
        }
        if done.contains(m) {
            return None;
        }
        stack.push(m.to_string());
        for next in graph.get(m).into_iter().flatten() {
            if let Some(c) = visit(next, graph, stack, done) {
                return Some(c);
            }
        }
        stack.pop();
        done.insert(m.to_string());
        None
    }
    let (mut stack, mut done) = (Vec::new(), BTreeSet::new());
    graph
        .keys()
        .find_map(|m| visit(m, graph, &mut stack, &mut done))
}

#[test]
fn the_parser_sees_use_trees_and_inline_paths() {
    let code = "use super::{app::App, widgets::{plot, status}};\nuse crate::tui::save;\n\
                fn f() { super::export::write(x); crate::tui::format::sig(1.0, 2); }";
    let paths = named_paths(code);
    for want in [
        "super::app::App",
        "super::widgets::plot",
        "super::widgets::status",
        "crate::tui::save",
        "super::export::write",
        "crate::tui::format::sig",
    ] {
        assert!(paths.iter().any(|p| p == want), "{want} in {paths:?}");
    }
    let modules: BTreeSet<String> = ["tui", "tui::app", "tui::app::dialogs", "tui::save"]
        .map(String::from)
        .into();
    let t = |m, p| target(m, p, &modules);
    assert_eq!(
        t("tui::app::dialogs", "super::App").as_deref(),
        Some("tui::app")
    );
    assert_eq!(
        t("tui::app", "super::save::write").as_deref(),
        Some("tui::save")
    );
    assert_eq!(t("tui::app", "crate::model::params").as_deref(), None);
    let cyclic = BTreeMap::from([
        ("a".to_string(), BTreeSet::from(["b".to_string()])),
        ("b".to_string(), BTreeSet::from(["a".to_string()])),
    ]);
    assert!(find_cycle(&cyclic).is_some());
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = import_graph();
    assert!(graph.len() > 150, "read the tree: {:?}", graph.keys());
    // the graph sees the arrows this test is about
    for (from, to) in [
        ("cli::fit::multi", "cli::fit::save"),
        ("cli::fit::save", "cli::fit"),
        ("tui::views::map::update", "tui::views::map::state"),
    ] {
        assert!(graph[from].contains(to), "{from} → {to}: {:?}", graph[from]);
    }
    if let Some(cycle) = find_cycle(&graph) {
        panic!("import cycle in src: {}", cycle.join(" → "));
    }
}

/// The layer of a module, by its top folder: the command line over the explorer over the
/// figures over the library (everything else, physics and plain data, is the bottom).
fn layer(module: &str) -> u8 {
    match module.split("::").next().unwrap_or("") {
        "cli" => 3,
        "tui" => 2,
        "figure" => 1,
        _ => 0,
    }
}

/// Every edge that points up a layer, as "from → to".
fn upward(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    graph
        .iter()
        .flat_map(|(from, tos)| tos.iter().map(move |to| (from, to)))
        .filter(|(from, to)| layer(to) > layer(from))
        .map(|(from, to)| format!("{from} → {to}"))
        .collect()
}

#[test]
fn imports_point_down_the_layers() {
    let up = [("tui::app::form", "cli::number")];
    let fake: BTreeMap<String, BTreeSet<String>> = up
        .iter()
        .map(|(a, b)| (a.to_string(), BTreeSet::from([b.to_string()])))
        .collect();
    assert_eq!(upward(&fake), ["tui::app::form → cli::number"]);
    let graph = import_graph();
    assert!(graph["tui::views::map::export"].contains("map::csv"));
    let up = upward(&graph);
    assert!(up.is_empty(), "imports up a layer:\n{}", up.join("\n"));
}

/// Whether `code` names the explorer's `App` (as a word, in code, not in comments).
fn names_app(code: &str) -> bool {
    code.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .flat_map(|l| l.split(|c: char| !(c.is_alphanumeric() || c == '_')))
        .any(|w| w == "App")
}

#[test]
fn widgets_draw_from_view_structs_not_the_app() {
    assert!(names_app("fn render(app: &App, area: Rect)"));
    assert!(!names_app(
        "/// reads `App::help_scroll`\nstruct Help { scroll: u16 }"
    ));
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/tui");
    let mut files = Vec::new();
    rust_files(&src.join("widgets"), &mut files);
    rust_files(&src.join("views"), &mut files);
    // in a view's folder, the widgets are `widget.rs` and the raster `cells.rs`
    files.retain(|f| {
        !f.starts_with(src.join("views")) || f.ends_with("widget.rs") || f.ends_with("cells.rs")
    });
    assert!(files.len() > 15, "{files:?}");
    for f in files {
        let text = fs::read_to_string(&f).unwrap();
        let code = text.split("#[cfg(test)]").next().unwrap_or("");
        assert!(!names_app(code), "{} takes the whole App", f.display());
    }
}

/// The `src/…` paths ARCHITECTURE.md names in backticks (placeholders such as
/// `src/tui/views/<view>/` left out).
fn named_in(doc: &str) -> BTreeSet<String> {
    doc.split('`')
        .skip(1)
        .step_by(2)
        .filter(|s| s.starts_with("src/") && !s.contains('<') && !s.contains(' '))
        .map(String::from)
        .collect()
}

/// The folders directly under `dir`, as `src/…/` paths.
fn folders(root: &Path, dir: &str) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(root.join(dir))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .map(|p| format!("{}/", p.strip_prefix(root).unwrap().display()))
        .collect();
    v.sort();
    v
}

#[test]
fn architecture_md_names_every_folder_and_only_what_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = fs::read_to_string(root.join("ARCHITECTURE.md")).unwrap();
    let named = named_in(&doc);
    assert!(
        named_in("`src/a/` and `src/tui/views/<view>/`, `cargo test`") == ["src/a/".into()].into()
    );
    for path in &named {
        assert!(
            root.join(path).exists(),
            "ARCHITECTURE.md names {path}, which does not exist"
        );
    }
    let mut wanted = folders(root, "src");
    wanted.extend(folders(root, "src/tui/views"));
    assert!(wanted.len() > 15, "{wanted:?}");
    for folder in wanted {
        assert!(
            named.contains(&folder),
            "ARCHITECTURE.md does not name {folder}: say what it owns and may import"
        );
    }
}
