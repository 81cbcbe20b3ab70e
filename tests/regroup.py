#!/usr/bin/env python3
"""Group the integration tests into a few test binaries by area (issue 55 item 3).

Cargo links one test binary for every top-level `tests/*.rs`; 150 of them made a fresh
`cargo test` link for most of a quarter hour on a two-core machine. This script moves each
top-level test file into the folder of its area, `tests/<area>/<name>.rs`, which
`tests/<area>/main.rs` (written here, whole, every run) compiles as one crate with one
module a file. The module keeps the file's name, so `cargo test --test cli_golden` becomes
`cargo test --test cli cli_golden::`.

Run it from anywhere, as often as wanted (it changes nothing the second time):

    python3 tests/regroup.py            # move, fix, write the main.rs files, say what it did
    python3 tests/regroup.py --check    # exit 1 if anything is left to do (CI, after a merge)

What it does, in order:

1. Shared helpers (a folder `tests/<x>/mod.rs`: common, tui_common, fit_common, pty, …) move
   to `tests/support/<x>/`, one place; an area's `main.rs` declares the ones its files use
   (`#[path = "../support/<x>/mod.rs"] mod <x>;`, with the helpers those use) and a file's
   `mod <x>;` becomes `use crate::<x>;` (dropped where the file never names it), a helper's
   too (clippy refuses a file loaded as two modules).
2. Every top-level `tests/<name>.rs` moves to the area the table below gives it (explicit
   names first, then name prefixes; a name in neither goes to `cli` if it runs the binary,
   else to `physics`, and the script says so: add it to AREA_OF to keep it there on
   purpose). Files that must stay a process of their own (a `#[global_allocator]`, or the
   STANDALONE list) stay where they are.
   Moving a file fixes the paths it names relative to itself (`#[path = "…"]`,
   `include_str!`/`include_bytes!`); `env!("CARGO_MANIFEST_DIR")` paths and the working
   directory (the package root) do not change. Its proptest regressions file
   (`<name>.proptest-regressions`) goes with it.
3. insta names a snapshot `<module path>__<name>.snap`, in `snapshots/` beside the source:
   `tests/snapshots/tui_form__form_80x24.snap` becomes
   `tests/tui/snapshots/tui__tui_form__form_80x24.snap`, its content byte for byte (the
   header's `source:` line is metadata insta does not compare).
4. The repository's text names the new places: `tests/<name>.rs` becomes
   `tests/<area>/<name>.rs`, `tests/<helper>/` becomes `tests/support/<helper>/`, and
   `--test <name>` becomes `--test <area> <name>::` (goldens and snapshots untouched).
"""

import os
import re
import shutil
import subprocess
import sys
import textwrap

TESTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(TESTS)
SUPPORT = "support"

# area -> what its binary holds (the main.rs's first line)
AREAS = {
    "cli": "The command line's contract, run through the `bouncelab` binary: subcommands, "
    "goldens, exit codes, bad input, outputs, signals.",
    "tui": "The explorer: `App::update` and the drawn screen (insta snapshots), and the real "
    "binary under a pseudo-terminal.",
    "physics": "The library's physics: closed forms, the solvers, maps, oblique impacts, "
    "drops, flights, peers, targets, standards, the rows Python reads.",
    "analysis": "Fits, their intervals and coverage, Monte Carlo, batches, measured files.",
    "figures": "The SVG figures and their CSV data.",
    "project": "The house rules: ARCHITECTURE.md against the code, the docs' examples run.",
}

# explicit names: checked before the prefixes
AREA_OF = {
    "architecture": "project",
    "docs_examples": "project",
    "measured_explorer": "tui",
    "cli": "cli",
    "escaping": "cli",
    "field_names": "cli",
    "numbers_as_typed": "cli",
    "outputs_regular_only": "cli",
    "signals_early": "cli",
    "session_file": "cli",
    "answer_reach": "cli",
    "answer_warnings": "cli",
    "calibration": "cli",
    "intervals_physical": "analysis",
    "closed_forms": "physics",
    "fuzz_regressions": "physics",
    "hertz_table": "physics",
    "presets": "physics",
    "properties": "physics",
    "solver_agreement": "physics",
    "standards": "physics",
    "target_pair": "physics",
    "figures": "figures",
}

# name prefixes, longest first wins
PREFIXES = {
    "cli_": "cli",
    "tui_": "tui",
    "fit_": "analysis",
    "mc_": "analysis",
    "batch_": "analysis",
    "measured_": "analysis",
    "figure": "figures",
    "map": "physics",
    "oblique": "physics",
    "drop": "physics",
    "flight": "physics",
    "taylor": "physics",
    "peers": "physics",
    "rows": "physics",
    "run_": "physics",
    "surface": "physics",
    "conditions": "physics",
    "shot": "physics",
}

