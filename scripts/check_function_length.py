#!/usr/bin/env python3
"""Fails (exit 1) when a function in include/, src/, python/src or explorer/ is longer than the limit.

  python3 scripts/check_function_length.py [ROOT] [--limit 80] [--list N]

C++ (.hpp, .cpp, .h; explorer/ holds the WebAssembly module's source). How it measures: comments and string/char literals are blanked, then braces are matched. A `{`
met outside any function body opens a function body when the text before it (back to the last
`;`, `{` or `}`) ends in a parameter list `)` — optionally followed by const, noexcept, override,
a trailing return type or a constructor's member initializers — and does not start with a
control keyword. The length is the number of lines from the line of the signature's `(` to the
closing `}`, inclusive: the lines a reader has to take in at once. Lambdas and local classes count
as part of the function that contains them.

JavaScript (.js under explorer/: the page's scripts, the worker, the tests; not node_modules). How
it measures: comments, string, template and regular-expression literals are blanked, then braces
are matched. A `{` met outside any function body opens a function body when it follows `=>` (an
arrow function), or a parameter list `)` whose `(` follows `function [name]` (a function
declaration or expression) or a name that is not a control keyword (a method). The length is the
number of lines from the line of `function` (of the method's name, of the arrow's `=>`) to the
closing `}`, inclusive. A function inside another counts as part of it; so does a whole file
wrapped in one: a file's top-level block `{ ... }` (which keeps its names local) is not a function.
"""
import os
import re
import sys

LIMIT = 80
DIRS = ["include", "src", "python/src", "explorer"]
JS_DIRS = ["explorer"]
SKIP_DIRS = {"node_modules"}
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


JS_CONTROL = {"if", "for", "while", "switch", "catch", "with", "return", "typeof", "await", "yield", "in", "of",
              "new", "delete", "void", "instanceof", "case", "do", "else"}
# A `/` after one of these characters or keywords (or at the start) opens a regular expression;
# after a name, a number, a literal, `)` or `]` it divides.
JS_REGEX_AFTER = set("(,=:[!&|?{};+-*%<>~^") | JS_CONTROL | {""}
JS_WORD = re.compile(r"[A-Za-z_$][\w$]*|\d[\w.]*")


def js_literal_end(code, i):
    """The index after the string, template or regex literal that starts at i (its flags too)."""
    quote, j, n = code[i], i + 1, len(code)
    while j < n and code[j] != quote:
        if quote == "/" and code[j] == "[":  # a character class: "/" does not end the regex there
            while j < n and code[j] != "]":
                j += 2 if code[j] == "\\" else 1
        j += 2 if j < n and code[j] == "\\" else 1
    j += 1
    while quote == "/" and j < n and (code[j].isalnum() or code[j] == "_"):
        j += 1
    return min(j, n)


def js_blank(code):
    """JavaScript with comments and string, template and regex literals replaced by spaces."""
    out, i, n = [], 0, len(code)
    last = ""  # the last word or significant character outside literals: a regex or a division?
    while i < n:
        c = code[i]
        word = JS_WORD.match(code, i)
        if word:
            out.append(word.group(0)); last = word.group(0); i = word.end()
            continue
        if code.startswith("//", i):
            j = code.find("\n", i)
            j = n if j < 0 else j
        elif code.startswith("/*", i):
            j = code.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif c in "'\"`" or (c == "/" and last in JS_REGEX_AFTER):
            j = js_literal_end(code, i)
            last = "a"  # a value: a "/" after it divides
        else:
            out.append(c)
            last = last if c.isspace() else c
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", code[i:j]))
        i = j
    return "".join(out)


def js_functions(code):
    """(name, first line, last line) of every outermost JavaScript function."""
    text = js_blank(code)
    line = lambda k: text.count("\n", 0, k) + 1
    found, depth, body_depth = [], 0, None
    for i, c in enumerate(text):
        if c == "{":
            if body_depth is None:
                start = js_function_start(text, i)
                if start is not None:
                    body_depth = depth
                    found.append([start[0], line(start[1]), None])
            depth += 1
        elif c == "}":
            depth -= 1
            if body_depth is not None and depth == body_depth:
                found[-1][2] = line(i)
                body_depth = None
    return [f for f in found if f[2] is not None]


def js_function_start(text, brace):
    """(name, index where the function starts) when the `{` at `brace` opens a function body."""
    k = brace - 1
    while k >= 0 and text[k].isspace():
        k -= 1
    if k >= 1 and text[k - 1:k + 1] == "=>":
        m = re.search(r"([\w$]+)\s*=\s*(async\s*)?(\([^()]*\)|[\w$]+)\s*=>\s*$", text[:brace])
        return (m.group(1) if m else "(arrow)", k - 1)
    if k < 0 or text[k] != ")":
        return None
    level, j = 0, k
    while j >= 0:  # the matching "("
        level += {")": 1, "(": -1}.get(text[j], 0)
        if level == 0:
            break
        j -= 1
    head = text[max(0, j - 200):j]
    m = re.search(r"\bfunction\b\s*\*?\s*([\w$]*)\s*$", head)
    if m:
        return (m.group(1) or "(function)", j - len(head) + m.start())
    m = re.search(r"([\w$]+)\s*$", head)
    if m and m.group(1) not in JS_CONTROL:
        return (m.group(1), j - len(head) + m.start(1))
    return None


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
    for d in sorted(set(DIRS) | set(JS_DIRS)):
        for base, dirs, files in os.walk(os.path.join(root, d)):
            dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS)
            for f in sorted(files):
                path = os.path.join(base, f)
                if d in DIRS and f.endswith((".hpp", ".cpp", ".h")):
                    finder = functions
                elif d in JS_DIRS and f.endswith(".js"):
                    finder = js_functions
                else:
                    continue
                code = open(path, encoding="utf-8").read()
                for name, a, b in finder(code):
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
