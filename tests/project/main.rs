//! The house rules: ARCHITECTURE.md against the code, the docs' examples run.
//!
//! One test binary, a module a file; tests/regroup.py writes this file (edit its
//! tables, then run it: `python3 tests/regroup.py`).

mod architecture;
mod docs_examples;
mod speed_figures;
mod string_literals;
