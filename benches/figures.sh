#!/usr/bin/env bash
# Every speed figure of README.md and docs/, measured in one run, printed as BENCHMARKS.md's
# table (issue 55 item 2): `benches/figures.sh` (release builds, divan's default samples,
# the sizes the table quotes) or
# `benches/figures.sh --quick` (debug builds, three samples, small sizes: a check that every
# row runs, its numbers not to be quoted). The baselines (SciPy, the linear closed form) are
# timed in the same run. The Python rows want the package importable by $PYTHON (default
# python3), e.g. PYTHON=/work/venv-ci/bin/python with the wheel built by maturin; without it
# they say "skipped". The table goes to stdout, the commands run to stderr.
set -euo pipefail
cd "$(dirname "$0")/.."
profile=bench
[[ " $* " == *" --quick "* ]] && profile=dev
export FIGURES_PROFILE="$profile"
# the SciPy baselines run `python3`: $PYTHON's, when it names one (a venv with SciPy)
if [[ -n "${PYTHON:-}" ]]; then
    PATH="$(dirname "$PYTHON"):$PATH"
    export PATH
fi
# the binary, the sweep example and the bench harnesses, built before any clock starts
if [[ "$profile" == dev ]]; then
    cargo build --locked --quiet --bin bouncelab --example sweep_timing
else
    cargo build --locked --quiet --release --bin bouncelab --example sweep_timing
fi
cargo bench --locked --quiet --profile "$profile" --no-run >/dev/null 2>&1 ||
    cargo bench --locked --profile "$profile" --no-run
exec python3 benches/figures.py "$@"
