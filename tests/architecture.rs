//! The explorer's modules import each other without a cycle: state and `update` below, the
//! widgets and the loop above, so a widget can be read (and changed) without the whole app.
//!
//! The test reads every file of `src/tui`, collects the modules each one names through
//! `use super::…`, `use crate::tui::…` or a path in the code (`super::save::write(..)`), and
//! looks for a cycle among them. Comments (doc links) and test modules (`#[cfg(test)]` to the
//! end of a file) are left out: they are no dependency of the explorer's code.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
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
/// `src/tui/widgets/mod.rs` → `tui::widgets`.
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
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
    for root in ["super::", "crate::tui::"] {
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
/// longest known prefix. `None` for a path outside `src/tui`.
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
        .find(|m| modules.contains(m) && m.starts_with("tui"))
        .filter(|m| m != "tui" || base.len() == 1)
}

/// module → the modules it names.
fn import_graph() -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src.join("tui"), &mut files);
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
fn the_explorer_modules_import_each_other_without_a_cycle() {
    let graph = import_graph();
    assert!(graph.len() > 20, "read the tree: {:?}", graph.keys());
    if let Some(cycle) = find_cycle(&graph) {
        panic!("import cycle in src/tui: {}", cycle.join(" → "));
    }
}
