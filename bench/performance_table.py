#!/usr/bin/env python3
"""Writes docs/performance.md, the project's one table of measured figures, from the benchmark
results in data/bench/: the studies of `bash bench/run` (context.csv, a_trace.csv, b_crossings.csv,
d_nodes.csv, e_s2.csv, f_classify.csv, f_classify_cli.csv), `bash bench/io` (g_io.csv), `bash
bench/io_ab` (h_io_ab.csv: the A build's figures), and performance.csv, the figures of whole
commands and sweeps (timed by bench/median_time.sh; the sweep programs of bench/, bench/explorer.js,
bench/python_speed.py ...) with the date, conditions and command of each. A row of performance.csv
with an anchor gets <a id="ANCHOR"> in the page, so the docs can link to the row itself.

  python3 bench/performance_table.py            # rewrites docs/performance.md
  python3 bench/performance_table.py --check    # exit 1 when docs/performance.md is not what it writes, or when
                                                # README.md or docs/*.md breaks the figure rule of
                                                # bench/doc_figures.py (ctest docs:performance)
"""
import csv
import os
import re
import sys

import doc_figures

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
DATA = os.path.join(ROOT, "data", "bench")
OUT = os.path.join(ROOT, "docs", "performance.md")

SECTIONS = [  # (anchor, title): the order of the table; every row of performance.csv names one
    ("trace", "Trace, files and CAD"), ("startup", "Start-up"), ("plot", "Pictures"),
    ("crossings", "Crossings and classify"), ("io", "Files and pipes"), ("atlas", "Atlas"), ("boundaries", "Boundaries"),
    ("tolerance", "Tolerance"),
    ("identify", "Identify"), ("synth-points", "Precision points"), ("free-axis", "Precision points, free axis"),
    ("fit", "Fit"), ("clinostat", "Clinostats"), ("chain", "Rotation chains"), ("wrist", "Geared wrists"), ("explorer", "Explorer"), ("python", "Python"), ("compile", "Compile time"),
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
    """Rows from the studies of bench/run (their own date: context.csv)."""
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
            spread = f"Google S2 {number(float(s2['s2_seconds']) * 1e3)} ms, {number(s2['s2_over_exact'], 2)}x slower" if s2 else ""
            rows.append(("crossings", f"crossing search of a 1e6-vertex trochoid (n = {r['curve'].replace('_', '/')})",
                         "bash bench/run (b_crossings.csv; e_s2.csv)", number(float(r["seconds"]) * 1e3) + " ms",
                         spread, date, load))
    nodes = {(r["case"], r["method"], r["samples"]): float(r["seconds"]) * 1e3 for r in read("d_nodes.csv")}
    uniform = [nodes.get(("eq39b_44b_n2", "uniform_chords", str(4 ** k)), 0.0) for k in (5, 8, 10)]
    census = [nodes.get((case, "census_newton", "1024"), 0.0) for case in ("eq25_n1", "eq39b_44b_n2")]
    rows.append(("crossings", "node positions by uniform sampling and chord intersection, no refinement (n = 2; N = 2^10 / 2^16 / 2^20)",
                 "bash bench/run (d_nodes.csv)", " / ".join(number(x, 2) for x in uniform) + " ms", "", date, load))
    rows.append(("crossings", "node positions by the census: 1024 samples + Newton (n = 1 / n = 2)", "bash bench/run (d_nodes.csv)",
                 " / ".join(number(x, 2) for x in census) + " ms", "", date, load))
    lib = sorted(float(r["milliseconds"]) for r in read("f_classify.csv"))
    if lib:
        rows.append(("crossings", f"sphtroch::classify in the library ({len(lib)} ratios with p and q <= 5)",
                     "bash bench/run (f_classify.csv)", f"{number(lib[0], 2)}-{number(lib[-1], 2)} ms", "", date, load))
    cli = read("f_classify_cli.csv")
    if cli:
        medians = sorted(float(r["wall_ms_median"]) for r in cli)
        rows.append(("crossings", f"sphtroch classify; whole process ({len(cli)} ratios with p and q <= 5)",
                     "bash bench/run (f_classify_cli.csv)", f"{number(medians[0], 2)}-{number(medians[-1], 2)} ms",
                     "median of 5 runs each", date, load))
    return rows


IO_CASES = {  # g_io.csv's cases: what each measures
    "trace_csv_file": "trace of 1e7 samples to a CSV file", "trace_npy_file": "trace of 1e7 samples to a .npy file",
    "trace_csv_devnull": "trace to CSV into /dev/null (computing and formatting)",
    "trace_npy_devnull": "trace to .npy into /dev/null (computing the points)",
    "trace_csv_1thread_file": "trace to a CSV file with --threads 1", "cat_csv_to_file": "cat of the CSV to a file",
    "cat_npy_to_file": "cat of the .npy to a file", "crossings_csv": "crossings of the CSV", "crossings_npy": "crossings of the .npy",
    "crossings_csv_stdin": "crossings of the CSV through a pipe", "cat_csv_read": "cat of the CSV into /dev/null",
    "cat_npy_read": "cat of the .npy into /dev/null", "crossings_csv_seconds_read": "crossings of the CSV: its seconds_read",
    "crossings_csv_seconds_search": "crossings of the CSV: its seconds_search",
    "crossings_npy_seconds_read": "crossings of the .npy: its seconds_read",
    "crossings_npy_seconds_search": "crossings of the .npy: its seconds_search",
}


def io_rows():
    """Rows from bench/io (g_io.csv: files on the machine's disk) and bench/io_ab (h_io_ab.csv: the A build, files in /dev/shm)."""
    rows = []
    io = read_with_comments("g_io.csv")
    when = io["comments"][-1].lstrip("# ").split(",")[0] if io["comments"] else ""
    conditions = io["comments"][-1].lstrip("# ").split(", ", 1)[1] if io["comments"] else ""
    sizes = dict(re.findall(r"(t\.csv|t\.npy) (\d+) bytes", " ".join(io["comments"])))
    for r in io["rows"]:
        command = re.sub(r"\S*/sphtroch\b", "sphtroch", r["command"])
        what = IO_CASES.get(r["case"], r["case"])
        size = sizes.get("t.csv" if "csv" in r["case"] else "t.npy")
        if size and r["case"] in ("trace_csv_file", "trace_npy_file"):
            what += f" ({float(size) / 1e6:.0f} MB)"
        if r["wall_s_min"]:
            spread = (f"{r['wall_s_min']}-{r['wall_s_max']} s; cpu: user {r['user_s']} s, sys {r['sys_s']} s; "
                      f"{r['peak_rss_mb']} MB peak")
            how = f"whole process; median of {r['runs']} runs; "
        else:
            spread, how = "reported by the tool (median of its runs)", ""
        rows.append(("io", what, "bash bench/io: " + command, r["wall_s_median"] + " s", spread,
                     when, how + conditions))
    ab = read_with_comments("h_io_ab.csv")
    when = ab["comments"][-1].split(",")[0].lstrip("# ")[:10] if ab["comments"] else ""
    for r in ab["rows"]:
        rows.append(("trace" if r["case"].startswith("trace") else "crossings", r["case"].replace("_", " ") + (" (1e6 vertices)" if r["case"].endswith("npy") else " (1e7 samples)"),
                     "A=build/bin/sphtroch BASELINE=... bash bench/io_ab: " + r["command"], r["a_wall_s"] + " s",
                     r["a_rss_mb"] + " MB peak", when, f"whole process; median of {r['pairs']} runs; files in /dev/shm"))
    return rows


def table_rows():
    """Every row: (section, what, command, median, spread, date, conditions, anchor)."""
    rows = [tuple(r[k] or "" for k in ("section", "figure", "command", "median", "spread", "date", "conditions")) + (r.get("anchor") or "",)
            for r in read("performance.csv")]
    known = {s for s, _ in SECTIONS}
    anchors = [r[7] for r in rows if r[7]]
    for r in rows:
        if r[0] not in known:
            sys.exit(f"performance_table: data/bench/performance.csv: section {r[0]!r} is not one of {sorted(known)}")
        if r[7] and (not re.fullmatch(r"[a-z0-9-]+", r[7]) or r[7] in known or anchors.count(r[7]) > 1):
            sys.exit(f"performance_table: data/bench/performance.csv: anchor {r[7]!r}: lower-case letters, digits and -, "
                     "not a section's, once")
    return rows + [r + ("",) for r in bench_run_rows() + io_rows()]


def cell(text):
    return text.replace("|", "\\|")


INTRO = """# Performance

Every figure the project quotes, measured on its 2-core machine (Debian 12, g++ 12, Release),
each with the command that measures it again, its date and the machine's load (the machine is
shared: load above ~1 inflates times). Medians unless the column says otherwise. Generated by
`python3 bench/performance_table.py` from `data/bench/` (columns: data/bench/README.md).

**The rule.** ctest `docs:performance` fails when this page is not what the data give, and when
README.md or a page of docs/ quotes a time, memory or size figure (a number with ms, s, min, KB,
MB, MiB, GB ...) that is neither a figure of this table nor in a sentence that links here; code,
bounds and settings ("at most 16 MiB", "W = 600 s") and the model's own quantities are not
figures (`bench/doc_figures.py` states the rule; ctest `docs:performance_rule` checks that it
fails on a bad page).

**Measuring a row again.** Run its command from the repository root with the Release build's
tools first on PATH (`PATH=$PWD/build/bin:$PATH`; the sweep programs `sphtroch_*_sweep` need
`-DSPHTROCH_BUILD_BENCH=ON`). A whole command is timed by `bash bench/median_time.sh -n N --
COMMAND`: N runs in turn, each under `/usr/bin/time -v` (Debian package `time`); it prints the
median wall time, the fastest and slowest run, the median CPU time and peak RSS, the exit status,
and the load before and after. The inputs the commands name: `pts.csv` (three points) is
`sphtroch trace --n 1/2 --a2 1 --a3 2 --phase 0.3 --samples 40 | sed -n '3p;12p;30p' | cut -d,
-f2-4 | (echo x,y,z; cat)`; `path.csv` (300 points) is `sphtroch trace --n 2 --a2 1.1 --a3 0.9
--phase 0.4 --samples 300 | cut -d, -f2-4`. Put the figures, the date and the load into
`data/bench/performance.csv` (or rerun the study that writes its own CSV) and run `python3
bench/performance_table.py`.
"""


def render():
    rows = table_rows()
    out = INTRO.splitlines() + [""]
    for anchor, title in SECTIONS:
        mine = [r for r in rows if r[0] == anchor]
        if not mine:
            continue
        out += [f'<a id="{anchor}"></a>', f"## {title}", "",
                "| what | median | spread | date | conditions | command |", "|---|---|---|---|---|---|"]
        for _, figure, command, median, spread, date, conditions, row_anchor in mine:
            date = date or read("context.csv")[0]["date"][:10]
            what = (f'<a id="{row_anchor}"></a>' if row_anchor else "") + cell(figure)
            out.append(f"| {what} | {cell(median)} | {cell(spread)} | {date} | {cell(conditions)} | `{cell(command)}` |")
        out.append("")
    return "\n".join(out)


def main():
    text = render()
    if "--check" in sys.argv[1:]:
        current = open(OUT, encoding="utf-8").read() if os.path.exists(OUT) else ""
        if current != text:
            sys.exit("performance_table: docs/performance.md is not what data/bench/ gives; run python3 bench/performance_table.py")
        problems = doc_figures.check(ROOT)
        for p in problems:
            print(p)
        if problems:
            sys.exit(f"performance_table: {len(problems)} figure(s) of README.md and docs/ break the rule of bench/doc_figures.py")
        print("performance_table: docs/performance.md matches data/bench/, and every figure of README.md and docs/ is one of it or cites it")
        return
    with open(OUT, "w", encoding="utf-8") as f:
        f.write(text)


if __name__ == "__main__":
    main()