# files that stay a test binary of their own: each is the only thing in its process
STANDALONE = {
    # its #[global_allocator] counts every byte the process allocates
    "fit_memory",
}

# text the references are rewritten in (goldens, snapshots and fuzz inputs are data)
TEXT_EXT = (".rs", ".md", ".py", ".pyi", ".toml", ".sh", ".txt", ".yml", ".yaml")
TEXT_FILES = (".ci/run",)
SKIP_DIRS = {".git", "target", "golden", "snapshots", "regressions", "corpus", "artifacts"}

said = []


def say(msg):
    said.append(msg)
    print(msg)


def rel(path):
    return os.path.relpath(path, ROOT)


def move(src, dst, check):
    say(f"move {rel(src)} -> {rel(dst)}")
    if check:
        return
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    tracked = (
        subprocess.run(
            ["git", "ls-files", "--error-unmatch", src],
            cwd=ROOT,
            capture_output=True,
        ).returncode
        == 0
    )
    if tracked:
        subprocess.run(["git", "mv", "-k", src, dst], cwd=ROOT, check=True)
    if os.path.exists(src):
        shutil.move(src, dst)


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def write(path, text, check):
    if os.path.exists(path) and read(path) == text:
        return
    say(f"write {rel(path)}")
    if not check:
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)


def area_dirs():
    return sorted(
        d
        for d in os.listdir(TESTS)
        if os.path.isfile(os.path.join(TESTS, d, "main.rs")) or d in AREAS
    )


def helper_names():
    """Helpers: folders with a mod.rs, at the top (not moved yet) or under support/."""
    names = set()
    for base in (TESTS, os.path.join(TESTS, SUPPORT)):
        if not os.path.isdir(base):
            continue
        for d in os.listdir(base):
            if d in AREAS or d == SUPPORT:
                continue
            if os.path.isfile(os.path.join(base, d, "mod.rs")) and not os.path.isfile(
                os.path.join(base, d, "main.rs")
            ):
                names.add(d)
    return names


def area_for(stem, text):
    if stem in AREA_OF:
        return AREA_OF[stem], None
    for prefix in sorted(PREFIXES, key=len, reverse=True):
        if stem.startswith(prefix):
            return PREFIXES[prefix], None
    runs_binary = "CARGO_BIN_EXE_bouncelab" in text or re.search(r"^\s*mod common;", text, re.M)
    area = "cli" if runs_binary else "physics"
    return area, (
        f"NOTE tests/{stem}.rs is in no table of tests/regroup.py: it goes to tests/{area}/ "
        f"({'it runs the binary' if runs_binary else 'the default'}); add it to AREA_OF"
    )


def standalone(stem, text):
    return stem in STANDALONE or "#[global_allocator]" in text


def fix_relative_paths(text, old_dir, new_dir, helpers):
    """Paths a file names relative to itself: `#[path = "…"]`, include_str!, include_bytes!
    (a path into a helper's folder follows the helper to support/)."""

    def shift(m):
        p = m.group(2)
        if os.path.isabs(p):
            return m.group(0)
        target = os.path.normpath(os.path.join(old_dir, p))
        inside = os.path.relpath(target, TESTS).split(os.sep)
        if inside[0] in helpers:
            target = os.path.join(TESTS, SUPPORT, *inside)
        moved = os.path.relpath(target, new_dir)
        return m.group(1) + moved.replace(os.sep, "/") + m.group(3)

    text = re.sub(r'(#\[path\s*=\s*")([^"]+)("\])', shift, text)
    return re.sub(r'(include_(?:str|bytes)!\(\s*")([^"]+)(")', shift, text)


def helper_mod_re(helpers):
    names = "|".join(sorted(map(re.escape, helpers))) or "(?!)"
    return re.compile(
        r'^([ \t]*)(?:#\[path\s*=\s*"[^"]*"\][ \t]*\n[ \t]*)?mod (' + names + r");[ \t]*$", re.M
    )


def use_helpers(text, helpers):
    """In an area's file: `mod common;` -> `use crate::common;` (main.rs declares it), or
    nothing where the file never names it (a `mod` line unused was no warning, a `use` is)."""
    names = "|".join(sorted(map(re.escape, helpers))) or "(?!)"
    uses = re.compile(r"^([ \t]*)use crate::(" + names + r");[ \t]*$", re.M)
    for pattern in (helper_mod_re(helpers), uses):

        def to_use(m, src=text):
            rest = strip_comments(src[: m.start()] + src[m.end() :])
            if not re.search(r"(?<![\w:])" + m.group(2) + r"\b", rest):
                return "\0"
            return f"{m.group(1)}use crate::{m.group(2)};"

        text = re.sub(r"\0\n", "", pattern.sub(to_use, text))
    return text


