#!/usr/bin/env python3
"""The figure rule: every measured figure of README.md and docs/*.md (not docs/performance.md
itself, not CHANGELOG.md) is a figure of docs/performance.md's table, or cites the table.

A figure is a number followed by a unit of time, memory or size: ms, s, min, minutes, seconds,
hours, KB, KiB, MB, MiB, GB, GiB ("0.5 s", "~10 s", "3.7–5.0 ms", "1380 KB"; not "Eq. 4", not
"48 ns"). A figure passes when
  (i)  a link to docs/performance.md stands in the same sentence (the text between two ". ", or
       the whole list item, table row or paragraph around it); the link's #anchor must be one of
       the page's; or
  (ii) it equals a figure of the table (the same numbers and unit: "3.7–5.0 ms" equals
       "3.7-5 ms"; "10 ms" does not equal "10.1 ms").
Not figures, and skipped:
  - code: fenced blocks, indented blocks (4 spaces after a blank line), `inline code` — commands,
    options such as `--window 600`, console output: inputs and outputs, not measurements;
  - bounds and settings: a number right after "at most", "at least", "up to", "more than", "less
    than", "limited to", "default", "steps of", "every", "for", "=", "≤", "<", ">" or "M(" (an
    optional "about" or "~" between): "at most 16 MiB", "W = 600 s", "M(600 s)";
  - the lines from a line `<!-- not measured: REASON -->` to the next blank line: quantities of
    the model (a clinostat's periods, windows and times to ε), not of the machine.
Vague words without a number ("takes minutes") are outside the rule: review catches those.

  python3 bench/doc_figures.py [REPO_ROOT]     # exit 1 naming file:line and figure for each that fails
  python3 bench/doc_figures.py --self-test     # the rule on small pages in a temporary directory

bench/performance_table.py --check runs the rule (ctest docs:performance); ctest
docs:performance_rule runs the self-test.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

UNIT = r"(ms|s|min|minutes|seconds|hours|KB|KiB|MB|MiB|GB|GiB)(?![\w/])"
NUMBER = r"\d[\d,]*(?:\.\d+)?"
FIGURE = re.compile(rf"(?<![\w.^/·−-])~?({NUMBER}(?:\s?[–-]\s?{NUMBER})?)[ \u00a0]{UNIT}")
BOUND = re.compile(r"(?:\b(?:at most|at least|up to|more than|less than|limited to|default|steps of|every|for)"
                   r"|[=≤<>]|M\()\s*(?:about\s+|~)?$")
LINK = re.compile(r"\]\(([^)\s]*)\)")
MARKER = re.compile(r"^<!-- not measured: .+ -->$")
SAME_UNIT = {"minutes": "min", "seconds": "s"}


def key(numbers, unit):
    """A figure's identity: its numbers as floats and its unit ("1,380" is 1380)."""
    return tuple(float(x.replace(",", "")) for x in re.findall(NUMBER, numbers)), SAME_UNIT.get(unit, unit)


def table_figures(page):
    """The figures of docs/performance.md's table rows (every cell but the command) and its anchors."""
    figures = set()
    for line in page.splitlines():
        if line.startswith("| ") and not line.startswith("| what |"):
            cells = re.split(r"(?<!\\)\|", line)[1:-2]  # the last cell is the command
            for m in FIGURE.finditer(" | ".join(cells)):
                figures.add(key(m.group(1), m.group(2)))
    return figures, set(re.findall(r'<a id="([\w-]+)"></a>', page))


def blocks(text):
    """The page's prose as blocks: (first line number, [lines]); a block is a paragraph, a list
    item or a table row. Code and the lines a marker covers are left out."""
    out, current, fence, indented, skipping, previous_blank = [], None, False, False, False, True
    for no, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if stripped.startswith(("```", "~~~")):
            fence, current = not fence, None
            continue
        blank = not stripped
        indented = (indented or previous_blank) and line.startswith(("    ", "\t")) if not blank else indented
        previous_blank = blank
        if fence or (indented and not blank):
            current = None
            continue
        if MARKER.match(stripped):
            skipping, current = True, None
            continue
        if blank:
            skipping, current = False, None
            continue
        if skipping:
            continue
        if current is None or stripped.startswith("|") or re.match(r"([-*]|\d+\.) ", stripped) or stripped.startswith("#"):
            current = (no, [])
            out.append(current)
        current[1].append(line)
    return out


