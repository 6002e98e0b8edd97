#!/usr/bin/env python3
"""The lists the docs keep about the tree, compared with the tree, so that they cannot drift.

    python3 scripts/check_doc_lists.py ROOT      (ctest docs:lists)

- CMake targets: the `add_library(sphtroch::X ALIAS ...)` of ROOT/CMakeLists.txt, the rows
  "| `sphtroch::X` |" of README.md's and docs/library.md's target tables, and the count word of
  docs/library.md's "<N> CMake targets" sentence.
- Guarded headers: the headers under include/sphtroch/ with an `#error` line, and the list between
  "<!-- guarded-headers -->" and "<!-- end guarded-headers -->" in docs/library.md (paths in
  backquotes, relative to include/sphtroch/); each listed header's #error names the target the
  list gives it.
- Umbrella: include/sphtroch/sphtroch.hpp includes every header under include/sphtroch/ but
  itself and exact_implementation.hpp (separate mode's one definition file); its opening comment
  and README.md's target table name every layer folder ("core/", ...).
Prints one line per disagreement; exit 1 if any, 0 otherwise, 2 on bad arguments.
"""
import pathlib
import re
import sys

COUNT_WORDS = {1: "One", 2: "Two", 3: "Three", 4: "Four", 5: "Five", 6: "Six", 7: "Seven", 8: "Eight"}
NOT_IN_UMBRELLA = {"sphtroch.hpp", "exact_implementation.hpp"}


def table_targets(text):
    return set(re.findall(r"^\| `(sphtroch::\w+)` \|", text, flags=re.M))


def check_targets(root, readme, library, problems):
    cmake = (root / "CMakeLists.txt").read_text(encoding="utf-8")
    defined = set(re.findall(r"add_library\((sphtroch::\w+) ALIAS", cmake))
    for name, text in (("README.md", readme), ("docs/library.md", library)):
        listed = table_targets(text)
        for t in sorted(defined - listed):
            problems.append(f"{name}: the target table lacks {t} (CMakeLists.txt defines it)")
        for t in sorted(listed - defined):
            problems.append(f"{name}: the target table lists {t}, which CMakeLists.txt does not define")
    m = re.search(r"\b(\w+) CMake targets", library)
    want = COUNT_WORDS.get(len(defined), str(len(defined)))
    if not m or m.group(1) != want:
        problems.append(f"docs/library.md: says '{m.group(1) if m else '?'} CMake targets', the tree has {want}")


def check_guarded(root, library, problems):
    include = root / "include" / "sphtroch"
    guarded = {}
    for h in sorted(include.rglob("*.hpp")):
        line = next((l for l in h.read_text(encoding="utf-8").splitlines() if l.startswith("#error")), None)
        if line:
            guarded[h.relative_to(include).as_posix()] = line
    m = re.search(r"<!-- guarded-headers -->(.*?)<!-- end guarded-headers -->", library, flags=re.S)
    if not m:
        problems.append("docs/library.md: no guarded-headers list (<!-- guarded-headers --> ... <!-- end guarded-headers -->)")
        return
    listed = {}
    # Groups separated by ";", each a list of backquoted header paths and then its target in parentheses.
    for group in m.group(1).split(";"):
        target = re.search(r"\(`(sphtroch::\w+)`\)", group)
        for header in re.findall(r"`([\w/]+\.hpp)`", group):
            listed[header] = target.group(1) if target else None
    for h in sorted(set(guarded) - set(listed)):
        problems.append(f"docs/library.md: the guarded-headers list lacks {h} (it has an #error)")
    for h in sorted(set(listed) - set(guarded)):
        problems.append(f"docs/library.md: the guarded-headers list names {h}, which has no #error")
    for h in sorted(set(listed) & set(guarded)):
        if listed[h] is None or listed[h] not in guarded[h]:
            problems.append(f"docs/library.md: {h} is listed under {listed[h]}, its #error says: {guarded[h][:100]}")


def check_umbrella(root, readme, problems):
    include = root / "include" / "sphtroch"
    umbrella = (include / "sphtroch.hpp").read_text(encoding="utf-8")
    included = set(re.findall(r'^#include "sphtroch/([\w/]+\.hpp)"', umbrella, flags=re.M))
    for h in sorted(include.rglob("*.hpp")):
        rel = h.relative_to(include).as_posix()
        if rel not in NOT_IN_UMBRELLA and rel not in included:
            problems.append(f"include/sphtroch/sphtroch.hpp: does not include sphtroch/{rel}")
    comment = "\n".join(l for l in umbrella.splitlines() if l.startswith("//"))
    table = "\n".join(l for l in readme.splitlines() if l.startswith("| `sphtroch::"))
    for folder in sorted(p.name for p in include.iterdir() if p.is_dir()):
        if f"{folder}/" not in comment:
            problems.append(f"include/sphtroch/sphtroch.hpp: its opening comment does not name {folder}/")
        if f"`{folder}/`" not in table:
            problems.append(f"README.md: the target table does not name `{folder}/`")


def main(argv):
    if len(argv) != 2 or not pathlib.Path(argv[1]).is_dir():
        print("usage: check_doc_lists.py ROOT", file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1])
    readme = (root / "README.md").read_text(encoding="utf-8")
    library = (root / "docs" / "library.md").read_text(encoding="utf-8")
    problems = []
    check_targets(root, readme, library, problems)
    check_guarded(root, library, problems)
    check_umbrella(root, readme, problems)
    for p in problems:
        print("check_doc_lists:", p)
    print(f"check_doc_lists: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