def strip_comments(text):
    return re.sub(r"//[^\n]*", "", text)


def top_level_helpers(text, helpers):
    """In a standalone top-level file: `mod common;` -> its #[path] under support/."""
    return helper_mod_re(helpers).sub(
        lambda m: f'{m.group(1)}#[path = "{SUPPORT}/{m.group(2)}/mod.rs"]\n'
        f"{m.group(1)}mod {m.group(2)};",
        text,
    )


def move_helpers(helpers, check):
    for h in sorted(helpers):
        src = os.path.join(TESTS, h)
        if not os.path.isdir(src):
            continue
        dst = os.path.join(TESTS, SUPPORT, h)
        # a helper's files, one by one: a merge may have left new ones at the old place
        for dirpath, _, files in os.walk(src):
            for f in sorted(files):
                old = os.path.join(dirpath, f)
                new = os.path.join(dst, os.path.relpath(old, src))
                if os.path.exists(new):
                    sys.exit(f"error: both {rel(old)} and {rel(new)} exist: merge them by hand")
                move(old, new, check)
                if f.endswith(".rs") and not check:
                    text = fix_relative_paths(read(new), dirpath, os.path.dirname(new), helpers)
                    write(new, text, check)
        if not check:
            shutil.rmtree(src, ignore_errors=True)


def move_snapshots(stem, area, check):
    """`tests/snapshots/<stem>__x.snap`, and `tests/<area>/snapshots/<stem>__x.snap` (where
    git's rename detection puts a snapshot a merge added at the old place), to
    `tests/<area>/snapshots/<area>__<stem>__x.snap`."""
    for snaps in (os.path.join(TESTS, "snapshots"), os.path.join(TESTS, area, "snapshots")):
        if not os.path.isdir(snaps):
            continue
        for name in sorted(os.listdir(snaps)):
            if name.startswith(stem + "__") and not name.startswith(f"{area}__"):
                dst = os.path.join(TESTS, area, "snapshots", f"{area}__{name}")
                if os.path.exists(dst):
                    sys.exit(f"error: {rel(dst)} exists and so does {rel(snaps)}/{name}")
                move(os.path.join(snaps, name), dst, check)


def move_tests(helpers, check):
    moved = {}
    for name in sorted(os.listdir(TESTS)):
        path = os.path.join(TESTS, name)
        if not name.endswith(".rs") or not os.path.isfile(path):
            continue
        stem = name[:-3]
        text = read(path)
        if standalone(stem, text):
            write(path, top_level_helpers(text, helpers), check)
            continue
        area, note = area_for(stem, text)
        if note:
            say(note)
        dst = os.path.join(TESTS, area, name)
        if os.path.exists(dst):
            sys.exit(f"error: both tests/{name} and {rel(dst)} exist: merge them by hand")
        if stem in ("main", "mod") or stem in helpers or stem == SUPPORT:
            sys.exit(f"error: tests/{name} would clash with a module of tests/{area}/main.rs")
        move(path, dst, check)
        if not check:
            new_dir = os.path.join(TESTS, area)
            write(dst, fix_relative_paths(text, TESTS, new_dir, helpers), check)
        for side in sorted(os.listdir(TESTS)):
            if side.startswith(stem + ".") and side != name:
                move(os.path.join(TESTS, side), os.path.join(TESTS, area, side), check)
        moved[stem] = area
    # snapshots left at the top by a merge, of files moved now or before
    for area in area_dirs():
        adir = os.path.join(TESTS, area)
        if os.path.isdir(adir):
            for f in os.listdir(adir):
                if f.endswith(".rs") and f != "main.rs":
                    move_snapshots(f[:-3], area, check)
    snaps = os.path.join(TESTS, "snapshots")
    if not check and os.path.isdir(snaps) and not os.listdir(snaps):
        os.rmdir(snaps)
    return moved


def main_rs(area, modules, used):
    about = textwrap.wrap(AREAS.get(area, "Integration tests."), 92)
    lines = [f"//! {line}" for line in about] + [
        "//!",
        "//! One test binary, a module a file; tests/regroup.py writes this file (edit its",
        "//! tables, then run it: `python3 tests/regroup.py`).",
        "",
    ]
    for h in sorted(used):
        lines += [f'#[path = "../{SUPPORT}/{h}/mod.rs"]', f"mod {h};"]
    if used:
        lines.append("")
    lines += [f"mod {m};" for m in sorted(modules)]
    return "\n".join(lines) + "\n"


