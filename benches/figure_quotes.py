#!/usr/bin/env python3
"""Where README.md and docs/*.md quote BENCHMARKS.md's current table, and whether they still
say what it says (issue 55 item 2; tests/project/speed_figures.rs is the guard).

A page quotes a figure as a link to the table: `[23.1 µs][bench]` with
`[bench]: ../BENCHMARKS.md#the-current-table` under the page (`BENCHMARKS.md#…` from the
README), or an inline link. A quote stands for a run of whole figures of one row's figure
cell (`3.61 µs`, or `1.02 ms–12.13 ms`); the row is the first whose cell holds it.

  figure_quotes.py --list           every quote: page:line, its text, the row it is from
  figure_quotes.py --check [TABLE]  the quotes not in TABLE's figure column (default:
                                    BENCHMARKS.md's table); exit 1 if any
  figure_quotes.py --update NEW     NEW is what `benches/figures.sh` printed (the
                                    "Measured …" line and the table): BENCHMARKS.md's table
                                    becomes NEW's, and each quote becomes the same figures
                                    of the same row in NEW; what cannot be carried is listed
                                    (exit 1)
"""

import glob
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ANCHOR = "BENCHMARKS.md#the-current-table"
# a number and its unit (tests/project/speed_figures.rs's UNITS), a × before a number excluded
FIGURE = re.compile(r"(?<![\w.\-])\d+(?:\.\d+)? ?"
                    r"(?:core-seconds|minutes|seconds|min|µs|ns|ms|MB|s|×)(?![\w])(?!\s*\d)")
LINK = re.compile(r"\[([^\[\]]+)\](?:\(([^()\s]+)\)|\[([^\[\]]+)\])")


def pages():
    return [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))


def table_rows(text):
    """(what, figure cell) of each row of a table, the first `| what | figure |` table in text."""
    rows = []
    for line in text.splitlines():
        if line.startswith("|") and not line.startswith(("|---", "| what |")):
            cells = line.split("|")
            rows.append((cells[1].strip(), cells[2].strip()))
        elif rows and not line.startswith("|"):
            break
    return rows


def current_section(text):
    """BENCHMARKS.md's "The current table" section: (start, end) of its "Measured" line and
    table."""
    head = text.index("\n## The current table\n")
    start = text.index("\nMeasured ", head) + 1
    end = text.index("\n\n", text.index("\n|", start) + 1) + 1
    return start, end


def quotes():
    """(page, line, start, end, text) of every link to the table whose text holds a figure."""
    out = []
    for page in pages():
        text = open(page, encoding="utf-8").read()
        target = ANCHOR if page.endswith("README.md") else "../" + ANCHOR
        labels = {m.group(1) for m in re.finditer(r"^\[([^\]]+)\]: *(\S+)$", text, re.M)
                  if m.group(2) == target}
        for m in LINK.finditer(text):
            if (m.group(2) == target or m.group(3) in labels) and FIGURE.search(m.group(1)):
                line = text.count("\n", 0, m.start()) + 1
                out.append((page, line, m.start(1), m.end(1), m.group(1)))
    return out


def find_all(rows, quoted):
    """Every (row index, first figure, last figure) where the quote is a run of whole figures
    of a row's cell."""
    hits = []
    for i, (_, cell) in enumerate(rows):
        spans = [m.span() for m in FIGURE.finditer(cell)]
        for at in [m.start() for m in re.finditer(re.escape(quoted), cell)]:
            first = [k for k, s in enumerate(spans) if s[0] == at]
            last = [k for k, s in enumerate(spans) if s[1] == at + len(quoted)]
            if first and last:
                hits.append((i, first[0], last[0]))
    return hits


def find(rows, quoted):
    hits = find_all(rows, quoted)
    return hits[0] if hits else None


def carry_one(old_rows, new_rows, hit):
    """The figures of one place of the old table in the new one, or None and why not."""
    i, a, b = hit
    what = old_rows[i][0]
    new = dict(new_rows).get(what)
    if new is None:
        return None, f"row “{what}” is not in the new table"
    spans = [m.span() for m in FIGURE.finditer(new)]
    old_count = len(list(FIGURE.finditer(old_rows[i][1])))
    if len(spans) != old_count:
        return None, f"row “{what}” has {len(spans)} figures now, {old_count} before: {new}"
    return new[spans[a][0]:spans[b][1]], what


def carry(old_rows, new_rows, quoted):
    """The quote's figures in the new table, or None and why not. A quote that two rows hold
    is carried only where both carry it to the same figures (else: fix it by hand)."""
    hits = find_all(old_rows, quoted)
    if not hits:
        return None, "not in the current table"
    carried = [carry_one(old_rows, new_rows, h) for h in hits]
    if any(c[0] is None for c in carried):
        return next(c for c in carried if c[0] is None)
    if len({c[0] for c in carried}) > 1:
        rows = "; ".join(f"“{why}”: {fig}" for fig, why in carried)
        return None, f"in {len(hits)} rows, which now differ ({rows}): which one by hand"
    return carried[0]


def rel(page):
    return os.path.relpath(page, ROOT)


def main(argv):
    bench = os.path.join(ROOT, "BENCHMARKS.md")
    text = open(bench, encoding="utf-8").read()
    start, end = current_section(text)
    rows = table_rows(text[start:end])
    if argv[:1] == ["--list"]:
        for page, line, _, _, quoted in quotes():
            hit = find(rows, quoted)
            row = f"“{rows[hit[0]][0]}”" if hit else "NOT IN THE TABLE"
            print(f"{rel(page)}:{line}: {quoted} — {row}")
        return 0
    if argv[:1] == ["--check"]:
        other = table_rows(open(argv[1], encoding="utf-8").read()) if len(argv) > 1 else rows
        bad = [(p, n, q) for p, n, _, _, q in quotes() if find(other, q) is None]
        for page, line, quoted in bad:
            print(f"{rel(page)}:{line}: {quoted} is not in the table")
        return 1 if bad else 0
    if argv[:1] == ["--update"] and len(argv) == 2:
        return update(argv[1], bench, text, start, end, rows)
    print(__doc__, file=sys.stderr)
    return 2


def update(new_file, bench, text, start, end, rows):
    new_text = open(new_file, encoding="utf-8").read()
    measured = new_text[new_text.index("Measured "):]
    new_rows = table_rows(measured)
    edits, problems = {}, []
    for page, line, s, e, quoted in quotes():
        figure, why = carry(rows, new_rows, quoted)
        if figure is None:
            problems.append(f"{rel(page)}:{line}: {quoted}: {why}")
        elif figure != quoted:
            edits.setdefault(page, []).append((s, e, figure))
            print(f"{rel(page)}:{line}: {quoted} → {figure} (“{why}”)")
    for page, spans in edits.items():
        body = open(page, encoding="utf-8").read()
        for s, e, figure in sorted(spans, reverse=True):
            body = body[:s] + figure + body[e:]
        open(page, "w", encoding="utf-8").write(body)
    block = measured.strip("\n") + "\n"
    cpu = re.compile(r"^Measured .*? on (.*?), \d+ cores")
    old_cpu, new_cpu = cpu.search(text[start:end]), cpu.search(block)
    if old_cpu and new_cpu and old_cpu.group(1) != new_cpu.group(1):
        problems.append(f"the processor is {new_cpu.group(1)} now, {old_cpu.group(1)} "
                        "before: say so in BENCHMARKS.md's “The machine” and README's "
                        "“Speed on …”")
    open(bench, "w", encoding="utf-8").write(text[:start] + block + text[end:])
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