def check_page(path, rel, figures, anchors, performance):
    """The problems of one page: 'file:line: ...' for every figure that fails and every bad anchor."""
    problems = []
    for first, lines in blocks(path.read_text(encoding="utf-8")):
        text = " ".join(lines)
        starts = [0]
        for line in lines[:-1]:
            starts.append(starts[-1] + len(line) + 1)
        line_of = lambda pos: first + max(i for i, s in enumerate(starts) if s <= pos)
        # inline code and HTML comments, blanked to keep the offsets
        prose = re.sub(r"`[^`]*`|<!--.*?-->", lambda m: " " * len(m.group(0)), text)
        cites = []
        for m in LINK.finditer(prose):
            target, _, anchor = m.group(1).partition("#")
            if target and (path.parent / target).resolve() == performance.resolve():
                cites.append(m.start())
                if anchor and anchor not in anchors:
                    problems.append(f"{rel}:{line_of(m.start())}: link to docs/performance.md#{anchor}, an anchor the page does not have")
        ends = [m.end() for m in re.finditer(r"[.!?](?=\s)", prose)] + [len(prose)]
        for m in FIGURE.finditer(prose):
            if BOUND.search(prose[max(0, m.start() - 40):m.start()].rstrip()) or key(m.group(1), m.group(2)) in figures:
                continue
            end = min(e for e in ends if e > m.start())
            start = max([e for e in ends if e <= m.start()], default=0)
            if not any(start <= c < end for c in cites):
                problems.append(f"{rel}:{line_of(m.start())}: {m.group(0).strip()!r} is not a figure of docs/performance.md, "
                                "and its sentence has no link to it (the rule: bench/doc_figures.py)")
    return problems


def check(root):
    """Every problem of README.md and docs/*.md against root's docs/performance.md."""
    root = pathlib.Path(root)
    performance = root / "docs" / "performance.md"
    figures, anchors = table_figures(performance.read_text(encoding="utf-8"))
    pages = [root / "README.md"] + sorted(p for p in (root / "docs").glob("*.md") if p.name != "performance.md")
    problems = []
    for page in pages:
        if page.exists():
            problems += check_page(page, page.relative_to(root).as_posix(), figures, anchors, performance)
    return problems


SELF_TEST_TABLE = """# Performance

<a id="clinostat"></a>
## Clinostats

| what | median | spread | date | conditions | command |
|---|---|---|---|---|---|
| a design grid | 6.9 s | cpu 13.6 s; 67 MiB peak | 2026-11-28 | load ~1.4 | `bash bench/median_time.sh -n 5 -- sphtroch clinostat design` |
| whole process | 3.7-5 ms |  | 2026-11-21 |  | `sphtroch classify` |
"""
SELF_TEST_PAGE = """# A page

A grid takes 6.9 s on 2 cores, and a process 3.7–5.0 ms.
Its memory is 12 MiB.
The pairs take 1.4 ms of CPU each ([performance](performance.md#clinostat)). Then 20 s
follow without one.
Budgets: within 2 s, see [the table](performance.md). The targets: 1 s.

```console
$ sphtroch clinostat --window 600   # 0.5 s
```

    sphtroch atlas  # 3 s, indented code

Options `--window 600 s` and Eq. 4 and 48 ns are no figures; at most 16 MiB, W = 600 s, M(600 s),
every 100 ms and the default 1 s are bounds and settings.

<!-- not measured: the model's times -->
| period | 100 min | 90 s / 2192 s |

A wrong anchor: 10 ms ([performance](performance.md#nowhere)).
- a list item: 7 min
  ([performance](performance.md#clinostat)).
- another: 8 min.
"""
SELF_TEST_PAGE_PATH = "/".join(("docs", "page.md"))
SELF_TEST_WANT = [f"{SELF_TEST_PAGE_PATH}:{where}" for where in ("4: '12 MiB'", "5: '20 s'", "7: '1 s'",
                                                               "21: link to docs/performance.md#nowhere", "24: '8 min'")]


def self_test():
    """The rule on a page with known good and bad figures: exactly the bad ones are named, the
    script exits 1 on it and 0 once they are gone. Exit 1 (naming what differs) when not."""
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        (root / "docs").mkdir()
        (root / "docs" / "performance.md").write_text(SELF_TEST_TABLE, encoding="utf-8")
        (root / "README.md").write_text("# Readme\n\nNo figures here but `sleep 1 s`.\n", encoding="utf-8")
        (root / "docs" / "page.md").write_text(SELF_TEST_PAGE, encoding="utf-8")
        got = [p.split(" is not a figure")[0].split(", an anchor")[0] for p in check(root)]
        if got != SELF_TEST_WANT:
            failures.append(f"named {got}, expected {SELF_TEST_WANT}")
        run = lambda: subprocess.run([sys.executable, os.path.abspath(__file__), str(root)], capture_output=True, text=True)
        bad = run()
        if bad.returncode != 1 or len(bad.stdout.splitlines()) != len(SELF_TEST_WANT):
            failures.append(f"on the bad page: exit {bad.returncode} with {len(bad.stdout.splitlines())} lines, expected exit 1 "
                            f"with {len(SELF_TEST_WANT)}")
        (root / "docs" / "page.md").write_text("A grid takes 6.9 s ([performance](performance.md#clinostat)).\n", encoding="utf-8")
        good = run()
        if good.returncode != 0:
            failures.append(f"on a good page: exit {good.returncode}: {good.stdout.strip()}")
    for f in failures:
        print("doc_figures self-test: " + f)
    if failures:
        sys.exit(1)
    print("doc_figures self-test: the rule names exactly the bad figures and anchors")


def main():
    if sys.argv[1:] == ["--self-test"]:
        self_test()
        return
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    problems = check(root)
    for p in problems:
        print(p)
    if problems:
        sys.exit(1)


if __name__ == "__main__":
    main()