def helper_texts(name):
    for dirpath, _, files in os.walk(os.path.join(TESTS, SUPPORT, name)):
        for f in sorted(files):
            if f.endswith(".rs"):
                yield read(os.path.join(dirpath, f))


def fix_helpers(helpers, check):
    """A helper's `#[path = "../x/mod.rs"] mod x;` of another helper -> `use crate::x;`."""
    for name in sorted(helpers):
        for dirpath, _, files in os.walk(os.path.join(TESTS, SUPPORT, name)):
            for f in sorted(files):
                if f.endswith(".rs"):
                    p = os.path.join(dirpath, f)
                    write(p, use_helpers(read(p), helpers - {name}), check)


def write_areas(helpers, check):
    for area in area_dirs():
        adir = os.path.join(TESTS, area)
        if not os.path.isdir(adir):
            continue
        modules, used = [], set()
        for f in sorted(os.listdir(adir)):
            if not f.endswith(".rs") or f == "main.rs":
                continue
            p = os.path.join(adir, f)
            text = use_helpers(read(p), helpers)
            write(p, text, check)
            modules.append(f[:-3])
            used |= set(re.findall(r"^\s*use crate::(\w+);", text, re.M)) & helpers
        # a helper's own helpers are the area's too: clippy refuses a file loaded as a
        # module twice (`duplicate_mod`), so a helper names another by `use crate::x;`
        todo = sorted(used)
        while todo:
            for text in helper_texts(todo.pop()):
                for dep in set(re.findall(r"^\s*use crate::(\w+);", text, re.M)) & helpers:
                    if dep not in used:
                        used.add(dep)
                        todo.append(dep)
        if modules:
            write(os.path.join(adir, "main.rs"), main_rs(area, modules, used), check)


def located():
    """Where each test module and helper lives now: stem -> 'area/stem.rs'."""
    where = {}
    for area in area_dirs():
        adir = os.path.join(TESTS, area)
        if os.path.isdir(adir):
            for f in os.listdir(adir):
                if f.endswith(".rs") and f != "main.rs":
                    where[f[:-3]] = area
    return where


def rewrite_references(helpers, check):
    where = located()
    if not where and not helpers:
        return
    stems = "|".join(sorted(map(re.escape, where), key=len, reverse=True))
    path_re = re.compile(r"(?<![\w./-])tests/(" + stems + r")\.rs\b")
    # `--test cli` names the area once the files moved: only the other names are rewritten
    names = "|".join(sorted((re.escape(s) for s in where if s not in AREAS), key=len, reverse=True))
    test_re = re.compile(r"--test (" + names + r")(?![\w:])(?!\s+[\w:]+::)")
    helper_re = None
    if helpers:
        names = "|".join(sorted(map(re.escape, helpers), key=len, reverse=True))
        helper_re = re.compile(r"(?<![\w./-])tests/(" + names + r")(?=/|\b)(?!\.rs)")
    for dirpath, dirnames, filenames in os.walk(ROOT):
        dirnames[:] = [
            d
            for d in dirnames
            if d not in SKIP_DIRS and (not d.startswith(".") or rel(os.path.join(dirpath, d)) == ".ci")
        ]
        for f in filenames:
            p = os.path.join(dirpath, f)
            if not (f.endswith(TEXT_EXT) or rel(p) in TEXT_FILES) or p == os.path.abspath(
                __file__
            ):
                continue
            try:
                text = read(p)
            except (UnicodeDecodeError, OSError):
                continue
            new = path_re.sub(lambda m: f"tests/{where[m.group(1)]}/{m.group(1)}.rs", text)
            new = test_re.sub(lambda m: f"--test {where[m.group(1)]} {m.group(1)}::", new)
            if helper_re:
                new = helper_re.sub(lambda m: f"tests/{SUPPORT}/{m.group(1)}", new)
            if new != text:
                write(p, new, check)


def main():
    check = "--check" in sys.argv[1:]
    helpers = helper_names()
    move_helpers(helpers, check)
    moved = move_tests(helpers, check)
    if not check:
        fix_helpers(helpers, check)
    write_areas(helpers, check)
    rewrite_references(helpers, check)
    binaries = [a for a in area_dirs() if os.path.isdir(os.path.join(TESTS, a))]
    alone = [f for f in os.listdir(TESTS) if f.endswith(".rs")]
    print(
        f"{len(moved)} files moved; test binaries: {len(binaries)} areas "
        f"({', '.join(binaries)}) + {len(alone)} standalone ({', '.join(sorted(alone))})"
    )
    if check and said:
        sys.exit("tests/regroup.py has work to do: run it")


if __name__ == "__main__":
    main()
