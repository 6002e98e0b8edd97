#!/usr/bin/env python3
"""Fails (exit 1) when a function body in include/, src/ or python/src is longer than the limit.

  python3 scripts/check_function_length.py [ROOT] [--limit 80] [--list N]

How it measures: comments and string/char literals are blanked, then braces are matched. A `{`
met outside any function body opens a function body when the text before it (back to the last
`;`, `{` or `}`) ends in a parameter list `)` — optionally followed by const, noexcept, override,
a trailing return type or a constructor's member initializers — and does not start with a
control keyword. The length is the number of lines from the line of the signature's `(` to the
closing `}`, inclusive: the lines a reader has to take in at once. Lambdas and local classes count
as part of the function that contains them.
"""
import os
import re
import sys

LIMIT = 80
DIRS = ["include", "src", "python/src"]
CONTROL = re.compile(r"^\s*(if|for|while|switch|catch|do|else|return|namespace|struct|class|union|enum)\b")


def blank(code):
    """Comments and literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(code)
    while i < n:
        c = code[i]
        if code.startswith("//", i):
            j = code.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif code.startswith("/*", i):
            j = code.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", code[i:j])); i = j
        elif c == 'R' and code.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', code[i:])
            end = code.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", code[i:j])); i = j
        elif c in "\"'" and not (c == "'" and i > 0 and code[i - 1].isalnum()):  # 1'000 separators
            j = i + 1
            while j < n and code[j] != c:
                j += 2 if code[j] == "\\" else 1
            out.append(c + " " * (j - i - 1) + c if j < n else ""); i = j + 1
        else:
            out.append(c); i += 1
    return "".join(out)


def functions(code):
    """(name, first line, last line) of every function body."""
    text = blank(code)
    found, depth, body_depth, head_start = [], 0, None, 0
    inner = []  # per open brace: True for a brace inside an unclosed "(" of a head (a default `= {}`)
    for i, c in enumerate(text):
        if c in ";{}" and body_depth is None:
            head = text[head_start:i]
        if c == "{":
            in_parens = body_depth is None and head.count("(") > head.count(")")
            inner.append(in_parens)
            if body_depth is None and not in_parens:
                h = " ".join(head.split())
                m = re.search(r"(\w[\w:~<>,\s]*?|operator\s*\S+)\s*\((.*)\)\s*(const|noexcept|override|final|mutable|->\s*[\w:<>,\s*&]+|:\s*.*)*\s*$", h)
                if m and "=" not in h.split("(")[0] and not CONTROL.match(h):
                    lead = len(head) - len(head.lstrip())
                    start = head_start + lead + head[lead:].find("(")
                    body_depth = depth
                    name = h.split("(")[0].split()[-1] if h.split("(")[0].split() else "?"
                    found.append([name, text.count("\n", 0, start) + 1, None])
            depth += 1
            if not in_parens:
                head_start = i + 1
        elif c == "}":
            depth -= 1
            was_inner = inner.pop() if inner else False
            if body_depth is not None and depth == body_depth:
                found[-1][2] = text.count("\n", 0, i) + 1
                body_depth = None
            if not was_inner:
                head_start = i + 1
        elif c == ";" and body_depth is None and text[head_start:i].count("(") <= text[head_start:i].count(")"):
            head_start = i + 1
        elif c == "#" and body_depth is None:  # preprocessor lines are not part of a head
            j = text.find("\n", i)
            head_start = j + 1 if j >= 0 else i + 1
    return [f for f in found if f[2] is not None]


def main():
    args = sys.argv[1:]
    limit = LIMIT
    listing = 0
    if "--limit" in args:
        k = args.index("--limit"); limit = int(args[k + 1]); del args[k:k + 2]
    if "--list" in args:
        k = args.index("--list"); listing = int(args[k + 1]); del args[k:k + 2]
    root = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    rows = []
    for d in DIRS:
        for base, _, files in os.walk(os.path.join(root, d)):
            for f in files:
                if f.endswith((".hpp", ".cpp", ".h")):
                    path = os.path.join(base, f)
                    code = open(path, encoding="utf-8").read()
                    for name, a, b in functions(code):
                        rows.append((b - a + 1, os.path.relpath(path, root), a, name))
    rows.sort(reverse=True)
    for r in rows[:listing]:
        print(f"{r[0]:5d}  {r[1]}:{r[2]}  {r[3]}")
    long = [r for r in rows if r[0] > limit]
    for r in long:
        print(f"check_function_length: {r[1]}:{r[2]} {r[3]} is {r[0]} lines (limit {limit})")
    print(f"check_function_length: {len(rows)} functions, longest {rows[0][0] if rows else 0} lines, "
          f"{len(long)} over {limit}")
    return 1 if long else 0


if __name__ == "__main__":
    sys.exit(main())
