#!/usr/bin/env python3
"""Every speed figure of README.md and docs/, measured in one run and printed as
BENCHMARKS.md's table (issue 55 item 2). Run it through `benches/figures.sh`, which builds
what it needs first; `--quick` runs every row at a small size and few samples (a check that
the script works, not figures to quote).

The baselines are timed in the same run: the linear closed form (`linear_fast_summary`, the
yardstick row) and SciPy (`scipy_ratio`, `benches/fit_scipy.py` inside `cargo bench --bench
fit`, the SciPy side of `benches/impacts_python.py`). Each row is (what, how it is measured,
a function that runs it and returns the figure); a row whose tool is missing (SciPy, the
Python package) says "skipped: why" in its figure column rather than stopping the table.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
QUICK = "--quick" in sys.argv[1:]
PROFILE = os.environ.get("FIGURES_PROFILE", "dev" if QUICK else "bench")
PYTHON = os.environ.get("PYTHON", sys.executable or "python3")
TARGET = os.environ.get("CARGO_TARGET_DIR") or json.loads(
    subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--no-deps"],
        cwd=ROOT,
        capture_output=True,
        check=True,
        text=True,
    ).stdout
)["target_directory"]
BIN = os.path.join(TARGET, "debug" if PROFILE == "dev" else "release", "bouncelab")
# divan's samples: its defaults in a full run, three of one iteration in a quick one
DIVAN = ["--sample-count", "3", "--sample-size", "1"] if QUICK else []
if QUICK:
    os.environ["BENCH_QUICK"] = "1"  # the hand-timed harnesses (fit, scipy_ratio): runs cut
UNITS = {"ns": 1e-9, "µs": 1e-6, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def run(argv, env=None, cwd=ROOT):
    log("$ " + " ".join(argv))
    e = dict(os.environ, **(env or {}))
    p = subprocess.run(argv, cwd=cwd, env=e, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"{argv[0]} exited {p.returncode}: {p.stderr.strip()[-300:]}")
    return p.stdout + p.stderr


_divan_cache = {}


# the benchmarks each harness runs for the table (the rest of a harness is left out)
FILTERS = {
    "solver": ["linear_fast_summary", "linear_impact_summary", "flattening_cells_lanes",
               "flattening_one_summary", "table_hertz_summary", "elastic_plastic_summary",
               "elastic_plastic_past_yield_256", "elastic_plastic_impact",
               "cor_zeta_sweep_4x400"],
    "map": ["fast_summary_grid_lanes"],
    "keystroke": ["keystroke_total"],
    "map_view": ["full_detail_"],
    "peers": ["hunt_crossley_impact", "exact_calibration"],
    "oblique": ["oblique_impact", "normal_impact"],
    "oblique_map": ["compute"],
    "shot": ["shot_one_bounce", "flights_alone"],
}


def divan(bench, env=None):
    """Medians (s) of one divan harness, by `name` and `name/arg`; run once per bench."""
    key = (bench, tuple(sorted((env or {}).items())))
    if key not in _divan_cache:
        out = run(["cargo", "bench", "--quiet", "--profile", PROFILE, "--bench", bench, "--"]
                  + DIVAN + FILTERS.get(bench, []), env)
        _divan_cache[key] = parse_divan(out)
    return _divan_cache[key]


def parse_divan(text):
    """divan's tree: `├─ name  fastest │ slowest │ median │ …`, args one level down."""
    medians, stack = {}, []
    for line in text.splitlines():
        m = re.match(r"^([│├╰─ ]*)(\S.*)$", line)
        if not m or "│" not in line:
            continue
        depth = len(m.group(1)) // 3
        cols = m.group(2).split("│")
        head = re.match(r"^(.*?)\s+([\d.]+ (?:ns|µs|us|ms|s))?\s*$", cols[0])
        name = head.group(1).strip() if head else cols[0].strip()
        stack[depth:] = [name]
        if head and head.group(2) and len(cols) >= 3:
            v, unit = cols[2].split()
            medians["/".join(stack[1:] if len(stack) > 1 else stack)] = float(v) * UNITS[unit]
    return medians


