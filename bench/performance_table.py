#!/usr/bin/env python3
"""Writes docs/performance.md, the project's one table of measured figures, from the benchmark
results in data/bench/: the studies of `bash bench/run` (context.csv, a_trace.csv, b_crossings.csv,
e_s2.csv, f_classify_cli.csv), `bash bench/io_ab` (h_io_ab.csv: the A build's figures), and performance.csv, the figures of
whole commands and sweeps (the sweep programs of bench/, farm-bench, bench/explorer.js, bench/python_speed.py)
with the date, conditions and command of each.

  python3 bench/performance_table.py            # rewrites docs/performance.md
  python3 bench/performance_table.py --check    # exit 1 when docs/performance.md is not what it writes (ctest docs:performance)
"""
import csv
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
DATA = os.path.join(ROOT, "data", "bench")
OUT = os.path.join(ROOT, "docs", "performance.md")

SECTIONS = [  # (anchor, title): the order of the table; every row of performance.csv names one
    ("trace", "Trace, files and CAD"), ("startup", "Start-up"), ("plot", "Pictures"),
    ("crossings", "Crossings and classify"), ("atlas", "Atlas"), ("boundaries", "Boundaries"),
    ("tolerance", "Tolerance"),
    ("identify", "Identify"), ("synth-points", "Precision points"), ("free-axis", "Precision points, free axis"),
    ("fit", "Fit"), ("clinostat", "Clinostats"), ("chain", "Rotation chains"), ("explorer", "Explorer"), ("python", "Python"), ("compile", "Compile time"),
    ("ci", "Continuous integration"),
]


def read(name):
    with open(os.path.join(DATA, name), newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def read_with_comments(name):
    """A CSV whose trailing lines start with '#': {"rows": [...], "comments": [...]}."""
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        lines = f.read().splitlines()
    comments = [line for line in lines if line.startswith("#")]
    rows = list(csv.DictReader([line for line in lines if not line.startswith("#")]))
    return {"rows": rows, "comments": comments}


def number(x, digits=3):
    return f"{float(x):.{digits}g}"


def bench_run_rows():
    """Rows from the studies of bench/run and bench/io (their own date: context.csv)."""
    ctx = read("context.csv")[0]
    date, load = ctx["date"][:10], f"load {number(ctx['load_avg_1m'], 2)} before the run"
    rows = []
    a = [r for r in read("a_trace.csv") if r["scalar"] == "double" and r["method"] == "direct"]
    if a:
        rows.append(("trace", "one trace point (double; n = 7/3)", "bash bench/run (a_trace.csv)",
                     number(a[0]["ns_per_point"]) + " ns", "max error " + number(a[0]["max_error"], 2), date, load))
    b = read("b_crossings.csv")
    e = {(r["curve"], r["vertices"]): r for r in read("e_s2.csv")}
    for r in b:
        if r["vertices"] == "1000000":
            s2 = e.get((r["curve"], r["vertices"]))
            spread = f"Google S2 {number(s2['s2_over_exact'], 2)}x slower" if s2 else ""
            rows.append(("crossings", f"crossing search of a 1e6-vertex trochoid (n = {r['curve'].replace('_', '/')})",
                         "bash bench/run (b_crossings.csv; e_s2.csv)", number(float(r["seconds"]) * 1e3) + " ms",
                         spread, date, load))
    cli = read("f_classify_cli.csv")
    if cli:
        medians = sorted(float(r["wall_ms_median"]) for r in cli)
        rows.append(("crossings", f"sphtroch classify; whole process ({len(cli)} ratios with p and q <= 5)",
                     "bash bench/run (f_classify_cli.csv)", f"{number(medians[0], 2)}-{number(medians[-1], 2)} ms",
                     "median of 5 runs each", date, load))
    ab = read_with_comments("h_io_ab.csv")
    when = ab["comments"][-1].split(",")[0].lstrip("# ")[:10] if ab["comments"] else date
    for r in ab["rows"]:
        rows.append(("trace" if r["case"].startswith("trace") else "crossings", r["case"].replace("_", " ") + (" (1e6 vertices)" if r["case"].endswith("npy") else " (1e7 samples)"),
                     "A=build/bin/sphtroch BASELINE=... bash bench/io_ab: " + r["command"], r["a_wall_s"] + " s",
                     r["a_rss_mb"] + " MB peak", when, f"whole process; median of {r['pairs']} runs; files in /dev/shm"))
    return rows


def table_rows():
    rows = [tuple(r.values()) for r in read("performance.csv")]
    known = {s for s, _ in SECTIONS}
    for r in rows:
        if r[0] not in known:
            sys.exit(f"performance_table: data/bench/performance.csv: section {r[0]!r} is not one of {sorted(known)}")
    return [r for r in rows if r[3] != "from g_io.csv"] + bench_run_rows()


def cell(text):
    return text.replace("|", "\\|")


def render():
    rows = table_rows()
    out = ["# Performance", "",
           "Every figure the project quotes, measured on its 2-core machine (Debian 12, g++ 12, Release),",
           "each with the command that measures it again, its date and the machine's load (the machine is",
           "shared: load above ~1 inflates times). Medians unless the column says otherwise. Generated by",
           "`python3 bench/performance_table.py` from `data/bench/` (columns: data/bench/README.md); ctest",
           "`docs:performance` fails when this page is not what the data give.", ""]
    for anchor, title in SECTIONS:
        mine = [r for r in rows if r[0] == anchor]
        if not mine:
            continue
        out += [f'<a id="{anchor}"></a>', f"## {title}", "",
                "| what | median | spread | date | conditions | command |", "|---|---|---|---|---|---|"]
        for _, figure, command, median, spread, date, conditions in mine:
            date = date or read("context.csv")[0]["date"][:10]
            out.append(f"| {cell(figure)} | {cell(median)} | {cell(spread)} | {date} | {cell(conditions)} | `{cell(command)}` |")
        out.append("")
    return "\n".join(out)


def main():
    text = render()
    if "--check" in sys.argv[1:]:
        current = open(OUT, encoding="utf-8").read() if os.path.exists(OUT) else ""
        if current != text:
            sys.exit("performance_table: docs/performance.md is not what data/bench/ gives; run python3 bench/performance_table.py")
        print("performance_table: docs/performance.md matches data/bench/")
        return
    with open(OUT, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main()
