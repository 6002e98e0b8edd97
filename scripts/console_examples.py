#!/usr/bin/env python3
"""Runs the console examples of README.md and docs/*.md and compares their output (ctest
docs:console_examples), so that the documentation cannot go stale.

  python3 scripts/console_examples.py SPHTROCH_EXE [REPO_ROOT]

A console example is a ```console block. Each line starting with "$ " is a command, run by bash
in a fresh temporary directory per block (commands of one block share it; `data/` there is the
repository's data/, and `sphtroch` on PATH is SPHTROCH_EXE); the lines after it, up to the next
command, are its expected output (stdout and stderr together). Matching is line by line, with
  - a line "..." in the document: any number of output lines (also none);
  - a line ending in " ..." in the document: an output line that starts with the rest;
  - measured times masked on both sides: JSON "seconds*" values, "N s" figures, "time: ..." lines.
Exit 1 naming the document, the line and the first difference; 0 when every example matches.
"""
import os
import pathlib
import re
import subprocess
import sys
import tempfile

MASKS = [
    (re.compile(r'("seconds[a-z_]*": ?)[-0-9.e+]+'), r"\1T"),
    (re.compile(r"\b\d+(?:\.\d+)?(?:e[-+]?\d+)? s\b"), "T s"),
    (re.compile(r"^time: .*$"), "time: T"),
]


def mask(line):
    for pattern, replacement in MASKS:
        line = pattern.sub(replacement, line)
    return line.rstrip()


def blocks(path):
    """(first line number, [(command line number, command, expected lines)]) of each console block."""
    lines = path.read_text(encoding="utf-8").splitlines()
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```console":
            start, i, runs = i + 1, i + 1, []
            while i < len(lines) and lines[i].strip() != "```":
                if lines[i].startswith("$ "):
                    runs.append((i + 1, lines[i][2:], []))
                elif runs:
                    runs[-1][2].append(lines[i])
                i += 1
            yield start, runs
        i += 1


def matches(expected, actual):
    """Whether the output lines match the expected ones (see the module doc)."""
    if not expected:
        return not actual
    head = expected[0]
    if head.strip() == "...":
        return any(matches(expected[1:], actual[k:]) for k in range(len(actual) + 1))
    if not actual:
        return False
    if head.endswith(" ..."):
        ok = mask(actual[0]).startswith(mask(head[:-4]))
    else:
        ok = mask(actual[0]) == mask(head)
    return ok and matches(expected[1:], actual[1:])


def first_difference(expected, actual):
    for k, e in enumerate(expected):
        if e.strip() == "...":
            return "(after a '...' line)"
        a = actual[k] if k < len(actual) else "<no more output>"
        if mask(a) != mask(e) and not (e.endswith(" ...") and mask(a).startswith(mask(e[:-4]))):
            return f"line {k + 1}: expected {e!r}, got {a!r}"
    return f"{len(actual) - len(expected)} extra output line(s), first {actual[len(expected)]!r}"


def main():
    exe = os.path.abspath(sys.argv[1])
    root = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else pathlib.Path(__file__).resolve().parent.parent)
    docs = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    failures, count = [], 0
    with tempfile.TemporaryDirectory() as tmp:
        bindir = pathlib.Path(tmp) / "bin"
        bindir.mkdir()
        (bindir / "sphtroch").symlink_to(exe)
        # Debian's python3 and tools first (the documents are for Debian 12; a pyenv may lack NumPy).
        env = dict(os.environ, PATH=f"{bindir}:/usr/bin:/bin:{os.environ.get('PATH', '')}", LC_ALL="C")
        for doc in docs:
            for start, runs in blocks(doc):
                work = pathlib.Path(tempfile.mkdtemp(dir=tmp))
                (work / "data").symlink_to(root / "data")
                for line_no, command, expected in runs:
                    count += 1
                    r = subprocess.run(["bash", "-c", command], cwd=work, env=env, capture_output=True, text=True,
                                       timeout=300)
                    actual = (r.stdout + r.stderr).splitlines()
                    if not matches(expected, actual):
                        failures.append(f"{doc.relative_to(root)}:{line_no}: $ {command}\n    "
                                        + first_difference(expected, actual))
    for f in failures:
        print("console_examples:", f)
    print(f"console_examples: {count} commands in {len(docs)} documents, {len(failures)} differ")
    return 1 if failures or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