def us(s, digits=2):
    return f"{s * 1e6:.{digits}f} µs"


def ms(s, digits=1):
    return f"{s * 1e3:.{digits}f} ms"


def timed(argv, env=None):
    """A command's CPU time (user + system) and peak resident memory (MB), its own
    (`wait4`'s rusage of that child alone)."""
    log("$ " + " ".join(argv))
    p = subprocess.Popen(argv, cwd=ROOT, env=dict(os.environ, **(env or {})),
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    if p.returncode != 0:
        raise RuntimeError(f"exit {p.returncode}: {' '.join(argv[:3])} …")
    return usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def python_ok():
    p = subprocess.run([PYTHON, "-c", "import bouncelab, numpy"], capture_output=True)
    return p.returncode == 0


def py(args, env=None):
    if not python_ok():
        raise RuntimeError(f"skipped: `{PYTHON} -c 'import bouncelab'` fails (PYTHON=…)")
    return run([PYTHON] + args, env)


# ---- the rows ----------------------------------------------------------------------------

def yardstick():
    return us(divan("solver")["linear_fast_summary"])


def solver_row(*names, per=1, digits=2):
    """`names`' medians, each divided by `per` (a number, or one a name: the impacts an
    iteration runs)."""
    pers = per if isinstance(per, tuple) else (per,) * len(names)

    def row():
        d = divan("solver")
        return " / ".join(us(d[n] / k, digits) for n, k in zip(names, pers))
    return row


def lanes_map():
    d = divan("map", {"RAYON_NUM_THREADS": "1"})
    return us(d["fast_summary_grid_lanes"] / (200 * 120), 3) + " an impact"


def scipy_ratio():
    out = run(["cargo", "bench", "--quiet", "--profile", PROFILE, "--bench", "scipy_ratio"])
    ours = re.search(r"median ([\d.]+) ms", out)
    if "skipped" in out:
        return "skipped: " + out.strip().splitlines()[-1]
    ratio = re.search(r"ratio \(scipy / bouncelab\): (\d+)x", out).group(1)
    return f"{ratio} × (bouncelab {ours.group(1)} ms)"


def keystroke():
    d = divan("keystroke")
    totals = [v for k, v in d.items() if k.startswith("keystroke_total/")]
    return f"{ms(min(totals), 2)}–{ms(max(totals), 2)}" if totals else "no keystroke_total"


def map_view():
    d = divan("map_view")
    names = ["full_detail_tennis", "full_detail_hertz", "full_detail_elastic_plastic"]
    return " / ".join(ms(d[n], 2) for n in names)


def hertz_map_cli():
    size = "20" if QUICK else "200"
    cpu, _ = timed([BIN, "map", "--preset", "tennis", "--law", "hertz", "--lambda",
                    f"0.01:100:{size}", "--zeta", "0.01:100:120"])
    return f"{cpu:.2f} s CPU" + (" (20 × 120)" if QUICK else "")


def reproduce_cli():
    with tempfile.TemporaryDirectory() as out:
        cpu, mb = timed([BIN, "reproduce", "--out", out])
    return f"{cpu:.2f} s CPU, {mb:.0f} MB"


_fit_out = []


def fit_bench():
    if not _fit_out:
        _fit_out.append(run(["cargo", "bench", "--quiet", "--profile", PROFILE,
                             "--bench", "fit"]))
    return _fit_out[0]


def fit_vs_scipy():
    out = fit_bench()
    ours = re.search(r"2000 samples: median ([\d.]+) ms", out).group(1)
    scipy = re.search(r"median_s ([\d.]+)", out)
    if not scipy:
        return f"{ours} ms / SciPy skipped"
    s = float(scipy.group(1))
    return f"{ours} ms / {s:.2f} s: {s / (float(ours) / 1e3):.0f} ×"


def dense_fit():
    out = fit_bench()
    rows = re.findall(r"dense trace, (\d+) rows: parse median ([\d.]+) ms, fit median ([\d.]+)"
                      r" ms.*?peak memory of the process so far (\d+ kB)", out)
    by = {int(r[0]): r for r in rows}
    a, b = by[10_000], by[999_999]
    return f"{a[1]} + {a[2]} ms / {b[1]} ms + {b[2]} ms, {int(b[3].split()[0]) / 1e3:.1f} MB"


def million_row_cli():
    rows = 10_000 if QUICK else 1_000_000
    hist = run([BIN, "run", "--preset", "tennis", "--v0", "3", "--history", "--format", "csv"])
    pts = [tuple(map(float, line.split(",")[:2])) for line in hist.splitlines()
           if re.match(r"^[\d.eE+-]+,", line)]
    t_end = pts[-1][0]
    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
        f.write("time_s,force_N\n")
        j = 0
        for i in range(rows):
            t = t_end * i / (rows - 1)
            while j + 1 < len(pts) - 1 and pts[j + 1][0] < t:
                j += 1
            (t0, f0), (t1, f1) = pts[j], pts[j + 1]
            w = 0.0 if t1 == t0 else (t - t0) / (t1 - t0)
            f.write(f"{t:.9g},{f0 + w * (f1 - f0):.9g}\n")
    try:
        cpu, mb = timed([BIN, "fit", "--preset", "tennis", "--v0", "3", "--force-time", f.name])
    finally:
        os.unlink(f.name)
    return f"{cpu:.2f} s CPU, {mb:.0f} MB" + (f" ({rows} rows)" if QUICK else "")


def peers():
    d = divan("peers")
    hc = d["hunt_crossley_impact"]
    cal = [v for k, v in d.items() if k.startswith("exact_calibration/")]
    return f"{us(hc, 1)} / {us(min(cal), 0)}–{us(max(cal), 0)}"


def oblique():
    d = divan("oblique")
    o, n = d["oblique_impact"], d["normal_impact"]
    return f"{us(o, 1)}, {o / n:.1f} × the normal impact"


def oblique_map():
    return ms(divan("oblique_map", {"RAYON_NUM_THREADS": "1"})["compute"], 0)


def shot():
    d = divan("shot")
    return f"{us(d['shot_one_bounce'], 1)} / {us(d['flights_alone'], 1)}"


def mc_shot_cli():
    n = "10000" if QUICK else "1000000"
    cpu, mb = timed([BIN, "mc", "--shot", "--preset", "tennis", "--height", "2.8", "--speed",
                     "50", "--elevation", "-6", "--spin", "200", "--friction", "0.6",
                     "--vary", "speed=2%,spin=30", "--samples", n],
                    {"RAYON_NUM_THREADS": "1"})
    return f"{cpu:.1f} s CPU, {mb:.0f} MB" + (f" ({n} shots)" if QUICK else "")


def mc_cli():
    n = "100000" if QUICK else "10000000"
    cpu, mb = timed([BIN, "mc", "--preset", "golf", "--vary", "k_p=5%,c=5%,k_r=5%", "--samples",
                     n, "--seed", "1", "--format", "json"], {"RAYON_NUM_THREADS": "1"})
    return f"{cpu:.2f} s, {mb:.0f} MB" + (f" ({n} samples)" if QUICK else "")


def mc_past_yield_cli():
    n = "5000" if QUICK else "500000"
    cpu, _ = timed([BIN, "mc", "--preset", "superball", "--law", "elastic-plastic", "--v0", "9.4",
                    "--vary", "k_p=5%,c=5%,k_r=5%", "--samples", n, "--seed", "1", "--format",
                    "json"],
                   {"RAYON_NUM_THREADS": "1"})
    return f"{cpu:.2f} s CPU" + (f" ({n} samples)" if QUICK else "")


_calls = []


def python_calls():
    if not _calls:
        _calls.append(py(["benches/impacts_python.py", "calls"], {"RAYON_NUM_THREADS": "1"}))
    return _calls[0]


def py_run_history():
    out = py(["-c", "import time, bouncelab\n"
              "n = 200 if __import__('sys').argv[1:] else 2000\n"
              "t = time.process_time()\n"
              "for _ in range(n): bouncelab.run(preset='golf', history=True)\n"
              "print((time.process_time() - t) / n)"] + (["q"] if QUICK else []))
    return us(float(out.split()[-1]), 0) + " CPU"


def py_run_calls():
    out = python_calls()
    golf = re.search(r"run\(preset='golf'\): ([\d.]+) µs", out).group(1)
    tennis = re.search(r"run\(preset='tennis'\): ([\d.]+) µs", out).group(1)
    return f"{golf} µs / {tennis} µs"


def py_impacts():
    out = py(["benches/impacts_python.py"], {"RAYON_NUM_THREADS": "1"})
    ns = re.search(r"(\d+) ns per impact", out).group(1)
    scipy = re.search(r"(\d[\d,.]*) ?× .*SciPy|SciPy.*?(\d[\d,.]*) ?×", out)
    return f"{int(ns) / 1e3:.2f} µs an element" + (f"; SciPy {scipy.group(0)}" if scipy else "")


def py_past():
    out = py(["benches/impacts_python.py", "past"])
    # "…: 1.061 µs wall per element (1.753 µs CPU)" (benches/impacts_python.py)
    m = re.search(r"([\d.]+ (?:ns|µs)) wall per element \(([\d.]+ (?:ns|µs)) CPU\)", out)
    return f"{m.group(1)} wall an element ({m.group(2)} CPU)"


def py_sweep():
    exe = os.path.join(TARGET, "debug" if PROFILE == "dev" else "release", "examples",
                       "sweep_timing")
    out = py(["python/examples/sweep_timing.py", exe])
    r = re.search(r"rust\s+([\d.]+) ms", out).group(1)
    p = re.search(r"python\s+([\d.]+) ms", out).group(1)
    ratio = re.search(r"python / rust = ([\d.]+)", out).group(1)
    return f"{p} ms / {r} ms: {ratio} ×"


ROWS = [
    ("one linear impact, closed form, summary (the yardstick)", yardstick,
     "cargo bench --bench solver -- linear_fast_summary"),
    ("one linear impact by the exact solver, summary", solver_row("linear_impact_summary"),
     "cargo bench --bench solver -- linear_impact_summary"),
    ("one impact with its history, from Python (`run(history=True)`)", py_run_history,
     "benches/figures.sh (python: run(preset='golf', history=True))"),
    ("linear impacts in lanes (200 × 120 map, one core)", lanes_map,
     "RAYON_NUM_THREADS=1 cargo bench --bench map -- fast_summary_grid_lanes"),
    ("a flattening cell, in lanes / alone",
     solver_row("flattening_cells_lanes", "flattening_one_summary", per=(1024, 1), digits=3),
     "cargo bench --bench solver -- flattening_cells_lanes flattening_one_summary"),
    ("a Hertz impact (the table)", solver_row("table_hertz_summary/0"),
     "cargo bench --bench solver -- table_hertz_summary"),
    ("elastic–plastic, below yield", solver_row("elastic_plastic_summary/0"),
     "cargo bench --bench solver -- elastic_plastic_summary"),
    ("elastic–plastic past yield, 256 batched / one by one, an impact",
     solver_row("elastic_plastic_past_yield_256/batch", "elastic_plastic_past_yield_256/single",
                per=256),
     "cargo bench --bench solver -- elastic_plastic_past_yield_256"),
    ("one elastic–fully-plastic impact by the adaptive solver, rtol 1e-9",
     solver_row("elastic_plastic_impact", digits=1),
     "cargo bench --bench solver -- elastic_plastic_impact"),
    ("4 × 400-point COR-against-ζ sweep",
     lambda: ms(divan("solver")["cor_zeta_sweep_4x400"], 2),
     "cargo bench --bench solver -- cor_zeta_sweep_4x400"),
    ("the same sweep, SciPy `solve_ivp` (RK45, rtol 1e-10) / bouncelab, same run", scipy_ratio,
     "cargo bench --bench scipy_ratio"),
    ("one key in the explorer, update and draw at 200 × 60", keystroke,
     "cargo bench --bench keystroke -- keystroke_total"),
    ("the explorer's map at full detail (tennis / Hertz / elastic–plastic)", map_view,
     "cargo bench --bench map_view -- full_detail"),
    ("tennis map under Hertz from the command line, 200 × 120", hertz_map_cli,
     "/usr/bin/time bouncelab map --preset tennis --law hertz --lambda 0.01:100:200 "
     "--zeta 0.01:100:120"),
    ("`reproduce`, the paper's 29 files (SVG, CSV and the report)", reproduce_cli,
     "/usr/bin/time bouncelab reproduce --out DIR"),
    ("a 3-parameter fit to a 2 000-sample force trace / SciPy `least_squares`", fit_vs_scipy,
     "cargo bench --bench fit"),
    ("dense traces: 10⁴ rows / 10⁶ rows, parse + fit", dense_fit, "cargo bench --bench fit"),
    ("the 10⁶-row fit from the command line", million_row_cli,
     "/usr/bin/time -v bouncelab fit --preset tennis --v0 3 --force-time FILE"),
    ("a Hunt–Crossley impact with its peaks / an exact peer calibration", peers,
     "cargo bench --bench peers"),
    ("an oblique impact, linear law (tennis, 25 m/s at 16°, 300 rad/s)", oblique,
     "cargo bench --bench oblique -- oblique_impact normal_impact"),
    ("the explorer's (angle, μ) map, 90 × 50, one core", oblique_map,
     "RAYON_NUM_THREADS=1 cargo bench --bench oblique_map -- compute"),
    ("one shot with one bounce (tennis serve) / its two flights alone", shot,
     "cargo bench --bench shot"),
    ("10⁶ shots in `mc --shot`, one core", mc_shot_cli,
     "RAYON_NUM_THREADS=1 /usr/bin/time bouncelab mc --shot --preset tennis --height 2.8 "
     "--speed 50 --elevation -6 --spin 200 --friction 0.6 --vary speed=2%,spin=30 "
     "--samples 1000000"),
    ("10⁷ linear Monte Carlo samples, one core", mc_cli,
     "RAYON_NUM_THREADS=1 /usr/bin/time bouncelab mc --preset golf --vary k_p=5%,c=5%,k_r=5% "
     "--samples 10000000 --seed 1 --format json"),
    ("5·10⁵ superball samples past yield, one core", mc_past_yield_cli,
     "RAYON_NUM_THREADS=1 /usr/bin/time bouncelab mc --preset superball --law elastic-plastic "
     "--v0 9.4 --vary k_p=5%,c=5%,k_r=5% --samples 500000 --seed 1 --format json"),
    ("`bouncelab.impacts`, 10⁶ linear elements, one thread (SciPy side by side)", py_impacts,
     "RAYON_NUM_THREADS=1 python benches/impacts_python.py"),
    ("`bouncelab.impacts` past yield, both cores", py_past,
     "python benches/impacts_python.py past"),
    ("`run(preset='golf')` / `'tennis'` from Python, one call", py_run_calls,
     "RAYON_NUM_THREADS=1 python benches/impacts_python.py calls"),
    ("`sweep_zeta`, 10⁵ points, from Python / in Rust", py_sweep,
     "python python/examples/sweep_timing.py"),
]


def main():
    started = time.time()
    load = os.getloadavg()[0]
    lines = ["| what | figure | command |", "|---|---|---|"]
    for what, row, command in ROWS:
        try:
            figure = row()
        except Exception as e:  # a row that cannot run says why; the table goes on
            msg = str(e).splitlines()[0] if str(e) else type(e).__name__
            figure = msg if msg.startswith("skipped") else f"failed: {msg}"
        log(f"  {what}: {figure}")
        lines.append(f"| {what} | {figure} | `{command}` |")
    cpu = subprocess.run(["sh", "-c", "lscpu | sed -n 's/^Model name: *//p'"],
                         capture_output=True, text=True).stdout.strip()
    print(f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} on {cpu or '?'}, "
          f"{os.cpu_count()} cores, load average {load:.1f} at the start, "
          f"profile {PROFILE}{' (--quick: small sizes, not figures to quote)' if QUICK else ''}, "
          f"{time.time() - started:.0f} s in all.\n")
    print("\n".join(lines))


if __name__ == "__main__":
    if shutil.which("cargo") is None:
        sys.exit("cargo is not on PATH")
    main()
